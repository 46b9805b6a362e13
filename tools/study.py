#!/usr/bin/python3
"""What accuracy costs in time: error against wall time for SPH and TVD (docs/study.md).

    /usr/bin/python3 tools/study.py [--quick] [--out results/study] [--reuse]
        [--hvi build/bin/hvi] [--threads 1] [--jobs 1]
        [--only sod,al_tube,noh_planar,noh_cyl,variant2] [--figures docs/figures] [--selftest]

Sweeps resolution (and the TVD limiter, the SPH kernel and viscosity alpha) on problems with
exact answers (Sod, the Tillotson aluminium impact tube, planar and cylindrical (r-z) Noh) and on
the variant-2 impact (error against the finest run of the same method, and against the finest
TVD run). Writes <out>/study.csv, <out>/study.json, <out>/study_tables.md, figures
<figures>/study_<problem>.png and prints the observed orders. The tables keep the rows of the
problems not run this time (from <out>/study.json), so `--only` adds or replaces problems
without dropping the others; figures are drawn for the problems run. --reuse keeps runs already
completed with the same arguments. --selftest checks the python exact solutions against
published values, the r-z particle weights of the error measure, and, if hvi is built, the C++
exact Riemann solver.
"""
import argparse
import csv
import json
import os
import sys
import time
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import study_analysis as an  # noqa: E402
import study_exact as ex  # noqa: E402
import study_measure as ms  # noqa: E402
from study_plan import plan_runs, PROBLEMS, ACCURACY_TARGETS, STRIP_ROWS  # noqa: E402
from study_run import run_hvi, reference_profile  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CSV_KEYS = ["problem", "solver", "option", "resolution", "work_items", "wall_seconds",
            "cpu_seconds", "error",
            "steps", "threads", "status", "reference", "load_before", "coverage", "note"]


def measure_exact(run, exact):
    """Error of a 1-D run against the exact profile; None (with the reason) when the run's
    samples do not fill the window (material missing: a broken fill, a hole), since an L1 over
    part of the window would flatter the run."""
    prob = PROBLEMS[run["problem"]]
    try:
        snap = ms.snapshot_at(run["dir"], prob["end"])
        rel, absl1, coverage = ms.l1_error_1d(snap, exact, prob["window"], STRIP_ROWS * run["h"])
    except (OSError, ValueError, KeyError) as e:
        return None, {"note": f"not measured: {e}"}
    extra = {"abs_l1": absl1, "coverage": coverage}
    # Cells cut by the window's ends and particle volumes m/rho (summation density) make the
    # covered share differ from 1 by a few per cent at most; 10 per cent means missing material.
    if abs(coverage - 1.0) > 0.1:
        extra["note"] = f"samples cover {coverage:.2f} of the window: not measured"
        extra["rel_l1_partial"] = rel
        return None, extra
    return rel, extra


def row_of(run, summary, error, extra=None):
    r = {"problem": run["problem"], "solver": run["solver"], "option": run["option"],
         "resolution": run["h"], "work_items": summary.get("work_items"),
         "wall_seconds": summary.get("wall_seconds"), "error": error,
         "steps": summary.get("steps"), "threads": summary.get("threads"),
         "status": summary.get("status"), "reference": bool(run.get("reference")),
         "load_before": summary.get("_load_before"),
         "cpu_seconds": summary.get("_cpu_seconds"), "run_dir": os.path.relpath(run["dir"], ROOT)}
    if extra:
        r.update(extra)
    return r


