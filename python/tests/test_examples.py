"""The two library usage examples run and write valid meshes: the Python
quick start (examples/python/quickstart.py, read back with meshio) and the C++
example (examples/cpp/mesh_cube.cpp, built as mesh_cube; read back with VTK)."""

import os
import subprocess
import sys

import meshio
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

import pqmesh
from conftest import DATA, SOURCE_DIR

VTK_TETRA = 10


def run(command):
    result = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_python_quickstart(tmp_path):
    output = tmp_path / "l_block.vtu"
    stdout = run([sys.executable, str(SOURCE_DIR / "examples" / "python" / "quickstart.py"), str(output)])
    assert stdout.startswith("valid: ") and "alpha 90.0 deg" in stdout
    mesh = meshio.read(output)
    tetrahedra = mesh.cells_dict["tetra"]
    assert len(tetrahedra) > 0
    # The same L-block as data/3d/l_block.poly: the mesh read back is valid for it.
    report = pqmesh.check(pqmesh.TetMesh(mesh.points, tetrahedra), pqmesh.read_domain(str(DATA / "3d" / "l_block.poly")))
    assert report.valid, report.text


def test_cpp_mesh_cube(tmp_path):
    output = tmp_path / "cube.vtu"
    stdout = run([os.environ["PQMESH_EXAMPLE_MESH_CUBE"], str(output)])
    assert stdout.startswith("valid: ")
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(output))
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfCells() > 0
    assert set(vtk_to_numpy(grid.GetCellTypesArray()).tolist()) == {VTK_TETRA}
    points = vtk_to_numpy(grid.GetPoints().GetData())
    tetrahedra = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)
    report = pqmesh.check(pqmesh.TetMesh(points, tetrahedra), pqmesh.read_domain(str(DATA / "3d" / "cube.poly")))
    assert report.valid, report.text
    assert np.isclose(report.mesh_volume, 1.0)
