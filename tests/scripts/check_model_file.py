#!/usr/bin/python3
"""Checks the VTKHDF 1.0 mesh layout of a radx HDF5 file (model file NAME_0000.hdf or results mesh
P.mesh.hdf) against docs/theory/results-format.md section 2, independently of the C++ writer.

usage: /usr/bin/python3 check_model_file.py FILE.hdf --nodes N --cells C [--types 9:100,12:8]

Checks: /VTKHDF @Version int64[2] = {1, 0}; @Type a scalar fixed-length ASCII string of exactly 16
bytes, NULLPAD, "UnstructuredGrid" without NUL; dataset types and shapes; NumberOfPoints = N,
NumberOfCells = C; Offsets starting at 0, monotone, ending at NumberOfConnectivityIds; node count of
each cell matching its VTK type; connectivity in [0, N); the type counts given by --types (the exact
histogram: a type not listed must not occur); PointData/node_id, CellData/part_id, CellData/element_id;
/XDMF/MixedTopology holding the same cells in XDMF Mixed encoding; HDF5 superblock version below 3
(library-version bounds not raised, no SWMR). Prints what it found. Exit 0 on success, 1 on failure
(each failure printed as "FAIL: ..."), 2 on usage errors.

Needs h5py and numpy: run with /usr/bin/python3 (Debian python3-h5py, python3-numpy).
"""
import argparse
import sys

import h5py
import numpy as np

# VTK cell type -> (name, node count or None when variable, XDMF Mixed code, XDMF needs a node count)
VTK_TYPES = {
    1: ("vertex", 1, 1, True),
    3: ("line", 2, 2, True),
    5: ("triangle", 3, 4, False),
    9: ("quad", 4, 5, False),
    10: ("tetra", 4, 6, False),
    12: ("hexahedron", 8, 9, False),
    13: ("wedge", 6, 8, False),
    25: ("quadratic hexahedron", 20, 48, False),
}


class Checker:
    def __init__(self):
        self.failures = []

    def fail(self, message):
        self.failures.append(message)
        print(f"FAIL: {message}")

    def expect(self, condition, message):
        if not condition:
            self.fail(message)
        return condition


def parse_types(text):
    counts = {}
    for item in text.split(","):
        item = item.strip()
        if not item:
            continue
        try:
            vtk_type, count = item.split(":")
            counts[int(vtk_type)] = int(count)
        except ValueError:
            raise argparse.ArgumentTypeError(f"bad --types item '{item}': expected TYPE:COUNT, e.g. 9:100")
    return counts


def dataset(c, group, name, dtype, shape=None, ndim=None):
    """Returns the dataset's data as a numpy array, or None (after a failure) when wrong."""
    path = f"{group.name.rstrip('/')}/{name}"
    if name not in group:
        c.fail(f"{path} is missing")
        return None
    obj = group[name]
    if not isinstance(obj, h5py.Dataset):
        c.fail(f"{path} is not a dataset")
        return None
    ok = c.expect(obj.dtype == np.dtype(dtype), f"{path} has type {obj.dtype}, expected {np.dtype(dtype)}")
    if shape is not None:
        ok &= c.expect(obj.shape == shape, f"{path} has shape {obj.shape}, expected {shape}")
    if ndim is not None:
        ok &= c.expect(obj.ndim == ndim, f"{path} has {obj.ndim} dimensions, expected {ndim}")
    return obj[()] if ok else None


def check_attributes(c, vtk):
    # Version: int64[2] = {1, 0}
    if c.expect("Version" in vtk.attrs, "/VTKHDF has no Version attribute"):
        version = vtk.attrs["Version"]
        aid = h5py.h5a.open(vtk.id, b"Version")
        atype = aid.get_type()
        c.expect(atype.get_class() == h5py.h5t.INTEGER and atype.get_size() == 8 and atype.get_sign() == 1,
                 "/VTKHDF@Version is not a signed 64-bit integer")
        c.expect(np.shape(version) == (2,) and list(version) == [1, 0],
                 f"/VTKHDF@Version is {version!r}, expected [1 0]")
        print(f"  @Version  {list(np.atleast_1d(version))} ({atype.get_size() * 8}-bit integer)")
    # Type: scalar fixed-length string of exactly 16 bytes, NULLPAD, no NUL
    if c.expect("Type" in vtk.attrs, "/VTKHDF has no Type attribute"):
        aid = h5py.h5a.open(vtk.id, b"Type")
        atype = aid.get_type()
        space = aid.get_space()
        is_string = atype.get_class() == h5py.h5t.STRING
        c.expect(is_string, "/VTKHDF@Type is not a string")
        if is_string:
            variable = atype.is_variable_str()
            c.expect(not variable, "/VTKHDF@Type is a variable-length string: the VTKHDF reader needs a "
                     "fixed-length one ('Unknown data set type')")
            size = atype.get_size()
            pad = atype.get_strpad()
            if not variable:
                c.expect(size == 16, f"/VTKHDF@Type is {size} bytes, expected exactly 16 (no terminating NUL)")
                c.expect(pad == h5py.h5t.STR_NULLPAD, f"/VTKHDF@Type padding is {pad}, expected NULLPAD "
                         f"({h5py.h5t.STR_NULLPAD})")
            c.expect(space.get_simple_extent_type() == h5py.h5s.SCALAR, "/VTKHDF@Type is not scalar")
            raw = vtk.attrs["Type"]
            raw = raw if isinstance(raw, bytes) else str(raw).encode()
            c.expect(b"\0" not in raw and raw == b"UnstructuredGrid",
                     f"/VTKHDF@Type is {raw!r}, expected b'UnstructuredGrid'")
            print(f"  @Type     {raw!r} ({'variable' if variable else size}-byte string, "
                  f"{'NULLPAD' if pad == h5py.h5t.STR_NULLPAD else 'pad ' + str(pad)}, "
                  f"{'scalar' if space.get_simple_extent_type() == h5py.h5s.SCALAR else 'not scalar'})")


