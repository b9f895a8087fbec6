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
    fig = plt.figure(figsize=(4.6, 4), dpi=150)
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
    _sparse_ticks(ax)
    ax.view_init(elev=20, azim=30)  # look at the plane obliquely, not edge-on
    plt.show()
    return float(n @ c + pi[3]), float(n @ u), float(n @ v)


def rotated_axes(R):
    """Draw the axes e1, e2, e3 (grey) and their images r1, r2, r3, the columns of ``R``."""
    R = np.asarray(R, dtype=float)
    fig = plt.figure(figsize=(4.6, 4), dpi=150)
    ax = fig.add_subplot(projection="3d")
    for i, color in enumerate(("tab:red", "tab:green", "tab:blue")):
        e = np.eye(3)[:, i]
        ax.quiver(0, 0, 0, *e, color="0.6", lw=1)
        ax.text(*(1.08 * e), f"$e_{i + 1}$", color="0.4")
        ax.quiver(0, 0, 0, *R[:, i], color=color, lw=2)
        # the label of r_i a little further out, so that it stays readable when r_i = e_i
        ax.text(*(1.3 * R[:, i]), f"$r_{i + 1}$", color=color)
    for setter in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        setter(-1.3, 1.3)
    ax.set_box_aspect((1, 1, 1))
    _sparse_ticks(ax)
    for set_ticks in (ax.set_xticks, ax.set_yticks, ax.set_zticks):
        set_ticks([-1, 0, 1])
    plt.show()
    return R


def _sparse_ticks(ax, n=3):
    """At most ``n`` ticks on each axis of a 3D plot, so that labels of neighbouring axes do not collide."""
    from matplotlib.ticker import MaxNLocator

    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.set_major_locator(MaxNLocator(n))
    ax.set_xlabel("$x$")
    ax.set_ylabel("$y$")
    ax.set_zlabel("$z$")


def posts_along_a_road(world, image):
    """Draw equally spaced posts on a road (``world`` positions) and their photographed positions."""
    _fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 2.8), sharex=False, dpi=150)
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


def angle_and_laguerre(l, m, cr):
    """Draw two lines ``l``, ``m`` (homogeneous 3-vectors, meeting at a finite point) with the angle θ
    turning the normal of ``l`` onto the normal of ``m``, and beside them Laguerre's cross-ratio ``cr``
    (a complex number) on the unit circle of the complex plane, at the angle −2θ.

    Returns θ and the argument of ``cr`` in degrees.
    """
    l, m = (np.array([float(c) for c in v]) for v in (l, m))
    cr = complex(cr)
    p = np.cross(l, m)
    p = p[:2] / p[2]
    theta = np.arctan2(l[0] * m[1] - l[1] * m[0], l[0] * m[0] + l[1] * m[1])
    _fig, (left, right) = plt.subplots(1, 2, figsize=(9, 4))
    s = np.linspace(-2.2, 2.2, 2)
    for line, name, color in ((l, r"$\mathbf{l}$", "tab:blue"), (m, r"$\mathbf{m}$", "tab:orange")):
        d = np.array([line[1], -line[0]]) / np.hypot(line[0], line[1])  # direction of the line
        left.plot(p[0] + s * d[0], p[1] + s * d[1], color=color, lw=1.8, label=name)
        n = np.array(line[:2]) / np.hypot(line[0], line[1])
        left.annotate("", p + 0.9 * n, p, arrowprops={"arrowstyle": "->", "color": color})
    a0 = np.arctan2(l[1], l[0])
    arc = a0 + np.linspace(0, theta, 50)
    left.plot(p[0] + 0.5 * np.cos(arc), p[1] + 0.5 * np.sin(arc), color="black", lw=1)
    mid = a0 + theta / 2
    left.text(p[0] + 0.62 * np.cos(mid), p[1] + 0.62 * np.sin(mid), r"$\theta$")
    left.plot(*p, "o", color="black")
    left.set_aspect("equal")
    left.set_xlim(p[0] - 2, p[0] + 2)
    left.set_ylim(p[1] - 2, p[1] + 2)
    left.legend(loc="lower right")
    left.set_title("two lines and the normals $(l_1, l_2)$, $(m_1, m_2)$", fontsize=9)
    t = np.linspace(0, 2 * np.pi, 200)
    right.plot(np.cos(t), np.sin(t), color="0.6", lw=1)
    right.axhline(0, color="0.8", lw=0.8)
    right.axvline(0, color="0.8", lw=0.8)
    right.plot([0, cr.real], [0, cr.imag], color="tab:red", lw=1.5)
    right.plot(cr.real, cr.imag, "o", color="tab:red")
    right.annotate(r"$(\mathbf{l}, \mathbf{m}; \mathbf{p}\vee\mathbf{I}, \mathbf{p}\vee\mathbf{J}) = e^{-2i\theta}$",
                   (cr.real, cr.imag), xytext=(-60, -22), textcoords="offset points", fontsize=9)
    arc2 = np.linspace(0, np.angle(cr), 50)
    right.plot(0.3 * np.cos(arc2), 0.3 * np.sin(arc2), color="black", lw=1)
    right.text(0.35, -0.25 if np.angle(cr) < 0 else 0.15, r"$-2\theta$")
    right.set_aspect("equal")
    right.set_xlim(-1.4, 1.4)
    right.set_ylim(-1.4, 1.4)
    right.set_xlabel("real part")
    right.set_ylabel("imaginary part")
    right.set_title("Laguerre's cross-ratio in the complex plane", fontsize=9)
    plt.tight_layout()
    plt.show()
    return float(np.degrees(theta)), float(np.degrees(np.angle(cr)))


