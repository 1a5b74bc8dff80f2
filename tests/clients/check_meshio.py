#!/usr/bin/python3
"""Reads the files of pqmesh_write_samples with meshio (Debian python3-meshio)
and checks point counts, cell counts per type, markers and orientation; then
lets meshio write files that pqmesh must read back.

usage: check_meshio.py SAMPLES_DIR WRITE_SAMPLES_EXE
Fails (exit 1) when meshio is missing: this test never skips.

Expected values come from tests/unit/io_mesh/sample_meshes.hpp:
  square: 4 vertices, triangles (0,1,2) (0,2,3) with markers 7, -2, edges
          (0,1) (1,2) (2,3) (3,0) with markers 1..4, vertex markers 1 0 3 -4;
          Gmsh physical tags: 7 -> 7, -2 -> 7 + 1 + 2 = 10.
  cube:   8 vertices, 6 tetrahedra with markers 1 2 3 0 -5 2, 12 boundary
          triangles with side markers 1..6 (two each), vertex markers i % 3;
          Gmsh physical tags: 1, 2, 3, 0 -> 3 + 1 = 4, -5 -> 3 + 1 + 5 = 9.
  quality field: element index + 0.5; quality32: the same values as Float32.
"""
import os
import subprocess
import sys
import tempfile

from client_checks import check, exit_code

try:
    import meshio
    import numpy as np
except ImportError as error:  # the project's install script installs python3-meshio
    print(f"FAIL: cannot import meshio/numpy with {sys.executable}: {error}")
    sys.exit(1)

SQUARE = dict(points=4, cell="triangle", cells=2, face="line", faces=4,
              cell_markers=[7, -2], face_markers=[1, 2, 3, 4], vertex_markers=[1, 0, 3, -4],
              physical={7: 7, -2: 10})
CUBE = dict(points=8, cell="tetra", cells=6, face="triangle", faces=12,
            cell_markers=[1, 2, 3, 0, -5, 2], face_markers=sorted([1, 2, 3, 4, 5, 6] * 2),
            vertex_markers=[i % 3 for i in range(8)],
            physical={1: 1, 2: 2, 3: 3, 0: 4, -5: 9})


def cells_of(mesh, cell_type):
    """Concatenated connectivity and per-block indices of one cell type."""
    blocks = [i for i, block in enumerate(mesh.cells) if block.type == cell_type]
    if not blocks:
        return np.zeros((0, 0), dtype=int), blocks
    return np.concatenate([mesh.cells[i].data for i in blocks]), blocks


def data_of(mesh, key, blocks):
    if key not in mesh.cell_data:
        return None
    return np.concatenate([np.asarray(mesh.cell_data[key][i]) for i in blocks]).astype(int).tolist()


def check_orientation(name, mesh, spec):
    cells, _ = cells_of(mesh, spec["cell"])
    p = mesh.points
    if spec["cell"] == "triangle":
        a, b, c = p[cells[:, 0]], p[cells[:, 1]], p[cells[:, 2]]
        area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
        check(bool(np.all(area > 0)), f"{name}: a triangle is not counter-clockwise")
    else:
        a, b, c, d = (p[cells[:, k]] for k in range(4))
        volume = np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a))
        check(bool(np.all(volume > 0)), f"{name}: a tetrahedron has non-positive volume")


