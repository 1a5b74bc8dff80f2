"""to_meshio: the mesh as a meshio.Mesh, written and read back unchanged."""

import meshio
import numpy as np

import pqmesh
from conftest import CUBE_FACETS, CUBE_MARKERS, CUBE_POINTS, DATA, assert_valid


def test_tetmesh_round_trip(tmp_path):
    mesh = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS)
    assert_valid(mesh)
    converted = mesh.to_meshio()
    assert isinstance(converted, meshio.Mesh)
    path = tmp_path / "cube.vtu"
    converted.write(path)
    back = meshio.read(path)
    assert np.array_equal(back.points, mesh.points)
    assert np.array_equal(back.cells_dict["tetra"], mesh.tetrahedra)
    assert np.array_equal(back.cells_dict["triangle"], mesh.faces)
    markers = dict(zip((block.type for block in back.cells), back.cell_data["marker"]))
    assert np.array_equal(markers["triangle"], mesh.face_markers)
    assert not markers["tetra"].any()  # no regions: 0
    # The mesh read back is the same valid mesh.
    again = pqmesh.TetMesh(back.points, back.cells_dict["tetra"], back.cells_dict["triangle"], markers["triangle"])
    assert_valid(again, mesh.domain)


def test_trimesh_round_trip(tmp_path):
    mesh = pqmesh.triangulate(domain=pqmesh.read_domain(str(DATA / "2d" / "regions.poly")))
    assert_valid(mesh)
    converted = mesh.to_meshio()
    path = tmp_path / "regions.vtu"
    converted.write(path)
    back = meshio.read(path)
    assert np.array_equal(back.points[:, :2], mesh.points)
    assert np.array_equal(back.cells_dict["triangle"], mesh.triangles)
    markers = dict(zip((block.type for block in back.cells), back.cell_data["marker"]))
    assert np.array_equal(markers["triangle"], mesh.triangle_markers)
    assert np.array_equal(markers["line"], mesh.edge_markers)
    again = pqmesh.TriMesh(back.points[:, :2], back.cells_dict["triangle"], back.cells_dict["line"], markers["line"])
    assert_valid(again, mesh.domain)


def test_library_writer_read_by_meshio(tmp_path):
    mesh = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS)
    assert_valid(mesh)
    mesh.write(str(tmp_path / "cube.vtu"))
    back = meshio.read(tmp_path / "cube.vtu")
    assert np.array_equal(back.points, mesh.points)
    assert np.array_equal(back.cells_dict["tetra"], mesh.tetrahedra)
