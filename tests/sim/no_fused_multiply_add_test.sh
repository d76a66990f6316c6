#!/bin/sh
# No fused multiply-add instruction anywhere in a program's own code: a fused a * b + c rounds once
# instead of twice and would change the bits every backend must share (docs/water.md). Checks the
# disassembly (objdump -d) for aarch64's fmla, fmls, fmadd, fmsub, fnmadd, fnmsub and x86's
# vfmadd..., vfmsub..., vfnmadd..., vfnmsub...; prints the functions that hold one.
# Usage: no_fused_multiply_add_test.sh OBJDUMP PROGRAM
set -u
objdump=$1 program=$2
listing=$(mktemp) || exit 1
trap 'rm -f "$listing"' EXIT
"$objdump" -d --no-show-raw-insn "$program" > "$listing" || { echo "FAIL: $objdump -d $program: exit $?"; exit 1; }
[ -s "$listing" ] || { echo "FAIL: $objdump printed nothing for $program"; exit 1; }
fused=$(awk '/^[0-9a-f]+ <.*>:$/ { fn = $2 }
             $2 ~ /^(fmla|fmls|fmadd|fmsub|fnmadd|fnmsub|vfn?m(add|sub)(sub|add)?[0-9]+[ps][sdh])$/ { print fn, $2 }' "$listing" |
        sort | uniq -c)
if [ -n "$fused" ]; then
  echo "FAIL: fused multiply-adds in $program (count, function, instruction):"
  echo "$fused" | head -20
  exit 1
fi
echo "no fused multiply-add in $(grep -c '^[0-9a-f]* <' "$listing") functions of $program"
