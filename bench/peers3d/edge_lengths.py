#!/usr/bin/env python3
"""Edge lengths of the tetrahedra of an ASCII Gmsh 4.1 mesh, relative to a size H.

    edge_lengths.py MESH.msh H

Prints one line: "tets N edges E mean M p99 P max X above_sqrt3 F", the mean,
99th percentile and largest edge length divided by H, and the fraction of
edges longer than sqrt(3) H (the longest edge pqmesh's --max-size H allows a
tetrahedron made by its improvement stage). Each edge counted once.
Used by bench/matched_size_3d.sh to match tools by their mean edge length.
"""
import math
import sys


def read_msh41(path):
    lines = open(path).read().split("\n")
    points, tets, i = {}, [], 0
    while i < len(lines):
        if lines[i] == "$Nodes":
            blocks = int(lines[i + 1].split()[0])
            i += 2
            for _ in range(blocks):
                n = int(lines[i].split()[3])
                ids = [int(lines[i + 1 + k]) for k in range(n)]
                for k in range(n):
                    points[ids[k]] = tuple(map(float, lines[i + 1 + n + k].split()[:3]))
                i += 1 + 2 * n
        elif lines[i] == "$Elements":
            blocks = int(lines[i + 1].split()[0])
            i += 2
            for _ in range(blocks):
                _, _, kind, n = map(int, lines[i].split())
                if kind == 4:  # 4-node tetrahedron
                    tets.extend(list(map(int, lines[i + 1 + k].split()[1:5])) for k in range(n))
                i += 1 + n
        else:
            i += 1
    return points, tets


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    points, tets = read_msh41(sys.argv[1])
    h = float(sys.argv[2])
    edges = {}
    for t in tets:
        for a in range(4):
            for b in range(a + 1, 4):
                e = (min(t[a], t[b]), max(t[a], t[b]))
                if e not in edges:
                    edges[e] = math.dist(points[e[0]], points[e[1]]) / h
    if not edges:
        sys.exit(f"{sys.argv[1]}: no tetrahedra")
    lengths = sorted(edges.values())
    above = sum(1 for x in lengths if x > math.sqrt(3))
    print(f"tets {len(tets)} edges {len(lengths)} mean {sum(lengths) / len(lengths):.3f} "
          f"p99 {lengths[int(0.99 * (len(lengths) - 1))]:.3f} max {lengths[-1]:.3f} "
          f"above_sqrt3 {above / len(lengths):.4f}")


if __name__ == "__main__":
    main()
