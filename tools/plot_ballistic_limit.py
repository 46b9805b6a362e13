#!/usr/bin/python3
"""Ballistic-limit curve of `hvi ballistic-limit` (docs/shield.md): the computed critical
diameters with their brackets, the runs that failed or survived the rear wall, and the
published Whipple BLE (Christiansen 1993, NASA/TM-2009-214785) for the same shield.

usage: /usr/bin/python3 tools/plot_ballistic_limit.py ballistic_limit.json out.png
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(src, dst):
    with open(src) as f:
        data = json.load(f)
    fig, ax = plt.subplots(figsize=(7.5, 5.0))
    ble = data.get("ble")
    if ble:
        v, d = zip(*ble["curve"])
        ax.plot(v, d, "k-", lw=1.5, label="Whipple BLE (Christiansen 1993)")
        for vr in ble["regimes_km_s"]:
            ax.axvline(vr, color="0.7", lw=0.8, ls=":")
    runs = data["runs"]
    for perforated, style, label in ((True, dict(marker="x", color="C3"), "rear wall failed"),
                                     (False, dict(marker="o", facecolors="none", edgecolors="C0"),
                                      "rear wall survived")):
        pts = [(r["speed_km_s"], r["diameter_cm"]) for r in runs if r.get("perforated") is perforated]
        if pts:
            xs, ys = zip(*pts)
            ax.scatter(xs, ys, label=label, zorder=3, **style)
    pts = [p for p in data["points"] if p["critical_diameter_cm"] is not None]
    if pts:
        xs = [p["speed_km_s"] for p in pts]
        ys = [p["critical_diameter_cm"] for p in pts]
        lo = [p["critical_diameter_cm"] - p["survived_cm"] for p in pts]
        hi = [p["failed_cm"] - p["critical_diameter_cm"] for p in pts]
        ax.errorbar(xs, ys, yerr=[lo, hi], fmt="s-", color="C2", capsize=3,
                    label=f"hvi {data['solver']} (tolerance {data['tolerance']:g})", zorder=4)
    shield = data["shield"]
    ax.set_title(shield["title"], fontsize=10)
    ax.set_xlabel("impact speed (km/s)")
    ax.set_ylabel("projectile diameter (cm)")
    ax.set_xlim(0, 15)
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(dst, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
