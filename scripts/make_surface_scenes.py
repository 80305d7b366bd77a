#!/usr/bin/env python3
"""Writes the surface scenes of docs/algorithms.md §3 (seed 004) into scenes/, deterministically.

Run from the repository root:  python3 scripts/make_surface_scenes.py [--preview DIR]

Standard library only; the number format and the JSON layout are make_demo_scenes.py's.

Scenes (256x256, the seed's parameters, figs 1-5):
  surf_ellipsoid  eq 2, open at y = 0.5b; the camera looks a little into the opening
  surf_relief     eq 3, the ellipsoid with surface relief
  surf_spiral     eq 5, the spiral figure with a rotating elliptic section
  surf_snail      eq 6, the "snail"
  surf_rocket     eq 7, the rocket defined on parameter intervals
  surf_mix        a relief ellipsoid and a rocket standing on a texture loop (z = 0), with a
                  tennis-ball seam curve (curve12's) wound round the ellipsoid: the nearest hit
                  across curves, textures and surfaces decides, objects overlap on screen at
                  different depths.

The single-primitive scenes keep the seed's frame (y up, unrotated, unscaled). Each camera
looks from a raised 3/4 view (azimuth 35 degrees); its target and field of view are computed
from dense samples of the parametric surface so that the object is centred and spans 70 % of
the image (the larger of its two extents). The checks at the end re-read the written files and
recompute the samples from them.

--preview DIR writes DIR/NAME.png: a z-buffered splat of the same samples (the surfaces, the
curve polyline and the texture strip), shaded by depth. A framing aid, not a renderer.
"""

import json
import math
import os
import struct
import sys
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_demo_scenes as demo  # noqa: E402  (number format, JSON layout, camera projection)

ROOT = demo.ROOT
FILL = 0.70  # fraction of the image the single primitive spans
SIZE = 256

# The seed's parameters (docs/scene-format.md; default_surface_params in ref/scene/surface.cpp).
SEED = {
    "ellipsoid": {"a": 1.0, "b": 2.0, "c": 1.0, "y_range": [-2.0, 1.0]},
    "relief_ellipsoid": {"a": 1.0, "b": 2.0, "c": 1.3, "d": 1.0, "e": 0.4, "y_range": [-2.0, 2.0]},
    "spiral": {"R": 0.7, "k": 0.5, "a": 0.2, "b": 0.16, "c": 0.64, "phi_max": 11.0},
    "snail": {"a": 0.01, "phi_max": 10.0 * math.pi},
    "rocket": {"a": 0.2, "b": 1.0, "c": 0.8, "d": 0.2, "e": 0.4},
}


# ------------------------------------------------------------------------------------------------
# The seed's parametric surfaces R(phi, v), local frame (y is the axis)

def params(s):
    """The surface's parameters: the seed's, overridden by the scene's."""
    p = dict(SEED[s["type"]])
    p.update({k: v for k, v in s.items() if k in ("a", "b", "c", "d", "e", "R", "k", "phi_max",
                                                   "y_range")})
    return p


def local_point(t, p, phi, v):
    if t in ("ellipsoid", "relief_ellipsoid"):  # eq 2, 3 (v = y)
        k = 1.0 if t == "ellipsoid" else p["d"] + p["e"] * math.sin(10 * phi) * math.cos(9 * v)
        s = math.sqrt(max(0.0, 1 - v * v / (p["b"] * p["b"])))
        return (k * p["a"] * s * math.sin(phi), v, k * p["c"] * s * math.cos(phi))
    if t == "spiral":  # eq 5 (v = gamma)
        axis = p["R"] + p["a"] * phi
        radial = (p["c"] * math.cos(v) * math.cos(4 * phi) +
                  p["b"] * math.sin(v) * math.sin(4 * phi))
        return ((axis + radial) * math.sin(phi),
                p["k"] * phi + p["b"] * math.sin(v) * math.cos(4 * phi)
                - p["c"] * math.cos(v) * math.sin(4 * phi),
                (axis + radial) * math.cos(phi))
    if t == "snail":  # eq 6 (v = gamma)
        k = math.floor(phi / (2 * math.pi))
        m = phi - 2 * math.pi * k
        R = p["a"] * phi + 2 * p["a"] * sum(2 * math.pi * i + m for i in range(k))
        r = p["a"] * phi
        return ((R + r * math.cos(v)) * math.sin(phi), r * math.sin(v),
                (R + r * math.cos(v)) * math.cos(phi))
    if t == "rocket":  # eq 7, cone a(1 - (y - b)/e) (v = y)
        if v <= 0:
            r = p["a"] + (math.sin(5 * phi) - 1) * v * p["d"] / p["c"]
        elif v <= p["b"]:
            r = p["a"]
        else:
            r = p["a"] * (1 - (v - p["b"]) / p["e"])
        return (r * math.sin(phi), v, r * math.cos(phi))
    raise ValueError(t)


