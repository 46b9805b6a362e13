#!/usr/bin/env bash
# Issue 15's cost of strength in SPH, two builds side by side (docs/strength.md, "Cost of
# strength in SPH"): per round each hvi_bench_sph runs variant 2 without strength (0) and with
# it (1), one thread; the two binaries' order alternates by round, so both see the same load.
# Prints particle-updates per CPU-second (set-up excluded), each binary's ratio and the load.
# For people, not CI; only ratios taken side by side mean anything on a loaded machine.
#   tools/bench_sph_strength_cost.sh BASE_BENCH [NEW_BENCH=build/bin/hvi_bench_sph]
#   ROUNDS=10 ARGS="5 200 0.04" TOGETHER=1 HVI_SPH_LANES=4 tools/bench_sph_strength_cost.sh ...
# TOGETHER=1 starts a binary's two runs at once (each then sees the same load as the other).
set -u
base=${1:?usage: $0 BASE_BENCH [NEW_BENCH]}
new=${2:-build/bin/hvi_bench_sph}
ROUNDS=${ROUNDS:-6} ARGS=${ARGS:-"5 200 0.04"}
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
rate() { sed -n 's/.*s: \([0-9.e+]*\) particle-updates per CPU-second/\1/p' "$1"; }
for r in $(seq 1 "$ROUNDS"); do
  order="base new"
  ((r % 2 == 0)) && order="new base"
  for side in $order; do
    b=$base
    [[ $side == new ]] && b=$new
    if [[ ${TOGETHER:-0} == 1 ]]; then
      "$b" $ARGS 0 > "$t/h" & "$b" $ARGS 1 > "$t/s" & wait
    else
      "$b" $ARGS 0 > "$t/h"
      "$b" $ARGS 1 > "$t/s"
    fi
    awk -v r="$r" -v side="$side" -v h="$(rate "$t/h")" -v s="$(rate "$t/s")" \
      -v l="$(cut -d' ' -f1 /proc/loadavg)" \
      'BEGIN { printf "round %d %-4s hydro %.4g strength %.4g ratio %.3f load %s\n", r, side, h, s, h / s, l }'
  done
done