def check_file(name, path, spec, marker_key, face_marker_key=None, has_faces=True, vertex_key=None,
               physical=False, field=None):
    try:
        mesh = meshio.read(path)
    except Exception as error:  # noqa: BLE001 - report any reader failure
        check(False, f"{name}: meshio cannot read {path}: {error}")
        return
    check(len(mesh.points) == spec["points"], f"{name}: {len(mesh.points)} points, expected {spec['points']}")
    cells, cell_blocks = cells_of(mesh, spec["cell"])
    check(len(cells) == spec["cells"], f"{name}: {len(cells)} {spec['cell']} cells, expected {spec['cells']}")
    faces, face_blocks = cells_of(mesh, spec["face"])
    expected_faces = spec["faces"] if has_faces else 0
    check(len(faces) == expected_faces, f"{name}: {len(faces)} {spec['face']} cells, expected {expected_faces}")
    expected_cell_markers = spec["cell_markers"]
    expected_face_markers = spec["face_markers"]
    if physical:
        expected_cell_markers = [spec["physical"][m] for m in expected_cell_markers]
        expected_face_markers = list(expected_face_markers)  # positive: tag = marker
    if marker_key:
        got = data_of(mesh, marker_key, cell_blocks)
        # Gmsh 4.1 groups elements by entity, so compare as multisets there.
        ok = got is not None and (sorted(got) == sorted(expected_cell_markers) if physical
                                  else got == expected_cell_markers)
        check(ok, f"{name}: element markers {got}, expected {expected_cell_markers}")
    if has_faces and face_marker_key:
        got = data_of(mesh, face_marker_key, face_blocks)
        check(got is not None and sorted(got) == sorted(expected_face_markers),
              f"{name}: boundary markers {got}, expected {sorted(expected_face_markers)}")
    if vertex_key:
        got = mesh.point_data.get(vertex_key)
        got = None if got is None else np.asarray(got).astype(int).tolist()
        check(got == spec["vertex_markers"], f"{name}: vertex markers {got}, expected {spec['vertex_markers']}")
    if field:
        got = data_of_float = None
        if field in mesh.cell_data:
            data_of_float = np.concatenate([np.asarray(mesh.cell_data[field][i]) for i in cell_blocks])
            got = sorted(data_of_float.tolist())
        check(got == [i + 0.5 for i in range(spec["cells"])], f"{name}: field {field} = {got}")
    if physical:
        names = {str(key): value for key, value in mesh.field_data.items()}
        for marker, tag in spec["physical"].items():
            entry = names.get(f"marker {marker}")
            check(entry is not None and int(entry[0]) == tag,
                  f"{name}: physical name 'marker {marker}' -> {entry}, expected tag {tag}")
    check_orientation(name, mesh, spec)


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 1
    samples, exe = sys.argv[1], sys.argv[2]
    print("meshio", meshio.__version__)
    for stem, spec in (("square", SQUARE), ("cube", CUBE)):
        path = lambda ext: os.path.join(samples, stem + ext)  # noqa: E731
        for ext in (".vtu", "_zlib.vtu", "_ascii.vtu"):
            for field in ("quality", "quality32"):  # Float64 and Float32 (single_precision) cell data
                check_file(stem + ext, path(ext), spec, "marker", has_faces=False, vertex_key="vertex_marker",
                           field=field)
        for ext in (".msh", "_41b.msh", "_22.msh"):
            check_file(stem + ext, path(ext), spec, "gmsh:physical", "gmsh:physical", vertex_key="vertex_marker",
                       physical=True)
        check_file(stem + ".mesh", path(".mesh"), spec, "medit:ref", "medit:ref", vertex_key="medit:ref")
        if stem == "cube":  # meshio's TetGen reader is 3D only and reads .node/.ele
            check_file(stem + ".node", path(".node"), spec, "tetgen:ref", has_faces=False, vertex_key="tetgen:ref")

    # The other direction: files written by meshio, read by pqmesh.
    with tempfile.TemporaryDirectory() as tmp:
        for stem, spec, dim in (("square", SQUARE, "2"), ("cube", CUBE, "3")):
            mesh = meshio.read(os.path.join(samples, stem + ".mesh"))
            # (meshio 5 cannot write MSH 4.1 with two cell types without
            # gmsh:dim_tags, so only 2.2 here; gmsh itself writes 4.1 in
            # check_gmsh.sh.)
            outputs = [("vtu", {"binary": True}), ("vtu", {"binary": False}),
                       ("msh", {"file_format": "gmsh22", "binary": False}), ("mesh", {})]
            for k, (ext, kwargs) in enumerate(outputs):
                target = os.path.join(tmp, f"{stem}{k}.{ext}")
                try:
                    if ext == "vtu" and kwargs.get("binary"):
                        meshio.write(target, mesh, compression=None, binary=True)
                    else:
                        meshio.write(target, mesh, **kwargs)
                except Exception as error:  # noqa: BLE001
                    check(False, f"meshio cannot write {target}: {error}")
                    continue
                run = subprocess.run([exe, "--read", target, dim], capture_output=True, text=True, timeout=60)
                check(run.returncode == 0, f"pqmesh cannot read meshio's {target} ({kwargs}): {run.stderr.strip()}")
                if run.returncode != 0:
                    continue
                counts = [int(x) for x in run.stdout.split("\n")[0].split()]
                expected_faces = spec["faces"]
                check(counts[0] == spec["points"] and counts[1] == spec["cells"] and counts[2] == expected_faces,
                      f"pqmesh read {counts} from meshio's {target} ({kwargs}), expected "
                      f"{[spec['points'], spec['cells'], expected_faces]}")
    return exit_code("meshio")


if __name__ == "__main__":
    sys.exit(main())
