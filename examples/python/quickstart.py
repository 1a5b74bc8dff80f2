"""Mesh an L-shaped block given as arrays, check the mesh, write it with meshio."""
import sys

import pqmesh

# The L of area 3 at z = 0 and at z = 1; each facet is a polygon of point ids.
l_shape = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
points = [(x, y, z) for z in (0, 1) for x, y in l_shape]
facets = [[5, 4, 3, 2, 1, 0], [6, 7, 8, 9, 10, 11]]  # bottom, top
facets += [[i, (i + 1) % 6, (i + 1) % 6 + 6, i + 6] for i in range(6)]  # the sides
markers = [1, 2] + [3] * 6

mesh = pqmesh.tetrahedralize(points, facets, facet_markers=markers, max_size=0.5)
report = pqmesh.check(mesh, mesh.domain)
print(report.text.splitlines()[0])
if not report.valid:
    sys.exit(1)
print(f"alpha {mesh.alpha:.1f} deg; worst aspect ratio {mesh.max_aspect_ratio:.1f} "
      f"(measured bound {mesh.aspect_bound:.0f}); dihedral angles "
      f"{mesh.min_dihedral:.1f} to {mesh.max_dihedral:.1f} deg")
mesh.to_meshio().write(sys.argv[1] if len(sys.argv) > 1 else "l_block.vtu")