def impact_rows(runs, results, hvi, out):
    """Variant 2: each run against the finest of its method (self-convergence; rows carry
    h_ref), against the finest TVD run (problem <name>_vs_tvd), and each SPH run against the TVD
    run at the same resolution (returned separately)."""
    rows, cross = [], []
    done = {r["dir"]: results[r["dir"]].get("status") == "completed" for r in runs}
    refs = {r["method"]: r for r in runs if r.get("reference")}
    tvd_ref = next((r for m, r in refs.items() if m.startswith("tvd")), None)

    def compare(a, b, tag):
        c = ms.hvi_compare(hvi, a["dir"], b["dir"], b["end"],
                           os.path.join(out, "compare", b["problem"], b["name"] + tag))
        return c

    for run in runs:
        if run.get("reference"):
            continue  # the reference is the zero of its own scale
        summ = results[run["dir"]]
        ref = refs.get(run["method"])
        c = compare(ref, run, "_vs_ref") if done[run["dir"]] and ref and done[ref["dir"]] else None
        extra = {"h_ref": ref["h"] if ref else None}
        if c:
            extra["iou_min"] = c["materials"]["min_iou"]
        rows.append(row_of(run, summ, c["density"]["material"]["rel_l1"] if c else None, extra))
    for run in runs:
        if tvd_ref is None or run is tvd_ref or not (done[run["dir"]] and done[tvd_ref["dir"]]):
            continue
        c = compare(tvd_ref, run, "_vs_tvd")
        extra = {"h_ref": tvd_ref["h"] if run["solver"] == "tvd" else 0.0}
        if c:
            extra["iou_min"] = c["materials"]["min_iou"]
        r2 = row_of(run, results[run["dir"]], c["density"]["material"]["rel_l1"] if c else None,
                    extra)
        r2["problem"] = run["problem"] + "_vs_tvd"
        r2["reference"] = False  # the finest SPH run is a point of this comparison
        rows.append(r2)
    tvd_at = {r["h"]: r for r in runs if r["solver"] == "tvd"}
    for run in runs:
        t = tvd_at.get(run["h"])
        if run["solver"] != "sph" or t is None or not (done[run["dir"]] and done[t["dir"]]):
            continue
        c = compare(t, run, "_vs_tvd_same_h")
        if c:
            cross.append({"method": run["method"], "resolution": run["h"],
                          "rel_l1": c["density"]["material"]["rel_l1"],
                          "iou_min": c["materials"]["min_iou"],
                          "features_diff": c.get("features_diff")})
    return rows, cross


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="small subset (a few minutes)")
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "study"))
    ap.add_argument("--figures", default=os.path.join(ROOT, "docs", "figures"))
    ap.add_argument("--reuse", action="store_true", help="keep completed runs")
    ap.add_argument("--hvi", default=os.path.join(ROOT, "build", "bin", "hvi"))
    ap.add_argument("--threads", type=int, default=1, help="OpenMP threads per run")
    ap.add_argument("--jobs", type=int, default=1, help="runs at the same time")
    ap.add_argument("--only", default="", help="comma-separated problems")
    ap.add_argument("--cost", choices=["wall", "cpu"], default="wall",
                    help="cost axis: the run's wall time, or its CPU time (busy machine)")
    ap.add_argument("--selftest", action="store_true")
    args = ap.parse_args()

    if args.selftest:
        print("python exact solutions:")
        ok = ex.selftest()
        ok &= ms.selftest_weights(os.path.join(args.out, "selftest"))
        if os.path.exists(args.hvi):
            from study_run import riemann_crosscheck
            ok &= riemann_crosscheck(args.hvi, os.path.join(args.out, "selftest"))
        sys.exit(0 if ok else 1)
    an.set_cost("wall_seconds" if args.cost == "wall" else "cpu_seconds")
    if not os.path.exists(args.hvi):
        sys.exit(f"study: {args.hvi} not found; build it first (cmake --build build --target hvi)")

    only = [p for p in args.only.split(",") if p] or list(PROBLEMS)
    runs = plan_runs(only, args.quick, os.path.join(args.out, "runs"))
    print(f"study: {len(runs)} runs ({'quick' if args.quick else 'full'}), {args.jobs} at a time, "
          f"{args.threads} thread(s) each")
    t0 = time.time()
    results = {}

    # References first (exact profiles for the tube; finest runs for the impacts are ordinary runs).
    exacts = {}
    for p in only:
        exacts[p] = reference_profile(PROBLEMS[p], args.hvi, os.path.join(args.out, "runs", p))

    def work(run):
        return run["dir"], run_hvi(args.hvi, run, args.threads, args.reuse)

    # Longest first so a parallel sweep ends together.
    order = sorted(runs, key=lambda r: -r["cost_guess"])
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for n, (d, summ) in enumerate(pool.map(work, order), 1):
            results[d] = summ
            print(f"  [{n}/{len(runs)}] {os.path.relpath(d, args.out)}: {summ.get('status')} "
                  f"{summ.get('wall_seconds', 0):.1f} s", flush=True)

    rows, cross = [], {}
    for p in only:
        pruns = [r for r in runs if r["problem"] == p]
        if PROBLEMS[p]["kind"] == "exact":
            for run in pruns:
                summ = results[run["dir"]]
                err, extra = None, {}
                if summ.get("status") == "completed" and exacts[p] is not None:
                    err, extra = measure_exact(run, exacts[p])
                elif summ.get("status") != "completed":
                    extra = {"note": f"run {summ.get('status')}: {summ.get('error', '')[:160]}"}
                rows.append(row_of(run, summ, err, extra))
        else:
            r, c = impact_rows(pruns, results, args.hvi, args.out)
            rows += r
            cross[p] = c

    write_outputs(rows, cross, args, time.time() - t0)


def base_problem(p):
    return p[:-len("_vs_tvd")] if p.endswith("_vs_tvd") else p


