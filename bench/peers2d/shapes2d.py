#!/usr/bin/env python3
"""Generated 2D inputs of the peer benchmarks (bench/run_2d.sh --natural):
shapes that stress a quality mesher in different ways. Deterministic.

  shapes2d.py NAME OUT.poly      NAME one of the keys of SHAPES below
  shapes2d.py --list             the names

  ngon1000      regular 1000-gon on the unit circle (short sides, no small angle)
  random200     star-shaped 200-gon with random radii in [0.5, 1] (seed 1):
                many small input angles
  comb16        unit square with 16 slots of width 1/512, depth 1/2
  plate64       unit square with an 8 x 8 grid of 16-gon holes of radius 1/40
  tiny_feature  unit square with a 1e-3 x 1e-3 notch in one side
"""
import math
import random
import sys


def write_poly(path, comment, loops, holes):
    """loops: lists of (x, y), the first the outer boundary; holes: one point inside each hole."""
    vertices, segments = [], []
    for loop in loops:
        base = len(vertices)
        vertices += loop
        segments += [(base + k, base + (k + 1) % len(loop)) for k in range(len(loop))]
    with open(path, "w") as f:
        f.write(f"# {comment} (bench/peers2d/shapes2d.py)\n{len(vertices)} 2 0 0\n")
        f.writelines(f"{i + 1} {x!r} {y!r}\n" for i, (x, y) in enumerate(vertices))
        f.write(f"{len(segments)} 0\n")
        f.writelines(f"{k + 1} {a + 1} {b + 1}\n" for k, (a, b) in enumerate(segments))
        f.write(f"{len(holes)}\n")
        f.writelines(f"{i + 1} {x!r} {y!r}\n" for i, (x, y) in enumerate(holes))


def circle(cx, cy, r, n):
    return [(cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n)) for k in range(n)]


def ngon1000(out):
    write_poly(out, "regular 1000-gon", [circle(0.0, 0.0, 1.0, 1000)], [])


def random200(out):
    rng = random.Random(1)
    loop = [(r * math.cos(2 * math.pi * k / 200), r * math.sin(2 * math.pi * k / 200))
            for k, r in ((k, rng.uniform(0.5, 1.0)) for k in range(200))]
    write_poly(out, "star-shaped random 200-gon, seed 1", [loop], [])


def comb16(out):
    w, depth, slots = 1.0 / 512, 0.5, 16
    loop = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]
    for k in reversed(range(slots)):  # along the top side, right to left
        c = (k + 1) / (slots + 1)
        loop += [(c + w / 2, 1.0), (c + w / 2, 1.0 - depth), (c - w / 2, 1.0 - depth), (c - w / 2, 1.0)]
    loop.append((0.0, 1.0))
    write_poly(out, "unit square with 16 slots of width 1/512", [loop], [])


def plate64(out):
    outer = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    centres = [((i + 0.5) / 8, (j + 0.5) / 8) for j in range(8) for i in range(8)]
    holes = [list(reversed(circle(cx, cy, 1.0 / 40, 16))) for cx, cy in centres]
    write_poly(out, "unit square plate with 64 holes", [outer] + holes, centres)


def tiny_feature(out):
    e = 1e-3
    loop = [(0.0, 0.0), (0.5 - e / 2, 0.0), (0.5 - e / 2, e), (0.5 + e / 2, e), (0.5 + e / 2, 0.0), (1.0, 0.0),
            (1.0, 1.0), (0.0, 1.0)]
    write_poly(out, "unit square with a 1e-3 notch", [loop], [])


SHAPES = {"ngon1000": ngon1000, "random200": random200, "comb16": comb16, "plate64": plate64,
          "tiny_feature": tiny_feature}

if __name__ == "__main__":
    if len(sys.argv) == 2 and sys.argv[1] == "--list":
        print(" ".join(SHAPES))
    elif len(sys.argv) == 3 and sys.argv[1] in SHAPES:
        SHAPES[sys.argv[1]](sys.argv[2])
    else:
        sys.exit(__doc__)
