#!/usr/bin/env python3
"""Writes the built-in demo scenes scenes/*.json (docs/scene-format.md), deterministically.

Run from the repository root:  python3 scripts/make_demo_scenes.py

Standard library only. Every number is rounded to 6 significant digits before it is written;
the checks at the end re-read the written files, so they test exactly what the renderer gets.

Scenes:
  curve12    12-point closed space curve (tennis-ball seam) in the cube [-1,1]^3 plus the cube's
             12 edges (seed 000, figs 1-2).
  ellipse6   6 points of the ellipse x^2/9 + y^2/4 = 1 as a closed texture on z = 0
             (seed 001, fig. 3).
  polyline9  closed irregular 9-point texture polyline on z = 0 (seed 001, fig. 4).
  airfield   a vector-texture airfield map in metres seen from an approach (seed 001's use case).
"""

import json
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE_DIR = os.path.join(ROOT, "scenes")

WHITE = [1.0, 1.0, 1.0]
YELLOW = [1.0, 0.85, 0.1]


# ------------------------------------------------------------------------------------------------
# Number rounding and compact JSON output

def r6(x):
    """x rounded to 6 significant digits (and -0 turned into 0)."""
    if abs(x) < 1e-9:  # trigonometric noise such as sin(pi) = 1.2e-16
        return 0.0
    v = float(format(float(x), ".6g"))
    return 0.0 if v == 0.0 else v


def rounded(obj):
    if isinstance(obj, bool) or isinstance(obj, str) or obj is None:
        return obj
    if isinstance(obj, int):
        return obj
    if isinstance(obj, float):
        return r6(obj)
    if isinstance(obj, list):
        return [rounded(v) for v in obj]
    if isinstance(obj, dict):
        return {k: rounded(v) for k, v in obj.items()}
    raise TypeError(type(obj))


def num(x):
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, int):
        return str(x)
    if not math.isfinite(x):
        raise ValueError("non-finite number")
    s = format(r6(x), ".6g")
    return "0" if s in ("0", "-0") else s


def inline(obj):
    if isinstance(obj, dict):
        return "{" + ", ".join(json.dumps(k) + ": " + inline(v) for k, v in obj.items()) + "}"
    if isinstance(obj, list):
        return "[" + ", ".join(inline(v) for v in obj) + "]"
    if isinstance(obj, str):
        return json.dumps(obj)
    return num(obj)


