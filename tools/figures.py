#!/usr/bin/python3
"""Reproduce the study's figures from hvi runs (CASES.md figs. 1-5) and compare the methods.

    /usr/bin/python3 tools/figures.py [--coarse] [--results results] [--out docs/figures]
                                      [--hvi build/bin/hvi] [--reuse] [--only RUN ...]

Runs the variant-1 and variant-2 scenes one after the other (or, with --reuse, uses results
already in --results) and writes PNGs (named ..._coarse.png with --coarse): fig1 density maps
(TVD, variant 1, r-z mirrored about the axis), fig2 material maps (variant 1), fig3 debris
cloud at 7.2 us (variant 1: section and a synthetic radiograph), fig1b density maps (modified
SPH in r-z, variant 1), fig4 density maps (modified
SPH, variant 2), fig5a/b/c split pictures at 5 us (SPH left x < 0, TVD right x > 0:
traditional SPH density, modified SPH density, material).
Then `hvi compare` at 5 us for modified SPH vs TVD, traditional SPH vs TVD and modified vs
traditional SPH (variant 2), and at 7.2 us for SPH vs TVD (variant 1), whose tables go to <out>/compare_<pair>[_coarse].txt. What each run did
(status, wall time from its summary.json, conservation) goes to <out>/runs[_coarse].json.
A run that fails does not stop the others; its figures show what it wrote before failing.
"""
import argparse
import glob
import json
import os
import shutil
import subprocess
import sys
import time

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_snapshot import axis_labels, draw, load, refit_markers  # noqa: E402

RUNS = {
    "v1_tvd": "variant1_tvd",
    "v1_sph": "variant1_sph",
    "v2_sph_mod": "variant2_sph_modified",
    "v2_sph_trad": "variant2_sph_traditional",
    "v2_tvd": "variant2_tvd",
}
PAIRS = [("modified_vs_tvd", "v2_sph_mod", "v2_tvd", 5.0),
         ("traditional_vs_tvd", "v2_sph_trad", "v2_tvd", 5.0),
         ("modified_vs_traditional", "v2_sph_mod", "v2_sph_trad", 5.0),
         ("v1_sph_vs_tvd", "v1_sph", "v1_tvd", 7.2)]
OBJECT_COLOURS = ["tab:red", "tab:blue"]  # object 0 striker, 1 shield; vacuum blank
OBJECT_CMAP = ListedColormap(OBJECT_COLOURS)
DENSITY_CMAP = "viridis"
DENSITY_MAX = 4.0  # g/cm^3: the colour scale's top; shocked aluminium here peaks near 1.5 rho0
V1_TIMES = [0.3, 1.0, 2.0, 4.0, 7.2]
V1_SHIELD_REAR_Z = 8.0  # cm, the plate's rear face in variant 1
V1_WINDOW = dict(xlim=(-3.5, 3.5), ylim=(2.5, 9.5))  # cm, r mirrored about the axis
V2_TIMES = [1.0, 2.0, 3.0, 4.0, 5.0]
V2_WINDOW = dict(xlim=(-3.0, 3.0), ylim=(-3.5, 2.0))  # cm, around the hole and the cloud
V2_ZOOM = dict(xlim=(-1.6, 1.6), ylim=(-3.2, -1.0))  # cm, the bubble's leading edge at 5 us
DPI = 120
ZOOM_DPI = 150  # one 0.01 cm particle spacing is ~2 pixels in the zoom


def run_scene(hvi, scene, out, interfaces=None):
    """Runs one scene; returns what its summary.json says (status, wall time, conservation).
    interfaces: the TVD interface mode to force (whole_cell reproduces the study's method)."""
    cmd = [hvi, "run", scene, "--out", out, "--quiet"]
    if interfaces and "_tvd" in os.path.basename(scene):
        cmd += ["--set", f"tvd.interfaces={interfaces}"]
    if os.path.isdir(out):  # snapshots of an earlier run would be mixed with the new ones
        shutil.rmtree(out)
    print("figures:", " ".join(cmd), flush=True)
    t0 = time.time()
    rc = subprocess.run(cmd).returncode
    rec = {"command": " ".join(cmd), "exit_status": rc,
           "elapsed_seconds": round(time.time() - t0, 1)}
    if rc != 0:
        print(f"figures: {scene} failed with status {rc}; going on with the others", flush=True)
    return rec


