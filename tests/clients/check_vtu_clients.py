#!/usr/bin/python3
"""The .vtu files of real `pqmesh mesh` runs on the data/ corpus, read by
meshio (Debian python3-meshio 5) and VTK (python3-vtk9,
vtkXMLUnstructuredGridReader), and .vtu files written by meshio and VTK in
all their modes, read by pqmesh.

usage: check_vtu_clients.py PQMESH_EXE READ_EXE DATA_DIR
  READ_EXE is pqmesh_write_samples (its --read prints what pqmesh reads).
Fails (exit 1), never skips, when meshio, numpy or vtk is missing.

1. For every corpus input: `pqmesh mesh IN -o raw.vtu`, `... --compress -o
   zlib.vtu` and `pqmesh convert raw.vtu ascii.vtu --ascii`. Each file must be
   read by meshio and by VTK with identical points, connectivity, cell types
   and cell data (names, types and values, bit for bit), with the counts and
   element markers pqmesh reads back, and the three files must hold the same
   arrays (except that the ASCII file has no all-zero marker array: pqmesh
   reads such an array as "no markers", so convert does not write it).
2. The raw.vtu of two corpus meshes (one 2D, one 3D) re-written by meshio
   (ASCII; binary uncompressed, zlib, LZMA; UInt32 and UInt64 headers) and by
   VTK (ascii, inline binary, appended raw and base64; no compressor, zlib,
   LZ4, LZMA; UInt32 and UInt64 headers): pqmesh reads each with the counts
   and markers of the original.
"""
import os
import subprocess
import sys
import tempfile

from client_checks import check, exit_code

try:
    import meshio
    import numpy as np
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError as error:
    print(f"FAIL: cannot import meshio/numpy/vtk with {sys.executable}: {error}")
    sys.exit(1)

# (input relative to DATA_DIR, dimension): small inputs, each meshed in a few seconds.
CORPUS = [("2d/" + name, 2) for name in ("comb.poly", "l_shape.poly", "regions.poly", "spike_1deg.poly",
                                          "spike_5deg.poly", "spike_10deg.poly", "square.poly", "square_holes.poly")]
CORPUS += [("3d/" + name, 3) for name in ("cube.poly", "l_block.poly", "schoenhardt.poly", "box_with_hole.stl",
                                          "channel_patches.poly")]
REWRITTEN = ("2d/regions.poly", "3d/l_block.poly")


def run(args):
    result = subprocess.run(args, capture_output=True, text=True, timeout=120)
    if not check(result.returncode == 0, f"{' '.join(args)} exited {result.returncode}: {result.stderr.strip()}"):
        return None
    return result.stdout


def pqmesh_read(read_exe, path, dim):
    """(vertices, elements, boundary items) and element markers as pqmesh reads them."""
    out = run([read_exe, "--read", path, str(dim)])
    if out is None:
        return None
    lines = out.split("\n")
    counts = [int(x) for x in lines[0].split()]
    markers = [int(x) for x in lines[1].split()] if len(lines) > 1 else []
    return counts, markers


def read_meshio(path):
    """Arrays as meshio gives them: points, cells (type, connectivity), cell data."""
    mesh = meshio.read(path)
    check(len(mesh.cells) == 1, f"meshio: {path} has {len(mesh.cells)} cell blocks, expected 1")
    block = mesh.cells[0]
    data = {name: np.asarray(arrays[0]) for name, arrays in mesh.cell_data.items()}
    return dict(points=np.asarray(mesh.points), cell_type=block.type, connectivity=np.asarray(block.data),
                cell_data=data)


class VtkErrors:
    """Collects VTK error events (VTK reports errors by event, not by exception)."""

    def __init__(self, obj):
        self.messages = []
        obj.AddObserver("ErrorEvent", lambda caller, event: self.messages.append(event))


