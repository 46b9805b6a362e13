#!/usr/bin/env bash
# hvi beside its two anchors (issue 17), side by side in one run, one thread each; prints ratios.
# For people, not CI (needs a network or a local clone, and minutes of machine time):
#
#   tools/bench_anchors.sh [sod|pysph|all]      (default: all)
#
#   sod    2-D Sod, 512 x 512 cells on [0,1]^2 (diaphragm x = 0.5 (hvi) / 0 on [-0.5,0.5]
#          (Athena++)), ideal gas 1.4, CFL 0.4, to t = 0.2: hvi's TVD (minmod, effects = [])
#          against Athena++ (--prob shock_tube --flux hllc, PLM, VL2) built with hvi's compiler
#          and optimisation (-O3; no -march, as hvi's default build). Ratio of cell-updates per
#          second (hvi: summary.json; Athena++: its zone-cycles/cpu_second).
#   pysph  hvi_bench_sph 5 200 (variant 2, modified SPH) against PySPH's 2-D solid_mech/impact.py
#          (Debian python3-pysph), 200 steps: particle-updates per CPU second of the time loop
#          (set-up excluded on both sides: hvi's fill and mass iteration, PySPH's code generation).
#
# Environment: ATHENA_DIR (default /work/anchors/athena; cloned from GitHub if absent, never
# inside this repository), HVI_BUILD (default build), N (Sod cells per side, default 512),
# N_HVI (hvi's cells per side, default N: a larger grid compares the L1 errors at equal CPU
# time), LIMITER (hvi's limiter, default minmod),
# ATHENA_REF (git commit, default the one issue 17 measured: ed4d1e3).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${HVI_BUILD:-$root/build}
athena=${ATHENA_DIR:-/work/anchors/athena}
n=${N:-512}
nh=${N_HVI:-$n}              # hvi's grid (N_HVI > N: hvi at equal CPU time, for the L1 error)
limiter=${LIMITER:-minmod}   # hvi's limiter
what=${1:-all}
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive
tmp=$(mktemp -d /tmp/hvi_anchors.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

ratio() { /usr/bin/python3 -c "print('%.3g' % ($1 / $2))"; }

sod() {
  if [[ ! -x $athena/bin/athena ]]; then
    if [[ ! -d $athena ]]; then
      git clone https://github.com/PrincetonUniversity/athena "$athena"
      git -C "$athena" checkout -q "${ATHENA_REF:-ed4d1e3}"
    fi
    (cd "$athena" && python3 configure.py --prob shock_tube --flux hllc --cxx g++ >/dev/null &&
      make -j"$(nproc)" >/dev/null)
  fi
  echo "Athena++ $(git -C "$athena" log -1 --format=%h), $(grep -m1 '^CXXFLAGS' "$athena/Makefile")"
  # hvi: the 2-D Sod scene (sod_x.toml's states on the unit square, walls all round).
  cat >"$tmp/sod2d.toml" <<TOML
title = "2-D Sod, $nh x $nh (issue 17 anchor)"
geometry = "planar"
solver = "tvd"
effects = []
[time]
start = "0 us"
end = "0.2 us"
[domain]
x = ["0 cm", "1 cm"]
z = ["0 cm", "1 cm"]
boundaries = { xmin = "wall", xmax = "wall", zmin = "wall", zmax = "wall" }
[materials.gas]
eos = "ideal_gas"
gamma = 1.4
rho0 = "1 g/cm^3"
[[bodies]]
name = "left"
material = "gas"
shape = "rect"
x = ["0 cm", "0.5 cm"]
z = ["0 cm", "1 cm"]
density = "1 g/cm^3"
pressure = "1 Mbar"
[[bodies]]
name = "right"
material = "gas"
shape = "rect"
x = ["0.5 cm", "1 cm"]
z = ["0 cm", "1 cm"]
density = "0.125 g/cm^3"
pressure = "0.1 Mbar"
[tvd]
cell_size = "$(/usr/bin/python3 -c "print(1/$nh)") cm"
limiter = "$limiter"
cfl = 0.4
[output]
times = ["0.2 us"]
hdf5 = false
vtk = false
TOML
  # CPU seconds of the process (Athena++ reports per CPU second too): on a shared machine the
  # wall time also counts the time other processes held the core. hvi's includes its set-up.
  /usr/bin/time -f "%U %S" -o "$tmp/hvi_time" "$build/bin/hvi" run "$tmp/sod2d.toml" -o "$tmp/hvi_sod" -q
  local hvi_ups hvi_steps hvi_wall hvi_cpu
  hvi_cpu=$(awk '{print $1 + $2}' "$tmp/hvi_time")
  read -r hvi_ups hvi_steps hvi_wall < <(/usr/bin/python3 -c "import json; s = json.load(open('$tmp/hvi_sod/summary.json')); print(s['work_items'] * s['steps'] / $hvi_cpu, s['steps'], s['wall_seconds'])")
  # Athena++: its own Sod input, made 2-D and matched (outputs only at the start and end).
  (cd "$tmp" && "$athena/bin/athena" -i "$athena/inputs/hydro/athinput.sod" \
    mesh/nx1="$n" mesh/nx2="$n" mesh/x2min=-0.5 mesh/x2max=0.5 \
    time/cfl_number=0.4 time/tlim=0.2 time/xorder=2 time/integrator=vl2 time/ncycle_out=100000 \
    output1/dt=1 output2/dt=1 problem/compute_error=1 hydro/gamma=1.4 >"$tmp/athena.log")
  local ath_zc ath_cpu
  ath_zc=$(awk -F= '/zone-cycles\/cpu_second/ {gsub(/ /, "", $2); print $2}' "$tmp/athena.log")
  ath_cpu=$(awk -F= '/cpu time used/ {gsub(/ /, "", $2); print $2}' "$tmp/athena.log")
  echo "hvi TVD:  $nh x $nh, $limiter, $hvi_steps steps, CPU $hvi_cpu s (wall $hvi_wall s), $(printf %.3e "$hvi_ups") cell-updates per CPU second"
  echo "hvi L1 density error at t = 0.2 (mean |rho - rho_exact| over the cells): $(/usr/bin/python3 "$root/tools/sod_l1.py" "$tmp/hvi_sod/checkpoint.bin")"
  echo "Athena++: $(awk -v c=$((n * n)) '/^zone-cycles =/ {print $3 / c " cycles"}' "$tmp/athena.log"), CPU $ath_cpu s, $ath_zc zone-cycles per CPU second"
  [[ -f $tmp/shock-errors.dat ]] && echo "Athena++ L1 errors (Nx1 Nx2 Nx3 cycles RMS rho M1 M2 M3 E): $(tail -1 "$tmp/shock-errors.dat")"
  echo "SOD RATIO hvi / Athena++ = $(ratio "$hvi_ups" "$ath_zc")   (issue 17 target: >= 1.5)"
}

pysph() {
  if ! /usr/bin/python3 -c 'import pysph' 2>/dev/null; then
    echo "PySPH missing: apt-get install python3-pysph" >&2
    return 1
  fi
  "$build/bin/hvi_bench_sph" 5 200 | tee "$tmp/hvi_sph.log"
  local hvi_ups
  hvi_ups=$(awk '/per CPU-second/ {for (i = 1; i <= NF; ++i) if ($i == "particle-updates") print $(i - 1)}' "$tmp/hvi_sph.log")
  (cd "$tmp" && /usr/bin/python3 - <<'PY' | tee "$tmp/pysph.log"
import time
from pysph.examples.solid_mech.impact import Impact
import pysph.solver.solver as S
span = []
solve = S.Solver.solve
def timed(self, *a, **k):  # the time loop only: not the set-up (code generation, compile)
    t = time.process_time()
    r = solve(self, *a, **k)
    span.append(time.process_time() - t)
    return r
S.Solver.solve = timed
app = Impact(fname="impact")
app.run(["--max-steps", "200", "--disable-output", "-d", "pysph_out"])
wall = span[0]
n = sum(pa.get_number_of_particles() for pa in app.particles)
steps = app.solver.count
print("PySPH impact.py: %d particles, %d steps, %.1f s CPU: %.3e particle-updates/s" % (n, steps, wall, n * steps / wall))
PY
  )
  local py_ups
  py_ups=$(awk '/^PySPH/ {print $(NF - 1)}' "$tmp/pysph.log")
  echo "SPH RATIO hvi / PySPH = $(ratio "$hvi_ups" "$py_ups")"
}

case $what in
  sod) sod ;;
  pysph) pysph ;;
  all) sod; pysph ;;
  *) echo "usage: $0 [sod|pysph|all]" >&2; exit 2 ;;
esac
