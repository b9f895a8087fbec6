"""Figures shared by the chapters: plotting code that is not part of the mathematics.

Each function draws one figure and returns the numbers it drew, so that the calling cell can assert
what the reader sees.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np


def meet_of_two_lines(l, m, x):
    """Draw the lines ``l`` and ``m`` (homogeneous 3-vectors) and their meet ``x`` (an ordinary point)."""
    l, m, x = (np.array([float(c) for c in v]) for v in (l, m, x))
    px = x[:2] / x[2]
    _fig, ax = plt.subplots(figsize=(4.2, 3.6))
    xs = np.linspace(px[0] - 3, px[0] + 3, 2)
    for line, name in ((l, r"$\mathbf{l}$"), (m, r"$\mathbf{l}'$")):
        ax.plot(xs, -(line[0] * xs + line[2]) / line[1], lw=1.5, label=name)  # both lines are not vertical
    ax.plot(*px, "o", color="black")
    ax.annotate(r"$\mathbf{x} = \mathbf{l} \times \mathbf{l}'$", px, xytext=(8, -14), textcoords="offset points")
    ax.set_aspect("equal")
    ax.set_xlim(px[0] - 3, px[0] + 3)
    ax.set_ylim(px[1] - 2.5, px[1] + 2.5)
    ax.legend(loc="upper left")
    ax.grid(alpha=0.3)
    plt.show()
    return px


def point_as_ray(x, scales=(0.5, 1.0, 1.5)):
    """Draw the ray of R^3 through the homogeneous vector ``x``, the plane w = 1 and representatives."""
    x = np.asarray(x, dtype=float)
    fig = plt.figure(figsize=(5, 4))
    ax = fig.add_subplot(projection="3d")
    g = np.linspace(-1, 3, 2)
    gx, gy = np.meshgrid(g, g)
    ax.plot_surface(gx, gy, np.ones_like(gx), alpha=0.15, color="tab:blue")
    top = max(scales) * 1.2
    ax.plot([0, top * x[0]], [0, top * x[1]], [0, top * x[2]], color="tab:orange", lw=2)
    reps = np.array([k * x for k in scales])
    ax.scatter(*reps.T, color="black", s=15)
    ax.scatter(0, 0, 0, color="black", marker="x")
    on_plane = x / x[2]
    ax.scatter(*on_plane, color="tab:red", s=40)
    ax.text(*on_plane, "  (x, y, 1)", color="tab:red")
    ax.set_xlabel("$x_1$")
    ax.set_ylabel("$x_2$")
    ax.set_zlabel("$x_3$")
    ax.set_box_aspect((1, 1, 0.8))
    plt.show()
    return on_plane


def plane_with_normal(pi, centre):
    """Draw the plane ``pi`` = (n, d) near the point ``centre`` on it, with its normal n."""
    pi, c = np.asarray(pi, dtype=float), np.asarray(centre, dtype=float)
    n = pi[:3]
    u = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 * np.linalg.norm(n) else [0, 1.0, 0])
    u /= np.linalg.norm(u)
    v = np.cross(n, u) / np.linalg.norm(n)
    s = np.linspace(-1, 1, 2)
    a, b = np.meshgrid(s, s)
    pts = c[:, None, None] + u[:, None, None] * a + v[:, None, None] * b
    fig = plt.figure(figsize=(4.6, 4))
    ax = fig.add_subplot(projection="3d")
    ax.plot_surface(*pts, alpha=0.3, color="tab:blue")
    unit = n / np.linalg.norm(n)
    ax.quiver(*c, *unit, color="tab:red", lw=2)
    ax.text(*(c + 1.1 * unit), r"$\mathbf{n}$", color="tab:red")
    ax.scatter(*c, color="black")
    lo, hi = c - 1.3, c + 1.3
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=20, azim=30)  # look at the plane obliquely, not edge-on
    plt.show()
    return float(n @ c + pi[3]), float(n @ u), float(n @ v)


def rotated_axes(R):
    """Draw the axes e1, e2, e3 (grey) and their images r1, r2, r3, the columns of ``R``."""
    R = np.asarray(R, dtype=float)
    fig = plt.figure(figsize=(4.6, 4))
    ax = fig.add_subplot(projection="3d")
    for i, color in enumerate(("tab:red", "tab:green", "tab:blue")):
        e = np.eye(3)[:, i]
        ax.quiver(0, 0, 0, *e, color="0.6", lw=1)
        ax.text(*(1.08 * e), f"$e_{i + 1}$", color="0.4")
        ax.quiver(0, 0, 0, *R[:, i], color=color, lw=2)
        ax.text(*(1.12 * R[:, i]), f"$r_{i + 1}$", color=color)
    for setter in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        setter(-1, 1)
    ax.set_box_aspect((1, 1, 1))
    plt.show()
    return R


def posts_along_a_road(world, image):
    """Draw equally spaced posts on a road (``world`` positions) and their photographed positions."""
    _fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 2.8), sharex=False)
    for ax, xs, title in ((top, world, "on the road"), (bottom, image, "in the photograph")):
        ax.axhline(0, color="0.5", lw=1)
        for k, xk in enumerate(xs):
            ax.plot([xk, xk], [0, 1], color="tab:brown", lw=3)
            ax.text(xk, 1.15, "ABCD"[k] if k < 4 else "", ha="center")
        ax.set_ylim(-0.2, 1.6)
        ax.set_yticks([])
        ax.set_title(title, fontsize=9)
    plt.tight_layout()
    plt.show()
    return np.diff(world), np.diff(image)