def summary_record(run_dir, rec=None):
    rec = dict(rec or {})
    path = os.path.join(run_dir, "summary.json")
    if not os.path.exists(path):
        rec["status"] = "missing"
        return rec
    with open(path) as f:
        s = json.load(f)
    c = s.get("conservation", {})
    rec.update({k: s.get(k) for k in ("solver", "status", "error", "wall_seconds", "steps",
                                      "final_time_us", "end_time_us", "threads", "work_items")})
    rec["mass_rel_error"] = c.get("mass_rel_error")
    rec["energy_rel_error"] = c.get("energy_rel_error")
    return rec


def snapshots(run_dir):
    """(time, file) of every snapshot of a run, the state at failure included, by time."""
    out = []
    files = glob.glob(os.path.join(run_dir, "snap_*.h5"))
    files += glob.glob(os.path.join(run_dir, "failed_*.h5"))
    for f in files:
        with h5py.File(f, "r") as h:
            out.append((float(h.attrs["time"]), f))
    return sorted(out)


def snapshot_at(run_dir, t):
    """The snapshot at time t (within 1e-3 t), or None."""
    for ts, f in snapshots(run_dir):
        if abs(ts - t) <= 1e-6 + 1e-3 * t and "failed_" not in f:
            return f
    return None


def object_field(h5path):
    d = load(h5path, "object")
    if d["kind"] == "grid":
        d["vacuum"] = d["values"] < 0
    return d


def density_field(h5path):
    return load(h5path, "density")


def no_state(ax, text):
    ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center", va="center", fontsize=8,
            wrap=True)


def object_legend(fig_or_ax, **kw):
    handles = [Patch(color=OBJECT_COLOURS[0], label="striker"),
               Patch(color=OBJECT_COLOURS[1], label="shield"),
               Patch(facecolor="white", edgecolor="0.6", label="vacuum")]
    fig_or_ax.legend(handles=handles, **kw)


def save(fig, out):
    refit_markers(fig, DPI)
    fig.savefig(out, dpi=DPI, bbox_inches="tight")
    plt.close(fig)
    print(f"figures: wrote {out} ({os.path.getsize(out) // 1024} KB)", flush=True)


def panel_row(files, maker, cmap, vmin, vmax, suptitle, out, window, cbar_label=None, note=""):
    """One panel per (time, file); a shared colour bar, or the object legend if no label."""
    n = len(files)
    fig, axes = plt.subplots(1, n, figsize=(2.6 * n + 1.2, 3.6), squeeze=False,
                             layout="constrained")
    art = None
    for ax, (t, f) in zip(axes[0], files):
        ax.set_xlim(*window["xlim"])
        ax.set_ylim(*window["ylim"])
        ax.set_title(f"t = {t:g} µs", fontsize=9)
        if f is None:
            axis_labels(ax, "rz" if "v1" in out else "planar")
            no_state(ax, f"no state at {t:g} µs\n{note}")
            continue
        d = maker(f)
        axis_labels(ax, d["geometry"])
        art = draw(ax, d, vmin=vmin, vmax=vmax, cmap=cmap)
    for ax in axes[0][1:]:
        ax.set_ylabel("")
    fig.suptitle(suptitle, fontsize=10)
    if cbar_label and art is not None:
        fig.colorbar(art, ax=axes[0].tolist(), label=cbar_label, shrink=0.85, extend="max")
    elif not cbar_label:
        object_legend(fig, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=3, fontsize=8)
    save(fig, out)


