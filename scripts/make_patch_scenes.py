#!/usr/bin/env python3
"""Writes the built-in patch scenes of docs/algorithms.md §4 (issue 13) into scenes/:
  teapot.json  the Newell teapot, 32 bicubic Bézier patches (public-domain data, read from
               TEAPOT.json: {"patches": [[16 points], ...]}, rows of constant u)
  column.json  a B-spline surface of revolution: a column (cubic profile x cubic closed ring)
  torus.json   an exact NURBS torus: rational biquadratic, 9x9 control points, weights 1, √2/2
Usage: python3 scripts/make_patch_scenes.py TEAPOT.json"""
import json
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def r6(x):
    return round(x, 9) + 0.0


def dump(v, indent=0):
    """JSON with objects one key a line and arrays of numbers (points) on one line."""
    pad = "  " * indent
    if isinstance(v, dict):
        items = [f'{pad}  {json.dumps(k)}: {dump(x, indent + 1)}' for k, x in v.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(v, list) and v and isinstance(v[0], (list, dict)):
        return "[\n" + ",\n".join(pad + "  " + dump(x, indent + 1) for x in v) + "\n" + pad + "]"
    return json.dumps(v, ensure_ascii=False)


def write(name, scene):
    with open(os.path.join(ROOT, "scenes", name + ".json"), "w") as f:
        f.write(dump(scene) + "\n")


def teapot(src):
    with open(src) as f:
        data = json.load(f)
    return {
        "about": "The Newell teapot (1975): 32 bicubic Bézier patches, one bezier_set "
                 "(docs/algorithms.md §4, seed 003; thesis table 2). Public-domain data.",
        "camera": {"eye": [6.0, -9.0, 6.0], "target": [0.3, 0.0, 1.3], "up": [0, 0, 1],
                   "fov_deg": 33, "width": 512, "height": 512},
        "background": [0.08, 0.09, 0.12],
        "patches": [{"type": "bezier_set", "degree": [3, 3], "color": [0.85, 0.7, 0.45],
                     "patches": data["patches"]}],
    }


def column():
    # Profile (radius, height), cubic, non-uniform knots; the ring: a closed cubic B-spline
    # around a regular 10-gon, starting and ending at the middle of an edge (tangent-continuous
    # seam); the surface is the tensor product (r_i·c_j, z_i).
    profile = [(0.0, 0.0), (1.35, 0.0), (1.35, 0.25), (1.05, 0.35), (0.95, 0.6), (0.92, 2.5),
               (0.82, 4.6), (0.85, 4.9), (1.15, 5.05), (1.45, 5.3), (1.45, 5.6), (0.0, 5.6)]
    nu = len(profile)
    interior_u = [0.06, 0.12, 0.2, 0.35, 0.6, 0.8, 0.86, 0.92]
    assert len(interior_u) == nu - 4
    knots_u = [0.0] * 4 + interior_u + [1.0] * 4
    m = 10
    corners = [(math.cos(2 * math.pi * k / m) / math.cos(math.pi / m),
                math.sin(2 * math.pi * k / m) / math.cos(math.pi / m)) for k in range(m)]
    mid = ((corners[-1][0] + corners[0][0]) / 2, (corners[-1][1] + corners[0][1]) / 2)
    ring = [mid] + corners + [mid]
    nv = len(ring)
    knots_v = [0.0] * 4 + [k / (nv - 3) for k in range(1, nv - 3)] + [1.0] * 4
    pts = [[r6(r * cx), r6(r * cy), r6(z)] for (r, z) in profile for (cx, cy) in ring]
    return {
        "about": "A column: a cubic B-spline surface of revolution (profile x closed ring, "
                 "12 x 12 control points, non-uniform knots in u) (docs/algorithms.md §4, "
                 "thesis table 3).",
        "camera": {"eye": [7.5, -10.0, 6.5], "target": [0.0, 0.0, 2.7], "up": [0, 0, 1],
                   "fov_deg": 31, "width": 512, "height": 512},
        "background": [0.08, 0.09, 0.12],
        "patches": [{"type": "bspline", "degree": [3, 3], "size": [nu, nv], "knots_u": knots_u,
                     "knots_v": knots_v, "control_points": pts, "color": [0.8, 0.8, 0.75]}],
    }


def torus():
    # Rational quadratic circle: 9 points on the square around the unit circle, weights
    # 1, √2/2, ...; the torus is the tensor product of the tube circle (u) and the ring (v).
    s = math.sqrt(0.5)
    circ = [(1, 0, 1), (1, 1, s), (0, 1, 1), (-1, 1, s), (-1, 0, 1), (-1, -1, s), (0, -1, 1),
            (1, -1, s), (1, 0, 1)]
    knots = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]
    R, r = 2.0, 0.75
    # Tilt the torus by 30° about the x axis so that the hole is seen.
    ca, sa = math.cos(math.radians(30)), math.sin(math.radians(30))
    pts, weights = [], []
    for (tx, tz, tw) in circ:          # tube: radius R + r·tx, height r·tz
        for (cx, cy, cw) in circ:      # ring
            x, y, z = (R + r * tx) * cx, (R + r * tx) * cy, r * tz
            y, z = y * ca - z * sa, y * sa + z * ca
            pts.append([r6(x), r6(y), r6(z)])
            weights.append(r6(tw * cw))
    return {
        "about": "An exact NURBS torus (R = 2, r = 0.75), one rational biquadratic patch, 9 x 9 "
                 "control points, weights 1, √2/2 and 1/2, tilted 30° (docs/algorithms.md §4, "
                 "thesis table 5).",
        "camera": {"eye": [0.0, -9.0, 5.5], "target": [0.0, 0.0, 0.0], "up": [0, 0, 1],
                   "fov_deg": 40, "width": 512, "height": 512},
        "background": [0.08, 0.09, 0.12],
        "patches": [{"type": "nurbs", "degree": [2, 2], "size": [9, 9], "knots_u": knots,
                     "knots_v": knots, "control_points": pts, "weights": weights,
                     "color": [0.4, 0.75, 0.9]}],
    }


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: make_patch_scenes.py TEAPOT.json")
    write("teapot", teapot(sys.argv[1]))
    write("column", column())
    write("torus", torus())
