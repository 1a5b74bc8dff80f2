"""Shared inputs and helpers of the pqmesh Python tests.

The tests run on the module of the build tree: ctest sets PYTHONPATH to
build/python (python/CMakeLists.txt) and test_module.py asserts that this is
the copy imported. numpy, meshio and pytest are hard requirements: a missing
one fails the import below instead of skipping tests.
"""

import os
import pathlib

import meshio  # noqa: F401  (a required test dependency)
import numpy  # noqa: F401  (a required test dependency)

import pqmesh

SOURCE_DIR = pathlib.Path(os.environ.get("PQMESH_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
DATA = SOURCE_DIR / "data"

# The unit cube; facet markers 1..6 as in data/3d/cube.poly.
CUBE_POINTS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_FACETS = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
CUBE_MARKERS = [1, 2, 3, 4, 5, 6]
# The plane of each cube facet, by marker: (axis, coordinate).
CUBE_PLANES = {1: (2, 0.0), 2: (2, 1.0), 3: (1, 0.0), 4: (0, 1.0), 5: (1, 1.0), 6: (0, 0.0)}

# The square [0, 4]^2 with the hole [1, 3]^2; segment markers 1..4 outside, 5 on the hole.
HOLED_SQUARE_POINTS = [(0, 0), (4, 0), (4, 4), (0, 4), (1, 1), (1, 3), (3, 3), (3, 1)]
HOLED_SQUARE_SEGMENTS = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4)]
HOLED_SQUARE_MARKERS = [1, 2, 3, 4, 5, 5, 5, 5]


def cube_with_cavity():
    """The cube [0, 4]^3 with the cavity [1, 3]^3 (a second shell), as arrays."""
    points, facets = [], []
    for lo, hi, outward in ((0, 4, True), (1, 3, False)):
        base = len(points)
        points += [(x, y, z) for z in (lo, hi) for (x, y) in ((lo, lo), (hi, lo), (hi, hi), (lo, hi))]
        for facet in CUBE_FACETS:
            loop = [base + v for v in facet]
            facets.append(loop if outward else loop[::-1])
    return points, facets


def assert_valid(mesh, domain=None, **options):
    """Run the validity checker against the domain the mesh was made from."""
    report = pqmesh.check(mesh, mesh.domain if domain is None else domain, **options)
    assert report.valid, report.text
    assert report.domain_checked
    return report
