"""Bad input raises pqmesh.InputError subclasses carrying the library's code,
ids, path and line, with the CLI's message text; bad options raise ValueError."""

import os
import subprocess

import numpy as np
import pytest

import pqmesh
from conftest import CUBE_FACETS, CUBE_MARKERS, CUBE_POINTS, assert_valid

SQUARE_POLY = """# the unit square
4 2 0 0
1 0 0
2 1 0
3 1 1
4 0 1
4 0
1 1 2
2 2 3
3 3 {end}
4 4 1
0
"""


def cli_message(*args):
    """stderr of the pqmesh CLI (exit code 2: invalid input) without its "pqmesh mesh: " prefix."""
    run = subprocess.run([os.environ["PQMESH_CLI"], *args], capture_output=True, text=True)
    assert run.returncode == 2, run.stderr
    prefix = f"pqmesh {args[0]}: "
    assert run.stderr.startswith(prefix), run.stderr
    return run.stderr[len(prefix):].rstrip("\n")


def test_hierarchy():
    assert issubclass(pqmesh.InputError, ValueError) and issubclass(pqmesh.InputError, pqmesh.Error)
    for cls in (pqmesh.ParseError, pqmesh.DomainError, pqmesh.MeshNotSupported):
        assert issubclass(cls, pqmesh.InputError)
    assert issubclass(pqmesh.OutputError, OSError) and issubclass(pqmesh.InternalError, RuntimeError)


def test_file_error_has_ids_path_line_and_the_cli_message(tmp_path):
    path = tmp_path / "bad.poly"
    path.write_text(SQUARE_POLY.format(end=9))  # segment 3 ends at vertex 9 (line 10)
    with pytest.raises(pqmesh.ParseError) as caught:
        pqmesh.read_domain(str(path))
    error = caught.value
    assert error.code == "index-out-of-range"
    assert error.ids == [3, 9]  # the segment and the vertex it names
    assert error.path == str(path)
    assert error.line == 10
    assert str(error) == cli_message("mesh", str(path), "-o", str(tmp_path / "out.vtu"))
    assert str(error).startswith(f"{path}:10: error [index-out-of-range]: ")
    assert str(error).endswith(error.detail)


def test_syntax_error_names_the_line(tmp_path):
    path = tmp_path / "syntax.poly"
    path.write_text(SQUARE_POLY.format(end="x"))
    with pytest.raises(pqmesh.ParseError) as caught:
        pqmesh.read_domain(str(path))
    assert caught.value.code == "syntax" and caught.value.line == 10 and caught.value.path == str(path)
    assert str(caught.value) == cli_message("mesh", str(path), "-o", str(tmp_path / "out.vtu"))


def test_missing_file():
    with pytest.raises(pqmesh.ParseError) as caught:
        pqmesh.read_domain("/nonexistent/domain.poly")
    assert caught.value.code == "unreadable"


def test_index_out_of_range_in_arrays_names_the_facet():
    facets = [list(f) for f in CUBE_FACETS]
    facets[4] = [2, 3, 7, 60]
    with pytest.raises(pqmesh.DomainError) as caught:
        pqmesh.tetrahedralize(CUBE_POINTS, facets)
    assert caught.value.code == "index-out-of-range"
    assert caught.value.ids == [4]
    assert caught.value.path is None and caught.value.line is None


def test_open_boundary():
    with pytest.raises(pqmesh.DomainError) as caught:
        pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS[:-1])
    assert caught.value.code == "open-boundary"
    assert caught.value.ids


@pytest.mark.parametrize("call, code, words", [
    (lambda: pqmesh.tetrahedralize([(0, 0), (1, 0), (0, 1)], [[0, 1, 2]]), "wrong-count", "points"),
    (lambda: pqmesh.triangulate([(0, 0), (1, 0), (0, 1)], [(0, 1), (1, 2), (2, 0.5)]), "syntax", "segments"),
    (lambda: pqmesh.triangulate([(0, 0), (1, 0), (0, 1)], [(0, 1, 2)]), "wrong-count", "segments"),
    (lambda: pqmesh.triangulate([(0, 0), (1, 0), ("a", 1)], [(0, 1), (1, 2), (2, 0)]), "syntax", "points"),
    (lambda: pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=[1, 2]), "wrong-count",
     "facet_markers"),
    (lambda: pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS[:5] + [[3, 0, 4, 7.5]]), "syntax", "facet 5"),
])
def test_bad_arrays(call, code, words):
    with pytest.raises(pqmesh.InputError) as caught:
        call()
    assert caught.value.code == code
    assert words in str(caught.value)


def test_bad_facet_entry_names_the_facet():
    with pytest.raises(pqmesh.InputError) as caught:
        pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS[:5] + [[3, 0, 4, 2**40]])
    assert caught.value.code == "index-out-of-range" and caught.value.ids == [5]


@pytest.mark.parametrize("options", [{"max_size": 0}, {"max_size": -1.0}, {"max_size": float("nan")}])
def test_bad_options_are_value_errors(options):
    with pytest.raises(ValueError) as caught:
        pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, **options)
    assert not isinstance(caught.value, pqmesh.InputError)


def test_bad_2d_options():
    square = ([(0, 0), (1, 0), (1, 1), (0, 1)], [(0, 1), (1, 2), (2, 3), (3, 0)])
    with pytest.raises(ValueError):
        pqmesh.triangulate(*square, refine_angle=45)
    with pytest.raises(ValueError):
        pqmesh.triangulate(*square, no_boundary_steiner=True, max_size=0.1)
    with pytest.raises(TypeError):
        pqmesh.triangulate(*square, domain=pqmesh.Domain2(*square))


def test_write_to_missing_directory_is_output_error(tmp_path):
    mesh = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS)
    assert_valid(mesh)
    with pytest.raises(pqmesh.OutputError):
        mesh.write(str(tmp_path / "missing" / "cube.vtu"))
    mesh.write(str(tmp_path / "cube.vtu"))
    assert (tmp_path / "cube.vtu").stat().st_size > 0


def test_checker_reports_a_broken_mesh():
    mesh = pqmesh.tetrahedralize(CUBE_POINTS, CUBE_FACETS, facet_markers=CUBE_MARKERS)
    assert_valid(mesh)
    tetrahedra = np.array(mesh.tetrahedra)
    tetrahedra[5, [0, 1]] = tetrahedra[5, [1, 0]]  # flip one tetrahedron
    broken = pqmesh.TetMesh(mesh.points, tetrahedra, mesh.faces, mesh.face_markers)
    report = pqmesh.check(broken, mesh.domain)
    assert not report.valid
    assert report.counts["orientation"] == 1
    orientation = [issue for issue in report.issues if issue.kind == "orientation"]
    assert orientation[0].ids == [5]
    assert any("5" in message for message in report.messages)
    assert not pqmesh.check_topology(broken).valid
    with pytest.raises(TypeError):
        pqmesh.check(broken, pqmesh.Domain2([(0, 0), (1, 0), (0, 1)], [(0, 1), (1, 2), (2, 0)]))
