"""Opens a radx result set in ParaView (pvpython) through both indexes and checks what ParaView sees.

usage: pvpython check_results_paraview.py --series P.hdf.series --xmf P.xmf --expect-states N
           --expect-cells NC --expect-arrays a,b,c [--expect-times t0,t1,...] [--expect-cell-types 9,12]
           [--last-displacement-from P_00000K.hdf] [--xdmf-readers XDMFReader,Xdmf3ReaderS]

docs/theory/results-format.md sections 4 and 6. The .hdf.series is opened with OpenDataFile (ParaView's file series
over its VTKHDF reader); the .xmf with each XDMF reader named (default: the XDMF 2 reader and the Xdmf3
reader). For every reader: the number of states, the times (relative 1e-12), the point and cell array
names (every expected name present), the cell count and the VTK cell types of the last state, and, with
--last-displacement-from, the number of components of every array of that state file and its
PointData/displacement fetched through ParaView, compared with the same file read independently by h5py
in /usr/bin/python3 (Debian python3-h5py): exact equality, since both read the same float32 values. Run with QT_QPA_PLATFORM=offscreen; judge by the exit code
(ParaView 5.11 prints HDF5 diagnostics on stderr on some paths). Exit 0 on success, 1 with FAIL lines.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np
from paraview import servermanager
from paraview.simple import Delete, ForceTime, OpenDataFile, XDMFReader, Xdmf3ReaderS, Xdmf3ReaderT
from vtkmodules.util.numpy_support import vtk_to_numpy

# Run by /usr/bin/python3: saves the state file's displacement and writes, per line, "point|cell name k"
# for every array of the file (external links followed), k its number of components.
H5PY_READ = """
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    d = f["/VTKHDF/PointData/displacement"]
    if d.dtype != np.float32:
        sys.exit(f"{sys.argv[1]}:/VTKHDF/PointData/displacement is {d.dtype}, expected float32")
    np.save(sys.argv[2], d[()])
    with open(sys.argv[3], "w") as out:
        for center, group in (("point", "PointData"), ("cell", "CellData")):
            for name, ds in f["/VTKHDF/" + group].items():
                unit = ds.attrs.get("units", b"-")
                unit = unit.decode() if isinstance(unit, bytes) else str(unit)
                out.write(f"{center}\\t{name}\\t{ds.shape[1] if len(ds.shape) > 1 else 1}\\t{unit}\\n")
        ids = f["/VTKHDF/FieldData/part_ids"]
        for i, t in zip(ids[()], ids.attrs["titles"]):
            out.write(f"part\\t{i}\\t{t.decode() if isinstance(t, bytes) else t}\\n")
"""


def parse_list(text, kind):
    return [kind(x) for x in text.split(",") if x.strip()] if text else None


def timesteps(reader):
    t = reader.TimestepValues
    if t is None:
        return []
    return [float(x) for x in t] if not isinstance(t, (float, int)) else [float(t)]


def leaves(data):
    """The datasets of a (possibly composite) data object."""
    if data is None:
        return []
    if data.IsA("vtkCompositeDataSet"):
        out = []
        it = data.NewIterator()
        it.InitTraversal()
        while not it.IsDoneWithTraversal():
            out.append(it.GetCurrentDataObject())
            it.GoToNextItem()
        return out
    return [data]


def read_state_h5py(path):
    """PointData/displacement of a state file and {(center, name): components} of its arrays, read by h5py
    outside ParaView's own HDF5 library."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "displacement.npy")
        listing = os.path.join(tmp, "arrays.txt")
        run = subprocess.run(["/usr/bin/python3", "-c", H5PY_READ, path, out, listing], capture_output=True,
                             text=True)
        if run.returncode != 0:
            raise RuntimeError(f"h5py could not read {path}: {run.stderr.strip() or run.stdout.strip()}")
        components, units, parts = {}, {}, []
        for line in open(listing, encoding="utf-8"):
            fields = line.rstrip("\n").split("\t")
            if fields[0] == "part":
                parts.append((int(fields[1]), fields[2]))
                continue
            center, name, k, unit = fields
            components[(center, name)] = int(k)
            units[name] = unit
        return np.load(out), components, units, parts


