#!/usr/bin/python3
"""Density (or another field) picture of an hvi snapshot: axes in cm, colour bar with units.

Usage: /usr/bin/python3 tools/plot_snapshot.py RUN_DIR_OR_H5 [--png FILE] [--field density]
                                               [--xlim X0 X1] [--zlim Z0 Z1] [--vmax V]
A run folder means its last snapshot (snap_*.h5). r-z results are mirrored about the axis.
Vacuum (grid cells with material -1, places without particles) is left blank.
"""
import argparse
import glob
import os
import re
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# Unit strings as written in the HDF5 files -> how they are printed on axes.
PRETTY_UNITS = {"g/cm^3": "g/cm³", "cm^2/us^2": "cm²/µs²", "cm/us": "cm/µs", "us": "µs",
                "1": ""}


def pretty_unit(u):
    return PRETTY_UNITS.get(u, u)


def last_snapshot(path):
    if os.path.isfile(path):
        return path
    snaps = glob.glob(os.path.join(path, "snap_*.h5"))
    if not snaps:
        sys.exit(f"plot_snapshot: no snap_*.h5 in {path}")
    return max(snaps, key=lambda f: int(re.findall(r"snap_(\d+)\.h5", f)[0]))


def _str(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def load(h5path, field):
    """One field of a snapshot: values, particle positions or grid, and where vacuum is."""
    with h5py.File(h5path, "r") as f:
        a = f.attrs
        d = {"time": float(a["time"]), "kind": _str(a["kind"]), "geometry": _str(a["geometry"]),
             "solver": _str(a["solver"]), "file": h5path}
        ds = f["fields"][field]
        d["unit"] = _str(ds.attrs.get("unit", b""))
        d["values"] = np.asarray(ds[...], dtype=float)
        if d["values"].ndim > 1:  # vectors: the magnitude
            d["values"] = np.linalg.norm(d["values"], axis=1)
        if d["kind"] == "particles":
            d["x"] = f["particles/x"][...]
            d["z"] = f["particles/z"][...]
            has_h = "smoothing_length" in f["fields"]
            d["h"] = f["fields/smoothing_length"][...] if has_h else None
            if "mass" in f["fields"]:  # deleted particles carry no mass
                keep = f["fields/mass"][...] > 0
                for k in ("x", "z", "values", "h"):
                    if d[k] is not None:
                        d[k] = d[k][keep]
        else:
            g = f["grid"].attrs
            d["grid"] = {k: g[k] for k in ("nx", "nz", "x0", "z0", "dx", "dz")}
            if "material" in f["fields"]:
                d["vacuum"] = f["fields/material"][...] < 0
            elif field == "density":
                d["vacuum"] = d["values"] <= 0
    return d


def particle_spacing(d):
    """Median smoothing length (h = h_factor dx with h_factor 1 in the shipped scenes)."""
    if d.get("h") is not None and len(d["h"]):
        return float(np.median(d["h"]))
    return 0.01


def marker_size(ax, d):
    """Scatter size (points^2) of a dot one particle spacing wide at the axes' scale (the limits
    must be set first for a zoomed picture), and never below one pixel. The axes' box moves when
    the layout is done: call refit_markers(fig) before saving."""
    spacing = particle_spacing(d)
    fig = ax.figure
    box = ax.get_position()
    w_in, h_in = box.width * fig.get_figwidth(), box.height * fig.get_figheight()
    if ax.get_autoscalex_on() or ax.get_autoscaley_on():
        xs = np.concatenate([d["x"], -d["x"]]) if d["geometry"] == "rz" else d["x"]
        xspan = max(float(np.ptp(xs)), spacing)
        zspan = max(float(np.ptp(d["z"])), spacing)
    else:
        xspan = abs(np.diff(ax.get_xlim())[0])
        zspan = abs(np.diff(ax.get_ylim())[0])
    inch_per_cm = min(w_in / xspan, h_in / zspan)  # aspect "equal" shrinks the box to fit
    pixel_pt = 72.0 / fig.dpi
    return max(pixel_pt ** 2, (spacing * inch_per_cm * 72.0) ** 2)


def refit_markers(fig, dpi=None):
    """Lays the figure out, then resizes every particle scatter to one spacing per dot."""
    if dpi:
        fig.set_dpi(dpi)
    fig.canvas.draw()
    for ax in fig.axes:
        for c in ax.collections:
            d = getattr(c, "hvi_particles", None)
            if d is not None:
                c.set_sizes([marker_size(ax, d)])


def draw(ax, d, vmin=None, vmax=None, cmap="viridis", mirror=True):
    """Draws `d` on `ax`; returns the artist for a colour bar. Particles are square dots one
    spacing wide, grids an image with vacuum blank (NaN values are blank too)."""
    v = np.asarray(d["values"], dtype=float)
    if d["kind"] == "particles":
        x, z = d["x"], d["z"]
        size = marker_size(ax, d)
        kw = dict(s=size, cmap=cmap, vmin=vmin, vmax=vmax, linewidths=0, marker="s",
                  rasterized=True)
        sc = ax.scatter(x, z, c=v, **kw)
        sc.hvi_particles = {"h": d.get("h"), "x": x, "z": z, "geometry": d["geometry"]}
        if d["geometry"] == "rz" and mirror:
            ax.scatter(-x, z, c=v, **kw).hvi_particles = sc.hvi_particles
        return sc
    g = d["grid"]
    nx, nz = int(g["nx"]), int(g["nz"])
    img = v.reshape(nz, nx).copy()
    if "vacuum" in d:
        img[np.asarray(d["vacuum"]).reshape(nz, nx)] = np.nan
    img = np.ma.masked_invalid(img)
    x0, z0 = float(g["x0"]), float(g["z0"])
    x1 = x0 + nx * float(g["dx"])
    z1 = z0 + nz * float(g["dz"])
    kw = dict(origin="lower", cmap=cmap, vmin=vmin, vmax=vmax, interpolation="nearest")
    im = ax.imshow(img, extent=[x0, x1, z0, z1], **kw)
    if d["geometry"] == "rz" and mirror:
        ax.imshow(img[:, ::-1], extent=[-x1, -x0, z0, z1], **kw)
    return im


def axis_labels(ax, geometry):
    ax.set_aspect("equal")
    ax.set_xlabel("r (cm)" if geometry == "rz" else "x (cm)")
    ax.set_ylabel("z (cm)")


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("path")
    p.add_argument("--png")
    p.add_argument("--field", default="density")
    p.add_argument("--xlim", nargs=2, type=float)
    p.add_argument("--zlim", nargs=2, type=float)
    p.add_argument("--vmax", type=float)
    args = p.parse_args()
    h5 = last_snapshot(args.path)
    d = load(h5, args.field)
    fig, ax = plt.subplots(figsize=(8, 6))
    axis_labels(ax, d["geometry"])
    if args.xlim:
        ax.set_xlim(*args.xlim)
    if args.zlim:
        ax.set_ylim(*args.zlim)
    art = draw(ax, d, vmax=args.vmax)
    ax.set_title(f"{d['solver'].upper()} {args.field}, t = {d['time']:.3g} µs")
    unit = pretty_unit(d["unit"])
    fig.colorbar(art, ax=ax, label=f"{args.field} ({unit})" if unit else args.field)
    out = args.png or os.path.join(os.path.dirname(h5) if os.path.isfile(args.path) else args.path,
                                   f"{args.field}.png")
    refit_markers(fig, 130)
    fig.savefig(out, dpi=130, bbox_inches="tight")
    print(f"plot_snapshot: wrote {out}")


if __name__ == "__main__":
    main()