def split_picture(sph_file, tvd_file, maker, cmap, vmin, vmax, title, out, window, cbar_label=None):
    """SPH on the left half (x < 0), TVD on the right half (x > 0) of one picture."""
    fig, ax = plt.subplots(figsize=(6.4, 5.0), layout="constrained")
    ax.set_xlim(*window["xlim"])
    ax.set_ylim(*window["ylim"])
    s = maker(sph_file)
    keep = s["x"] < 0
    for k in ("x", "z", "values", "h"):
        if s.get(k) is not None:
            s[k] = s[k][keep]
    axis_labels(ax, s["geometry"])
    art = draw(ax, s, vmin=vmin, vmax=vmax, cmap=cmap, mirror=False)
    g = maker(tvd_file)
    grid = g["grid"]
    nx, nz = int(grid["nx"]), int(grid["nz"])
    xc = float(grid["x0"]) + (np.arange(nx) + 0.5) * float(grid["dx"])
    img = np.asarray(g["values"], dtype=float).reshape(nz, nx).copy()
    img[:, xc < 0] = np.nan
    g["values"] = img.ravel()
    draw(ax, g, vmin=vmin, vmax=vmax, cmap=cmap, mirror=False)
    ax.axvline(0.0, color="k", lw=0.6)
    y = window["ylim"][1] - 0.04 * (window["ylim"][1] - window["ylim"][0])
    ax.text(window["xlim"][0] * 0.96, y, s["solver"].upper(), va="top", fontsize=9)
    ax.text(window["xlim"][1] * 0.96, y, "TVD", va="top", ha="right", fontsize=9)
    ax.set_title(title, fontsize=10)
    if cbar_label:
        fig.colorbar(art, ax=ax, label=cbar_label, shrink=0.85, extend="max")
    else:
        object_legend(ax, loc="lower right", fontsize=8)
    save(fig, out)


def leading_edge_zoom(files, title, out):
    """Material near the bubble's leading edge, one panel per (label, file): where the study
    saw traditional SPH open a crack at the striker-shield contact."""
    fig, axes = plt.subplots(1, len(files), figsize=(4.2 * len(files), 3.6), squeeze=False,
                             layout="constrained")
    for ax, (label, f) in zip(axes[0], files):
        ax.set_xlim(*V2_ZOOM["xlim"])
        ax.set_ylim(*V2_ZOOM["ylim"])
        d = object_field(f)
        axis_labels(ax, d["geometry"])
        draw(ax, d, vmin=-0.5, vmax=1.5, cmap=OBJECT_CMAP)
        ax.set_title(label, fontsize=9)
    object_legend(fig, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=3, fontsize=8)
    fig.suptitle(title, fontsize=10)
    refit_markers(fig, ZOOM_DPI)
    fig.savefig(out, dpi=ZOOM_DPI, bbox_inches="tight")
    plt.close(fig)
    print(f"figures: wrote {out} ({os.path.getsize(out) // 1024} KB)", flush=True)


def areal_density(d):
    """Line-of-sight integral of an r-z grid density across the axis (a radiograph's view):
    for each chord at distance |x| from the axis, sum over rings of rho times the chord's
    length inside the ring, exact for a density constant on each ring. g/cm^2 on (z, x)."""
    g = d["grid"]
    nr, nz, dr = int(g["nx"]), int(g["nz"]), float(g["dx"])
    rho = np.asarray(d["values"], dtype=float).reshape(nz, nr).copy()
    if "vacuum" in d:
        rho[np.asarray(d["vacuum"]).reshape(nz, nr)] = 0.0
    faces = float(g["x0"]) + dr * np.arange(nr + 1)
    xc = float(g["x0"]) + dr * (np.arange(nr) + 0.5)
    half = np.sqrt(np.maximum(faces[None, :] ** 2 - xc[:, None] ** 2, 0.0))  # (x, face)
    chord = 2.0 * (half[:, 1:] - half[:, :-1])  # (x, ring)
    return rho @ chord.T


