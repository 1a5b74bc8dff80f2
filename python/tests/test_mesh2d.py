"""pqmesh.triangulate from arrays and from files; every mesh is checked."""

import numpy as np
import pytest

import pqmesh
from conftest import (DATA, HOLED_SQUARE_MARKERS, HOLED_SQUARE_POINTS, HOLED_SQUARE_SEGMENTS,
                      assert_valid)

SQUARE = [(0, 0), (1, 0), (1, 1), (0, 1)]
SQUARE_SEGMENTS = [(0, 1), (1, 2), (2, 3), (3, 0)]


def on_segment(p, a, b):
    """p on the closed segment ab (exact for the axis-parallel segments used here)."""
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
    return cross == 0 and np.all(lo <= p) and np.all(p <= hi)


def test_square_from_arrays():
    mesh = pqmesh.triangulate(SQUARE, SQUARE_SEGMENTS, segment_markers=[1, 2, 3, 4])
    report = assert_valid(mesh)
    assert mesh.points.shape[1] == 2 and mesh.points.dtype == np.float64
    assert mesh.triangles.shape[1] == 3 and mesh.triangles.dtype == np.int32
    assert report.mesh_volume == pytest.approx(1.0)
    assert mesh.alpha == pytest.approx(90.0)
    assert mesh.min_angle >= mesh.angle_bound
    assert mesh.stats["refined_input"] and mesh.seconds["mesh"] >= 0


def test_segment_markers_kept_on_their_segments():
    mesh = pqmesh.triangulate(HOLED_SQUARE_POINTS, HOLED_SQUARE_SEGMENTS, HOLED_SQUARE_MARKERS)
    assert_valid(mesh)
    points = np.array(HOLED_SQUARE_POINTS, dtype=float)
    assert sorted(set(mesh.edge_markers.tolist())) == [1, 2, 3, 4, 5]
    for edge, marker in zip(mesh.edges, mesh.edge_markers):
        owners = [s for s, m in enumerate(HOLED_SQUARE_MARKERS) if m == marker]
        assert any(all(on_segment(mesh.points[v], *points[list(HOLED_SQUARE_SEGMENTS[s])]) for v in edge)
                   for s in owners), (edge, marker)


def test_hole_from_arrays():
    mesh = pqmesh.triangulate(HOLED_SQUARE_POINTS, HOLED_SQUARE_SEGMENTS, holes=[(2, 2)])
    report = assert_valid(mesh)
    assert report.mesh_volume == pytest.approx(16 - 4)
    centroids = mesh.points[mesh.triangles].mean(axis=1)
    assert not np.any(np.all((centroids > 1) & (centroids < 3), axis=1))


@pytest.mark.parametrize("name, area", [("square.poly", 1), ("l_shape.poly", 3), ("square_holes.poly", 13)])
def test_from_file(name, area):
    domain = pqmesh.read_domain(str(DATA / "2d" / name))
    assert isinstance(domain, pqmesh.Domain2) and domain.area == pytest.approx(area)
    mesh = pqmesh.triangulate(domain)
    report = assert_valid(mesh, domain)
    assert report.mesh_volume == pytest.approx(area)
    if domain.segment_markers is not None:
        assert set(mesh.edge_markers.tolist()) == set(domain.segment_markers.tolist())


def test_regions_give_triangle_markers():
    square = pqmesh.triangulate(SQUARE, SQUARE_SEGMENTS, regions=[(0.5, 0.5, 4)])
    assert_valid(square)
    assert set(square.triangle_markers.tolist()) == {4}
    # data/2d/regions.poly: both region points lie in the one region; the first one's attribute wins.
    mesh = pqmesh.triangulate(domain=pqmesh.read_domain(str(DATA / "2d" / "regions.poly")))
    assert_valid(mesh)
    assert set(mesh.triangle_markers.tolist()) == {7}


def test_max_size_makes_more_elements():
    coarse = pqmesh.triangulate(SQUARE, SQUARE_SEGMENTS)
    fine = pqmesh.triangulate(SQUARE, SQUARE_SEGMENTS, max_size=0.05)
    assert_valid(coarse)
    assert_valid(fine)
    assert len(fine.triangles) > 4 * len(coarse.triangles)


def test_size_field_pair_refines_near_its_point():
    mesh = pqmesh.triangulate(SQUARE, SQUARE_SEGMENTS, size_field=([(0, 0)], [0.01]))
    assert_valid(mesh)
    centroids = mesh.points[mesh.triangles].mean(axis=1)
    near = np.linalg.norm(centroids, axis=1) < 0.5
    assert near.sum() > (~near).sum()


