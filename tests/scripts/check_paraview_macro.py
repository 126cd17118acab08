"""Runs a deck that deletes elements and opens it with the shipped ParaView macro (scripts/paraview/radx_open.py)
under `xvfb-run -a pvpython`, as a user would, and checks what ParaView shows of the last state.

usage: /usr/bin/python3 check_paraview_macro.py --radx RADX --deck NAME_0000.rad --out DIR
           --macro scripts/paraview/radx_open.py --part TITLE [--shots DIR]

Expected values come from the deck and the state files (h5py), not from ParaView:
  * the colour bar's title is "von_mises (U)", U the stress unit of the deck's /BEGIN work units (this script's
    own table of the usual systems), and the `units` attribute of the state's von_mises dataset is U too;
  * the colour range is the range of von_mises over the cells not deleted (element_status 1) of the last state,
    to float32 rounding (relative 1e-6: the values are float32, ParaView compares them as doubles);
  * the parts ParaView lists, in order, are the deck's /PART ids and titles;
  * deleted elements are hidden: the shell part's extracted surface (what ParaView draws) has as many cells as
    its shells not deleted, and that is fewer than its cells (the deck deletes some);
  * the screenshots are not blank: over 5 % of the pixels differ from the background, with over 20 colours
    (a colour map), and the one with the part picked by title differs from the one with all parts.
Screenshots are left in --shots (default: DIR). Exit 0 on success, 1 with FAIL lines, 77 (CTest's skip code)
with a note when pvpython or xvfb-run is missing.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys

SKIP = 77

# Stress unit of the consistent work-unit systems of crash decks (mass, length, time -> stress), and the
# composed label of io/listing/unit_labels for the others.
STRESS_UNITS = {("kg", "m", "s"): "Pa", ("Mg", "mm", "s"): "MPa", ("kg", "mm", "ms"): "GPa",
                ("g", "mm", "ms"): "MPa"}


def deck_units(starter):
    """(mass, length, time) names of the deck's /BEGIN (its third data line: input units, then work units)."""
    lines = [l.rstrip("\n") for l in open(starter, encoding="utf-8", errors="replace")]
    k = next(i for i, l in enumerate(lines) if l.startswith("/BEGIN"))
    data = [l for l in lines[k + 1:] if not l.startswith("#")]
    work = data[3].split()  # runname, version, input units, work units
    return tuple(work[:3])


def deck_parts(starter):
    lines = [l.rstrip("\n") for l in open(starter, encoding="utf-8", errors="replace")]
    parts = []
    for i, l in enumerate(lines):
        m = re.match(r"/PART/(\d+)\s*$", l)
        if m:
            parts.append((int(m.group(1)), lines[i + 1].strip()))
    return parts


# ---------------------------------------------------------------------------------------------------------
# Inside ParaView (pvpython under xvfb-run): open with the macro, take screenshots, report what it shows.

def inside_paraview(args):
    sys.path.insert(0, os.path.dirname(os.path.abspath(args.macro)))
    import numpy as np
    import radx_open
    from paraview import simple as pv
    from paraview import servermanager
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader

    def image_facts(path):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        img = reader.GetOutput()
        pixels = vtk_to_numpy(img.GetPointData().GetScalars())[:, :3].astype(int)
        background = np.round(np.array(view_background) * 255).astype(int)
        differs = np.any(np.abs(pixels - background) > 8, axis=1)
        step = int(differs.sum()) // 20000 or 1  # a sample of the drawn pixels is enough to count colours
        colours = len({tuple(p) for p in pixels[differs][::step]})
        return {"fraction": float(differs.mean()), "colours": colours, "pixels": pixels}

    run = radx_open.open_run(args.series)
    view_background = list(run.view.Background)
    rgb = list(run.lut.RGBPoints)
    report = {
        "field": run.field,
        "bar_title": run.bar.Title,
        "range": [rgb[0], rgb[-4]],
        "units": run.units,
        "parts": [[i, t] for i, t in run.parts],
        "part_items": list(run.part_sources),
    }
    surface = {}
    for title, source in run.part_sources.items():
        s = pv.ExtractSurface(Input=source)
        s.UpdatePipeline(pv.GetAnimationScene().AnimationTime)
        surface[title] = servermanager.Fetch(s).GetNumberOfCells()
        pv.Delete(s)
    report["surface_cells"] = surface
    all_png = os.path.join(args.shots, "macro_all_parts.png")
    radx_open.save_screenshot(run, all_png)
    shown = radx_open.show_only_parts(run, [args.part])
    rgb_part = list(run.lut.RGBPoints)
    report["shown_after_pick"] = shown
    report["range_after_pick"] = [rgb_part[0], rgb_part[-4]]
    part_png = os.path.join(args.shots, "macro_part_%s.png" % re.sub(r"\W+", "_", args.part))
    radx_open.save_screenshot(run, part_png)
    a, b = image_facts(all_png), image_facts(part_png)
    report["images"] = {all_png: {"fraction": a["fraction"], "colours": a["colours"]},
                        part_png: {"fraction": b["fraction"], "colours": b["colours"]}}
    report["images_differ"] = float(np.mean(np.any(a["pixels"] != b["pixels"], axis=1)))
    print("RESULT " + json.dumps(report))
    # ParaView 5.11 under Xvfb can fail in its OpenGL teardown at exit (GLXBadContext) after all is done: leave
    # without it, the report is written.
    sys.stdout.flush()
    os._exit(0)