def figure3(f, out, tag, note):
    fig, axes = plt.subplots(1, 2, figsize=(9.5, 5.2), layout="constrained")
    for ax in axes:
        ax.set_xlim(*V1_WINDOW["xlim"])
        ax.set_ylim(*V1_WINDOW["ylim"])
        axis_labels(ax, "rz")
    if f is None:
        no_state(axes[0], f"no state at 7.2 µs\n{note}")
        fig.suptitle("Fig. 3: variant 1 debris cloud at t = 7.2 µs (TVD)" + tag, fontsize=10)
        save(fig, out)
        return
    d = object_field(f)
    draw(axes[0], d, vmin=-0.5, vmax=1.5, cmap=OBJECT_CMAP)
    axes[0].set_title("material in the meridional section", fontsize=9)
    object_legend(axes[0], loc="lower right", fontsize=8)
    rho = density_field(f)
    proj = areal_density(rho)
    g = rho["grid"]
    x1 = float(g["x0"]) + int(g["nx"]) * float(g["dx"])
    z0 = float(g["z0"])
    z1 = z0 + int(g["nz"]) * float(g["dz"])
    # The plate seen edge-on is opaque (tens of g/cm^2); scale to the cloud beyond its rear face.
    zc = z0 + (np.arange(int(g["nz"])) + 0.5) * float(g["dz"])
    cloud = proj[zc < V1_SHIELD_REAR_Z]
    vmax = float(np.percentile(cloud[cloud > 0], 99)) if np.any(cloud > 0) else 1.0
    kw = dict(origin="lower", cmap="gray_r", vmin=0.0, vmax=vmax, interpolation="nearest")
    im = axes[1].imshow(proj, extent=[0.0, x1, z0, z1], **kw)
    axes[1].imshow(proj[:, ::-1], extent=[-x1, 0.0, z0, z1], **kw)
    axes[1].set_title("synthetic radiograph: areal density along the line of sight", fontsize=9)
    axes[1].set_xlabel("x (cm), across the line of sight")
    fig.colorbar(im, ax=axes[1], label="areal density (g/cm²)", shrink=0.85, extend="max")
    with h5py.File(f, "r") as h:
        t = float(h.attrs["time"])
    extra = "" if abs(t - 7.2) < 1e-3 else f" — no 7.2 µs state: {note}"
    fig.suptitle(f"Fig. 3: variant 1 debris cloud at t = {t:g} µs (TVD){tag}{extra}", fontsize=10)
    save(fig, out)


