"""What the study's table says: observed orders, the Pareto front, cost of a given accuracy,
and the log-log figures of error against wall time."""
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


# The cost axis: "wall_seconds" (the run's own clock, summary.json) or "cpu_seconds" (user +
# system time of the hvi process), the fairer measure for single-threaded runs on a busy machine.
COST = {"key": "wall_seconds", "label": "wall time of the run [s]"}


def set_cost(key):
    COST["key"] = key
    COST["label"] = ("wall time of the run [s]" if key == "wall_seconds"
                     else "CPU time of the run (user + system) [s]")


def method_key(row):
    return f"{row['solver']} {row['option']}".strip()


def group_by_method(rows):
    groups = {}
    for r in rows:
        if r.get("error") is None or not math.isfinite(r["error"]) or r["error"] <= 0:
            continue
        groups.setdefault(method_key(r), []).append(r)
    for g in groups.values():
        g.sort(key=lambda r: -r["resolution"])  # coarse to fine
    return groups


def observed_order(points, h_ref=0.0):
    """Observed order p from (h, E) pairs: least-squares slope of log E against log h.

    Against a finest run at h_ref (self-convergence), E(h) ~ C (h^p - h_ref^p) rather than
    C h^p: the reference's own error is subtracted, and a plain slope would climb as h nears
    h_ref. Then p minimises the spread of log E - log(h^p - h_ref^p) (scan in 0.001 steps).
    None below 2 points."""
    pts = [(h, e) for h, e in points if h > h_ref and e > 0]
    if len(pts) < 2:
        return None
    lh = np.log([p[0] for p in pts])
    le = np.log([p[1] for p in pts])
    if h_ref <= 0.0:
        return float(np.polyfit(lh, le, 1)[0])
    hs = np.array([p[0] for p in pts])
    scan = np.arange(0.05, 5.0, 0.001)
    spread = [float(np.var(le - np.log(hs ** p - h_ref ** p))) for p in scan]
    i = int(np.argmin(spread))
    # At an end of the scan no order fits: the errors fall more slowly than any p > 0.05 would
    # make them (not yet in the asymptotic range), or faster than fifth order.
    return None if i in (0, len(scan) - 1) else float(scan[i])