def domain(t, p):
    """(phi_end, v_lo, v_hi)."""
    if t in ("ellipsoid", "relief_ellipsoid"):
        return 2 * math.pi, p["y_range"][0], p["y_range"][1]
    if t in ("spiral", "snail"):
        return p["phi_max"], 0.0, 2 * math.pi
    return 2 * math.pi, -p["c"], p["b"] + p["e"]


def place(s, X):
    """world = position + Rz Ry Rx (scale X), degrees (docs/surfaces.md)."""
    ax, ay, az = (math.radians(v) for v in s.get("rotation_deg", [0, 0, 0]))
    x, y, z = (c * s.get("scale", 1.0) for c in X)
    y, z = math.cos(ax) * y - math.sin(ax) * z, math.sin(ax) * y + math.cos(ax) * z
    x, z = math.cos(ay) * x + math.sin(ay) * z, -math.sin(ay) * x + math.cos(ay) * z
    x, y = math.cos(az) * x - math.sin(az) * y, math.sin(az) * x + math.cos(az) * y
    px, py, pz = s.get("position", [0, 0, 0])
    return (px + x, py + y, pz + z)


def surface_samples(s, n_phi=360, n_v=48):
    """World points of the surface on an n_phi x n_v grid (ends included); n_phi per turn."""
    t, p = s["type"], params(s)
    phi_end, lo, hi = domain(t, p)
    n_phi = max(n_phi, int(n_phi * phi_end / (2 * math.pi)))
    out = []
    for i in range(n_phi + 1):
        phi = phi_end * i / n_phi
        for j in range(n_v + 1):
            out.append(place(s, local_point(t, p, phi, lo + (hi - lo) * j / n_v)))
    return out


def polyline_samples(points, closed, step):
    """Points along the polyline's chords every `step` (the curves' arcs stay near them)."""
    pts = [demo.to3(p) for p in points]
    pairs = list(zip(pts, pts[1:] + pts[:1] if closed else pts[1:]))
    out = []
    for a, b in pairs:
        n = max(1, int(math.ceil(demo.norm(demo.sub(b, a)) / step)))
        out += [demo.add(a, demo.mul(demo.sub(b, a), k / n)) for k in range(n)]
    return out


# ------------------------------------------------------------------------------------------------
# Framing

def extents(cam, pts):
    xs, ys = [], []
    for X in pts:
        x, y, c = demo.camera_project(cam, X)
        assert c > 0, "behind the camera"
        xs.append(x)
        ys.append(y)
    return min(xs), max(xs), min(ys), max(ys)


def frame(pts, up, azimuth_deg, elevation_deg, distance_factor=4.0, fill=FILL):
    """A camera looking at the points from (azimuth, elevation) about `up` ('y' or 'z'),
    centred on their projection and spanning `fill` of the square image."""
    lo = [min(p[k] for p in pts) for k in range(3)]
    hi = [max(p[k] for p in pts) for k in range(3)]
    target = tuple((a + b) / 2 for a, b in zip(lo, hi))
    dist = distance_factor * demo.norm(demo.sub(tuple(hi), tuple(lo))) / 2
    az, el = math.radians(azimuth_deg), math.radians(elevation_deg)
    horiz, vert = math.cos(el), math.sin(el)
    if up == "y":
        d, upv = (horiz * math.sin(az), vert, horiz * math.cos(az)), [0.0, 1.0, 0.0]
    else:
        d, upv = (horiz * math.sin(az), -horiz * math.cos(az), vert), [0.0, 0.0, 1.0]
    cam = {}
    for _ in range(6):  # move the target until the projection is centred
        cam = {"eye": list(demo.add(target, demo.mul(d, dist))), "target": list(target),
               "up": upv, "fov_deg": 60.0, "width": SIZE, "height": SIZE}
        x0, x1, y0, y1 = extents(cam, pts)
        W = demo.mul(d, -1.0)
        U = demo.cross3(W, tuple(upv))
        U = demo.mul(U, 1 / demo.norm(U))
        V = demo.cross3(U, W)
        target = demo.add(target, demo.add(demo.mul(U, (x0 + x1) / 2 * dist),
                                           demo.mul(V, (y0 + y1) / 2 * dist)))
    half = max(x1 - x0, y1 - y0) / 2 / fill
    cam["fov_deg"] = float(format(math.degrees(2 * math.atan(half)), ".4g"))
    return cam