def compare_pairs(hvi, dirs, results, out, suffix):
    for name, a, b, t in PAIRS:
        if a not in dirs or b not in dirs:
            continue
        cdir = os.path.join(results, f"compare_{name}{suffix}")
        cmd = [hvi, "compare", dirs[a], dirs[b], "--time", f"{t:g}", "--out", cdir]
        print("figures:", " ".join(cmd), flush=True)
        r = subprocess.run(cmd, capture_output=True, text=True)
        text = f"$ {' '.join(cmd)}\n{r.stdout}{r.stderr}(exit status {r.returncode})\n"
        path = os.path.join(out, f"compare_{name}{suffix}.txt")
        with open(path, "w") as f:
            f.write(text)
        print(text, flush=True)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--coarse", action="store_true",
                   help="use the *_coarse scenes (seconds to a minute each)")
    p.add_argument("--results", default="results")
    p.add_argument("--out", default="docs/figures")
    p.add_argument("--hvi", default="build/bin/hvi")
    p.add_argument("--reuse", action="store_true", help="reuse results already in --results")
    p.add_argument("--only", nargs="*", choices=sorted(RUNS), help="runs to use (default all)")
    p.add_argument("--no-compare", action="store_true", help="skip the hvi compare tables")
    p.add_argument("--tvd-interfaces", choices=["whole_cell", "conservative"],
                   help="TVD interface mode (default: the scenes' own, i.e. conservative; "
                        "whole_cell is the study's method)")
    a = p.parse_args()
    suffix = "_coarse" if a.coarse else ""
    os.makedirs(a.out, exist_ok=True)
    log_path = os.path.join(a.out, "runs" + suffix + ".json")
    log = {}
    if os.path.exists(log_path):
        with open(log_path) as f:
            log = json.load(f)
        if not isinstance(log, dict):
            log = {}
    dirs = {}
    for key, scene in RUNS.items():
        if a.only and key not in a.only:
            continue
        d = os.path.join(a.results, scene + suffix)
        dirs[key] = d
        rec = log.get(key)
        if not (a.reuse and os.path.exists(os.path.join(d, "summary.json"))):
            rec = run_scene(a.hvi, os.path.join("cases", "scenes", scene + suffix + ".toml"), d,
                            a.tvd_interfaces)
        log[key] = summary_record(d, rec)
        with open(log_path, "w") as f:
            json.dump(log, f, indent=1)
    tag = " (coarse)" if a.coarse else ""

    def note(key):
        r = log.get(key, {})
        if r.get("status") == "completed":
            return ""
        return f"run {r.get('status')} at t = {r.get('final_time_us') or 0:.3g} µs"

    def png(name):
        return os.path.join(a.out, name + suffix + ".png")

    rho = "density (g/cm³)"
    if "v1_tvd" in dirs:
        files = [(t, snapshot_at(dirs["v1_tvd"], t)) for t in V1_TIMES]
        panel_row(files, density_field, DENSITY_CMAP, 0.0, DENSITY_MAX,
                  "Fig. 1: variant 1 (sphere on plate, r-z mirrored about the axis), TVD density"
                  + tag, png("fig1_v1_tvd_density"), V1_WINDOW, rho, note("v1_tvd"))
        panel_row(files, object_field, OBJECT_CMAP, -0.5, 1.5,
                  "Fig. 2: variant 1, material (TVD)" + tag, png("fig2_v1_material"), V1_WINDOW,
                  None, note("v1_tvd"))
        f72 = files[-1][1]
        if f72 is None:  # the run stopped early: show its last regular state, and say so
            done = [f for _, f in snapshots(dirs["v1_tvd"]) if "failed_" not in f]
            f72 = done[-1] if done else None
        figure3(f72, png("fig3_v1_debris_cloud"), tag, note("v1_tvd"))

    if "v1_sph" in dirs:
        files = [(t, snapshot_at(dirs["v1_sph"], t)) for t in V1_TIMES]
        panel_row(files, density_field, DENSITY_CMAP, 0.0, DENSITY_MAX,
                  "Fig. 1b: variant 1 (sphere on plate, r-z mirrored about the axis), "
                  "modified SPH density" + tag, png("fig1b_v1_sph_density"), V1_WINDOW, rho,
                  note("v1_sph"))

    if "v2_sph_mod" in dirs:
        files = [(t, snapshot_at(dirs["v2_sph_mod"], t)) for t in V2_TIMES]
        panel_row(files, density_field, DENSITY_CMAP, 0.0, DENSITY_MAX,
                  "Fig. 4: variant 2 (rod on plate, planar), modified SPH density" + tag,
                  png("fig4_v2_sph_density"), V2_WINDOW, rho, note("v2_sph_mod"))

    if all(k in dirs for k in ("v2_sph_mod", "v2_sph_trad", "v2_tvd")):
        tvd = snapshot_at(dirs["v2_tvd"], 5.0)
        mod = snapshot_at(dirs["v2_sph_mod"], 5.0)
        trad = snapshot_at(dirs["v2_sph_trad"], 5.0)
        if tvd and trad:
            split_picture(trad, tvd, density_field, DENSITY_CMAP, 0.0, DENSITY_MAX,
                          "Fig. 5a: density at t = 5 µs, traditional SPH (x < 0) | TVD (x > 0)"
                          + tag, png("fig5a_v2_traditional_vs_tvd"), V2_WINDOW, rho)
        if tvd and mod:
            split_picture(mod, tvd, density_field, DENSITY_CMAP, 0.0, DENSITY_MAX,
                          "Fig. 5b: density at t = 5 µs, modified SPH (x < 0) | TVD (x > 0)"
                          + tag, png("fig5b_v2_modified_vs_tvd"), V2_WINDOW, rho)
            split_picture(mod, tvd, object_field, OBJECT_CMAP, -0.5, 1.5,
                          "Fig. 5c: material at t = 5 µs, modified SPH (x < 0) | TVD (x > 0)"
                          + tag, png("fig5c_v2_material"), V2_WINDOW)
        if tvd and mod and trad:
            leading_edge_zoom([("modified SPH", mod), ("traditional SPH", trad), ("TVD", tvd)],
                              "Fig. 5d: material at the bubble's leading edge, t = 5 µs" + tag,
                              png("fig5d_v2_leading_edge"))

    if not a.no_compare:
        compare_pairs(a.hvi, dirs, a.results, a.out, suffix)

    print("figures: runs (wall time from summary.json)")
    for key, r in log.items():
        print(f"  {key:12s} {r.get('status')!s:10s} wall {r.get('wall_seconds') or 0:8.1f} s  "
              f"steps {r.get('steps')}  t = {r.get('final_time_us')} us  "
              f"mass err {r.get('mass_rel_error')}  energy err {r.get('energy_rel_error')}")


if __name__ == "__main__":
    main()
