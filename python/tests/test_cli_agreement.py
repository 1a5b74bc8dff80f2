"""The module calls the entry points `pqmesh mesh` calls: on the same input and
options it makes the same mesh, array for array, as the CLI writes."""

import os
import subprocess

import meshio
import numpy as np
import pytest

import pqmesh
from conftest import DATA, assert_valid


def cli_mesh(tmp_path, input_path, *options):
    output = tmp_path / "cli.vtu"
    run = subprocess.run([os.environ["PQMESH_CLI"], "mesh", str(input_path), "-o", str(output), "--quiet", *options],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    return meshio.read(output)


@pytest.mark.parametrize("name, options, kwargs", [
    ("l_block.poly", [], {}),
    ("cube.poly", ["--max-size", "0.2", "--aligned-grid"], {"max_size": 0.2, "aligned_grid": True}),
])
def test_3d_same_as_cli(tmp_path, name, options, kwargs):
    mesh = pqmesh.tetrahedralize(pqmesh.read_domain(str(DATA / "3d" / name)), **kwargs)
    assert_valid(mesh)
    cli = cli_mesh(tmp_path, DATA / "3d" / name, *options)
    assert np.array_equal(cli.points, mesh.points)
    assert np.array_equal(cli.cells_dict["tetra"], mesh.tetrahedra)


@pytest.mark.parametrize("name, options, kwargs", [
    ("square_holes.poly", [], {}),
    ("l_shape.poly", ["--max-size", "0.1", "--refine-angle", "25"], {"max_size": 0.1, "refine_angle": 25}),
    ("comb.poly", ["--min-angle", "30"], {"min_angle": 30}),
    ("comb.poly", ["--no-improve"], {"improve": False}),
    ("square_holes.poly", ["--no-boundary-steiner"], {"no_boundary_steiner": True}),
    ("square_holes.poly", ["--no-boundary-steiner", "--min-angle", "5"], {"no_boundary_steiner": True, "min_angle": 5}),
    ("square_holes.poly", ["--no-boundary-steiner", "--pipeline"], {"no_boundary_steiner": True, "keep_better_cdt": False}),
])
def test_2d_same_as_cli(tmp_path, name, options, kwargs):
    mesh = pqmesh.triangulate(pqmesh.read_domain(str(DATA / "2d" / name)), **kwargs)
    assert_valid(mesh, no_boundary_steiner=kwargs.get("no_boundary_steiner", False))
    cli = cli_mesh(tmp_path, DATA / "2d" / name, *options)
    assert np.array_equal(cli.points[:, :2], mesh.points) and not cli.points[:, 2].any()
    assert np.array_equal(cli.cells_dict["triangle"], mesh.triangles)