# ------------------------------------------------------------------------------------------------
# Scenes

COLOURS = {
    "ellipsoid": [0.95, 0.55, 0.2],
    "relief_ellipsoid": [0.3, 0.7, 1.0],
    "spiral": [0.45, 0.9, 0.4],
    "snail": [0.95, 0.8, 0.3],
    "rocket": [0.85, 0.85, 0.9],
}

SINGLE = [
    # name, type, figure, elevation (degrees), about
    ("surf_ellipsoid", "ellipsoid", 1, 35.0,
     "The vector-described ellipsoid a = c = 1, b = 2, cut open at y = 0.5b (seed 004, eq 2, "
     "fig. 1); the raised view looks a little into the opening."),
    ("surf_relief", "relief_ellipsoid", 2, 20.0,
     "The ellipsoid with surface relief k = d + e sin 10phi cos 9y, a = 1, b = 2, c = 1.3, d = 1, "
     "e = 0.4 (seed 004, eq 3, fig. 2)."),
    ("surf_spiral", "spiral", 3, 20.0,
     "The spiral figure with a rotating elliptic section, R = 0.7, k = 0.5, a = 0.2, b = 0.16, "
     "c = 0.64, phi in [0, 11] (seed 004, eq 5, fig. 3)."),
    ("surf_snail", "snail", 4, 40.0,
     "The 'snail': a circle of radius a phi swept along a spiral in the plane y = 0, a = 0.01, "
     "phi in [0, 10 pi] (seed 004, eq 6, fig. 4)."),
    ("surf_rocket", "rocket", 5, 20.0,
     "The rocket defined on parameter intervals: fins, cylinder and cone, a = 0.2, b = 1, c = 0.8, "
     "d = 0.2, e = 0.4 (seed 004, eq 7 with the cone read as a(1 - (y - b)/e), fig. 5)."),
]


def scene_single(name, t, elevation, about):
    s = {"type": t, "color": COLOURS[t]}
    cam = frame(surface_samples(s), "y", 35.0, elevation)
    return {"about": about, "camera": cam, "background": [0.0, 0.0, 0.0], "surfaces": [s]}


def seam(centre, radius, n=12, phase_deg=10.0):
    """curve12's tennis-ball seam: n points on the sphere (centre, radius)."""
    a, b = 0.7, 0.3
    zc = 2 * math.sqrt(a * b)
    out = []
    for k in range(n):
        t = math.radians(phase_deg) + 2 * math.pi * k / n
        p = (a * math.cos(t) + b * math.cos(3 * t), a * math.sin(t) - b * math.sin(3 * t),
             zc * math.sin(2 * t))
        out.append([c + radius * v for c, v in zip(centre, p)])
    return out


def scene_mix():
    relief = {"type": "relief_ellipsoid", "position": [0.45, -0.35, 0.75],
              "rotation_deg": [90.0, 0.0, 110.0], "scale": 0.35, "color": COLOURS["relief_ellipsoid"]}
    rocket = {"type": "rocket", "position": [-0.45, 0.75, 0.8], "rotation_deg": [90.0, 0.0, 15.0],
              "scale": 1.0, "color": COLOURS["rocket"]}
    # The seam's sphere (radius 0.7) clears the ellipsoid (radial at most 1.4 · 1.3 · 0.35 = 0.64):
    # the curve runs in front of it and behind it.
    curve = {"points": seam((0.45, -0.35, 0.75), 0.7), "closed": True, "color": [1.0, 0.8, 0.2]}
    loop = [[1.7 * math.cos(math.radians(20 + 40 * k)), 1.3 * math.sin(math.radians(20 + 40 * k)) + 0.2]
            for k in range(9)]
    texture = {"points": loop, "closed": True, "half_width": 0.1, "color": [0.3, 0.8, 0.35]}
    pts = (surface_samples(relief, 180, 24) + surface_samples(rocket, 180, 24) +
           polyline_samples(curve["points"], True, 0.05) + polyline_samples(loop, True, 0.05))
    cam = frame(pts, "z", 30.0, 28.0, distance_factor=2.2, fill=0.9)
    return {
        "about": "A relief ellipsoid and a rocket (docs/algorithms.md §3) standing on a texture "
                 "loop (docs/algorithms.md §2, z = 0), with curve12's seam "
                 "(docs/algorithms.md §1) wound round the "
                 "ellipsoid, in front of it and behind it: the nearest hit across "
                 "kinds decides every pixel.",
        "camera": cam,
        "background": [0.0, 0.0, 0.0],
        "curves": [curve],
        "textures": [texture],
        "surfaces": [relief, rocket],
    }


