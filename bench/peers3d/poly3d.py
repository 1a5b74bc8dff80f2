#!/usr/bin/env python3
"""Helpers of the 3D peer benchmark (bench/run_3d.sh); one job per subcommand.

  poly3d.py info IN.poly            -> "facets F shells S"
  poly3d.py geo IN.poly OUT.geo LC  -> a gmsh .geo: one Plane Surface per facet
                                       (hole polygons as inner Curve Loops), one
                                       Surface Loop per shell, one Volume with
                                       the outer shell first, point size LC

Reads the TetGen .poly subset that data/3d/*.poly use: nodes (ids from 0 or
1, attributes and markers skipped), facets of polygons with hole points, a
hole list; regions are ignored. A facet's outer polygon is the one with the
largest area; its other polygons are holes in it. Shells are the classes of
facets joined by shared vertices; the outer shell is the one whose bounding box
is largest (the others are cavities).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from poly_numbers import number_lines, read_nodes  # noqa: E402


def read_poly(path):
    lines = number_lines(path)
    vertices, first_id = read_nodes(lines, 3)
    m = int(next(lines)[0])
    facets = []
    for _ in range(m):
        head = next(lines)
        polygons, holes = int(head[0]), int(head[1]) if len(head) > 1 else 0
        loops = []
        for _ in range(polygons):
            p = next(lines)
            k = int(p[0])
            loops.append([int(x) - first_id for x in p[1:1 + k]])
        for _ in range(holes):
            next(lines)
        facets.append(loops)
    return vertices, facets


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def loop_normal(vertices, loop):
    """Newell's normal: twice the vector area of the loop."""
    n = [0.0, 0.0, 0.0]
    for i, a in enumerate(loop):
        p, q = vertices[a], vertices[loop[(i + 1) % len(loop)]]
        c = cross(p, q)
        n = [n[j] + c[j] for j in range(3)]
    return n


def area2(vertices, loop):
    n = loop_normal(vertices, loop)
    return (n[0] ** 2 + n[1] ** 2 + n[2] ** 2) ** 0.5


def shells(vertices, facets):
    parent = list(range(len(vertices)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for loops in facets:  # a facet's hole polygons belong to its shell
        for loop in loops:
            for v in loop:
                parent[find(v)] = find(loops[0][0])
    groups = {}
    for f, loops in enumerate(facets):
        groups.setdefault(find(loops[0][0]), []).append(f)

    def extent(fs):
        pts = [vertices[v] for f in fs for loop in facets[f] for v in loop]
        return max(max(p[a] for p in pts) - min(p[a] for p in pts) for a in range(3))

    return sorted(groups.values(), key=lambda fs: (-extent(fs), fs[0]))


def write_geo(vertices, facets, out, lc):
    lines = []
    for i, p in enumerate(vertices):
        lines.append(f"Point({i + 1}) = {{{p[0]!r}, {p[1]!r}, {p[2]!r}, {lc!r}}};")
    edge_id = {}
    loop_id = 0
    surface_of_facet = []
    for loops in facets:
        outer = max(range(len(loops)), key=lambda i: area2(vertices, loops[i]))
        curve_loops = []
        for i in [outer] + [j for j in range(len(loops)) if j != outer]:
            loop = loops[i]
            ids = []
            for k, a in enumerate(loop):
                b = loop[(k + 1) % len(loop)]
                key = (min(a, b), max(a, b))
                if key not in edge_id:
                    edge_id[key] = len(edge_id) + 1
                    lines.append(f"Line({edge_id[key]}) = {{{key[0] + 1}, {key[1] + 1}}};")
                ids.append(edge_id[key] if a < b else -edge_id[key])
            loop_id += 1
            lines.append(f"Curve Loop({loop_id}) = {{{', '.join(map(str, ids))}}};")
            curve_loops.append(loop_id)
        surface_of_facet.append(len(surface_of_facet) + 1)
        lines.append(f"Plane Surface({surface_of_facet[-1]}) = {{{', '.join(map(str, curve_loops))}}};")
    shell_loops = []
    for s, fs in enumerate(shells(vertices, facets)):
        lines.append(f"Surface Loop({s + 1}) = {{{', '.join(str(surface_of_facet[f]) for f in fs)}}};")
        shell_loops.append(s + 1)
    lines.append(f"Volume(1) = {{{', '.join(map(str, shell_loops))}}};")
    lines.append("Physical Volume(1) = {1};")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


def main(argv):
    if len(argv) >= 2 and argv[0] == "info":
        v, f = read_poly(argv[1])
        print(f"facets {len(f)} shells {len(shells(v, f))}")
        return 0
    if len(argv) == 4 and argv[0] == "geo":
        v, f = read_poly(argv[1])
        write_geo(v, f, argv[2], float(argv[3]))
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
