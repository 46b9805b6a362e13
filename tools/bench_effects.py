#!/usr/bin/python3
"""Cost of each effect and of the marker-line mode on top of the bare scheme (issue 17, goal 4),
and peak memory per work item (goal 3). For people, not CI: timings on a shared machine are only
meaningful as ratios of runs made side by side, so the variants of one solver run interleaved,
round after round, and each round prints its own ratios.

  OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive tools/bench_effects.py [--rounds 2] [--solver sph,tvd]
  tools/bench_effects.py --memory            # peak RSS per SPH particle and per TVD cell

Cost of a variant = (CPU seconds per item-update of the variant) / (same of the bare scheme):
effects that change the dynamics (the tension cut-off, the marker lines change the time step) are
compared per update; the `run` column is the whole run's CPU time over the bare scheme's. CPU time of the whole process (user + system, /usr/bin/time), set-up
included (the mass iteration of mass_adjustment is set-up work): on a loaded machine wall time
also counts the time other processes held the core, CPU time does not. Snapshots are off
(output.hdf5/vtk = false, one output time at the end) so that file writing is not counted.

SPH's bare scheme keeps the Monaghan viscosity: without it a 6 km/s impact does not run (the time
step collapses within 0.08 us), so `artificial_viscosity` is part of the baseline, not an option.
Likewise TVD's keeps the tension cut-off: without it the study's Tillotson aluminium fails in the
first step (negative density at the free surface), as the solver's own throughput bench knows.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Variant 2 (rod on plate, planar) for both solvers; the bare scheme is effects = [].
SPH = {
    "scene": "cases/scenes/variant2_sph_modified.toml",
    "base": ['sph.spacing="0.02 cm"', 'time.end="0.4 us"'],
    "variants": [
        ("bare (artificial_viscosity only)", ["artificial_viscosity"]),
        ("+ tension_cutoff", ["artificial_viscosity", "tension_cutoff"]),
        ("+ mass_adjustment", ["artificial_viscosity", "mass_adjustment"]),
        ("+ phase_bookkeeping", ["artificial_viscosity", "phase_bookkeeping"]),
        ("+ energy_budget", ["artificial_viscosity", "energy_budget"]),
        ("+ features", ["artificial_viscosity", "features"]),
        ("all (the scene's six)", ["artificial_viscosity", "tension_cutoff", "mass_adjustment",
                                   "phase_bookkeeping", "energy_budget", "features"]),
    ],
}
TVD = {
    "scene": "cases/scenes/variant2_tvd.toml",
    "base": ['tvd.cell_size="0.03 cm"', 'time.end="1 us"'],
    "variants": [
        ("bare (tension_cutoff only)", ["tension_cutoff"]),
        ("+ material_interfaces, whole_cell", ["tension_cutoff", "material_interfaces"],
         "whole_cell"),
        ("+ material_interfaces, conservative", ["tension_cutoff", "material_interfaces"],
         "conservative"),
        ("+ phase_bookkeeping", ["tension_cutoff", "phase_bookkeeping"]),
        ("+ energy_budget", ["tension_cutoff", "energy_budget"]),
        ("+ features", ["tension_cutoff", "features"]),
        ("all (the scene's five, conservative)", ["tension_cutoff", "material_interfaces",
                                                  "phase_bookkeeping", "energy_budget",
                                                  "features"], "conservative"),
    ],
}
NO_FILES = ["output.hdf5=false", "output.vtk=false"]


def run(hvi, scene, overrides, out):
    """One `hvi run` under /usr/bin/time; returns summary.json plus peak RSS in bytes."""
    cmd = ["/usr/bin/time", "-f", "maxrss_kib %M cpu %U %S", hvi, "run", os.path.join(ROOT, scene), "-o",
           out, "-q"]
    for o in overrides:
        cmd += ["--set", o]
    p = subprocess.run(cmd, capture_output=True, text=True)
    rss, cpu = 0, float("nan")
    for line in p.stderr.splitlines():
        if line.startswith("maxrss_kib"):
            f = line.split()
            rss = int(f[1]) * 1024
            cpu = float(f[3]) + float(f[4])
    path = os.path.join(out, "summary.json")
    if p.returncode != 0 or not os.path.exists(path):
        tail = (p.stderr or p.stdout).strip().splitlines()[-3:]
        return {"status": "failed (rc %d): %s" % (p.returncode, " | ".join(tail)), "rss": rss}
    with open(path) as f:
        s = json.load(f)
    s["rss"] = rss
    s["cpu"] = cpu
    s["cpu_ups"] = s["work_items"] * s["steps_this_run"] / cpu
    return s


def overrides_of(cfg, v):
    eff = "effects=[%s]" % ", ".join('"%s"' % e for e in v[1])
    o = cfg["base"] + NO_FILES + [eff, 'output.times=["%s"]' % cfg["base"][1].split('"')[1]]
    if len(v) > 2:
        o.append("tvd.interfaces=%s" % v[2])
    return o


def effects(args, tmp):
    for name, cfg in (("sph", SPH), ("tvd", TVD)):
        if name not in args.solver:
            continue
        print("\n== %s: %s %s" % (name, cfg["scene"], " ".join("--set " + o for o in cfg["base"])))
        rounds = []
        for r in range(args.rounds):
            res = []
            for i, v in enumerate(cfg["variants"]):
                res.append(run(args.hvi, cfg["scene"], overrides_of(cfg, v),
                               os.path.join(tmp, "%s_%d_%d" % (name, r, i))))
            rounds.append(res)
        head = "%-40s %9s %6s" % ("variant", "items", "steps")
        head += "".join("  %13s %6s %6s" % ("CPU upd/s r%d" % (r + 1), "cost", "run")
                        for r in range(args.rounds))
        print(head)
        for i, v in enumerate(cfg["variants"]):
            s0 = rounds[0][i]
            line = "%-40s %9s %6s" % (v[0], s0.get("work_items", "-"), s0.get("steps", "-"))
            for r in range(args.rounds):
                s, b = rounds[r][i], rounds[r][0]
                if "cpu_ups" not in s:
                    line += "  %s" % s["status"]
                    continue
                cost = b["cpu_ups"] / s["cpu_ups"] if "cpu_ups" in b else float("nan")
                whole = s["cpu"] / b["cpu"] if "cpu_ups" in b else float("nan")
                line += "  %13.3e %6.2f %6.2f" % (s["cpu_ups"], cost, whole)
            print(line, flush=True)


def memory(args, tmp):
    """Peak RSS of a small and a large run of each solver (a few steps: the arrays are all
    allocated by the first step): RSS / items, and the marginal (large - small) / (items)."""
    cases = [
        ("sph", SPH["scene"], ['sph.spacing="%s cm"' % h for h in ("0.02", "0.01")],
         ["time.end=\"0.02 us\"", "effects=[\"artificial_viscosity\", \"tension_cutoff\", "
          "\"mass_adjustment\"]"]),
        ("tvd", TVD["scene"], ['tvd.cell_size="%s cm"' % h for h in ("0.03", "0.015")],
         ["time.end=\"0.02 us\"", "tvd.interfaces=conservative"]),
        # the bare scheme: one material, no marker lines (the batched sweep)
        ("tvd", TVD["scene"], ['tvd.cell_size="%s cm"' % h for h in ("0.015", "0.0075")],
         ["time.end=\"0.02 us\"", "effects=[\"tension_cutoff\"]"]),
    ]
    print("\n%-5s %-28s %10s %12s %10s %12s" % ("", "resolution", "items", "peak RSS MiB",
                                                  "B/item", "marginal B"))
    for c, (name, scene, sizes, extra) in enumerate(cases):
        if name not in args.solver:
            continue
        got = []
        for k, size in enumerate(sizes):
            s = run(args.hvi, scene, [size] + extra + NO_FILES + ['output.times=["0.02 us"]'],
                    os.path.join(tmp, "mem_%d_%d" % (c, k)))
            if "work_items" not in s:
                print(name, size, s["status"])
                continue
            got.append((s["work_items"], s["rss"]))
            marg = ""
            if len(got) == 2:
                marg = "%12.0f" % ((got[1][1] - got[0][1]) / (got[1][0] - got[0][0]))
            print("%-5s %-28s %10d %12.1f %10.0f %s" % (name, size, s["work_items"],
                                                        s["rss"] / 2**20,
                                                        s["rss"] / s["work_items"], marg),
                  flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--hvi", default=os.path.join(ROOT, "build/bin/hvi"))
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--solver", default="sph,tvd")
    ap.add_argument("--memory", action="store_true", help="peak RSS per item instead")
    args = ap.parse_args()
    if os.environ.get("OMP_NUM_THREADS") is None:
        print("note: OMP_NUM_THREADS unset; the costs are for all cores", file=sys.stderr)
    with tempfile.TemporaryDirectory(prefix="hvi_bench_") as tmp:
        (memory if args.memory else effects)(args, tmp)


if __name__ == "__main__":
    main()
