"""The package under test is the build tree's; domains and reports expose the
library's data."""

import os
import pathlib

import numpy as np
import pytest

import pqmesh
from conftest import CUBE_FACETS, CUBE_MARKERS, CUBE_POINTS, DATA, assert_valid


def test_imported_from_the_build_tree():
    build_dir = pathlib.Path(os.environ["PYTHONPATH"].split(os.pathsep)[0]).resolve()
    assert pathlib.Path(pqmesh.__file__).resolve().parent == build_dir / "pqmesh"
    assert pathlib.Path(pqmesh._pqmesh.__file__).resolve().parent == build_dir / "pqmesh"


def test_domain3_from_file():
    domain = pqmesh.read_domain(str(DATA / "3d" / "l_block.poly"))
    assert domain.dimension == 3 and domain.first_id == 1
    assert domain.points.shape == (12, 3) and domain.volume == pytest.approx(3)
    assert len(domain.facets) == 8 and sorted(set(domain.facet_markers.tolist())) == [1, 2, 3]
    assert domain.holes.shape == (0, 3) and domain.shells == 1
    assert domain.alpha == pytest.approx(90)


def test_domain2_from_file():
    domain = pqmesh.read_domain(str(DATA / "2d" / "square_holes.poly"))
    assert domain.dimension == 2 and domain.first_id == 1
    assert domain.points.shape == (15, 2) and domain.segments.shape == (15, 2)
    assert domain.segments.dtype == np.int32
    assert len(domain.loops) == 4 and domain.holes.shape == (3, 2)
    assert domain.area == pytest.approx(13)


def test_domain_round_trip_through_its_arrays():
    domain = pqmesh.Domain3(CUBE_POINTS, CUBE_FACETS, CUBE_MARKERS)
    again = pqmesh.Domain3(domain.points, domain.facets, domain.facet_markers)
    assert again.volume == pytest.approx(1) and again.facets == domain.facets


def test_check_report_contents():
    mesh = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS)
    report = assert_valid(mesh)
    assert report.dimension == 3 and report.counts == {} and report.messages == []
    assert report.text.startswith("valid: ") and str(report) == report.text
    assert report.boundary_faces == len(mesh.faces)
    topology = pqmesh.check_topology(mesh)
    assert topology.valid and not topology.domain_checked


def test_quality_2d():
    mesh = pqmesh.triangulate([(0, 0), (1, 0), (1, 1), (0, 1)], [(0, 1), (1, 2), (2, 3), (3, 0)])
    assert_valid(mesh)
    quality = pqmesh.quality(mesh)
    assert quality.dimension == 2 and quality.elements == len(mesh.triangles)
    assert quality.min_angle.min == mesh.min_angle and quality.max_angle.max == mesh.max_angle
    assert quality.aspect_ratio.min >= 2 - 1e-12
    assert sum(quality.min_angle_hist.counts) == quality.elements
    assert "aspect" in quality.text


def test_facets_with_holes_round_trip():
    domain = pqmesh.read_domain(str(DATA / "3d" / "cube_through_hole.poly"))
    holed = [facet for facet in domain.facets if isinstance(facet[0], list)]
    assert len(holed) == 2 and all(len(loops) == 2 for loops in holed)  # outer loop and hole
    again = pqmesh.Domain3(domain.points, domain.facets, domain.facet_markers)
    assert again.facets == domain.facets and again.volume == pytest.approx(48)
