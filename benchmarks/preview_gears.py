"""Quick matplotlib previews of the gear solver's pure-geometry outputs (not the sheet).

    .venv/bin/python benchmarks/preview_gears.py --z1 13 --z2 26 --module 9 --x1 0.63 --x2 0.67 -o /tmp/g
writes OUT_contour.png (blocking contour with the chosen point), OUT_mesh.png (meshing picture) and
OUT_sliding.png (specific sliding).
"""
from __future__ import annotations

import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from reportgen.gears.shifts import blocking_contour, choose_shifts  # noqa: E402

COLORS = {"undercut1": "tab:blue", "undercut2": "tab:cyan", "sharpening1": "tab:red",
          "sharpening2": "tab:orange", "contact_ratio": "tab:green", "interference1": "tab:purple",
          "interference2": "tab:pink", "eps_1": "olive", "equal_sliding": "black"}


def plot_contour(ax, contour, point=None, given=None):
    X1, X2 = np.meshgrid(contour.x1, contour.x2, indexing="ij")
    ax.contourf(X1, X2, contour.feasible.astype(float), levels=[0.5, 1.5], colors=["#d8f0d8"])
    for name, lines in contour.curves.items():
        for k, line in enumerate(lines):
            ax.plot(line[:, 0], line[:, 1], color=COLORS.get(name, "gray"), lw=1,
                    ls="--" if name in ("equal_sliding", "eps_1") else "-",
                    label=name if k == 0 else None)
    if point is not None:
        ax.plot(*point, "ko", ms=6, label=f"auto ({point[0]:.2f}, {point[1]:.2f})")
    if given is not None:
        ax.plot(*given, "r*", ms=9, label=f"given ({given[0]:.2f}, {given[1]:.2f})")
    ax.set_xlabel("x1")
    ax.set_ylabel("x2")
    ax.set_title(f"blocking contour z1 = {contour.z1}, z2 = {contour.z2}")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--z1", type=int, default=13)
    ap.add_argument("--z2", type=int, default=26)
    ap.add_argument("--module", type=float, default=9.0)
    ap.add_argument("--x1", default="auto")
    ap.add_argument("--x2", default="auto")
    ap.add_argument("-o", "--out", default="/tmp/gears")
    a = ap.parse_args()
    given = None
    try:
        choice = choose_shifts(a.z1, a.z2, a.module)
        point, contour = (choice.x1, choice.x2), choice.contour
    except Exception as exc:  # noqa: BLE001 - a preview shows what it can
        print("auto:", exc)
        point, contour = None, blocking_contour(a.z1, a.z2, a.module)
    if a.x1 != "auto":
        given = (float(a.x1), float(a.x2))
    fig, ax = plt.subplots(figsize=(8, 7))
    plot_contour(ax, contour, point, given)
    fig.savefig(f"{a.out}_contour.png", dpi=90)
    print("wrote", f"{a.out}_contour.png")
    try:
        from reportgen.gears.pair import solve_gear_pair
        from reportgen.gears.meshing import meshing_picture
    except ImportError:
        return
    x1 = point[0] if a.x1 == "auto" and point else float(a.x1)
    x2 = point[1] if a.x2 == "auto" and point else float(a.x2)
    pair = solve_gear_pair(a.z1, a.z2, a.module, x1, x2)
    pic = meshing_picture(pair)
    fig, ax = plt.subplots(figsize=(10, 10))
    for c in pic.circles:
        ax.add_patch(plt.Circle(c.centre, c.radius, fill=False, lw=0.6,
                                ls="-" if c.kind in ("tip", "root") else "-.",
                                color={"pitch": "b", "base": "g", "working": "r"}.get(c.kind, "k")))
    for poly in pic.teeth1 + pic.teeth2:
        ax.plot(poly[:, 0], poly[:, 1], "k", lw=0.8)
    for name, (p, q) in pic.segments.items():
        ax.plot([p[0], q[0]], [p[1], q[1]], lw=2 if name == "ab" else 0.8,
                color="r" if name == "ab" else "m")
    for lab in pic.labels:
        ax.plot(*lab.point, "k.", ms=4)
        ax.annotate(lab.text, lab.point, fontsize=8, xytext=(3, 3), textcoords="offset points")
    for zone in pic.zones:
        ax.plot([zone.start[0], zone.end[0]], [zone.start[1], zone.end[1]], lw=5, alpha=0.35,
                color="orange" if zone.pairs == 2 else "cyan")
    lim = pic.view
    ax.set_xlim(lim[0], lim[2])
    ax.set_ylim(lim[1], lim[3])
    ax.set_aspect("equal")
    ax.set_title(f"meshing z {a.z1}/{a.z2}, m {a.module}, x {x1:.3f}/{x2:.3f}")
    fig.savefig(f"{a.out}_mesh.png", dpi=90)
    print("wrote", f"{a.out}_mesh.png")
    rho, l1, l2 = pair.sliding.curve()
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.plot(rho, l1, label="λ1")
    ax.plot(rho, l2, label="λ2")
    for row in pair.sliding.rows:
        ax.axvline(row.rho, color="gray", lw=0.5)
        if row.label:
            ax.annotate(row.label, (row.rho, 1.0))
    ax.set_ylim(-6, 1.5)
    ax.legend()
    fig.savefig(f"{a.out}_sliding.png", dpi=90)
    print("wrote", f"{a.out}_sliding.png")


if __name__ == "__main__":
    main()
