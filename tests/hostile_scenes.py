#!/usr/bin/env python3
"""Writes the scenes of the hostile-input cases of issue 24 (tests/cli_hostile.cmake) into a
directory: patches crossing the eye plane, many patches and surfaces, closed models of many
patches, a large B-spline, scaled copies of built-in scenes, NURBS weights scaled by a common
factor, a flat strip through the eye plane at several fields of view.

    python3 tests/hostile_scenes.py OUT_DIR SOURCE_DIR [GROUP...]

GROUP is one of the groups below (default: all of them); tests/cli_hostile.cmake writes the
group of its mode only. Deterministic: the same files on every run.
"""
import json
import math
import os
import sys


def camera(eye, target, fov=40, width=8, height=8, up=(0, 0, 1)):
    return {"eye": list(eye), "target": list(target), "up": list(up), "fov_deg": fov,
            "width": width, "height": height}


def scaled(obj, s):
    """Every 3-vector of numbers in obj multiplied by s."""
    if isinstance(obj, list):
        if len(obj) == 3 and all(isinstance(v, (int, float)) for v in obj):
            return [v * s for v in obj]
        return [scaled(v, s) for v in obj]
    return obj


def eye_plane_patch():
    # A bicubic patch spanning y from -5 to 5 at z about 0.5: it crosses the eye plane y = 0 of a
    # camera at the origin looking along +y.
    return [[x, y, 0.5 + 0.1 * ((i + j) % 2)]
            for i, x in enumerate([-1, -0.33, 0.33, 1])
            for j, y in enumerate([-5, -1.67, 1.67, 5])]


def small_patch():
    return [[x, 0.1 * ((i * j) % 3), z]
            for i, x in enumerate([-1, -0.33, 0.33, 1])
            for j, z in enumerate([-1, -0.33, 0.33, 1])]


def cube(per_side):
    """A closed cube [-1, 1]^3 of 6·per_side² bilinear patches, every normal outward."""
    patches = []
    for axis in range(3):
        for side in (-1, 1):
            def point(s, t):
                p = [0.0, 0.0, 0.0]
                p[axis] = side
                p[(axis + 1) % 3] = s
                p[(axis + 2) % 3] = t
                return p
            for a in range(per_side):
                for b in range(per_side):
                    s0, s1 = -1 + 2 * a / per_side, -1 + 2 * (a + 1) / per_side
                    t0, t1 = -1 + 2 * b / per_side, -1 + 2 * (b + 1) / per_side
                    # S_u × S_v = e_(axis+1) × e_(axis+2) = e_axis with u along s: outward on the
                    # + side; the − side swaps u and v.
                    if side > 0:
                        patches.append([point(s0, t0), point(s0, t1), point(s1, t0), point(s1, t1)])
                    else:
                        patches.append([point(s0, t0), point(s1, t0), point(s0, t1), point(s1, t1)])
    return patches


def strip(fov, size=64):
    # A flat 1 × 10 strip on z = -0.5 from y = -5 to 5: it runs through the eye plane of a camera
    # at the origin looking along +y; its parameter centre (0, 0, -0.5) is beside the eye.
    return {"camera": camera((0, 0, 0), (0, 1, 0), fov, size, size),
            "patches": [{"type": "bezier", "degree": [1, 1],
                         "control_points": [[-0.5, -5, -0.5], [-0.5, 5, -0.5],
                                            [0.5, -5, -0.5], [0.5, 5, -0.5]]}]}


def strip_hits(fov, size=64):
    """The exact hit count of strip(fov, size): the pixel-centre rays meeting the rectangle."""
    sigma = 2 * math.tan(math.radians(fov) / 2) / size
    n = 0
    for j in range(size):
        for i in range(size):
            a = (i + 0.5 - 0.5 * size) * sigma
            b = (0.5 * size - j - 0.5) * sigma
            if b >= 0:
                continue
            t = -0.5 / b  # the ray (a, 1, b)·t meets z = -0.5
            if abs(a * t) <= 0.5 and t <= 5:
                n += 1
    return n


def main():
    out, src = sys.argv[1], sys.argv[2]
    groups = set(sys.argv[3:]) or {"budgets", "images", "volume", "surfaces"}
    os.makedirs(out, exist_ok=True)

    def write(name, scene):
        with open(os.path.join(out, name), "w") as f:
            json.dump(scene, f)

    def builtin(name):
        with open(os.path.join(src, "scenes", name + ".json")) as f:
            return json.load(f)

    if "budgets" in groups:
        write_budgets(write, out)
    if "images" in groups:
        write_images(write, builtin, out)
    if "volume" in groups:
        write_volume(write, builtin)
    if "surfaces" in groups:
        write_surfaces(write, builtin)