def read_vtk(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    errors = VtkErrors(reader)
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if not check(not errors.messages and grid is not None and grid.GetPoints() is not None,
                 f"vtk: cannot read {path}: {errors.messages}"):
        return None
    cells = grid.GetCells()
    types = vtk_to_numpy(grid.GetCellTypesArray())
    nodes = {5: 3, 10: 4}.get(int(types[0]), 0) if len(types) else 0
    connectivity = vtk_to_numpy(cells.GetConnectivityArray())
    check(len(set(types.tolist())) == 1 and nodes > 0, f"vtk: {path} has cell types {sorted(set(types.tolist()))}")
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    check(bool(np.all(np.diff(offsets) == nodes)), f"vtk: {path} has cells of varying size")
    cd = grid.GetCellData()
    data = {cd.GetArrayName(i): vtk_to_numpy(cd.GetArray(i)) for i in range(cd.GetNumberOfArrays())}
    return dict(points=vtk_to_numpy(grid.GetPoints().GetData()), cell_type={3: "triangle", 4: "tetra"}.get(nodes),
                connectivity=connectivity.reshape(-1, nodes) if nodes else connectivity, cell_data=data)


def same_arrays(label, a, b):
    """a and b (from read_meshio/read_vtk) hold identical arrays."""
    ok = check(a["cell_type"] == b["cell_type"], f"{label}: cell type {a['cell_type']} vs {b['cell_type']}")
    ok &= check(a["points"].shape == b["points"].shape and np.array_equal(a["points"], b["points"]),
                f"{label}: points differ ({a['points'].shape} vs {b['points'].shape})")
    ok &= check(a["connectivity"].shape == b["connectivity"].shape
                and np.array_equal(a["connectivity"], b["connectivity"]), f"{label}: connectivity differs")
    ok &= check(sorted(a["cell_data"]) == sorted(b["cell_data"]),
                f"{label}: cell data {sorted(a['cell_data'])} vs {sorted(b['cell_data'])}")
    for name in set(a["cell_data"]) & set(b["cell_data"]):
        x, y = a["cell_data"][name], b["cell_data"][name]
        ok &= check(x.dtype == y.dtype and x.shape == y.shape and np.array_equal(x, y),
                    f"{label}: cell data '{name}' differs ({x.dtype}{x.shape} vs {y.dtype}{y.shape})")
    return ok


def check_written(label, path, dim, read_exe, reference=None):
    """meshio and VTK read path identically, with pqmesh's counts and markers;
    returns the meshio arrays (compared with reference when given)."""
    try:
        ours = read_meshio(path)
    except Exception as error:  # noqa: BLE001 - any reader failure is a failure
        check(False, f"{label}: meshio cannot read {path}: {error}")
        return None
    theirs = read_vtk(path)
    if theirs is not None:
        same_arrays(f"{label} (meshio vs vtk)", ours, theirs)
    if reference is not None:
        same_arrays(f"{label} (vs the raw file)", reference, ours)
    got = pqmesh_read(read_exe, path, dim)
    if got is None:
        return ours
    (nv, nc, _), markers = got
    expected_type = "triangle" if dim == 2 else "tetra"
    check(ours["cell_type"] == expected_type, f"{label}: cells are {ours['cell_type']}, expected {expected_type}")
    check(len(ours["points"]) == nv and len(ours["connectivity"]) == nc,
          f"{label}: meshio reads {len(ours['points'])} points, {len(ours['connectivity'])} cells; "
          f"pqmesh reads {nv}, {nc}")
    check(nc > 0, f"{label}: no elements")
    marker = ours["cell_data"].get("marker")
    want = markers if markers else [0] * nc  # pqmesh drops an all-zero marker array
    got_markers = [0] * nc if marker is None else marker.astype(int).tolist()
    check(got_markers == want, f"{label}: meshio's markers differ from pqmesh's")
    fields = sorted(ours["cell_data"])
    check(any(name != "marker" for name in fields), f"{label}: no quality fields in the cell data ({fields})")
    return ours


def check_corpus(pqmesh, read_exe, data, tmp):
    for rel, dim in CORPUS:
        stem = os.path.join(tmp, rel.replace("/", "_"))
        source = os.path.join(data, rel)
        raw, zlib_file, ascii_file = stem + ".vtu", stem + "_zlib.vtu", stem + "_ascii.vtu"
        if run([pqmesh, "mesh", source, "-o", raw, "--quiet"]) is None:
            continue
        reference = check_written(rel, raw, dim, read_exe)
        if run([pqmesh, "mesh", source, "-o", zlib_file, "--compress", "--quiet"]) is not None:
            with open(zlib_file, "rb") as f:
                check(b'compressor="vtkZLibDataCompressor"' in f.read(2000), f"{zlib_file} is not compressed")
            check_written(rel + " --compress", zlib_file, dim, read_exe, reference)
            # Below a few KiB the zlib headers can outweigh what compression
            # saves (a 2-triangle square: 1079 bytes raw, 1241 compressed).
            if os.path.getsize(raw) >= 4096:
                check(os.path.getsize(zlib_file) < os.path.getsize(raw), f"{rel}: --compress did not shrink the file")
        if run([pqmesh, "convert", raw, ascii_file, "--ascii"]) is not None and reference is not None:
            # pqmesh reads an all-zero marker array as "no markers", so convert does not write it.
            converted = dict(reference, cell_data=dict(reference["cell_data"]))
            marker = converted["cell_data"].get("marker")
            if marker is not None and not marker.any():
                del converted["cell_data"]["marker"]
            check_written(rel + " ascii", ascii_file, dim, read_exe, converted)
        print(f"ok: {rel} ({os.path.getsize(raw)} bytes raw, {os.path.getsize(zlib_file)} zlib)")


def vtk_writers(grid, stem):
    """grid written by vtkXMLUnstructuredGridWriter in every mode: (label, path)."""
    modes = [("ascii", "None", 64), ("binary", "None", 32), ("binary", "ZLib", 64), ("binary", "LZ4", 32),
             ("binary", "LZMA", 64), ("appended", "None", 32), ("appended", "None", 64), ("appended", "ZLib", 32),
             ("appended", "LZ4", 64), ("appended", "LZMA", 32), ("appended64", "ZLib", 64),
             ("appended64", "None", 32), ("appended64", "LZMA", 64)]
    for mode, compressor, header in modes:
        path = f"{stem}_vtk_{mode}_{compressor}_{header}.vtu"
        writer = vtk.vtkXMLUnstructuredGridWriter()
        errors = VtkErrors(writer)
        writer.SetFileName(path)
        writer.SetInputData(grid)
        {"ascii": writer.SetDataModeToAscii, "binary": writer.SetDataModeToBinary}.get(
            mode, writer.SetDataModeToAppended)()
        writer.SetEncodeAppendedData(mode == "appended64")
        getattr(writer, f"SetCompressorTypeTo{compressor}")()
        writer.SetHeaderType(writer.UInt32 if header == 32 else writer.UInt64)
        if check(writer.Write() == 1 and not errors.messages, f"vtk cannot write {path}: {errors.messages}"):
            yield f"vtk {mode} {compressor} UInt{header}", path


def meshio_writers(mesh, stem):
    modes = [("ascii", dict(binary=False)), ("raw", dict(binary=True, compression=None)),
             ("zlib", dict(binary=True, compression="zlib")), ("lzma", dict(binary=True, compression="lzma")),
             ("raw64", dict(binary=True, compression=None, header_type="UInt64")),
             ("zlib64", dict(binary=True, compression="zlib", header_type="UInt64"))]
    for label, kwargs in modes:
        path = f"{stem}_meshio_{label}.vtu"
        try:
            meshio.write(path, mesh, **kwargs)
        except Exception as error:  # noqa: BLE001
            check(False, f"meshio cannot write {path} ({kwargs}): {error}")
            continue
        yield f"meshio {label}", path


def check_rewritten(read_exe, tmp):
    for rel in REWRITTEN:
        dim = 2 if rel.startswith("2d/") else 3
        raw = os.path.join(tmp, rel.replace("/", "_") + ".vtu")
        original = pqmesh_read(read_exe, raw, dim) if os.path.exists(raw) else None
        if not check(original is not None, f"{raw} (of part 1) is missing"):
            continue
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(raw)
        reader.Update()
        stem = raw[:-4]
        outputs = list(vtk_writers(reader.GetOutput(), stem)) + list(meshio_writers(meshio.read(raw), stem))
        for label, path in outputs:
            got = pqmesh_read(read_exe, path, dim)
            if got is not None:
                check(got == original, f"{rel} via {label}: pqmesh reads {got[0]}, expected {original[0]}"
                      f"{'' if got[1] == original[1] else ' (markers differ)'}")
        print(f"ok: {rel} re-written in {len(outputs)} modes")


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 1
    pqmesh, read_exe, data = sys.argv[1:]
    print("meshio", meshio.__version__, "vtk", vtk.vtkVersion.GetVTKVersion())
    with tempfile.TemporaryDirectory() as tmp:
        check_corpus(pqmesh, read_exe, data, tmp)
        check_rewritten(read_exe, tmp)
    return exit_code(".vtu client")


if __name__ == "__main__":
    sys.exit(main())
