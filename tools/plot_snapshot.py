#!/usr/bin/python3
"""Density (and material) picture of an hvi snapshot: axes in cm, colour bar with units.

Usage: /usr/bin/python3 tools/plot_snapshot.py RUN_DIR_OR_H5 [--png FILE] [--field density]
A run folder means its last snapshot (snap_*.h5). r-z results are mirrored about the axis.
"""
import argparse
import glob
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def last_snapshot(path):
    if os.path.isfile(path):
        return path
    snaps = sorted(glob.glob(os.path.join(path, "snap_*.h5")))
    if not snaps:
        sys.exit(f"plot_snapshot: no snap_*.h5 in {path}")
    return snaps[-1]


def load(h5path, field):
    with h5py.File(h5path, "r") as f:
        a = f.attrs
        kind = a["kind"].decode() if isinstance(a["kind"], bytes) else str(a["kind"])
        geom = a["geometry"].decode() if isinstance(a["geometry"], bytes) else str(a["geometry"])
        d = {"time": float(a["time"]), "kind": kind, "geometry": geom,
             "solver": str(a["solver"].decode() if isinstance(a["solver"], bytes) else a["solver"])}
        data = f["fields"][field][...]
        unit = f["fields"][field].attrs.get("unit", b"")
        d["unit"] = unit.decode() if isinstance(unit, bytes) else str(unit)
        d["values"] = data
        if kind == "particles":
            d["x"] = f["particles/x"][...]
            d["z"] = f["particles/z"][...]
            if "smoothing_length" in f["fields"]:
                d["h"] = f["fields/smoothing_length"][...]
        else:
            g = f["grid"].attrs
            d["grid"] = {k: g[k] for k in ("nx", "nz", "x0", "z0", "dx", "dz")}
    return d


def marker_size(ax, d):
    """Scatter size (points^2) that makes each particle a dot about one particle spacing wide."""
    spacing = float(np.median(d["h"])) if "h" in d and len(d["h"]) else 0.01
    xs = np.concatenate([d["x"], -d["x"]]) if d["geometry"] == "rz" else d["x"]
    extent = max(float(np.ptp(xs)), float(np.ptp(d["z"])), spacing)
    axes_points = 72.0 * min(ax.figure.get_size_inches()) * 0.8
    return max(0.05, (spacing / extent * axes_points) ** 2)


def draw(ax, d, vmin=None, vmax=None, cmap="viridis", mirror=True):
    v = d["values"]
    if d["kind"] == "particles":
        x, z = d["x"], d["z"]
        size = marker_size(ax, d)
        sc = ax.scatter(x, z, c=v, s=size, cmap=cmap, vmin=vmin, vmax=vmax, linewidths=0)
        if d["geometry"] == "rz" and mirror:
            ax.scatter(-x, z, c=v, s=size, cmap=cmap, vmin=vmin, vmax=vmax, linewidths=0)
        return sc
    g = d["grid"]
    img = np.ma.masked_invalid(v.reshape(int(g["nz"]), int(g["nx"])))
    x0, z0 = float(g["x0"]), float(g["z0"])
    x1 = x0 + int(g["nx"]) * float(g["dx"])
    z1 = z0 + int(g["nz"]) * float(g["dz"])
    im = ax.imshow(img, origin="lower", extent=[x0, x1, z0, z1], cmap=cmap, vmin=vmin, vmax=vmax,
                   interpolation="nearest")
    if d["geometry"] == "rz" and mirror:
        ax.imshow(img[:, ::-1], origin="lower", extent=[-x1, -x0, z0, z1], cmap=cmap, vmin=vmin,
                  vmax=vmax, interpolation="nearest")
    return im


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("path")
    p.add_argument("--png")
    p.add_argument("--field", default="density")
    args = p.parse_args()
    h5 = last_snapshot(args.path)
    d = load(h5, args.field)
    v = d["values"]
    if args.field == "density" and d["kind"] == "grid":
        v = np.where(v > 1e-3, v, np.nan)  # vacuum drawn blank
        d["values"] = v
    fig, ax = plt.subplots(figsize=(8, 6))
    art = draw(ax, d)
    ax.set_aspect("equal")
    ax.set_xlabel("r (cm)" if d["geometry"] == "rz" else "x (cm)")
    ax.set_ylabel("z (cm)")
    ax.set_title(f"{d['solver'].upper()} {args.field}, t = {d['time']:.3g} us")
    fig.colorbar(art, ax=ax, label=f"{args.field} ({d['unit']})")
    out = args.png or os.path.join(os.path.dirname(h5) if os.path.isfile(args.path) else args.path,
                                   f"{args.field}.png")
    fig.savefig(out, dpi=130, bbox_inches="tight")
    print(f"plot_snapshot: wrote {out}")


if __name__ == "__main__":
    main()