def check_mixed(c, f, conn, offsets, types):
    if not c.expect("XDMF" in f and "MixedTopology" in f["XDMF"], "/XDMF/MixedTopology is missing"):
        return
    mixed = dataset(c, f["XDMF"], "MixedTopology", np.int64, ndim=1)
    if mixed is None:
        return
    nc = types.size
    lut_code = np.zeros(256, dtype=np.int64)
    lut_header = np.ones(256, dtype=np.int64)
    for vtk_type, (_, _, code, counted) in VTK_TYPES.items():
        lut_code[vtk_type] = code
        lut_header[vtk_type] = 2 if counted else 1
    header = lut_header[types]
    expected_len = int(header.sum()) + conn.size
    if not c.expect(mixed.size == expected_len,
                    f"/XDMF/MixedTopology has {mixed.size} values, expected {expected_len} "
                    f"(cells {nc} type codes + {conn.size} node ids + node counts of lines/vertices)"):
        return
    counts = np.diff(offsets)
    cum_header = np.cumsum(header)  # headers up to and including cell i
    start = offsets[:-1] + cum_header - header  # position of cell i's type code
    bad = np.nonzero(mixed[start] != lut_code[types])[0]
    c.expect(bad.size == 0, f"/XDMF/MixedTopology: {bad.size} cells with a wrong type code"
             + (f", first cell {bad[0]}: {mixed[start[bad[0]]]} for VTK type {types[bad[0]]}" if bad.size else ""))
    counted = header == 2
    if counted.any():
        c.expect(np.array_equal(mixed[start[counted] + 1], counts[counted]),
                 "/XDMF/MixedTopology: wrong node count after a line or vertex code")
    cell_of = np.repeat(np.arange(nc, dtype=np.int64), counts)
    positions = np.arange(conn.size, dtype=np.int64) + cum_header[cell_of]
    bad_nodes = np.nonzero(mixed[positions] != conn)[0]
    c.expect(bad_nodes.size == 0, f"/XDMF/MixedTopology: {bad_nodes.size} node ids differ from "
             "/VTKHDF/Connectivity" + (f", first in cell {cell_of[bad_nodes[0]]}" if bad_nodes.size else ""))
    print(f"  /XDMF/MixedTopology     int64[{mixed.size}], same cells as Connectivity: "
          f"{'yes' if bad.size == 0 and bad_nodes.size == 0 else 'no'}")