def circle_pencil(circles, a, b):
    """Draw circles ``(cx, cy, r)`` of the pencil through the points ``a`` and ``b`` (and I, J), and the
    line ``ab``, the finite part of the pencil's degenerate member ``ab ∪ l∞``.

    Returns the largest distance of ``a`` or ``b`` from a drawn circle (zero up to rounding).
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    _fig, ax = plt.subplots(figsize=(5.6, 5))
    t = np.linspace(0, 2 * np.pi, 300)
    worst = 0.0
    colors = plt.cm.viridis(np.linspace(0, 0.9, len(circles)))
    for (cx, cy, r), color in zip(circles, colors, strict=True):
        cx, cy, r = float(cx), float(cy), float(r)
        ax.plot(cx + r * np.cos(t), cy + r * np.sin(t), color=color, lw=1.3)
        ax.plot(cx, cy, "+", color=color)
        worst = max(worst, *(abs(np.hypot(*(q - (cx, cy))) - r) for q in (a, b)))
    d = (b - a) / np.linalg.norm(b - a)
    ax.plot(*np.array([a - 6 * d, b + 6 * d]).T, color="black", lw=1, ls="--", label=r"$\mathbf{a} \vee \mathbf{b}$")
    mid = (a + b) / 2
    ax.plot(*np.array([mid - 6 * d[::-1] * (1, -1), mid + 6 * d[::-1] * (1, -1)]).T, color="0.6", lw=0.8,
            ls=":", label="centres")
    for q, name in ((a, r"$\mathbf{a}$"), (b, r"$\mathbf{b}$")):
        ax.plot(*q, "o", color="black")
        ax.annotate(name, q, xytext=(5, 5), textcoords="offset points")
    ax.set_aspect("equal")
    ax.set_xlim(-3.5, 3.5)
    ax.set_ylim(-3.5, 3.5)
    ax.legend(loc="upper right", fontsize=8)
    ax.set_title(r"the pencil of conics through $\mathbf{a}, \mathbf{b}, \mathbf{I}, \mathbf{J}$", fontsize=9)
    plt.show()
    return worst


def involution_on_a_line(vertices, pairs, y=0.0):
    """Draw a complete quadrangle, the horizontal line ``y = y`` and the pairs of points where it meets
    opposite sides (Desargues's involution theorem).

    ``vertices`` maps the names of the four points to ``(x, y)``; ``pairs`` is a list of three entries
    ``((side, x), (side, x'))``: the two opposite sides (as two-letter names) and the abscissae where they
    meet the line. Returns the abscissae drawn, pair by pair.
    """
    _fig, ax = plt.subplots(figsize=(6.4, 4.2))
    colors = ("tab:blue", "tab:green", "tab:purple")
    drawn = []
    for ((s, x), (t, x2)), color in zip(pairs, colors, strict=True):
        for side, cut in ((s, x), (t, x2)):
            p, q = (np.asarray(vertices[n], dtype=float) for n in side)
            far = max((p, q), key=lambda v: abs(v[1] - y))  # draw the side from its cut to its far vertex
            ax.plot([float(cut), far[0]], [y, far[1]], color=color, lw=0.9)
            ax.plot([float(cut)], [y], "o", color=color, ms=5)
            ax.annotate(side, (float(cut), y), xytext=(-6, -14), textcoords="offset points", color=color, fontsize=8)
        mid, half = (float(x) + float(x2)) / 2, abs(float(x2) - float(x)) / 2
        arc = np.linspace(0, np.pi, 60)
        ax.plot(mid + half * np.cos(arc), y - 0.35 * half * np.sin(arc), ls=":", color=color, lw=1)
        drawn.append((float(x), float(x2)))
    lo = min(min(p) for p in drawn) - 1
    hi = max(max(p) for p in drawn) + 1
    ax.plot([lo, hi], [y, y], color="tab:red", lw=1.5)
    ax.annotate(r"$l$", (hi, y), xytext=(4, 4), textcoords="offset points", color="tab:red")
    for name, (px, py) in vertices.items():
        ax.plot([float(px)], [float(py)], "o", color="black", ms=4)
        ax.annotate(name, (float(px), float(py)), xytext=(4, 4), textcoords="offset points", fontsize=9)
    ax.set_aspect("equal")
    ax.set_title("Desargues's involution: opposite sides meet $l$ in pairs of one involution", fontsize=9)
    plt.show()
    return drawn


def euclidean_figure(points, *, segments=(), lines=(), circles=(), highlight=(), title="", size=(5.6, 4.8),
                     pad=1.0, offsets=None):
    """Draw a Euclidean configuration from coordinates (exact numbers are converted to floats here).

    ``points`` maps names to ``(x, y)``; ``segments`` is a list of ``(P, Q, color)`` drawn between two named
    points, ``lines`` a list of ``(P, Q, color)`` drawn through them across the whole figure, ``circles`` a
    list of ``(centre, r², color)`` with ``centre`` a name or ``(x, y)``. Points named in ``highlight`` are red;
    ``offsets`` maps a name to its label's offset in points (default ``(4, 4)``), to keep labels apart.
    Returns the radii drawn, for the calling cell to compare with its exact squared radii.
    """
    pts = {n: np.array([float(c) for c in p]) for n, p in points.items()}
    xs, ys = zip(*pts.values(), strict=True)
    lo, hi = np.array([min(xs), min(ys)]) - pad, np.array([max(xs), max(ys)]) + pad
    radii = []
    for centre, r2, _color in circles:
        c = pts[centre] if isinstance(centre, str) else np.array([float(v) for v in centre])
        r = float(np.sqrt(float(r2)))
        radii.append(r)
        lo, hi = np.minimum(lo, c - r - pad / 2), np.maximum(hi, c + r + pad / 2)
    _fig, ax = plt.subplots(figsize=size)
    t = np.linspace(0, 2 * np.pi, 400)
    for (centre, _r2, color), r in zip(circles, radii, strict=True):
        c = pts[centre] if isinstance(centre, str) else np.array([float(v) for v in centre])
        ax.plot(c[0] + r * np.cos(t), c[1] + r * np.sin(t), color=color, lw=1.2)
    span = float(np.max(hi - lo))
    for p, q, color in lines:
        a, b = pts[p], pts[q]
        d = (b - a) / np.linalg.norm(b - a)
        ax.plot(*np.array([a - 3 * span * d, a + 3 * span * d]).T, color=color, lw=1.0)
    for p, q, color in segments:
        ax.plot(*np.array([pts[p], pts[q]]).T, color=color, lw=1.2)
    offsets = offsets or {}
    for name, p in pts.items():
        color = "tab:red" if name in highlight else "black"
        ax.plot(*p, "o", color=color, ms=4, zorder=3)
        ax.annotate(name, p, xytext=offsets.get(name, (4, 4)), textcoords="offset points", fontsize=9, color=color,
                    bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8}, zorder=4)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=9)
    plt.show()
    return radii


def line_through(ax, p, q, extend=0.25, **kw):
    """Draw the segment from ``p`` to ``q`` (pairs of floats), extended by a fraction of its length at
    both ends; returns the two end points drawn."""
    (x1, y1), (x2, y2) = p, q
    dx, dy = x2 - x1, y2 - y1
    ends = ((x1 - extend * dx, y1 - extend * dy), (x2 + extend * dx, y2 + extend * dy))
    ax.plot([ends[0][0], ends[1][0]], [ends[0][1], ends[1][1]], **kw)
    return ends


def mark_points(ax, points, color="k", offsets=None):
    """Mark named points (``name -> (x, y)``) with a dot and a label; ``offsets`` maps a name to the
    label's offset in points (default ``(4, 4)``), to keep labels off the lines."""
    offsets = offsets or {}
    for name, (x, y) in points.items():
        ax.plot([x], [y], "o", color=color, ms=4, zorder=3)
        ax.annotate(name, (x, y), textcoords="offset points", xytext=offsets.get(name, (4, 4)), fontsize=9,
                    color=color, bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8},
                    zorder=4)


def radial_offsets(points, centre=(0.0, 0.0), distance=9):
    """Label offsets pointing away from ``centre``: for points on a circle, the labels sit outside it."""
    out = {}
    for name, (x, y) in points.items():
        d = np.hypot(x - centre[0], y - centre[1]) or 1.0
        out[name] = (distance * (x - centre[0]) / d - 4, distance * (y - centre[1]) / d - 4)
    return out


def _span(ax, points, margin=0.0, **kw):
    """Draw the segment covering collinear 3D ``points``, with ``margin`` (a fraction of its length)."""
    pts = np.array(points, dtype=float)
    d = pts[-1] - pts[0]
    d = d / np.linalg.norm(d)
    t = (pts - pts[0]) @ d
    lo, hi = t.min(), t.max()
    pad = margin * (hi - lo)
    ends = np.array([pts[0] + (lo - pad) * d, pts[0] + (hi + pad) * d])
    ax.plot(*ends.T, **kw)


def desargues_in_space(triangles, centre, axis_points):
    """Draw two triangles of space in perspective from ``centre`` (3D float triples), the rays from the centre
    through corresponding vertices, the sides extended (dashed) to the points where corresponding sides meet,
    and the axis through those points.

    ``triangles`` is a pair of dicts ``name -> (x, y, z)`` listing corresponding vertices in the same order;
    ``axis_points`` maps the names of the three meets (of sides 12, 23, 31) to their points. Returns the
    number of rays drawn.
    """
    fig = plt.figure(figsize=(6.4, 5.6))
    ax = fig.add_subplot(projection="3d")
    colors = ("tab:blue", "tab:green")
    meets = list(axis_points.values())
    for tri, color in zip(triangles, colors, strict=True):
        pts = list(tri.values())
        ring = [*pts, pts[0]]
        ax.plot(*zip(*ring, strict=True), color=color, lw=1.5)
        for k in range(3):
            _span(ax, [pts[k], pts[(k + 1) % 3], meets[k]], color=color, lw=0.7, ls="--")
        for name, p in tri.items():
            ax.scatter(*p, color=color, s=12)
            ax.text(*p, f" {name}", color=color, fontsize=9)
    rays = 0
    for p, q in zip(triangles[0].values(), triangles[1].values(), strict=True):
        _span(ax, [centre, p, q], color="0.5", lw=0.8, ls=":")
        rays += 1
    ax.scatter(*centre, color="black", s=14)
    ax.text(*centre, " O", fontsize=9)
    _span(ax, meets, margin=0.25, color="tab:red", lw=1.5)
    for n, p in axis_points.items():
        ax.scatter(*p, color="tab:red", s=14)
        ax.text(*p, f" {n}", color="tab:red", fontsize=9)
    ax.view_init(elev=18, azim=-35)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.set_title("Desargues in space: the axis is the meet of the two planes", fontsize=9)
    plt.tight_layout()
    plt.show()
    return rays
