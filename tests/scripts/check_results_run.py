"""Runs a deck through radx (starter, then engine) and checks its animation states as a user would see them.

usage: /usr/bin/python3 check_results_run.py --radx RADX --deck NAME_0000.rad --out DIR
           --paraview-check check_results_paraview.py

docs/theory/results-format.md: the states are written at the first cycle whose time reaches each /ANIM/DT time
(Tstart, Tstart + dT, ... up to Tstop and the end time), plus the first and the last cycle. This script derives
those due times from the engine deck itself (its own small reader of /RUN and /ANIM/DT), the arrays from the
/ANIM names (its own table of Radioss names, written from docs/theory/results-format.md), and the cell count and VTK
types from the model file (h5py); then checks:
  * the number of states and that state k's time t_k lies in [due_k, due_k + dt_max), dt_max the largest time
    step of the run (a state is written on the first cycle at or after its due time);
  * every state carries the same arrays, and they are the expected ones;
  * the index files list exactly the state files, in order, with their times (17 significant digits: exact);
  * no .part or .tmp file is left;
  * then opens the .hdf.series and the .xmf with pvpython (check_results_paraview.py): states, times, array
    names, cell count, cell types, and the last displacement seen by ParaView equals the file's (h5py).
The last state's displacement must also equal x_last - x0 of the summary's final state: checked as
displacement = Points - mesh Points to float32 rounding (relative 1e-6 of the largest coordinate).
"""
import argparse
import glob
import os
import re
import sys

import h5py
import numpy as np

import results_common as rc

ANIM_ARRAYS = {  # Radioss /ANIM name -> radx array (docs/theory/results-format.md section 3)
    ("ELEM", "VONM"): "von_mises", ("ELEM", "EPSP"): "plastic_strain", ("ELEM", "THIC"): "thickness",
    ("ELEM", "ENER"): "internal_energy_density", ("ELEM", "P"): "pressure", ("ELEM", "DENS"): "density",
    ("ELEM", "HOUR"): "hourglass_energy_density", ("VECT", "VEL"): "velocity", ("VECT", "DISP"): "displacement",
    ("VECT", "ACC"): "acceleration", ("VECT", "CONT"): "contact_force", ("VECT", "FINT"): "internal_force",
    ("VECT", "FEXT"): "external_force", ("VECT", "FREAC"): "reaction_force", ("TENS", "STRESS"): "stress",
    ("NODA", "DMAS"): "added_mass", ("NODA", "DT"): "nodal_time_step",
}
ALWAYS_POINT = {"displacement", "velocity", "node_id"}
ALWAYS_CELL = {"element_status", "part_id", "element_id", "vtkGhostType"}
# Beside von_mises and stress when the model has shells (docs/results.md section 7).
SHELL_LAYERS = {"von_mises": {"von_mises_bottom", "von_mises_middle", "von_mises_top"},
                "stress": {"stress_bottom", "stress_middle", "stress_top"}}


def fail(msg):
    rc.check(False, msg)


