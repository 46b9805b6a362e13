"""Errors the study reports: 1-D L1 density error against an exact profile, and `hvi compare`.

The 1-D problems run in a thin strip (walls above and below), so every quantity depends on x
only. The error is a quadrature of

    E = int_W |rho_h - rho_exact| dx / int_W rho_exact dx        (relative L1 over a window W)

with the method's own areas in the x-z (r-z) plane: TVD cells (dx dz), SPH particles (m / rho
per unit depth). Both sample the exact profile at the cell centre / particle position, so a shock
smeared over k cells costs ~ k dx * jump / |W| for either method: the measure does not favour one
kind of output.

In r-z (cylindrical Noh) x is the radius r and the same line measure dr is used, not the volume
measure r dr: the errors near the axis (wall heating) count as much as those at the shock. An
r-z SPH particle is a ring whose `mass` field is the whole ring's, m = 2 pi r mu
(docs/sph-rz.md); its area in the r-z plane is mu / rho = m / (2 pi r rho), the counterpart of a
TVD cell's dr dz. m / rho (2 pi r times that) would weight the samples by r.
"""
import glob
import json
import os
import subprocess

import h5py
import numpy as np


def _attr(a, key):
    v = a[key]
    return v.decode() if isinstance(v, bytes) else str(v) if not np.isscalar(v) else v


def snapshot_at(run_dir, time=None):
    """The snapshot of a run folder at `time` (us; within 1e-6 relative) or the last one."""
    snaps = sorted(glob.glob(os.path.join(run_dir, "snap_*.h5")))
    if not snaps:
        raise FileNotFoundError(f"no snap_*.h5 in {run_dir}")
    if time is None:
        return snaps[-1]
    for s in snaps:
        with h5py.File(s, "r") as f:
            if abs(float(f.attrs["time"]) - time) <= 1e-6 * max(1.0, time):
                return s
    raise FileNotFoundError(f"no snapshot at t = {time} us in {run_dir}")


def load_samples(h5path):
    """Positions x (the radius r in r-z), z, density and quadrature weights (area in the x-z or
    r-z plane) of a snapshot."""
    with h5py.File(h5path, "r") as f:
        kind = _attr(f.attrs, "kind")
        geometry = _attr(f.attrs, "geometry") if "geometry" in f.attrs else "planar"
        t = float(f.attrs["time"])
        rho = f["fields/density"][...]
        if kind == "particles":
            x = f["particles/x"][...]
            z = f["particles/z"][...]
            m = f["fields/mass"][...]
            if "fields/volume" in f:
                # The symmetric r-z form's own particle area (docs/sph-rz.md), finite at the axis.
                m = f["fields/volume"][...] * rho
            elif geometry == "rz":
                # Ring mass -> planar weight mu = m / (2 pi r) (docs/sph-rz.md); particles stay
                # off the axis (r > 0), the guard only keeps a stray r = 0 finite.
                m = m / (2.0 * np.pi * np.maximum(x, 1e-300))
            w = m / np.maximum(rho, 1e-300)  # mass per unit depth / density = area
        else:
            g = f["grid"].attrs
            nx, nz = int(g["nx"]), int(g["nz"])
            dx, dz = float(g["dx"]), float(g["dz"])
            i = np.tile(np.arange(nx), nz)
            k = np.repeat(np.arange(nz), nx)
            x = float(g["x0"]) + (i + 0.5) * dx
            z = float(g["z0"]) + (k + 0.5) * dz
            w = np.full(nx * nz, dx * dz)
            if "material" in f["fields"]:
                w = np.where(f["fields/material"][...] >= 0, w, 0.0)  # vacuum cells hold nothing
    return {"kind": kind, "geometry": geometry, "time": t, "x": x, "z": z, "rho": rho, "w": w}


