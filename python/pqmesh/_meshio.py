"""TriMesh.to_meshio / TetMesh.to_meshio: the mesh as a meshio.Mesh (meshio is
imported when first needed). Two cell blocks: the elements, then the boundary
faces (edges in 2D); cell_data "marker" holds the region attribute of each
element and the input marker of each boundary face, 0 where the mesh has none."""

import numpy as np


def _markers(markers, count):
    return np.zeros(count, dtype=np.int32) if markers is None else np.array(markers)


def _to_meshio(mesh, element_type, elements, element_markers, face_type, faces, face_markers):
    import meshio

    cells = [(element_type, np.array(elements)), (face_type, np.array(faces))]
    marker = [_markers(element_markers, len(elements)), _markers(face_markers, len(faces))]
    return meshio.Mesh(np.array(mesh.points), cells, cell_data={"marker": marker})


def tri_to_meshio(self):
    """This mesh as a meshio.Mesh: "triangle" and "line" (boundary edge) cells, cell_data "marker"."""
    return _to_meshio(self, "triangle", self.triangles, self.triangle_markers, "line", self.edges,
                      self.edge_markers)


def tet_to_meshio(self):
    """This mesh as a meshio.Mesh: "tetra" and "triangle" (boundary face) cells, cell_data "marker"."""
    return _to_meshio(self, "tetra", self.tetrahedra, self.tetrahedron_markers, "triangle", self.faces,
                      self.face_markers)