def write_budgets(write, out):
    # Patches crossing the eye plane at 8×8.
    for n in (1, 100, 1000):
        write(f"eye_plane_{n}.json", {"camera": camera((0, 0, 0), (0, 1, 0)),
                                      "patches": [{"type": "bezier_set", "degree": [3, 3],
                                                   "patches": [eye_plane_patch()] * n}]})
    # Many patches: the most a scene may have, stacked, and more than that.
    for n in (4096, 4097, 10000):
        write(f"patches_{n}.json", {"camera": camera((0, -4, 0), (0, 0, 0), 40, 256, 256),
                                    "patches": [{"type": "bezier_set", "degree": [3, 3],
                                                 "patches": [small_patch()] * n}]})
    # A 1000×1000 cubic B-spline (about 30 MB), written as text directly (json.dump of a million
    # points takes many seconds): x and z on a grid, y a ripple along i + j.
    n = 1000
    knots = [0, 0, 0, 0] + [i / (n - 3) for i in range(1, n - 3)] + [1, 1, 1, 1]
    coord = ["%.6g" % (2 * i / n - 1) for i in range(n)]
    ripple = ["%.6g" % (0.05 * math.sin(0.1 * k)) for k in range(2 * n)]
    points = ",".join("[%s,%s,%s]" % (coord[i], ripple[i + j], coord[j])
                      for i in range(n) for j in range(n))
    head = json.dumps({"camera": camera((0, -4, 0), (0, 0, 0), 40, 64, 64)})[:-1]
    patch = json.dumps({"type": "bspline", "degree": [3, 3], "size": [n, n],
                        "knots_u": knots, "knots_v": knots})[:-1]
    with open(os.path.join(out, "bspline_1000.json"), "w") as f:
        f.write(head + ', "patches": [' + patch + ', "control_points": [' + points + "]}]}")
    # Its exact hit count: the clamped surface is a graph over the square x, z in [lo, hi] (its
    # edge control points) at y within ±0.05 of 0 (the control points' range), seen from
    # (0, -4, 0); a pixel centre's ray meets it iff its slopes x/c and z/c lie within
    # (lo, hi)/(4 + y), and the count is the same for every y in [-0.05, 0.05].
    sigma = 2 * math.tan(math.radians(40) / 2) / 64
    lo, hi = 2 * 0 / n - 1, 2 * (n - 1) / n - 1
    counts = set()
    for y in (-0.05, 0.05):
        side = sum(1 for i in range(64) if lo / (4 + y) < (i + 0.5 - 32) * sigma < hi / (4 + y))
        counts.add(side * side)
    assert len(counts) == 1
    with open(os.path.join(out, "bspline_hits.txt"), "w") as f:
        f.write(f"{counts.pop()}\n")


def write_images(write, builtin, out):
    # NURBS weights multiplied by a common factor: the same surface.
    torus = builtin("torus")
    for name, factor in (("1e-200", 1e-200), ("2e-300", 2e-300)):
        t = json.loads(json.dumps(torus))
        t["patches"][0]["weights"] = [w * factor for w in t["patches"][0]["weights"]]
        write(f"torus_weights_{name}.json", t)
    # The flat strip through the eye plane, and its exact hit counts.
    with open(os.path.join(out, "strip_hits.txt"), "w") as f:
        for fov in (40, 90, 120, 150, 170, 179.9):
            write(f"strip_{fov}.json", strip(fov))
            f.write(f"{fov} {strip_hits(fov)}\n")
    write("strip_179.95.json", strip(179.95))  # past the widest field of view of the patches
    # The teapot and its camera scaled by a common factor.
    teapot = builtin("teapot")
    for s in (1e-9, 1e-10, 1e-100, 1e-300):
        t = json.loads(json.dumps(teapot))
        t["camera"]["eye"] = scaled(t["camera"]["eye"], s)
        t["camera"]["target"] = scaled(t["camera"]["target"], s)
        for p in t["patches"]:
            p["patches"] = scaled(p["patches"], s)
        write(f"teapot_{s:g}.json", t)


def write_volume(write, builtin):
    # Closed cubes of many bilinear patches.
    for per_side in (13, 20):
        write(f"cube_{6 * per_side * per_side}.json",
              {"camera": camera((3, -4, 2), (0, 0, 0)),
               "patches": [{"type": "bezier_set", "degree": [1, 1], "patches": cube(per_side)}]})
    # The Bézier sphere scaled by a common factor.
    sphere = builtin("bezier_sphere")
    for s in (1e-9, 1e-100, 1e-300):
        b = json.loads(json.dumps(sphere))
        for p in b["patches"]:
            for key in ("control_points", "patches"):
                if key in p:
                    p[key] = scaled(p[key], s)
        write(f"sphere_{s:g}.json", b)


def write_surfaces(write, builtin):
    spiral_camera = camera((11.5, 10.2, 16.2), (-0.14, 2.77, -0.44), 26.36, 16, 16, (0, 1, 0))
    for n in (1, 64, 256, 257, 1000, 10000):
        write(f"spirals_{n}.json", {"camera": spiral_camera, "surfaces": [{"type": "spiral"}] * n})
    # The surfaces of surf_mix, and the same scene with its camera scaled by a common factor.
    mix = builtin("surf_mix")
    mix["curves"], mix["textures"] = [], []
    write("surf_mix_surfaces.json", mix)
    for s in (1e-5, 1e-8, 1e-9):
        m = json.loads(json.dumps(mix))
        m["camera"]["eye"] = scaled(m["camera"]["eye"], s)
        m["camera"]["target"] = scaled(m["camera"]["target"], s)
        for surface in m["surfaces"]:
            surface["position"] = scaled(surface.get("position", [0, 0, 0]), s)
            surface["scale"] = surface.get("scale", 1) * s
        write(f"surf_mix_{s:g}.json", m)


if __name__ == "__main__":
    main()
