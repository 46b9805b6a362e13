#!/usr/bin/env bash
# Behaviour-unchanged check for refactors: runs the same short scenes with two hvi binaries and
# compares every result file byte for byte (HDF5 carries no time stamps, so identical results
# are identical files). summary.json is compared without its wall-time and throughput keys.
#
#   tools/same_results.sh OLD_HVI NEW_HVI [WORKDIR]
#
# OLD_HVI is typically a build of the commit before the refactor (git worktree add ../base REV;
# cmake -S ../base -B ../base/build -DHVI_ENABLE_TESTS=OFF; cmake --build ../base/build --target hvi).
# Exit 0 when every file of every scene is identical, 1 otherwise (the differing files are listed).
set -uo pipefail
old=$(realpath "$1") new=$(realpath "$2")
work=${3:-$(mktemp -d /tmp/hvi-same.XXXXXX)}
root=$(cd "$(dirname "$0")/.." && pwd)
export OMP_WAIT_POLICY=passive OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}

# scene | extra --set overrides (short end times keep the whole check to a few minutes)
scenes=(
  "default.toml|time.end=1 us;output.times=[\"0.5 us\",\"1 us\"]"
  "variant1_sph_coarse.toml|time.end=1 us;output.times=[\"0.3 us\",\"1 us\"]"
  "variant1_tvd_coarse.toml|time.end=2 us;output.times=[\"1 us\",\"2 us\"]"
  "variant2_sph_traditional_coarse.toml|time.end=0.5 us;output.times=[\"0.5 us\"]"
  "variant2_tvd_coarse.toml|time.end=2 us;output.times=[\"1 us\",\"2 us\"]"
  "sod_x.toml|"
  "al_impact_tube.toml|"
  "hard/oblique_45.toml|time.end=0.5 us;output.times=[\"0.5 us\"]"
  "hard/dense_striker.toml|time.end=0.3 us;output.times=[\"0.3 us\"]"
  "study/noh_cylindrical_rz.toml|"
  # effects strength and fracture (planar Steinberg-Guinan, r-z Johnson-Cook, both alloys)
  "spall_plate_sph.toml|time.end=1 us;output.times=[\"0.5 us\",\"1 us\"]"
  "taylor_copper_sph.toml|time.end=3 us;output.times=[\"1 us\",\"3 us\"]"
  "variant1_alloys_sph_coarse.toml|time.end=1 us;output.times=[\"0.5 us\",\"1 us\"]"
  "variant1_alloys_tvd_coarse.toml|time.end=0.5 us;output.times=[\"0.5 us\"]"
)
mkdir -p "$work/old" "$work/new"
status=0
for entry in "${scenes[@]}"; do
  scene=${entry%%|*}
  sets=()
  IFS=';' read -ra kv <<< "${entry#*|}"
  for s in "${kv[@]}"; do [[ -n $s ]] && sets+=(--set "$s"); done
  name=${scene//\//_}
  name=${name%.toml}
  for side in old new; do
    bin=$old; [[ $side == new ]] && bin=$new
    rm -rf "$work/$side/$name"
    "$bin" run "$root/cases/scenes/$scene" --out "$work/$side/$name" --quiet "${sets[@]}" \
      > "$work/$side.$name.log" 2>&1
    echo "$?" > "$work/$side/$name.rc"
  done
  if ! cmp -s "$work/old/$name.rc" "$work/new/$name.rc"; then
    echo "DIFF $name: exit $(cat "$work/old/$name.rc") vs $(cat "$work/new/$name.rc")"; status=1; continue
  fi
  diffs=0
  for f in "$work/old/$name"/*; do
    b=$(basename "$f")
    g="$work/new/$name/$b"
    if [[ ! -e $g ]]; then echo "DIFF $name: $b missing in new"; diffs=1; continue; fi
    if [[ $b == summary.json ]]; then
      /usr/bin/python3 - "$f" "$g" <<'EOF' || diffs=1
import json, sys
drop = {"wall_seconds", "updates_per_second", "updates_per_second_per_core", "scene"}
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for k in drop: a.pop(k, None); b.pop(k, None)
if a != b:
    print(f"DIFF summary.json: {sys.argv[1]}"); sys.exit(1)
EOF
    elif ! cmp -s "$f" "$g"; then
      echo "DIFF $name: $b"; diffs=1
    fi
  done
  for g in "$work/new/$name"/*; do
    [[ -e "$work/old/$name/$(basename "$g")" ]] || { echo "DIFF $name: $(basename "$g") only in new"; diffs=1; }
  done
  [[ $diffs == 0 ]] && echo "same $name (exit $(cat "$work/new/$name.rc"))" || status=1
done
echo "results in $work"
exit $status