def dump(obj, indent=0, width=100):
    """Compact pretty printer: anything that fits on a line stays on it; long lists of points
    are written one point per line."""
    pad = " " * indent
    one = inline(obj)
    if len(pad) + len(one) <= width or not isinstance(obj, (dict, list)):
        return one
    inner = " " * (indent + 2)
    if isinstance(obj, dict):
        items = [inner + json.dumps(k) + ": " + dump(v, indent + 2, width).lstrip()
                 for k, v in obj.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    items = [inner + dump(v, indent + 2, width).lstrip() for v in obj]
    return "[\n" + ",\n".join(items) + "\n" + pad + "]"


def write_scene(name, scene):
    text = dump(rounded(scene)) + "\n"
    path = os.path.join(SCENE_DIR, name + ".json")
    with open(path, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)
    return path


# ------------------------------------------------------------------------------------------------
# Small vector helpers (tuples)

def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def mul(a, s):
    return tuple(x * s for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def norm(a):
    return math.sqrt(dot(a, a))


def cross3(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def to3(p):
    return (p[0], p[1], p[2] if len(p) > 2 else 0.0)


# ------------------------------------------------------------------------------------------------
# Scene 1: curve12

def scene_curve12():
    # Tennis-ball seam x = a cos t + b cos 3t, y = a sin t - b sin 3t, z = 2 sqrt(ab) sin 2t
    # (on the unit sphere for a + b = 1), scaled into the cube, 12 samples, phase-shifted so the
    # samples are not aligned with the seam's symmetry planes.
    a, b, scale, phase = 0.7, 0.3, 0.85, math.radians(10.0)
    zc = 2.0 * math.sqrt(a * b)
    pts = []
    for k in range(12):
        t = phase + 2.0 * math.pi * k / 12
        pts.append([scale * (a * math.cos(t) + b * math.cos(3 * t)),
                    scale * (a * math.sin(t) - b * math.sin(3 * t)),
                    scale * zc * math.sin(2 * t)])
    curves = [{"points": pts, "closed": True, "color": [1.0, 0.8, 0.2]}]
    corners = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    for c0 in corners:
        for c1 in corners:
            diff = [j - i for i, j in zip(c0, c1)]
            if c0 < c1 and sum(abs(d) for d in diff) == 2:
                curves.append({"points": [[float(v) for v in c0], [float(v) for v in c1]],
                               "closed": False, "color": [0.5, 0.5, 0.5]})
    return {
        "about": "A 12-point closed space curve (a tennis-ball seam) smoothed by spherical "
                 "interpolation with derived normals, inside the grey edges of the cube "
                 "[-1,1]^3 (seed 000, figs 1-2).",
        "camera": {"eye": [3.2, -4.2, 2.6], "target": [0.0, 0.0, 0.0], "up": [0.0, 0.0, 1.0],
                   "fov_deg": 45.0, "width": 256, "height": 256},
        "background": [0.0, 0.0, 0.0],
        "curves": curves,
    }


# ------------------------------------------------------------------------------------------------
# Scenes 2 and 3: ellipse6, polyline9

PLANE_CAMERA = {"eye": [0.0, -7.0, 6.0], "target": [0.0, 0.0, 0.0], "up": [0.0, 0.0, 1.0],
                "fov_deg": 50.0, "width": 256, "height": 256}


def scene_ellipse6():
    pts = [[3.0 * math.cos(math.radians(60 * k)), 2.0 * math.sin(math.radians(60 * k))]
           for k in range(6)]
    return {
        "about": "Six points of the ellipse x^2/9 + y^2/4 = 1 as a closed vector texture on the "
                 "plane z = 0, smoothed by spherical interpolation (seed 001, fig. 3).",
        "camera": dict(PLANE_CAMERA),
        "background": [0.05, 0.15, 0.05],
        "textures": [{"points": pts, "closed": True, "half_width": 0.05, "color": [1.0, 1.0, 1.0]}],
    }


def scene_polyline9():
    # Star-shaped about the origin (vertices in increasing polar angle), so it is simple;
    # alternating radii make it look irregular.
    polar = [(8, 2.7), (47, 1.6), (78, 2.9), (113, 2.1), (151, 2.8),
             (197, 1.9), (232, 2.75), (277, 1.45), (318, 2.6)]
    pts = [[round(r * math.cos(math.radians(a)), 2), round(r * math.sin(math.radians(a)), 2)]
           for a, r in polar]
    return {
        "about": "A closed irregular 9-point polyline as a vector texture on the plane z = 0, "
                 "smoothed by spherical interpolation (seed 001, fig. 4).",
        "camera": dict(PLANE_CAMERA),
        "background": [0.05, 0.15, 0.05],
        "textures": [{"points": pts, "closed": True, "half_width": 0.05, "color": [1.0, 1.0, 0.3]}],
    }


# ------------------------------------------------------------------------------------------------
# Scene 4: airfield (metres, z = 0 plane, x east, y north)

class Turtle:
    """Builds a polyline from straight runs and circular arcs; headings in degrees."""

    def __init__(self, x, y, heading):
        self.x, self.y, self.h = float(x), float(y), float(heading)
        self.pts = [(self.x, self.y)]

    def forward(self, length, step):
        n = max(1, math.ceil(length / step - 1e-9))
        hx, hy = math.cos(math.radians(self.h)), math.sin(math.radians(self.h))
        x0, y0 = self.x, self.y
        for i in range(1, n + 1):
            self.pts.append((x0 + hx * length * i / n, y0 + hy * length * i / n))
        self.x, self.y = self.pts[-1]
        return self

    def forward_to(self, coord, value, step):
        """Straight on until x (coord 0) or y (coord 1) reaches value."""
        h = math.radians(self.h)
        rate = math.cos(h) if coord == 0 else math.sin(h)
        cur = self.x if coord == 0 else self.y
        length = (value - cur) / rate
        assert length > 0, (coord, value, cur)
        return self.forward(length, step)

    def turn(self, radius, angle, step_deg):
        """Arc of `radius` turning by `angle` degrees (positive = left)."""
        side = 1.0 if angle > 0 else -1.0
        h = math.radians(self.h)
        cx = self.x - side * radius * math.sin(h)
        cy = self.y + side * radius * math.cos(h)
        a0 = math.atan2(self.y - cy, self.x - cx)
        n = max(1, math.ceil(abs(angle) / step_deg - 1e-9))
        for i in range(1, n + 1):
            a = a0 + math.radians(angle) * i / n
            self.pts.append((cx + radius * math.cos(a), cy + radius * math.sin(a)))
        self.x, self.y = self.pts[-1]
        self.h += angle
        return self


def straight(p, q, step):
    n = max(1, math.ceil(norm(sub(q, p)) / step - 1e-9))
    return [add(p, mul(sub(q, p), i / n)) for i in range(n + 1)]


def clean(pts):
    """Rounds and drops consecutive repeats (after rounding)."""
    out = []
    for p in pts:
        q = (r6(p[0]), r6(p[1]))
        if not out or q != out[-1]:
            out.append(q)
    return [list(q) for q in out]


class Runway:
    """Runway with centreline from start (threshold 1) along unit dir, frame (s, l): position
    = start + s*dir + l*left. Coordinates are exact when dir*5 and start are integral."""

    def __init__(self, start, direction, length, width):
        self.o, self.e, self.len, self.w = start, direction, length, width
        self.left = (-direction[1], direction[0])

    def at(self, s, l=0.0):
        return add(add(self.o, mul(self.e, s)), mul(self.left, l))


def scene_airfield():
    tex = []

    def line(pts, hw, color):
        pts = clean(pts)
        assert len(pts) >= 2
        tex.append({"points": pts, "closed": False, "half_width": hw, "color": color})

    EDGE_HW, DASH_HW, BAR_HW, AIM_HW, TAXI_HW = 6.0, 3.0, 2.0, 5.0, 3.0
    W = 45.0

    # Runway 09/27: 2800 m along the x axis, centred at the origin.
    r1 = Runway((-1400.0, 0.0), (1.0, 0.0), 2800.0, W)
    # Runway 04/22: 2000 m on heading (0.8, 0.6) (about 37 degrees from 09/27), its centreline
    # crossing 09/27's at (500, 0), 1700 m from its south-west threshold.
    r2 = Runway((-860.0, -1020.0), (0.8, 0.6), 2000.0, W)

    def in_r1_strip(p, margin):
        return abs(p[1]) < W / 2 + margin and -1400 - margin < p[0] < 1400 + margin

    for rw, primary in ((r1, True), (r2, False)):
        # Edge lines, one point every 50 m; the secondary runway's lines stop at the primary's.
        for side in (1, -1):
            l = side * W / 2
            samples = list(range(0, int(rw.len) + 1, 50))
            if primary:
                line([rw.at(s, l) for s in samples], EDGE_HW, WHITE)
                continue
            # Split at the primary runway: last/first multiple of 5 m clear of its strip.
            fine = range(0, int(rw.len) + 1, 5)
            outside = [s for s in fine if not in_r1_strip(rw.at(s, l), EDGE_HW)]
            lo = max(s for s in outside if rw.at(s, l)[1] < 0)
            hi = min(s for s in outside if rw.at(s, l)[1] > 0)
            line([rw.at(s, l) for s in samples if s < lo - 10] + [rw.at(lo, l)], EDGE_HW, WHITE)
            line([rw.at(hi, l)] + [rw.at(s, l) for s in samples if s > hi + 10], EDGE_HW, WHITE)
        # Centre line: 30 m dashes, 20 m gaps, between the two 150 m threshold zones.
        zone = rw.len - 2 * 150.0
        count = int((zone + 20) // 50)
        s0 = 150.0 + (zone - (count * 50 - 20)) / 2
        for k in range(count):
            a, b = rw.at(s0 + 50 * k), rw.at(s0 + 50 * k + 30)
            if not primary and (in_r1_strip(a, 12) or in_r1_strip(b, 12)
                                or (a[1] < 0) != (b[1] < 0)):
                continue
            line([a, b], DASH_HW, WHITE)
        # Threshold bars (6 per end, 30 m long, 6 m from the end) and aiming-point markings
        # (two 60 m bars each side of the centre line, 400 m from the threshold).
        for s_end, sign in ((0.0, 1), (rw.len, -1)):
            for l in (-16, -10, -4, 4, 10, 16):
                line([rw.at(s_end + sign * 6, l), rw.at(s_end + sign * 36, l)], BAR_HW, WHITE)
            for l in (-14, 14):
                line([rw.at(s_end + sign * 400, l), rw.at(s_end + sign * 460, l)], AIM_HW, WHITE)

    # Taxiway A: parallel to 09/27 on its north side (centre lines 250 m apart), joined to both
    # runway ends by 80 m fillets; yellow lines stop 40 m from the runway centre line.
    ta = Turtle(-1370, 40, 90).forward_to(1, 250 - 80, 50).turn(80, -90, 15)
    ta.forward_to(0, 1370 - 80, 100).turn(80, -90, 15).forward_to(1, 40, 50)
    line(ta.pts, TAXI_HW, YELLOW)

    # Two rapid-exit taxiways for landings towards the east: a 400 m turn-off curve leaving the
    # runway centre line through 30 degrees (the line starts once clear of the runway edge),
    # straight at 30 degrees, then a 150 m fillet merging into taxiway A.
    for x0 in (-300.0, 620.0):
        theta0 = math.degrees(math.acos(1 - 36.0 / 400))  # first point 36 m off the centre line
        t = Turtle(x0 + 400 * math.sin(math.radians(theta0)), 36.0, theta0)
        t.turn(400, 30 - theta0, 7.5)
        y_after_fillet = 150 * (1 - math.cos(math.radians(30)))
        t.forward_to(1, 250 - y_after_fillet, 100).turn(150, -30, 7.5)
        assert abs(t.y - 250) < 1e-6
        line(t.pts, TAXI_HW, YELLOW)

    # Runway 04/22's north-east end: a stem on its extended centre line, splitting into a 60 m
    # fillet towards the east and a 30 m fillet turning back west onto taxiway A.
    stem0 = r2.at(r2.len + 15)
    h2 = math.degrees(math.atan2(r2.e[1], r2.e[0]))
    t = Turtle(stem0[0], stem0[1], h2)
    split = (250 - 30 * (1 + r2.e[0]) - stem0[1]) / r2.e[1]  # where the west fillet leaves
    t.forward(split, 50)
    split_pt = (t.x, t.y)
    t.forward_to(1, 250 - 60 * (1 - r2.e[0]), 50).turn(60, -h2, 7.5)
    assert abs(t.y - 250) < 1e-6
    line(t.pts, TAXI_HW, YELLOW)
    t = Turtle(split_pt[0], split_pt[1], h2).turn(30, 180 - h2, 15)
    assert abs(t.y - 250) < 1e-6
    line(t.pts, TAXI_HW, YELLOW)

    # Apron north of taxiway A: a taxilane loop (in at x = -900, along y = 430, out at x = -500)
    # with 40 m fillets, four stand lead-in lines with 25 m fillets, and the apron edge line.
    t = Turtle(-940, 250, 0).turn(40, 90, 15).forward_to(1, 430 - 40, 50).turn(40, -90, 15)
    t.forward_to(0, -500 - 40, 50).turn(40, -90, 15).forward_to(1, 250 + 40, 50).turn(40, 90, 15)
    assert abs(t.y - 250) < 1e-6
    line(t.pts, TAXI_HW, YELLOW)
    for xs in (-820, -740, -660, -580):
        t = Turtle(xs - 25, 430, 0).turn(25, 90, 15).forward_to(1, 540, 50)
        line(t.pts, TAXI_HW, YELLOW)
    t = Turtle(-1000, 300, 90).forward_to(1, 580 - 30, 50).turn(30, -90, 15)
    t.forward_to(0, -400 - 30, 50).turn(30, -90, 15).forward_to(1, 300, 50)
    line(t.pts, TAXI_HW, YELLOW)

    return {
        "about": "An airfield map in metres as vector textures on z = 0 (runways 09/27 and 04/22 "
                 "crossing, parallel taxiway, rapid exits, apron with stands) seen on the "
                 "from 2300 m above a point south of the field.",
        # South of the field, 2300 m up, looking down at about 50 degrees: the whole map is in
        # view. Lines are 4-12 m wide against pixels of ~7 m, so thin cross-view lines alias:
        # there is no anti-aliasing by design (exact colours, README "Command line").
        "camera": {"eye": [-200.0, -1900.0, 2300.0], "target": [0.0, -250.0, 0.0],
                   "up": [0.0, 0.0, 1.0], "fov_deg": 72.0, "width": 640, "height": 480},
        "background": [0.12, 0.16, 0.12],
        "textures": tex,
    }


# ------------------------------------------------------------------------------------------------
# Independent checks on the written files

def derive_normals(pts, closed):
    """docs/algorithms.md §1, 'Normals when the input has none' (3-D points; planar curves
    stay planar)."""
    n = len(pts)
    out = []
    for i in range(n):
        if closed:
            prev, nxt = pts[(i - 1) % n], pts[(i + 1) % n]
        else:
            prev = pts[i - 1] if i > 0 else sub(mul(pts[0], 2), pts[1])
            nxt = pts[i + 1] if i + 1 < n else sub(mul(pts[-1], 2), pts[-2])
        T = sub(nxt, prev)
        bend = add(sub(nxt, pts[i]), sub(prev, pts[i]))
        perp = sub(bend, mul(T, dot(bend, T) / dot(T, T)))
        scale = math.sqrt(dot(sub(nxt, pts[i]), sub(nxt, pts[i]))
                          + dot(sub(prev, pts[i]), sub(prev, pts[i])))
        if norm(perp) <= 1e-12 * scale:
            # any perpendicular of T (in the plane z = 0 when T is horizontal)
            perp = (-T[1], T[0], 0.0) if abs(T[2]) < 1e-15 else cross3(T, (1.0, 0.0, 0.0))
            if norm(perp) == 0:
                perp = cross3(T, (0.0, 1.0, 0.0))
        out.append(mul(perp, 1.0 / norm(perp)))
    return out


def seg_seg_dist2d(p, q, r, s):
    def pt_seg(x, a, b):
        d = sub(b, a)
        t = max(0.0, min(1.0, dot(sub(x, a), d) / dot(d, d)))
        return norm(sub(x, add(a, mul(d, t))))

    def orient(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])

    o1, o2, o3, o4 = orient(p, q, r), orient(p, q, s), orient(r, s, p), orient(r, s, q)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return 0.0
    return min(pt_seg(p, r, s), pt_seg(q, r, s), pt_seg(r, p, q), pt_seg(s, p, q))


def camera_project(cam, X):
    """Screen coordinates (x, y) on the screen plane, and depth c (docs/algorithms.md §1.1)."""
    h = tuple(cam["eye"])
    W = sub(tuple(cam["target"]), h)
    W = mul(W, 1 / norm(W))
    U = cross3(W, tuple(cam["up"]))
    U = mul(U, 1 / norm(U))
    V = cross3(U, W)
    q = sub(to3(X), h)
    c = dot(q, W)
    return (dot(q, U) / c if c > 0 else None, dot(q, V) / c if c > 0 else None, c)


def in_view(cam, X, margin_px=0.0):
    half = math.tan(math.radians(cam["fov_deg"]) / 2)
    sigma = 2 * half / cam["width"]
    x, y, c = camera_project(cam, X)
    if c <= 0:
        return False
    hx = half - margin_px * sigma
    hy = half * cam["height"] / cam["width"] - margin_px * sigma
    return -hx <= x <= hx and -hy <= y <= hy


def check_scene(name, path, expect):
    with open(path, encoding="utf-8") as f:
        sc = json.load(f)
    assert set(sc) <= {"about", "camera", "background", "curves", "textures"}, sc.keys()
    assert isinstance(sc["about"], str) and sc["about"].endswith("."), name
    cam = sc["camera"]
    assert set(cam) == {"eye", "target", "up", "fov_deg", "width", "height"}
    assert 0 < cam["fov_deg"] < 180 and cam["width"] >= 1 and cam["height"] >= 1
    assert isinstance(cam["width"], int) and isinstance(cam["height"], int)
    for c in [sc["background"]] + [p["color"] for k in ("curves", "textures")
                                   for p in sc.get(k, [])]:
        assert len(c) == 3 and all(0.0 <= v <= 1.0 for v in c), (name, c)
    nseg = 0
    min_len = math.inf
    min_sine = math.inf
    for kind, dim in (("curves", 3), ("textures", 2)):
        for i, pl in enumerate(sc.get(kind, [])):
            where = "%s: %s[%d]" % (name, kind, i)
            allowed = {"points", "normals", "closed", "color"} | (
                {"half_width"} if kind == "textures" else set())
            assert set(pl) <= allowed and "normals" not in pl, where
            if kind == "textures":
                assert pl["half_width"] > 0, where
            pts = [tuple(float(v) for v in p) for p in pl["points"]]
            closed = pl["closed"]
            assert all(len(p) == dim and all(math.isfinite(v) for v in p) for p in pts), where
            assert len(pts) >= (3 if closed else 2), where
            segs = [(pts[j], pts[(j + 1) % len(pts)])
                    for j in range(len(pts) if closed else len(pts) - 1)]
            for j, (p, q) in enumerate(segs):
                assert p != q, "%s: repeated point %d" % (where, j)
                min_len = min(min_len, norm(sub(q, p)))
            nseg += len(segs)
            # The normals the compiler will derive must not be parallel to a chord.
            p3 = [to3(p) for p in pts]
            nrm = derive_normals(p3, closed)
            for j in range(len(segs)):
                k = (j + 1) % len(pts)
                d = sub(p3[k], p3[j])
                for nn in (nrm[j], nrm[k]):
                    cosv = dot(nn, d) / norm(d)
                    min_sine = min(min_sine, math.sqrt(max(0.0, 1 - cosv * cosv)))
            if expect.get("no_collinear") and i == 0:
                m = len(pts)
                for j in range(m if closed else m - 2):
                    a, b, c = p3[j], p3[(j + 1) % m], p3[(j + 2) % m]
                    area = norm(cross3(sub(b, a), sub(c, a)))
                    assert area > 1e-3 * norm(sub(b, a)) * norm(sub(c, a)), \
                        "%s: points %d..%d nearly collinear" % (where, j, j + 2)
    assert min_sine > 1e-3, (name, min_sine)

    if "npoints" in expect:  # point count of the first primitive
        first = (sc.get("curves") or sc.get("textures"))[0]
        assert len(first["points"]) == expect["npoints"] and first["closed"], name
    if "ncurves" in expect:
        assert len(sc.get("curves", [])) == expect["ncurves"], name
    if "ntextures" in expect:
        assert len(sc.get("textures", [])) == expect["ntextures"], name
    if "nseg" in expect:
        lo, hi = expect["nseg"]
        assert lo <= nseg <= hi, (name, nseg)
    if "box" in expect:
        lo, hi = expect["box"]
        for k in ("curves", "textures"):
            for pl in sc.get(k, []):
                for p in pl["points"]:
                    assert all(lo <= v <= hi for v in p), (name, p)
    if expect.get("simple"):
        pts = sc["textures"][0]["points"]
        m = len(pts)
        for a in range(m):
            for b in range(a + 2, m):
                if a == 0 and b == m - 1:
                    continue
                assert seg_seg_dist2d(pts[a], pts[(a + 1) % m], pts[b], pts[(b + 1) % m]) > 0.3, \
                    (name, "self-intersecting", a, b)
    for X in expect.get("visible", []):
        assert in_view(cam, X, 2), (name, "not in view", X)
    if expect.get("colour_clearance"):
        # Lines of different colours never touch, so no pixel depends on which of two equally
        # deep textures wins.
        by_colour = {}
        for pl in sc["textures"]:
            pts, hw = pl["points"], pl["half_width"]
            segs = [(pts[j], pts[j + 1], hw) for j in range(len(pts) - 1)]
            by_colour.setdefault(tuple(pl["color"]), []).extend(segs)
        groups = list(by_colour.values())
        for g in range(len(groups)):
            for g2 in range(g + 1, len(groups)):
                for p, q, w in groups[g]:
                    for r, s, w2 in groups[g2]:
                        if min(p[0], q[0]) - 100 > max(r[0], s[0]) or \
                           min(r[0], s[0]) - 100 > max(p[0], q[0]):
                            continue
                        dist = seg_seg_dist2d(p, q, r, s)
                        assert dist > w + w2 + 2.0, (name, "colours touch", p, q, r, s, dist)
    nvis = sum(1 for k in ("curves", "textures") for pl in sc.get(k, []) for p in pl["points"]
               if in_view(cam, p))
    npts = sum(len(pl["points"]) for k in ("curves", "textures") for pl in sc.get(k, []))
    print("%-10s curves %3d  textures %3d  segments %4d  points %4d (%d in view)  "
          "min segment %.3g  %dx%d" % (name, len(sc.get("curves", [])),
                                        len(sc.get("textures", [])), nseg, npts, nvis,
                                        min_len, cam["width"], cam["height"]))


def main():
    os.makedirs(SCENE_DIR, exist_ok=True)
    cube = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    ellipse = [(3 * math.cos(a / 10), 2 * math.sin(a / 10)) for a in range(63)]
    jobs = [
        ("curve12", scene_curve12(),
         {"npoints": 12, "ncurves": 13, "nseg": (24, 24), "no_collinear": True,
          "box": (-1.0, 1.0), "visible": cube}),
        ("ellipse6", scene_ellipse6(),
         {"npoints": 6, "ntextures": 1, "nseg": (6, 6), "no_collinear": True,
          "visible": ellipse}),
        ("polyline9", scene_polyline9(),
         {"npoints": 9, "ntextures": 1, "nseg": (9, 9), "no_collinear": True,
          "box": (-3.0, 3.0), "simple": True,
          "visible": [(3, 3), (-3, 3), (3, -3), (-3, -3)]}),
        ("airfield", scene_airfield(),
         {"nseg": (300, 500), "colour_clearance": True,
          # both ends of 09/27, the far threshold of 04/22, the apron corners
          "visible": [(-1400, 0), (1400, 0), (-860, -1020), (740, 180),
                      (-1000, 580), (-400, 580)]}),
    ]
    for name, scene, expect in jobs:
        path = write_scene(name, scene)
        check_scene(name, path, expect)
    return 0


if __name__ == "__main__":
    sys.exit(main())