def pareto_front(points):
    """Indices of the points (time, error) that no other point beats on both (lower is better)."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], math.inf
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def time_for_error(rows, target):
    """Wall time a method needs for relative error `target`, interpolating log t against log E
    between its measured resolutions (no extrapolation); None when the target is outside."""
    pts = sorted(((r["error"], r[COST["key"]]) for r in rows), key=lambda p: -p[0])
    best = None
    for (e0, t0), (e1, t1) in zip(pts, pts[1:]):
        lo, hi = min(e0, e1), max(e0, e1)
        if lo <= target <= hi and e0 != e1 and t0 > 0 and t1 > 0:
            f = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            t = math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0)))
            best = t if best is None else min(best, t)
    for e, t in pts:  # a measured point at or below the target also answers
        if e <= target and t > 0:
            best = t if best is None else min(best, t)
    return best


def summarise(rows):
    """Per problem and method: observed order, finest error, its cost."""
    out = {}
    for problem in dict.fromkeys(r["problem"] for r in rows):
        prs = [r for r in rows if r["problem"] == problem]
        methods = {}
        for m, g in group_by_method(prs).items():
            conv = [r for r in g if not r.get("reference")]
            methods[m] = {
                "order": observed_order([(r["resolution"], r["error"]) for r in conv],
                                        g[0].get("h_ref", 0.0)),
                "slope": observed_order([(r["resolution"], r["error"]) for r in conv]),
                "points": len(conv),
                "finest_error": conv[-1]["error"] if conv else None,
                "finest_seconds": conv[-1][COST["key"]] if conv else None,
            }
        out[problem] = methods
    return out


def accuracy_table(rows, targets):
    """{problem: {target: {method: seconds or None}}} from `time_for_error`."""
    out = {}
    for problem in dict.fromkeys(r["problem"] for r in rows):
        groups = group_by_method([r for r in rows if r["problem"] == problem
                                  and not r.get("reference")])
        out[problem] = {t: {m: time_for_error(g, t) for m, g in groups.items()}
                        for t in targets.get(problem, [])}
    return out


def plot_problem(rows, problem, title, ylabel, path):
    """Error against wall time per method, log-log, Pareto front highlighted."""
    groups = group_by_method([r for r in rows if r["problem"] == problem
                              and not r.get("reference")])
    if not groups:
        return False
    fig, ax = plt.subplots(figsize=(7.2, 5.0))
    markers = "osD^v<>ph*"
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    allpts = []
    for n, (m, g) in enumerate(sorted(groups.items())):
        t = [max(r[COST["key"]], 1e-3) for r in g]
        e = [r["error"] for r in g]
        p = observed_order([(r["resolution"], r["error"]) for r in g], g[0].get("h_ref", 0.0))
        lab = m + (f"  (order {p:.2f})" if p is not None else "")
        ls = "-" if g[0]["solver"] == "tvd" else "--"
        ax.plot(t, e, ls, marker=markers[n % len(markers)], color=colours[n % len(colours)],
                label=lab, ms=5, lw=1.2)
        for r, ti, ei in zip(g, t, e):
            allpts.append((ti, ei))
    front = pareto_front(allpts)
    fp = sorted(allpts[i] for i in front)
    if fp:
        # Staircase: below and left of it nothing was measured.
        xs, ys = [fp[0][0]], [fp[0][1]]
        for (t0, e0), (t1, e1) in zip(fp, fp[1:]):
            xs += [t1, t1]
            ys += [e0, e1]
        ax.plot(xs, ys, color="k", lw=3, alpha=0.25, zorder=0, label="Pareto front")
        ax.scatter([p[0] for p in fp], [p[1] for p in fp], s=120, facecolors="none",
                   edgecolors="k", lw=1.0, zorder=5)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(COST["label"])
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return True


def markdown(rows, summary, targets, cross):
    """The tables of docs/study.md, generated from the measured rows."""
    key = COST["key"]
    out = []
    for p in dict.fromkeys(r["problem"] for r in rows):
        out.append(f"### {p}\n")
        out.append(f"| method | h [cm] | cells / particles | steps | {key.replace('_', ' ')} | "
                   "error |")
        out.append("|---|---|---|---|---|---|")
        for r in sorted((r for r in rows if r["problem"] == p),
                        key=lambda r: (method_key(r), -r["resolution"])):
            err = f"{r['error']:.4g}" if r.get("error") is not None else (r.get("note") or "-")
            cost = f"{r[key]:.3g}" if r.get(key) is not None else "-"
            out.append(f"| {method_key(r)} | {r['resolution']:g} | {r.get('work_items') or '-'} | "
                       f"{r.get('steps') or '-'} | {cost} | {err} |")
        out.append("")
        out.append("| method | observed order | log-log slope | finest error | its cost [s] |")
        out.append("|---|---|---|---|---|")
        for m, s in sorted(summary.get(p, {}).items()):
            o = f"{s['order']:.2f}" if s["order"] is not None else "-"
            sl = f"{s['slope']:.2f}" if s["slope"] is not None else "-"
            fe = f"{s['finest_error']:.3g}" if s["finest_error"] is not None else "-"
            ft = f"{s['finest_seconds']:.3g}" if s["finest_seconds"] is not None else "-"
            out.append(f"| {m} | {o} | {sl} | {fe} | {ft} |")
        out.append("")
        for t, d in targets.get(p, {}).items():
            cells = ", ".join(f"{m} {v:.3g} s" if v is not None else f"{m} not reached"
                              for m, v in sorted(d.items()))
            out.append(f"- cost of error {t:g}: {cells}")
        out.append("")
    for p, lst in cross.items():
        out.append(f"### {p}: SPH against TVD at the same resolution\n")
        out.append("| method | h [cm] | rel L1 (material) | min IoU |")
        out.append("|---|---|---|---|")
        for c in lst:
            iou = f"{c['iou_min']:.3f}" if c["iou_min"] is not None else "-"
            out.append(f"| {c['method']} | {c['resolution']:g} | {c['rel_l1']:.4f} | {iou} |")
        out.append("")
    return "\n".join(out) + "\n"


def plot_profiles(rows, problem, exact, end, window, path, load, coordinate="x"):
    """Density against x (or r: `coordinate`) at one resolution (the finest every method
    reached), all methods, with the exact profile: what the L1 numbers are made of.
    `load(run_dir)` gives x, rho."""
    prs = [r for r in rows if r["problem"] == problem and r.get("error") is not None]
    if not prs:
        return False
    per_method = {}
    for r in prs:
        per_method.setdefault(method_key(r), set()).add(r["resolution"])
    common = set.intersection(*per_method.values())
    h = min(common) if common else min(r["resolution"] for r in prs)
    fig, ax = plt.subplots(figsize=(8.0, 4.6))
    a, b = window
    lo = a - 0.1 * (b - a)
    xs = np.linspace(max(lo, 0.0) if coordinate == "r" else lo, b + 0.1 * (b - a), 4000)
    ax.plot(xs, exact(xs, end), "k-", lw=1.5, label="exact", zorder=10)
    for r in sorted((r for r in prs if r["resolution"] == h), key=method_key):
        x, rho = load(r["run_dir"])
        o = np.argsort(x)
        style = "-" if r["solver"] == "tvd" else "."
        ax.plot(x[o], rho[o], style, ms=2, lw=1, label=f"{method_key(r)} (E = {r['error']:.3g})")
    ax.axvspan(a, b, color="0.9", zorder=0)
    ax.set_xlim(xs[0], xs[-1])
    ax.set_xlabel(f"{coordinate} [cm]")
    ax.set_ylabel("density [g/cm^3]")
    ax.set_title(f"{problem}: density at t = {end:g} us, h = {h:g} cm (shaded: error window)",
                 fontsize=10)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return True