def l1_error_1d(h5path, exact, window, height):
    """Relative L1 density error over x in `window` against `exact(x, t)` (vectorised), the
    absolute one, and the share of the window (strip of `height`) the samples' volumes cover."""
    s = load_samples(h5path)
    a, b = window
    sel = (s["x"] >= a) & (s["x"] <= b) & (s["w"] > 0.0)
    if not np.any(sel):
        raise ValueError(f"{h5path}: nothing inside the window {window}")
    x, rho, w = s["x"][sel], s["rho"][sel], s["w"][sel]
    ex = exact(x, s["time"])
    # The windows lie inside the material at the final time (free ends excluded), so the
    # samples' own volumes cover the window and normalise the quadrature.
    absl1 = float(np.sum(np.abs(rho - ex) * w) / np.sum(w))
    xs = np.linspace(a, b, 20001)
    mean_exact = float(np.mean(exact(xs, s["time"])))
    coverage = float(np.sum(w)) / ((b - a) * height)
    return absl1 / mean_exact, absl1, coverage


def selftest_weights(tmp):
    """The quadrature weights on synthetic particle snapshots: a square lattice of spacing d
    (cells of area d^2) carrying rho = 2 + r, planar (m = rho d^2 per unit depth) and r-z (ring
    mass m = 2 pi r rho d^2). Both must give every particle the area d^2, hence coverage 1 and
    zero error against rho itself; the r-z masses read as planar ones would weight by 2 pi r."""
    os.makedirs(tmp, exist_ok=True)
    d, rows = 0.01, 4
    r = np.tile((np.arange(40) + 0.5) * d, rows)
    z = np.repeat((np.arange(rows) + 0.5) * d, 40)
    rho = 2.0 + r
    ok = True
    for geometry, mass in (("planar", rho * d * d), ("rz", 2.0 * np.pi * r * rho * d * d)):
        path = os.path.join(tmp, f"weights_{geometry}.h5")
        with h5py.File(path, "w") as f:
            f.attrs["kind"], f.attrs["geometry"], f.attrs["time"] = "particles", geometry, 0.0
            f["particles/x"], f["particles/z"] = r, z
            f["fields/density"], f["fields/mass"] = rho, mass
        s = load_samples(path)
        rel, _, coverage = l1_error_1d(path, lambda x, t: 2.0 + x, (0.0, 0.4), rows * d)
        # Areas d^2 summed in double precision: exact to round-off (1e-12 is 1e4 ulps).
        good = (np.allclose(s["w"], d * d, rtol=1e-12) and abs(coverage - 1.0) < 1e-12
                and rel < 1e-12)
        ok &= good
        print(f"  {geometry} particle areas: coverage {coverage:.12f}, rel L1 {rel:.1e} "
              f"{'ok' if good else 'MISMATCH'}")
    return ok


def profile_from_grid(h5path):
    """Exact profile from a 1-D grid snapshot (the riemann solver's): returns exact(x, t)."""
    s = load_samples(h5path)
    order = np.argsort(s["x"])
    xs, rs = s["x"][order], s["rho"][order]
    t_ref = s["time"]
    dx = float(np.min(np.diff(xs))) if xs.size > 1 else 1.0

    def exact(x, t):
        if abs(t - t_ref) > 1e-6 * max(1.0, t_ref):
            raise ValueError(f"reference is at t = {t_ref} us, asked for t = {t}")
        # Nearest reference cell: the reference is sampled at its cell centres.
        idx = np.clip(np.rint((np.asarray(x) - xs[0]) / dx).astype(int), 0, xs.size - 1)
        return rs[idx]

    return exact


def hvi_compare(hvi, a, b, time, out_dir, spacing=None):
    """Runs `hvi compare A B --time T`; returns compare.json as a dict (None if it failed)."""
    os.makedirs(out_dir, exist_ok=True)
    cmd = [hvi, "compare", a, b, "--time", f"{time:g}", "--out", out_dir, "--quiet"]
    if spacing:
        cmd += ["--spacing", f"{spacing:g}"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    path = os.path.join(out_dir, "compare.json")
    if r.returncode not in (0, 1) or not os.path.exists(path):
        print(f"study: hvi compare failed ({r.returncode}): {' '.join(cmd)}\n{r.stderr.strip()}")
        return None
    with open(path) as f:
        return json.load(f)
