# Sourced by the checks that count pond's calls under VK_LAYER_POND_discrete_gpu ($work: their
# directory). counted NAME COMMAND...: runs COMMAND with the layer's counters written to
# $work/NAME.json (its output to NAME.out and NAME.err); exits 1 on a non-zero exit, no counters or
# a validation message. count NAME KEY: one counter of that run.
counted() {
  name=$1
  shift
  rm -f "$work/$name.json"
  POND_DISCRETE_GPU_STATS="$work/$name.json" "$@" > "$work/$name.out" 2> "$work/$name.err"
  rc=$?
  if [ $rc -ne 0 ] || [ ! -s "$work/$name.json" ]; then
    echo "FAILED: $name: exit $rc, no counters? $(head -c 2000 "$work/$name.err")"
    exit 1
  fi
  if grep -qi "validation\|VUID" "$work/$name.err"; then
    echo "FAILED: $name: validation messages: $(head -c 2000 "$work/$name.err")"
    exit 1
  fi
}
count() { sed -n "s/.*\"$2\": \([0-9]*\).*/\1/p" "$work/$1.json"; }
