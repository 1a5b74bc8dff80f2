"""pqmesh.tetrahedralize from arrays and from files; every mesh is checked."""

import numpy as np
import pytest

import pqmesh
from conftest import (CUBE_FACETS, CUBE_MARKERS, CUBE_PLANES, CUBE_POINTS, DATA, assert_valid,
                      cube_with_cavity)


def test_cube_from_arrays():
    mesh = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS)
    report = assert_valid(mesh)
    assert mesh.points.dtype == np.float64 and mesh.points.shape[1] == 3
    assert mesh.tetrahedra.dtype == np.int32 and mesh.tetrahedra.shape[1] == 4
    assert mesh.faces.shape == (len(mesh.face_markers), 3)
    assert report.elements == len(mesh.tetrahedra) and report.vertices == len(mesh.points)
    assert report.mesh_volume == pytest.approx(1.0)
    # Every input corner is a mesh vertex.
    for corner in CUBE_POINTS:
        assert np.any(np.all(mesh.points == corner, axis=1)), corner


def test_facet_markers_kept_on_their_facets():
    mesh = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS)
    assert_valid(mesh)
    assert sorted(set(mesh.face_markers.tolist())) == CUBE_MARKERS
    for face, marker in zip(mesh.faces, mesh.face_markers):
        axis, value = CUBE_PLANES[int(marker)]
        assert np.all(mesh.points[face][:, axis] == value), (face, marker)


def test_numpy_facets_same_mesh_as_lists():
    from_lists = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS)
    from_arrays = pqmesh.tetrahedralize(np.array(CUBE_POINTS, dtype=float), np.array(CUBE_FACETS),
                                        facet_markers=np.array(CUBE_MARKERS))
    assert_valid(from_lists)
    assert_valid(from_arrays)
    assert np.array_equal(from_lists.points, from_arrays.points)
    assert np.array_equal(from_lists.tetrahedra, from_arrays.tetrahedra)


def test_summary_figures():
    mesh = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS)
    assert_valid(mesh)
    assert mesh.alpha == pytest.approx(90.0)
    assert 3.0 <= mesh.max_aspect_ratio <= mesh.aspect_bound
    assert 0 < mesh.min_dihedral <= 70.53 <= mesh.max_dihedral < 180
    quality = pqmesh.quality(mesh)
    assert quality.aspect_ratio.max == mesh.max_aspect_ratio
    assert quality.min_angle.min == mesh.min_dihedral
    assert quality.elements == len(mesh.tetrahedra)
    assert quality.inverted == 0 and quality.degenerate == 0
    assert quality.total_size == pytest.approx(1.0)
    per_element = quality.per_element
    assert per_element["aspect_ratio"].shape == (len(mesh.tetrahedra),)
    assert per_element["min_angle"].min() == quality.min_angle.min
    assert mesh.stats["leaves"] > 0 and mesh.seconds["mesh"] >= 0


@pytest.mark.parametrize("name", ["cube.poly", "l_block.poly"])
def test_from_file(name):
    domain = pqmesh.read_domain(str(DATA / "3d" / name))
    assert isinstance(domain, pqmesh.Domain3) and domain.path == str(DATA / "3d" / name)
    mesh = pqmesh.tetrahedralize(domain)
    assert mesh.domain is domain
    report = assert_valid(mesh, domain)
    assert report.mesh_volume == pytest.approx(domain.volume)
    assert set(mesh.face_markers.tolist()) == set(domain.facet_markers.tolist())


def test_domain_keyword_and_file_domain_equal_array_domain():
    domain = pqmesh.read_domain(str(DATA / "3d" / "cube.poly"))
    from_file = pqmesh.tetrahedralize(domain=domain)
    from_arrays = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS)
    assert_valid(from_file)
    assert_valid(from_arrays)
    assert np.array_equal(from_file.points, from_arrays.points)
    assert np.array_equal(from_file.tetrahedra, from_arrays.tetrahedra)
    assert np.array_equal(from_file.face_markers, from_arrays.face_markers)


def test_max_size_makes_more_elements():
    coarse = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, aligned_grid=True)
    fine = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, aligned_grid=True, max_size=0.125)
    assert_valid(coarse)
    assert_valid(fine)
    assert len(fine.tetrahedra) > len(coarse.tetrahedra)
    assert fine.stats["depth"] > coarse.stats["depth"]


def test_full_separation_builds_the_thesis_octree():
    light = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS)
    thesis = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, full_separation=True)
    assert_valid(light)
    assert_valid(thesis)
    assert not light.stats["separated"] and light.stats["separated_faces"] == 0
    assert light.stats["light_rejected"] == ""
    assert light.stats["grid_shift"] == 0  # the first generic offset: nothing was dropped
    assert thesis.stats["separated"]
    # The constructions differ; the improvement may coarsen both to the same few tetrahedra.
    assert thesis.stats["constructed_tetrahedra"] > light.stats["constructed_tetrahedra"]
    assert light.max_aspect_ratio <= light.aspect_bound and thesis.max_aspect_ratio <= thesis.aspect_bound