# ------------------------------------------------------------------------------------------------
# Checks (on the written files) and the preview

def scene_points(sc, dense=True):
    """(point, colour index) samples of everything in the scene."""
    out = []
    for k, s in enumerate(sc.get("surfaces", [])):
        n = (720, 96) if dense else (240, 32)
        out += [(X, ("s", k)) for X in surface_samples(s, *n)]
    for k, c in enumerate(sc.get("curves", [])):
        out += [(X, ("c", k)) for X in polyline_samples(c["points"], c.get("closed", False), 0.01)]
    for k, t in enumerate(sc.get("textures", [])):
        # the strip: the centre line and both edges
        pts = [demo.to3(p) for p in t["points"]]
        n = len(pts)
        for i in range(n if t.get("closed") else n - 1):
            a, b = pts[i], pts[(i + 1) % n]
            d = demo.sub(b, a)
            side = demo.mul((-d[1], d[0], 0.0), t["half_width"] / demo.norm(d))
            m = max(1, int(demo.norm(d) / 0.01))
            for j in range(m):
                p = demo.add(a, demo.mul(d, j / m))
                for w in (-1.0, -0.5, 0.0, 0.5, 1.0):
                    out.append((demo.add(p, demo.mul(side, w)), ("t", k)))
    return out


def check(name, path, fill_range):
    with open(path, encoding="utf-8") as f:
        sc = json.load(f)
    cam = sc["camera"]
    pts = [X for X, _ in scene_points(sc, dense=False)]
    x0, x1, y0, y1 = extents(cam, pts)
    half = math.tan(math.radians(cam["fov_deg"]) / 2)
    fill = max(x1 - x0, y1 - y0) / (2 * half)
    offset = max(abs(x0 + x1), abs(y0 + y1)) / 2 / half
    assert fill_range[0] <= fill <= fill_range[1], (name, "fill", fill)
    assert all(demo.in_view(cam, X, 2) for X in pts), (name, "not in view")
    print("%-15s %dx%d  fov %.4g  fill %.3f  off-centre %.3f  surfaces %d curves %d textures %d"
          % (name, cam["width"], cam["height"], cam["fov_deg"], fill, offset,
             len(sc.get("surfaces", [])), len(sc.get("curves", [])), len(sc.get("textures", []))))
    return sc


def write_png(path, w, h, rgb):
    raw = b"".join(b"\x00" + bytes(rgb[j * w * 3:(j + 1) * w * 3]) for j in range(h))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def preview(sc, path):
    cam = sc["camera"]
    w, h = cam["width"], cam["height"]
    half = math.tan(math.radians(cam["fov_deg"]) / 2)
    sigma = 2 * half / w
    depth = [math.inf] * (w * h)
    who = [None] * (w * h)
    for X, key in scene_points(sc):
        x, y, c = demo.camera_project(cam, X)
        if c <= 0:
            continue
        i, j = int(math.floor((x + half) / sigma)), int(math.floor((half * h / w - y) / sigma))
        if 0 <= i < w and 0 <= j < h and c < depth[j * w + i]:
            depth[j * w + i], who[j * w + i] = c, key
    hit = [d for d in depth if d < math.inf]
    lo, hi = (min(hit), max(hit)) if hit else (0, 1)
    colours = {("s", k): s["color"] for k, s in enumerate(sc.get("surfaces", []))}
    colours.update({("c", k): c["color"] for k, c in enumerate(sc.get("curves", []))})
    colours.update({("t", k): t["color"] for k, t in enumerate(sc.get("textures", []))})
    rgb = bytearray(w * h * 3)
    for k in range(w * h):
        if who[k] is not None:
            shade = 1.0 - 0.6 * (depth[k] - lo) / max(hi - lo, 1e-12)
            for ch in range(3):
                rgb[3 * k + ch] = int(255 * colours[who[k]][ch] * shade)
    write_png(path, w, h, rgb)


def main(argv):
    preview_dir = None
    if len(argv) == 3 and argv[1] == "--preview":
        preview_dir = argv[2]
        os.makedirs(preview_dir, exist_ok=True)
    elif len(argv) != 1:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    jobs = [(name, scene_single(name, t, el, about), (FILL - 0.02, FILL + 0.02))
            for name, t, _, el, about in SINGLE]
    jobs.append(("surf_mix", scene_mix(), (0.85, 0.95)))
    for name, scene, fill_range in jobs:
        path = demo.write_scene(name, scene)
        sc = check(name, path, fill_range)
        if preview_dir:
            preview(sc, os.path.join(preview_dir, name + ".png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
