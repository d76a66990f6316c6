#!/bin/sh
# The IA-32 build (-m32 -msse2 -mfpmath=sse) gives the golden hash of the default scene after
# 1,000 steps on its scalar and SSE backends, the same bits as the 64-bit build and the GPU.
# Usage: ia32_golden_test.sh PATH/TO/32-bit/pond EXPECTED_HASH WORKDIR
set -u
pond=$1
want=$2
work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
# The ELF header's fifth byte (EI_CLASS) is 1 for a 32-bit program: read with od (coreutils), since
# `file` is not on a minimal Debian.
magic=$(od -An -c -j1 -N3 "$pond" 2>/dev/null | tr -d ' ')
class=$(od -An -tu1 -j4 -N1 "$pond" 2>/dev/null | tr -d ' ')
[ "$magic" = "ELF" ] && [ "$class" = "1" ] || { echo "FAIL: $pond is not a 32-bit ELF executable (EI_CLASS ${class:-?})"; exit 1; }
# Some x86-64 kernels are built without IA-32 emulation ("Exec format error" for every 32-bit
# program). There the same 32-bit machine code runs under qemu-i386 (user-mode emulation; its SSE
# is IEEE softfloat, denormals and signed zeros included), which scripts/setup.sh installs.
run=
if ! "$pond" --help >/dev/null 2>&1; then
  command -v qemu-i386 >/dev/null 2>&1 || {
    echo "FAIL: this kernel cannot run 32-bit programs and qemu-i386 is missing (install qemu-user)"; exit 1; }
  run=qemu-i386
  echo "this kernel cannot run 32-bit programs: running $pond under qemu-i386"
fi
status=0
for solver in scalar sse; do
  got=$($run "$pond" simulate --steps 1000 --solver "$solver" --out "$work/$solver.npy" | sed -n 's/^state hash //p')
  if [ "$got" != "$want" ]; then
    echo "FAIL: IA-32 $solver: actual hash $got, golden $want"
    status=1
  else
    echo "IA-32 $solver: $got"
  fi
done
$run "$pond" simulate --steps 1 --solver avx2 --out "$work/x.npy" 2> "$work/err"
[ $? -eq 2 ] && grep -q "not in this build" "$work/err" || { echo "FAIL: avx2 in IA-32: $(cat "$work/err")"; status=1; }
$run "$pond" simulate --steps 1 --solver gpu --out "$work/x.npy" 2> "$work/err"
[ $? -eq 2 ] && grep -q "CPU-only" "$work/err" || { echo "FAIL: gpu in IA-32: $(cat "$work/err")"; status=1; }
exit $status