# ---------------------------------------------------------------------------------------------------------
# Outside: run the deck, read the expected values with h5py, start ParaView, compare.

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx")
    ap.add_argument("--deck")
    ap.add_argument("--out")
    ap.add_argument("--macro", required=True)
    ap.add_argument("--part", required=True, help="title of a shell part that loses elements")
    ap.add_argument("--shots")
    ap.add_argument("--inside-paraview", action="store_true")
    ap.add_argument("--series")
    args = ap.parse_args()
    if args.inside_paraview:
        return inside_paraview(args)

    missing = [tool for tool in ("pvpython", "xvfb-run") if shutil.which(tool) is None]
    if missing:
        print("SKIP: %s not found; the macro test needs ParaView's pvpython and xvfb-run "
              "(scripts/deps.sh installs python3-paraview, xvfb and xauth)" % " and ".join(missing))
        return SKIP

    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import h5py
    import numpy as np
    import results_common as rc

    failures = []

    def check(ok, text):
        if not ok:
            failures.append(text)

    base = rc.run_radx(args.radx, args.deck, args.out)
    series = os.path.join(args.out, base + ".hdf.series")
    last = rc.listed_states(args.out, base)[-1][0]
    with h5py.File(os.path.join(args.out, last), "r") as f:
        vm = f["/VTKHDF/CellData/von_mises"]
        vm_unit = vm.attrs["units"]
        vm = vm[()]
        status = f["/VTKHDF/CellData/element_status"][()]
        part_id = f["/VTKHDF/CellData/part_id"][()]
        types = f["/VTKHDF/Types"][()]
    vm_unit = vm_unit.decode() if isinstance(vm_unit, bytes) else str(vm_unit)
    stress_unit = STRESS_UNITS.get(deck_units(args.deck), "?")
    check(vm_unit == stress_unit, f"von_mises carries the unit {vm_unit!r}, the deck's stress unit is {stress_unit!r}")
    parts = deck_parts(args.deck)
    title_to_id = {t: i for i, t in parts}
    check(args.part in title_to_id, f"--part {args.part!r} is not a /PART title of the deck ({parts})")
    active = status == 1
    want_range = [float(vm[active].min()), float(vm[active].max())]

    shots = args.shots or args.out
    os.makedirs(shots, exist_ok=True)
    # xvfb-run -a takes the first free display number; two started at once (parallel tests) can pick the same
    # one, and the loser's ParaView finds no X server: start it again then, on another number.
    for attempt in range(3):
        run = subprocess.run(["xvfb-run", "-a", "pvpython", os.path.abspath(__file__), "--inside-paraview",
                              "--macro", args.macro, "--series", series, "--part", args.part, "--shots", shots],
                             capture_output=True, text=True, timeout=600)
        if "bad X server connection" not in run.stdout + run.stderr:
            break
        print(f"xvfb-run attempt {attempt + 1}: ParaView found no X server; starting it again")
    line = next((l for l in run.stdout.splitlines() if l.startswith("RESULT ")), None)
    if run.returncode != 0 or line is None:
        print("FAIL: pvpython with the macro failed (exit %d):\n%s\n%s"
              % (run.returncode, run.stdout[-3000:], run.stderr[-3000:]))
        return 1
    got = json.loads(line[len("RESULT "):])
    print("ParaView shows:", json.dumps({k: v for k, v in got.items() if k != "units"}, indent=1))

    check(got["field"] == "von_mises", f"coloured by {got['field']}, expected von_mises")
    check(got["bar_title"] == f"von_mises ({stress_unit})",
          f"colour bar titled {got['bar_title']!r}, expected 'von_mises ({stress_unit})'")
    check(got["units"].get("von_mises") == stress_unit, f"field data units {got['units']}")
    for k in range(2):
        check(abs(got["range"][k] - want_range[k]) <= 1e-6 * max(abs(want_range[1]), 1e-30),
              f"colour range {got['range']}, von_mises of the cells not deleted spans {want_range}")
    check([tuple(p) for p in got["parts"]] == parts, f"parts {got['parts']}, the deck has {parts}")
    check(got["shown_after_pick"] == [args.part], f"picking {args.part!r} shows {got['shown_after_pick']}")
    # The picked part's cells: its shells not deleted are what ParaView draws.
    pid = title_to_id.get(args.part)
    in_part = part_id == pid
    shells = in_part & np.isin(types, [5, 9])
    deleted = int(np.sum(in_part & ~active))
    check(deleted > 0, f"part {args.part!r} has no deleted element in the last state: the deck does not test hiding")
    check(bool(np.all(shells == in_part)), f"part {args.part!r} is not made of shells only")
    drawn = got["surface_cells"].get(args.part)
    check(drawn == int(np.sum(in_part & active)),
          f"ParaView draws {drawn} cells of part {args.part!r}: it has {int(in_part.sum())} cells, {deleted} deleted")
    part_range = [float(vm[in_part & active].min()), float(vm[in_part & active].max())]
    for k in range(2):
        check(abs(got["range_after_pick"][k] - part_range[k]) <= 1e-6 * max(abs(part_range[1]), 1e-30),
              f"colour range after picking {got['range_after_pick']}, the part's von_mises spans {part_range}")
    for path, facts in got["images"].items():
        check(facts["fraction"] > 0.05 and facts["colours"] > 20,
              f"{path} looks blank: {facts['fraction']:.1%} of pixels not background, {facts['colours']} colours")
    check(got["images_differ"] > 0.01, f"picking a part changed {got['images_differ']:.2%} of the pixels")

    for f in failures:
        print("FAIL:", f)
    if not failures:
        print(f"ok: {base}: von_mises [{stress_unit}] over {want_range}, part {args.part!r} drawn with "
              f"{drawn} of {int(in_part.sum())} cells ({deleted} deleted hidden), screenshots in {shots}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