def check(path, nodes, cells, type_counts):
    c = Checker()
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        c.fail(f"cannot open {path}: {e}")
        return c
    with f:
        print(f"{path}")
        superblock = f.id.get_create_plist().get_version()[0]
        c.expect(superblock < 3, f"HDF5 superblock version {superblock}: library-version bounds were raised "
                 "(or SWMR used); docs/theory/results-format.md section 2 forbids it")
        print(f"  HDF5 superblock version {superblock}")
        for name in ("radx_model_format_version", "radx_version"):
            if name in f.attrs:
                print(f"  @{name} = {f.attrs[name]!r}")
        if not c.expect("VTKHDF" in f and isinstance(f["VTKHDF"], h5py.Group), "/VTKHDF group is missing"):
            return c
        vtk = f["VTKHDF"]
        check_attributes(c, vtk)

        scalars = {}
        for name in ("NumberOfPoints", "NumberOfCells", "NumberOfConnectivityIds"):
            value = dataset(c, vtk, name, np.int64, shape=(1,))
            scalars[name] = int(value[0]) if value is not None else None
            print(f"  {name:24s}{scalars[name]}")
        np_, nc, nconn = scalars["NumberOfPoints"], scalars["NumberOfCells"], scalars["NumberOfConnectivityIds"]
        c.expect(np_ == nodes, f"NumberOfPoints is {np_}, expected {nodes}")
        c.expect(nc == cells, f"NumberOfCells is {nc}, expected {cells}")
        if None in (np_, nc, nconn):
            return c

        points = dataset(c, vtk, "Points", np.float64, shape=(np_, 3))
        if points is not None and np_ > 0:
            c.expect(np.isfinite(points).all(), "/VTKHDF/Points has non-finite coordinates")
            print(f"  Points                  float64[{np_},3], bounding box {points.min(axis=0)} .. "
                  f"{points.max(axis=0)}")
        conn = dataset(c, vtk, "Connectivity", np.int64, shape=(nconn,))
        offsets = dataset(c, vtk, "Offsets", np.int64, shape=(nc + 1,))
        types = dataset(c, vtk, "Types", np.uint8, shape=(nc,))

        if conn is not None and conn.size:
            lo, hi = int(conn.min()), int(conn.max())
            c.expect(lo >= 0 and hi < np_, f"/VTKHDF/Connectivity values in [{lo}, {hi}], expected 0-based "
                     f"in [0, {np_ - 1}]")
            print(f"  Connectivity            int64[{nconn}], values in [{lo}, {hi}]")
        structure_ok = conn is not None and offsets is not None and types is not None
        if offsets is not None:
            counts = np.diff(offsets)
            monotone = bool((counts >= 0).all())
            structure_ok &= bool(offsets[0] == 0 and monotone and offsets[-1] == nconn)
            c.expect(offsets[0] == 0, f"/VTKHDF/Offsets[0] is {offsets[0]}, expected 0")
            c.expect(monotone, "/VTKHDF/Offsets is not monotone")
            c.expect(offsets[-1] == nconn, f"/VTKHDF/Offsets ends at {offsets[-1]}, expected "
                     f"NumberOfConnectivityIds = {nconn}")
            print(f"  Offsets                 int64[{nc + 1}], 0 .. {offsets[-1]}, monotone: {monotone}")
        if types is not None:
            found = {int(t): int(n) for t, n in zip(*np.unique(types, return_counts=True))}
            names = ", ".join(f"{t} {VTK_TYPES.get(t, ('unknown',))[0]}: {n}" for t, n in sorted(found.items()))
            print(f"  Types                   uint8[{nc}]: {names or 'no cells'}")
            unknown = sorted(set(found) - set(VTK_TYPES))
            c.expect(not unknown, f"/VTKHDF/Types has unknown VTK cell types {unknown}")
            structure_ok &= not unknown
            if type_counts is not None:
                wanted = {t: n for t, n in type_counts.items() if n}
                c.expect(found == wanted, f"/VTKHDF/Types counts {dict(sorted(found.items()))}, expected "
                         f"{dict(sorted(wanted.items()))}")
            if structure_ok:
                lut = np.zeros(256, dtype=np.int64)
                for t, (_, npts, _, _) in VTK_TYPES.items():
                    lut[t] = npts
                fixed = ~np.isin(types, [1, 3])  # vertex and line cells may be poly-cells
                bad = np.nonzero(fixed & (np.diff(offsets) != lut[types]))[0]
                c.expect(bad.size == 0, f"{bad.size} cells whose node count does not match their VTK type"
                         + (f", first cell {bad[0]} (type {types[bad[0]]}, {np.diff(offsets)[bad[0]]} nodes)"
                            if bad.size else ""))

        node_id = dataset(c, vtk["PointData"], "node_id", np.int64, shape=(np_,)) \
            if c.expect("PointData" in vtk, "/VTKHDF/PointData is missing") else None
        if node_id is not None and np_ > 0:
            c.expect(np.unique(node_id).size == np_, "/VTKHDF/PointData/node_id has repeated ids")
            print(f"  PointData/node_id       int64[{np_}], ids {node_id.min()} .. {node_id.max()}")
        if c.expect("CellData" in vtk, "/VTKHDF/CellData is missing"):
            part_id = dataset(c, vtk["CellData"], "part_id", np.int64, shape=(nc,))
            element_id = dataset(c, vtk["CellData"], "element_id", np.int64, shape=(nc,))
            if part_id is not None and nc > 0:
                print(f"  CellData/part_id        int64[{nc}], parts {sorted(set(part_id.tolist()))[:20]}")
            if element_id is not None and nc > 0:
                print(f"  CellData/element_id     int64[{nc}], ids {element_id.min()} .. {element_id.max()}")

        if structure_ok:
            check_mixed(c, f, conn, offsets, types)
        else:
            print("  /XDMF/MixedTopology not checked: Connectivity, Offsets or Types are invalid")
    return c


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("file")
    parser.add_argument("--nodes", type=int, required=True, help="expected NumberOfPoints")
    parser.add_argument("--cells", type=int, required=True, help="expected NumberOfCells")
    parser.add_argument("--types", type=parse_types, default=None,
                        help="expected count per VTK cell type, e.g. 9:100,5:2,12:8 (exact histogram)")
    args = parser.parse_args()
    c = check(args.file, args.nodes, args.cells, args.types)
    if c.failures:
        print(f"{args.file}: {len(c.failures)} failure(s)")
        return 1
    print(f"{args.file}: VTKHDF layout OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