def test_improve_coarsens_within_the_constructions_worst():
    coarse = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS)
    construction = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS, improve=False)
    assert_valid(coarse)
    assert_valid(construction)
    assert len(coarse.tetrahedra) < len(construction.tetrahedra)
    assert coarse.stats["constructed_tetrahedra"] == len(construction.tetrahedra)
    assert coarse.max_aspect_ratio <= construction.max_aspect_ratio
    assert coarse.stats["collapses"] > 0 and construction.stats["collapses"] == 0
    with pytest.raises(ValueError):
        pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, target_aspect=2)


def test_min_dihedral_target_keeps_the_guarantee():
    construction = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS, improve=False)
    for target in (15.0, 25.0):
        mesh = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS, min_dihedral=target)
        assert_valid(mesh)
        assert mesh.max_aspect_ratio <= construction.max_aspect_ratio
        assert "boundary_flips" in mesh.stats
    for bad in (-1.0, 71.0):
        with pytest.raises(ValueError):
            pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, min_dihedral=bad)
    # Unset: 20 degrees without a size bound, none with one; 0: none.
    assert pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS).stats["min_dihedral_target"] == 20
    assert pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, max_size=0.5).stats["min_dihedral_target"] == 0
    assert pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, min_dihedral=0).stats["min_dihedral_target"] == 0


def test_cavity():
    points, facets = cube_with_cavity()
    mesh = pqmesh.tetrahedralize(points, facets, holes=[(2, 2, 2)], aligned_grid=True)
    assert mesh.domain.shells == 2
    report = assert_valid(mesh)
    assert report.mesh_volume == pytest.approx(64 - 8)
    # No tetrahedron inside the cavity.
    centroids = mesh.points[mesh.tetrahedra].mean(axis=1)
    assert not np.any(np.all((centroids > 1) & (centroids < 3), axis=1))


def test_regions_give_tetrahedron_markers():
    points, facets = cube_with_cavity()
    mesh = pqmesh.tetrahedralize(points, facets, regions=[(0.5, 0.5, 0.5, 7)], aligned_grid=True)
    assert_valid(mesh)
    assert mesh.tetrahedron_markers is not None
    assert set(mesh.tetrahedron_markers.tolist()) == {7}


def test_deterministic():
    domain = pqmesh.read_domain(str(DATA / "3d" / "l_block.poly"))
    first = pqmesh.tetrahedralize(domain)
    second = pqmesh.tetrahedralize(domain)
    for name in ("points", "tetrahedra", "faces", "face_markers"):
        assert np.array_equal(getattr(first, name), getattr(second, name)), name
    assert_valid(first)
    assert_valid(second)


def test_arrays_are_read_only_views():
    mesh = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS)
    assert_valid(mesh)
    with pytest.raises(ValueError):
        mesh.points[0, 0] = 5.0
    points = mesh.points
    del mesh
    assert points.shape[1] == 3 and np.isfinite(points).all()  # the view keeps the mesh alive


def test_size_field_refines_near_its_point():
    def near_and_far(mesh):
        distance = np.linalg.norm(mesh.points[mesh.tetrahedra].mean(axis=1), axis=1)
        return (distance < 0.25).sum(), (distance > 1.5).sum()

    # The construction's grading (the improvement stage coarsens both).
    plain = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, aligned_grid=True, improve=False)
    graded = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, aligned_grid=True, size_field=([(0, 0, 0)], [0.05]),
                                   improve=False)
    assert_valid(plain)
    assert_valid(graded)
    (plain_near, plain_far), (graded_near, graded_far) = near_and_far(plain), near_and_far(graded)
    assert graded_near > 10 * plain_near  # fine next to the point
    assert graded_far == plain_far  # the field asks for nothing finer far from it


def test_size_field_file_is_the_pair(tmp_path):
    path = tmp_path / "field.txt"
    path.write_text("# x y z size\n0 0 0 0.05\n")
    from_file = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, aligned_grid=True, size_field=str(path))
    from_pair = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, aligned_grid=True, size_field=([(0, 0, 0)], [0.05]))
    assert_valid(from_file)
    assert np.array_equal(from_file.points, from_pair.points)
    assert np.array_equal(from_file.tetrahedra, from_pair.tetrahedra)


def test_size_field_file_error_names_the_line(tmp_path):
    path = tmp_path / "bad_field.txt"
    path.write_text("0 0 0 0.05\n0 0 0.5\n")
    with pytest.raises(pqmesh.ParseError) as error:
        pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, size_field=str(path))
    assert error.value.line == 2 and error.value.path == str(path)
