#!/usr/bin/python3
"""Reproduce the study's figures from hvi runs (CASES.md figs. 1-5).

    /usr/bin/python3 tools/figures.py [--coarse] [--results results] [--out docs/figures]
                                      [--hvi build/bin/hvi] [--reuse]

Runs the variant-1 and variant-2 scenes (or, with --reuse, uses results already in --results)
and writes PNGs: fig1 density maps (TVD, variant 1), fig2 material maps (variant 1), fig3 debris
cloud at 7.2 us (variant 1), fig4 density maps (SPH, variant 2), fig5a/b/c split pictures at 5 us
(SPH left x < 0, TVD right x > 0: traditional SPH density, modified SPH density, material).
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import time

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_snapshot import draw, load  # noqa: E402

RUNS = {
    "v1_tvd": "variant1_tvd",
    "v2_sph_mod": "variant2_sph_modified",
    "v2_sph_trad": "variant2_sph_traditional",
    "v2_tvd": "variant2_tvd",
}
MATERIAL_CMAP = ListedColormap(["white", "tab:red", "tab:blue"])  # vacuum, striker, shield
DENSITY_MAX = 6.0  # g/cm^3: shocked aluminium stays below ~2.2 rho0


def run_scene(hvi, scene, out, log):
    t0 = time.time()
    cmd = [hvi, "run", scene, "--out", out, "--quiet"]
    print("figures:", " ".join(cmd), flush=True)
    r = subprocess.run(cmd)
    if r.returncode != 0:
        sys.exit(f"figures: {' '.join(cmd)} failed with status {r.returncode}")
    log.append({"command": " ".join(cmd), "wall_seconds": round(time.time() - t0, 1)})


def snapshot_at(run_dir, t):
    best, best_dt = None, 1e300
    for f in glob.glob(os.path.join(run_dir, "snap_*.h5")):
        with h5py.File(f, "r") as h:
            dt = abs(float(h.attrs["time"]) - t)
        if dt < best_dt:
            best, best_dt = f, dt
    if best is None or best_dt > 1e-6 + 1e-3 * t:
        sys.exit(f"figures: no snapshot at t = {t} us in {run_dir}")
    return best


def object_field(h5path):
    d = load(h5path, "object")
    d["values"] = np.asarray(d["values"], dtype=float) + 1.0  # -1 vacuum -> 0
    return d


def density_field(h5path):
    d = load(h5path, "density")
    if d["kind"] == "grid":
        d["values"] = np.where(d["values"] > 1e-3, d["values"], np.nan)
    return d


def label(ax, d, title):
    ax.set_aspect("equal")
    ax.set_xlabel("r (cm)" if d["geometry"] == "rz" else "x (cm)")
    ax.set_ylabel("z (cm)")
    ax.set_title(title, fontsize=9)


def panel_row(files, maker, cmap, vmin, vmax, cbar_label, suptitle, out, xlim=None, ylim=None):
    fig, axes = plt.subplots(1, len(files), figsize=(3.2 * len(files), 4.2), squeeze=False)
    art = None
    for ax, (t, f) in zip(axes[0], files):
        d = maker(f)
        art = draw(ax, d, vmin=vmin, vmax=vmax, cmap=cmap)
        label(ax, d, f"t = {t:g} us")
        if xlim:
            ax.set_xlim(*xlim)
        if ylim:
            ax.set_ylim(*ylim)
    fig.suptitle(suptitle)
    fig.colorbar(art, ax=axes[0].tolist(), label=cbar_label, shrink=0.8)
    fig.savefig(out, dpi=140, bbox_inches="tight")
    plt.close(fig)
    print("figures: wrote", out)


def split_picture(sph_file, tvd_file, maker, cmap, vmin, vmax, cbar_label, title, out, xlim, ylim):
    fig, ax = plt.subplots(figsize=(7, 5))
    s = maker(sph_file)
    keep = s["x"] < 0
    for k in ("x", "z", "values"):
        s[k] = s[k][keep]
    art = draw(ax, s, vmin=vmin, vmax=vmax, cmap=cmap, mirror=False)
    g = maker(tvd_file)
    grid = g["grid"]
    nx, nz = int(grid["nx"]), int(grid["nz"])
    xc = float(grid["x0"]) + (np.arange(nx) + 0.5) * float(grid["dx"])
    img = g["values"].reshape(nz, nx).astype(float)
    img[:, xc < 0] = np.nan
    g["values"] = img.ravel()
    draw(ax, g, vmin=vmin, vmax=vmax, cmap=cmap, mirror=False)
    ax.axvline(0.0, color="k", lw=0.5)
    label(ax, s, title)
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    fig.colorbar(art, ax=ax, label=cbar_label, shrink=0.8)
    fig.savefig(out, dpi=140, bbox_inches="tight")
    plt.close(fig)
    print("figures: wrote", out)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--coarse", action="store_true", help="use the *_coarse scenes (about a minute each)")
    p.add_argument("--results", default="results")
    p.add_argument("--out", default="docs/figures")
    p.add_argument("--hvi", default="build/bin/hvi")
    p.add_argument("--reuse", action="store_true", help="reuse results already in --results")
    p.add_argument("--only", nargs="*", choices=sorted(RUNS), help="runs to make (default all)")
    a = p.parse_args()
    suffix = "_coarse" if a.coarse else ""
    os.makedirs(a.out, exist_ok=True)
    log = []
    dirs = {}
    for key, scene in RUNS.items():
        if a.only and key not in a.only:
            continue
        d = os.path.join(a.results, scene + suffix)
        dirs[key] = d
        if not (a.reuse and os.path.exists(os.path.join(d, "summary.json"))):
            run_scene(a.hvi, os.path.join("cases", "scenes", scene + suffix + ".toml"), d, log)
    tag = " (coarse)" if a.coarse else ""

    if "v1_tvd" in dirs:
        times = [0.3, 1.0, 2.0, 4.0, 7.2]
        files = [(t, snapshot_at(dirs["v1_tvd"], t)) for t in times]
        lim = dict(xlim=(-4.0, 4.0), ylim=(3.0, 9.5))
        panel_row(files, density_field, "viridis", 0.0, DENSITY_MAX, "density (g/cm^3)",
                  "Fig. 1: variant 1 (sphere on plate, r-z), TVD density" + tag,
                  os.path.join(a.out, "fig1_v1_tvd_density.png"), **lim)
        panel_row(files, object_field, MATERIAL_CMAP, -0.5, 2.5, "0 vacuum, 1 striker, 2 shield",
                  "Fig. 2: variant 1, material" + tag, os.path.join(a.out, "fig2_v1_material.png"), **lim)
        f72 = files[-1][1]
        fig, ax = plt.subplots(figsize=(6, 6))
        d = object_field(f72)
        art = draw(ax, d, vmin=-0.5, vmax=2.5, cmap=MATERIAL_CMAP)
        label(ax, d, "Fig. 3: variant 1 debris cloud at t = 7.2 us (TVD)" + tag)
        ax.set_facecolor("white")
        fig.colorbar(art, ax=ax, label="0 vacuum, 1 striker, 2 shield", shrink=0.8)
        out = os.path.join(a.out, "fig3_v1_debris_cloud.png")
        fig.savefig(out, dpi=140, bbox_inches="tight")
        plt.close(fig)
        print("figures: wrote", out)

    if "v2_sph_mod" in dirs:
        times = [1.0, 2.0, 3.0, 5.0]
        files = [(t, snapshot_at(dirs["v2_sph_mod"], t)) for t in times]
        panel_row(files, density_field, "viridis", 0.0, DENSITY_MAX, "density (g/cm^3)",
                  "Fig. 4: variant 2 (rod on plate, planar), modified SPH density" + tag,
                  os.path.join(a.out, "fig4_v2_sph_density.png"), xlim=(-4, 4), ylim=(-3.5, 2.0))

    if all(k in dirs for k in ("v2_sph_mod", "v2_sph_trad", "v2_tvd")):
        t = 5.0
        tvd = snapshot_at(dirs["v2_tvd"], t)
        lim = dict(xlim=(-4, 4), ylim=(-3.5, 2.0))
        split_picture(snapshot_at(dirs["v2_sph_trad"], t), tvd, density_field, "viridis", 0.0,
                      DENSITY_MAX, "density (g/cm^3)",
                      "Fig. 5a: t = 5 us, traditional SPH (x < 0) | TVD (x > 0)" + tag,
                      os.path.join(a.out, "fig5a_v2_traditional_vs_tvd.png"), **lim)
        split_picture(snapshot_at(dirs["v2_sph_mod"], t), tvd, density_field, "viridis", 0.0,
                      DENSITY_MAX, "density (g/cm^3)",
                      "Fig. 5b: t = 5 us, modified SPH (x < 0) | TVD (x > 0)" + tag,
                      os.path.join(a.out, "fig5b_v2_modified_vs_tvd.png"), **lim)
        split_picture(snapshot_at(dirs["v2_sph_mod"], t), tvd, object_field, MATERIAL_CMAP, -0.5, 2.5,
                      "0 vacuum, 1 striker, 2 shield",
                      "Fig. 5c: t = 5 us, material, modified SPH (x < 0) | TVD (x > 0)" + tag,
                      os.path.join(a.out, "fig5c_v2_material.png"), **lim)

    if log:
        with open(os.path.join(a.out, "runs" + suffix + ".json"), "w") as f:
            json.dump(log, f, indent=1)


if __name__ == "__main__":
    main()