def merge_previous(rows, cross, out):
    """Rows (and SPH-against-TVD lists) of the problems not run now, from <out>/study.json, so a
    study of some problems (--only) does not drop the others' results; returns the merged rows,
    the merged cross lists and the names of the problems kept."""
    path = os.path.join(out, "study.json")
    ran = {base_problem(r["problem"]) for r in rows} | set(cross)
    if not os.path.exists(path):
        return rows, cross, []
    with open(path) as f:
        old = json.load(f)
    kept = [r for r in old.get("rows", []) if base_problem(r["problem"]) not in ran]
    kept_cross = {p: c for p, c in old.get("sph_vs_tvd_same_resolution", {}).items()
                  if p not in ran}
    names = list(dict.fromkeys(r["problem"] for r in kept))
    return kept + rows, {**kept_cross, **cross}, names


def write_outputs(rows, cross, args, elapsed):
    os.makedirs(args.out, exist_ok=True)
    new_problems = list(dict.fromkeys(r["problem"] for r in rows))
    rows, cross, kept = merge_previous(rows, cross, args.out)
    if kept:
        print(f"study: kept the rows of {', '.join(kept)} from {args.out}/study.json")
    with open(os.path.join(args.out, "study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=CSV_KEYS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r)
    summary = an.summarise(rows)
    targets = an.accuracy_table(rows, ACCURACY_TARGETS)
    doc = {"quick": args.quick, "cost": an.COST["key"], "threads_per_run": args.threads, "parallel_jobs": args.jobs,
           "cpu_count": os.cpu_count(), "elapsed_seconds": elapsed,
           "kept_from_previous": kept, "rows": rows,
           "orders": summary, "sph_vs_tvd_same_resolution": cross,
           "seconds_for_error": {p: {str(t): v for t, v in d.items()} for p, d in targets.items()}}
    with open(os.path.join(args.out, "study.json"), "w") as f:
        json.dump(doc, f, indent=1)
    os.makedirs(args.figures, exist_ok=True)
    for p in new_problems:  # the kept problems' figures stay as they were drawn
        base = base_problem(p)
        title = PROBLEMS[base]["title"] + ("\nerror against the finest TVD run"
                                           if p.endswith("_vs_tvd") else
                                           "\nerror against the finest run of the same method"
                                           if PROBLEMS[base]["kind"] == "impact" else "")
        ylabel = PROBLEMS[base]["ylabel"]
        chosen = an.COST["key"]
        # The chosen cost axis under study_<problem>.png; the other one beside it (_cpu / _wall).
        for key, suffix in ((chosen, ""), ("cpu_seconds" if chosen == "wall_seconds"
                                           else "wall_seconds", None)):
            an.set_cost(key)
            name = f"study_{p}{suffix if suffix is not None else '_' + key.split('_')[0]}.png"
            if an.plot_problem(rows, p, title, ylabel, os.path.join(args.figures, name)):
                print(f"study: wrote {os.path.join(args.figures, name)}")
        an.set_cost(chosen)
    with open(os.path.join(args.out, "study_tables.md"), "w") as f:
        f.write(an.markdown(rows, summary, targets, cross))
    for p in new_problems:
        prob = PROBLEMS.get(p)
        if prob and prob["kind"] == "exact" and prob["exact"][0] == "python":
            path = os.path.join(args.figures, f"study_profiles_{p}.png")
            if an.plot_profiles(rows, p, prob["exact"][1], prob["end"], prob["window"], path,
                                profile_loader(prob["end"]), prob.get("coordinate", "x")):
                print(f"study: wrote {path}")
    print_summary({p: summary[p] for p in new_problems if p in summary}, targets)
    for p, lst in ((p, cross[p]) for p in new_problems if p in cross):
        print(f"\n{p}: SPH against TVD at the same resolution (rel L1 over material, min IoU)")
        for c in lst:
            iou = f"{c['iou_min']:.3f}" if c["iou_min"] is not None else "-"
            print(f"  {c['method']:20s} h = {c['resolution']:<6g} {c['rel_l1']:.3f}  {iou}")
    print(f"study: {len(rows)} rows in {os.path.join(args.out, 'study.csv')}, "
          f"{elapsed:.0f} s in all")


def profile_loader(end):
    def load(run_dir):
        s = ms.load_samples(ms.snapshot_at(os.path.join(ROOT, run_dir), end))
        return s["x"], s["rho"]
    return load


def print_summary(summary, targets):
    for p, methods in summary.items():
        print(f"\n{p}: method, observed order, finest error, its {an.COST['key']}")
        for m, s in sorted(methods.items()):
            o = f"{s['order']:.2f}" if s["order"] is not None else "-"
            fe = f"{s['finest_error']:.3g}" if s["finest_error"] is not None else "-"
            ft = f"{s['finest_seconds']:.2f}" if s["finest_seconds"] is not None else "-"
            print(f"  {m:28s} {o:>6s} {fe:>10s} {ft:>8s}")
        for t, d in targets.get(p, {}).items():
            cells = ", ".join(f"{m} {v:.2f} s" if v is not None else f"{m} -"
                              for m, v in sorted(d.items()))
            print(f"  seconds for error {t:g}: {cells}")


if __name__ == "__main__":
    main()