def test_default_is_the_refined_cdt_and_quadtree_the_option():
    domain = pqmesh.read_domain(str(DATA / "2d" / "comb.poly"))
    default, quad = pqmesh.triangulate(domain), pqmesh.triangulate(domain, quadtree=True)
    assert_valid(default)
    assert_valid(quad)
    assert default.stats["refined_input"] and not quad.stats["refined_input"]
    assert quad.stats["leaves"] > 0
    assert default.min_angle >= default.angle_bound and quad.min_angle >= quad.angle_bound
    assert len(default.triangles) < len(quad.triangles)


def test_refine_angle_off_and_on():
    off = pqmesh.triangulate(domain=pqmesh.read_domain(str(DATA / "2d" / "l_shape.poly")), refine_angle=0)
    on = pqmesh.triangulate(domain=pqmesh.read_domain(str(DATA / "2d" / "l_shape.poly")), refine_angle=25)
    assert_valid(off)
    assert_valid(on)
    assert off.stats["refine_points"] == 0
    assert on.min_angle >= off.min_angle


def test_no_boundary_steiner_keeps_input_boundary_vertices():
    domain = pqmesh.read_domain(str(DATA / "2d" / "square_holes.poly"))
    mesh = pqmesh.triangulate(domain, no_boundary_steiner=True)
    assert_valid(mesh, no_boundary_steiner=True)
    boundary_vertices = set(np.unique(mesh.edges).tolist())
    assert boundary_vertices == set(range(len(domain.points)))
    assert np.array_equal(mesh.points[: len(domain.points)], domain.points)
    assert mesh.min_angle <= mesh.upper_bound + 1e-9
    assert mesh.path in ("full", "q-only", "cdt", "cdt-better", "refined")
    # The quadtree mesher, by contrast, adds boundary vertices here.
    quad = pqmesh.triangulate(domain, quadtree=True)
    assert_valid(quad)
    assert not pqmesh.check(quad, domain, no_boundary_steiner=True).valid


def test_deterministic():
    domain = pqmesh.read_domain(str(DATA / "2d" / "square_holes.poly"))
    first, second = pqmesh.triangulate(domain), pqmesh.triangulate(domain)
    assert_valid(first)
    assert_valid(second)
    for name in ("points", "triangles", "edges", "edge_markers"):
        assert np.array_equal(getattr(first, name), getattr(second, name)), name


def test_improvement_keeps_the_input_vertices_and_never_adds_triangles():
    domain = pqmesh.read_domain(str(DATA / "2d" / "comb.poly"))
    built, improved = pqmesh.triangulate(domain, improve=False), pqmesh.triangulate(domain)
    assert_valid(built)
    assert_valid(improved)
    assert not built.stats["improved"] and improved.stats["improved"]
    assert improved.stats["constructed_triangles"] == len(built.triangles)
    assert improved.stats["improve_target"] == 20  # the default refinement angle (the comb's bound is below)
    assert len(improved.triangles) <= len(built.triangles)
    assert improved.min_angle >= min(20.0, built.min_angle)
    # Boundary Steiner points exactly on a segment may go: the boundary keeps its length and
    # every input vertex (its exact shape is the checker's, in assert_valid).
    length = lambda m: np.linalg.norm(m.points[m.edges[:, 1]] - m.points[m.edges[:, 0]], axis=1).sum()  # noqa: E731
    assert abs(length(improved) - length(built)) <= 1e-12 * length(built)
    assert {tuple(p) for p in domain.points.tolist()} <= {tuple(p) for p in improved.points.tolist()}


def test_min_angle_30_on_the_comb():
    mesh = pqmesh.triangulate(pqmesh.read_domain(str(DATA / "2d" / "comb.poly")), min_angle=30)
    assert_valid(mesh)
    assert mesh.min_angle >= 30  # the comb has no input angle below 60 degrees
    with pytest.raises(ValueError):
        pqmesh.triangulate(pqmesh.read_domain(str(DATA / "2d" / "comb.poly")), min_angle=34)


def test_min_angle_without_boundary_steiner_is_reported():
    domain = pqmesh.read_domain(str(DATA / "2d" / "square_holes.poly"))
    mesh = pqmesh.triangulate(domain, no_boundary_steiner=True, min_angle=5)
    assert_valid(mesh, no_boundary_steiner=True)
    assert mesh.target == 5
    assert mesh.target_reached == (mesh.min_angle >= 5)
    assert mesh.min_angle <= mesh.upper_bound + 1e-9
