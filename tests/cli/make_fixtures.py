#!/usr/bin/env python3
"""Writes the small hand-derived meshes the CLI tests use (run from this directory).

cube_kuhn.mesh   the unit cube split into the 6 Kuhn tetrahedra along the diagonal
                 (0,0,0)-(1,1,1): for each order (p, q, r) of the axes, the path
                 0 -> e_p -> e_p + e_q -> (1,1,1). Vertex order is fixed so that each
                 tetrahedron has positive volume det(b-a, c-a, d-a) > 0.
cube_flipped.mesh  the same with the first tetrahedron's last two vertices swapped.
cube_missing.mesh  the same without the last tetrahedron (a hole in the mesh).
square_two.mesh  the unit square split along the diagonal (0,0)-(1,1), counter-clockwise.
"""
import itertools


def det3(u, v, w):
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def corner(bits):
    return (bits & 1, (bits >> 1) & 1, (bits >> 2) & 1)


def kuhn_tets():
    tets = []
    for order in itertools.permutations(range(3)):
        path, bits = [0], 0
        for axis in order:
            bits |= 1 << axis
            path.append(bits)
        a, b, c, d = (corner(x) for x in path)
        sub = lambda p, q: tuple(pi - qi for pi, qi in zip(p, q))
        if det3(sub(b, a), sub(c, a), sub(d, a)) < 0:
            path[2], path[3] = path[3], path[2]
        tets.append(path)
    return tets


def write_tet_mesh(name, tets):
    with open(name, "w") as out:
        out.write("MeshVersionFormatted 2\nDimension 3\nVertices\n8\n")
        for bits in range(8):
            x, y, z = corner(bits)
            out.write(f"{x} {y} {z} 0\n")
        out.write(f"Tetrahedra\n{len(tets)}\n")
        for t in tets:
            out.write(" ".join(str(v + 1) for v in t) + " 1\n")
        out.write("End\n")


tets = kuhn_tets()
write_tet_mesh("fixtures/cube_kuhn.mesh", tets)
flipped = [list(t) for t in tets]
flipped[0][2], flipped[0][3] = flipped[0][3], flipped[0][2]
write_tet_mesh("fixtures/cube_flipped.mesh", flipped)
write_tet_mesh("fixtures/cube_missing.mesh", tets[:-1])

with open("fixtures/square_two.mesh", "w") as out:
    out.write("MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n")
    out.write("Triangles\n2\n1 2 3 1\n1 3 4 1\nEnd\n")
