#!/bin/bash
# SPH whole-step throughput of two builds side by side (issue 17): rounds alternate the builds
# so that both see the same load; the load is printed with each run. For people, not CI.
#   tools/bench_sph_versus.sh BASE_BUILD_DIR [NEW_BUILD_DIR=build]
#   ROUNDS=2 THREADS="1 2" ARGS="5 200" tools/bench_sph_versus.sh /work/main/build
# Compare the "per CPU-second" lines (set-up excluded); wall time is inflated by other load.
# The peak RSS line is the whole process's (set-up included).
set -eu
BASE=${1:?usage: $0 BASE_BUILD_DIR [NEW_BUILD_DIR]}
NEW=${2:-build}
export OMP_WAIT_POLICY=passive
for r in $(seq 1 "${ROUNDS:-2}"); do
  for t in ${THREADS:-1 2}; do
    for dir in "$BASE" "$NEW"; do
      echo "round $r, $t threads, $dir, load $(uptime | sed 's/.*average: //')"
      OMP_NUM_THREADS=$t /usr/bin/time -f "peak RSS %M KiB" "$dir/bin/hvi_bench_sph" ${ARGS:-5 200} 2>&1 |
        grep -E "particles|per thread|CPU|drift|peak RSS" | sed 's/^/   /'
    done
  done
done