def text_lines(field_data, name):
    """Lines of a text field-data array (UTF-8 bytes stored as uint8)."""
    array = field_data.GetArray(name)
    if array is None:
        return None
    return bytes(int(array.GetValue(i)) for i in range(array.GetNumberOfValues())).decode("utf-8").splitlines()


def check_reader(label, reader, args, expected, failures, vtkhdf=False):
    fail_count = len(failures)

    def fail(text):
        failures.append(f"{label}: {text}")

    reader.UpdatePipelineInformation()
    times = timesteps(reader)
    if len(times) != args.expect_states:
        fail(f"{len(times)} states, expected {args.expect_states}")
    if any(b <= a for a, b in zip(times, times[1:])):
        fail(f"times not strictly increasing: {times}")
    if args.expect_times is not None:
        if len(times) != len(args.expect_times):
            fail(f"times {times}, expected {args.expect_times}")
        else:
            for got, want in zip(times, args.expect_times):
                if abs(got - want) > 1e-12 * max(abs(want), abs(got), 1e-300):
                    fail(f"time {got!r} differs from the expected {want!r} (relative tolerance 1e-12)")
    if not times:
        return
    last = times[-1]
    reader.UpdatePipeline(last)
    info = reader.GetDataInformation()
    point_names = sorted(reader.PointData.keys())
    cell_names = sorted(reader.CellData.keys())
    missing = [a for a in args.expect_arrays if a not in point_names and a not in cell_names]
    if missing:
        fail(f"arrays {missing} missing (point arrays {point_names}, cell arrays {cell_names})")
    if expected is not None:  # every array of the state file, with its number of components
        seen = {("point", a.Name): a.GetNumberOfComponents() for a in reader.PointData}
        seen.update({("cell", a.Name): a.GetNumberOfComponents() for a in reader.CellData})
        for key, k in sorted(expected[1].items()):
            if seen.get(key) != k:
                fail(f"{key[0]} array {key[1]} has {seen.get(key)} components in ParaView, {k} in the state file")
    if info.GetNumberOfCells() != args.expect_cells:
        fail(f"{info.GetNumberOfCells()} cells, expected {args.expect_cells}")

    # The data of the last state itself: ForceTime pins the time, so the fetch cannot fall back to state 0.
    pinned = ForceTime(Input=reader, ForcedTime=last, IgnorePipelineTime=1)
    data = leaves(servermanager.Fetch(pinned))
    Delete(pinned)
    cell_types = set()
    displacement = []
    for block in data:
        if block.IsA("vtkUnstructuredGrid") and block.GetCellTypesArray() is not None:
            cell_types.update(int(t) for t in np.unique(vtk_to_numpy(block.GetCellTypesArray())))
        else:
            cell_types.update(block.GetCellType(i) for i in range(block.GetNumberOfCells()))
        array = block.GetPointData().GetArray("displacement")
        if array is not None:
            displacement.append(vtk_to_numpy(array))
        # The units and the parts as the state's field data (the VTKHDF reader; the XDMF index has none).
        if expected is not None and vtkhdf:
            units = text_lines(block.GetFieldData(), "units")
            if units is None:
                fail("no field data 'units'")
            else:
                listed = dict(l.split("\t", 1) for l in units)
                for name, unit in sorted(expected[2].items()):
                    if listed.get(name) != unit:
                        fail(f"field data units give {name} [{listed.get(name)}], its dataset's attribute [{unit}]")
            titles = text_lines(block.GetFieldData(), "part_titles")
            ids = block.GetFieldData().GetArray("part_ids")
            seen = [] if ids is None or titles is None else \
                list(zip((int(ids.GetValue(i)) for i in range(ids.GetNumberOfValues())), titles))
            if seen != expected[3]:
                fail(f"field data parts {seen}, the mesh file's {expected[3]}")
    if args.expect_cell_types is not None and cell_types != set(args.expect_cell_types):
        fail(f"VTK cell types {sorted(cell_types)}, expected {sorted(args.expect_cell_types)}")
    if expected is not None:
        expected_displacement = expected[0]
        if len(displacement) != 1:
            fail(f"displacement found in {len(displacement)} blocks of the last state, expected 1")
        else:
            got = displacement[0]
            want = expected_displacement.reshape(got.shape) if got.size == expected_displacement.size else None
            if want is None:
                fail(f"displacement has shape {got.shape}, the state file {expected_displacement.shape}")
            elif got.dtype != np.float32:
                fail(f"displacement arrives as {got.dtype}, expected float32")
            elif not np.array_equal(got, want):
                bad = int(np.argmax(np.any(got != want, axis=-1) if got.ndim > 1 else got != want))
                fail(f"last state displacement differs from {args.last_displacement_from}: "
                     f"first at point {bad}: {got[bad]} != {want[bad]}")
    state = "ok" if len(failures) == fail_count else "FAILED"
    print(f"{label}: {state}: {len(times)} states {times[0]!r}..{last!r}, {info.GetNumberOfCells()} cells, "
          f"cell types {sorted(cell_types)}, point arrays {point_names}, cell arrays {cell_names}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--series", help="the .hdf.series index (checked when given)")
    parser.add_argument("--xmf", help="the .xmf index (checked when given)")
    parser.add_argument("--expect-states", type=int, required=True)
    parser.add_argument("--expect-cells", type=int, required=True)
    parser.add_argument("--expect-arrays", required=True, help="comma-separated point and cell array names")
    parser.add_argument("--expect-times", help="comma-separated state times")
    parser.add_argument("--expect-cell-types", help="comma-separated VTK cell types, e.g. 9,12")
    parser.add_argument("--last-displacement-from", help="state file whose displacement the last state has")
    parser.add_argument("--xdmf-readers", default="XDMFReader,Xdmf3ReaderS")
    args = parser.parse_args()
    args.expect_arrays = parse_list(args.expect_arrays, str)
    args.expect_times = parse_list(args.expect_times, float)
    args.expect_cell_types = parse_list(args.expect_cell_types, int)

    failures = []
    if not args.series and not args.xmf:
        failures.append("give --series, --xmf or both")
    for path in (p for p in (args.series, args.xmf) if p):
        if not os.path.isfile(path):
            failures.append(f"{path} does not exist")
    expected = None
    if args.last_displacement_from:
        try:
            expected = read_state_h5py(args.last_displacement_from)
        except RuntimeError as e:
            failures.append(str(e))
    if failures:
        for f in failures:
            print("FAIL:", f)
        return 1

    series = OpenDataFile(args.series) if args.series else None
    if not args.series:
        pass
    elif series is None:
        failures.append(f"ParaView found no reader for {args.series}")
    else:
        check_reader(f"{os.path.basename(args.series)} ({type(series).__name__})", series, args, expected,
                     failures, vtkhdf=True)
        Delete(series)
    makers = {
        "XDMFReader": lambda p: XDMFReader(FileNames=[p]),
        "Xdmf3ReaderS": lambda p: Xdmf3ReaderS(FileName=[p]),
        "Xdmf3ReaderT": lambda p: Xdmf3ReaderT(FileName=[p]),
    }
    for name in (parse_list(args.xdmf_readers, str) or []) if args.xmf else []:
        if name not in makers:
            failures.append(f"unknown XDMF reader {name} (one of {sorted(makers)})")
            continue
        reader = makers[name](args.xmf)
        check_reader(f"{os.path.basename(args.xmf)} ({name})", reader, args, expected, failures)
        Delete(reader)

    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