def engine_controls(path):
    """t_stop, (Tstart, dT, Tstop) and the /ANIM names of an engine deck (free-format data lines)."""
    lines = [l.rstrip("\n") for l in open(path) if not l.startswith("#")]
    t_stop, anim, names = None, (0.0, 0.0, 1e20), []
    for i, l in enumerate(lines):
        if l.startswith("/RUN/"):
            t_stop = float(lines[i + 1].split()[0])
        elif l.startswith("/ANIM/DT"):
            v = [float(x) for x in lines[i + 1].split()]
            anim = (v[0], v[1], v[2] if len(v) > 2 and v[2] > 0 else 1e20)
        else:
            m = re.match(r"/ANIM/(ELEM|VECT|TENS|NODA)/(\w+)", l)
            if m:
                names.append((m.group(1), m.group(2).upper()))
    return t_stop, anim, names


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--paraview-check", required=True)
    a = ap.parse_args()

    base = rc.run_radx(a.radx, a.deck, a.out)
    engine_deck = a.deck.replace("_0000.rad", "_0001.rad")
    t_stop, (t0, dT, t1), names = engine_controls(engine_deck)
    summary = rc.read_summary(a.out, base)
    if summary["status"] != "normal":
        sys.exit("the run did not end normally: " + summary["message"])

    # Due times: the first cycle (t = 0), Tstart + k dT up to min(Tstop, t_stop), the last cycle.
    due = [0.0]
    if dT > 0:
        k = 0
        while t0 + k * dT <= min(t1, t_stop) * (1 + 1e-12):
            t = t0 + k * dT
            if t > due[-1]:
                due.append(t)
            k += 1
    if summary["time"] > due[-1] * (1 + 1e-12):
        due.append(summary["time"])
    states = sorted(glob.glob(os.path.join(a.out, base + "_[0-9][0-9][0-9][0-9][0-9][0-9].hdf")))
    if len(states) != len(due):
        fail("%d state files, expected %d (due times %s)" % (len(states), len(due), due))
    # Largest step of the run: from the listing lines' dt column would need parsing; the summary's last dt
    # times 1.1^k bounds it loosely, so use the spacing of the state times instead: a state is late by less
    # than one cycle, and a cycle is shorter than t_stop / cycles * 10 on these decks.
    dt_max = 10.0 * summary["time"] / max(1, summary["cycles"])
    times, arrays = [], None
    for k, f in enumerate(states):
        with h5py.File(f, "r") as h:
            t = float(h["/VTKHDF/FieldData/TimeValue"][0])
            times.append(t)
            pa = set(h["/VTKHDF/PointData"].keys())
            ca = set(h["/VTKHDF/CellData"].keys())
            if arrays is None:
                arrays = (pa, ca)
            elif (pa, ca) != arrays:
                fail("%s carries arrays %s, the first state %s" % (f, (pa, ca), arrays))
        if k < len(due) and not (due[k] * (1 - 1e-12) <= t < due[k] + dt_max):
            fail("state %d at time %.17g, due at %.17g (late by at most one cycle, < %.3g)" % (k, t, due[k], dt_max))
    expected = {ANIM_ARRAYS[n] for n in names}
    with h5py.File(os.path.join(a.out, base + "_0000.hdf"), "r") as m:
        ncells = int(m["/VTKHDF/NumberOfCells"][0])
        types = sorted(set(int(x) for x in m["/VTKHDF/Types"][()]))
        x0 = m["/VTKHDF/Points"][()]
    point_arrays = {n for n in expected if n in {"velocity", "displacement", "acceleration", "contact_force",
                                                  "internal_force", "external_force", "reaction_force",
                                                  "added_mass", "nodal_time_step"}} | ALWAYS_POINT
    cell_arrays = (expected - point_arrays) | ALWAYS_CELL
    if any(t in (5, 9) for t in types):  # shells: their layers, and the stress at each point
        for name, layers in SHELL_LAYERS.items():
            if name in cell_arrays:
                cell_arrays |= layers
        if "stress" in cell_arrays and arrays:
            points = sorted(int(n[len("stress_point_"):]) for n in arrays[1] if re.fullmatch(r"stress_point_\d+", n))
            if points != list(range(1, len(points) + 1)):
                fail("shell point stresses %s, expected stress_point_1 .. stress_point_N" % points)
            cell_arrays |= {"stress_point_%d" % k for k in points}
    if arrays and (arrays[0] != point_arrays or arrays[1] != cell_arrays):
        fail("arrays %s, expected point %s cell %s" % (arrays, sorted(point_arrays), sorted(cell_arrays)))

    listed = rc.listed_states(a.out, base)
    if listed != [(os.path.basename(f), t) for f, t in zip(states, times)]:
        fail("the series lists %s, the files are %s" % (listed, list(zip(map(os.path.basename, states), times))))
    stray = glob.glob(os.path.join(a.out, "*.part")) + glob.glob(os.path.join(a.out, "*.tmp"))
    if stray:
        fail("temporary files left: %s" % stray)
    with h5py.File(states[-1], "r") as h:
        disp = h["/VTKHDF/PointData/displacement"][()].astype(np.float64)
        pts = h["/VTKHDF/Points"][()]
    tol = 1e-6 * max(1.0, float(np.max(np.abs(pts))))
    if np.max(np.abs(disp - (pts - x0))) > tol:
        fail("last displacement differs from Points - initial points by %.3g" % np.max(np.abs(disp - (pts - x0))))

    pv = rc.paraview_check(a.paraview_check, "--series", os.path.join(a.out, base + ".hdf.series"),
                           "--xmf", os.path.join(a.out, base + ".xmf"), "--expect-states", str(len(states)),
                           "--expect-cells", str(ncells),
                           "--expect-arrays", ",".join(sorted((point_arrays | cell_arrays) - {"node_id"})),
                           "--expect-times", ",".join("%.17g" % t for t in times),
                           "--expect-cell-types", ",".join(map(str, types)),
                           "--last-displacement-from", states[-1])
    print(pv.stdout)
    if pv.returncode != 0:
        fail("ParaView check failed:\n" + pv.stdout[-3000:] + pv.stderr[-2000:])
    rc.finish("%d states at %s, arrays %s, %d cells" % (len(states), times, sorted(point_arrays | cell_arrays), ncells))


if __name__ == "__main__":
    main()
