"""Opens a radx run in ParaView with the usual views (docs/results.md section 2).

  * the deformed shape (the states' points are the current coordinates) coloured by von Mises, with a colour
    bar titled with the array's unit (read from the states' field data `units`);
  * one pipeline item per part, named by its title, so that a part is shown, hidden or picked by name
    (a Threshold on the cell array part_id; the titles come from the field data `part_titles`);
  * the energy plot of NAME_energy.csv (kinetic, internal, hourglass, contact, external work, total) in a
    line chart beside it.
Deleted elements are hidden by VTK's ghost-cell flag (cell array vtkGhostType), whatever is shown.

In the ParaView GUI: Macros > Import new macro... (this file, once); then open NAME.hdf.series, select it in the
pipeline browser and click radx_open in the Macros menu (or start ParaView with RADX_RUN=path/NAME.hdf.series
in the environment and run the macro).
From pvpython or the Python shell:

    import radx_open
    run = radx_open.open_run("path/NAME.hdf.series")   # or "path/NAME", the result prefix
    radx_open.show_only_parts(run, ["Plate"])           # parts by title
    radx_open.save_screenshot(run, "shot.png")

Command line (pvpython under xvfb-run -a where there is no display; Debian's pvpython crashes with
--force-offscreen-rendering):

    pvpython radx_open.py NAME.hdf.series [--part TITLE]... [--field von_mises] [--screenshot out.png]
"""
import argparse
import os
import sys

from paraview import servermanager
from paraview import simple as pv

FIELD_DATA_SCRIPT = """
out = self.GetOutputDataObject(0)
out.GetFieldData().ShallowCopy(self.GetInputDataObject(0, 0).GetFieldData())
"""


class Run:
    """What open_run set up: the reader, the views and displays, the units and the parts."""

    def __init__(self):
        self.series = None  # path of NAME.hdf.series
        self.prefix = None  # path/NAME
        self.reader = None
        self.view = None
        self.chart = None
        self.layout = None
        self.field = None  # the array the shape is coloured by
        self.units = {}  # array name -> unit label
        self.parts = []  # (id, title) in the model's order
        self.part_sources = {}  # title -> Threshold of that part
        self.displays = {}  # source -> its display in the render view
        self.lut = None
        self.bar = None
        self.energy = None


def series_path(path):
    """NAME.hdf.series from NAME.hdf.series, NAME (the result prefix) or a state file NAME_000012.hdf."""
    if path.endswith(".hdf.series"):
        return path
    base = path[:-4] if path.endswith(".hdf") else path
    if os.path.isfile(base + ".hdf.series"):
        return base + ".hdf.series"
    head, _, tail = base.rpartition("_")
    if tail.isdigit() and os.path.isfile(head + ".hdf.series"):
        return head + ".hdf.series"
    raise FileNotFoundError(f"no {base}.hdf.series: give NAME.hdf.series or its prefix NAME")


def text_lines(field_data, name):
    """The lines of a text field-data array (UTF-8 bytes as uint8: ParaView 5.11's VTKHDF reader reads no
    string arrays)."""
    array = field_data.GetArray(name)
    if array is None:
        return []
    raw = bytes(int(array.GetValue(i)) for i in range(array.GetNumberOfValues()))
    return raw.decode("utf-8").splitlines()


def field_data(source):
    """The field data of `source`'s current output, fetched without its points and cells."""
    extract = pv.ProgrammableFilter(Input=source, OutputDataSetType="vtkTable", Script=FIELD_DATA_SCRIPT)
    data = servermanager.Fetch(extract)
    pv.Delete(extract)
    return data.GetFieldData()


def title_of(name, unit):
    # Parentheses: ParaView 5.11 draws square brackets of a colour bar or chart title as parentheses anyway.
    return f"{name} ({unit})" if unit and unit != "1" else name


def color_by(run, field, displays=None):
    """Colours the shown displays by the cell or point array `field`, the colour bar titled with its unit, the
    range that of the field over what they show at the current time (deleted elements, hidden, are left
    out: ParaView's data information skips ghost cells)."""
    run.field = field
    centre = "CELLS" if field in run.reader.CellData.keys() else "POINTS"
    shown = displays or [d for d in run.displays.values() if d.Visibility]
    for display in shown:
        pv.ColorBy(display, (centre, field))
    run.lut = pv.GetColorTransferFunction(field)
    low, high = float("inf"), float("-inf")
    sources = [s for s, d in run.displays.items() if d in shown]
    for source in sources:
        source.UpdatePipeline(pv.GetAnimationScene().AnimationTime)
        info = source.CellData if centre == "CELLS" else source.PointData
        if field in info.keys():
            component = -1 if info[field].GetNumberOfComponents() > 1 else 0
            r = info[field].GetRange(component)
            if r[0] <= r[1]:
                low, high = min(low, r[0]), max(high, r[1])
    if low <= high:
        run.lut.RescaleTransferFunction(low, high)
        pv.GetOpacityTransferFunction(field).RescaleTransferFunction(low, high)
        run.lut.AutomaticRescaleRangeMode = "Never"  # keep the range when a part is shown or hidden
    run.bar = pv.GetScalarBar(run.lut, run.view)
    run.bar.Title = title_of(field, run.units.get(field))
    run.bar.ComponentTitle = ""
    run.bar.Visibility = 1
    return run.lut


def show_only_parts(run, titles):
    """Shows the parts of the given titles (case-insensitive) and hides the others; [] shows all."""
    wanted = {t.strip().lower() for t in titles}
    unknown = wanted - {t.lower() for t in run.part_sources}
    if unknown:
        known = ", ".join(repr(t) for t in run.part_sources)
        raise KeyError(f"no part titled {sorted(unknown)} in {run.series}; the parts are {known}")
    for title, source in run.part_sources.items():
        shown = not wanted or title.lower() in wanted
        display = run.displays[source]
        display.Visibility = 1 if shown else 0
    if run.field:
        color_by(run, run.field)
    return [t for t in run.part_sources if not wanted or t.lower() in wanted]


def part_threshold(reader, part_id):
    threshold = pv.Threshold(Input=reader)
    threshold.Scalars = ["CELLS", "part_id"]
    threshold.LowerThreshold = part_id
    threshold.UpperThreshold = part_id
    if hasattr(threshold, "ThresholdMethod"):  # ParaView >= 5.10
        threshold.ThresholdMethod = "Between"
    return threshold


def open_energy(run, layout):
    csv = run.prefix + "_energy.csv"
    if not os.path.isfile(csv):
        return None
    reader = pv.CSVReader(registrationName=os.path.basename(csv), FileName=[csv])
    reader.UpdatePipeline()
    chart = pv.CreateView("XYChartView")
    layout.AssignView(2, chart)
    display = pv.Show(reader, chart)
    display.UseIndexForXAxis = 0
    with open(csv, encoding="utf-8") as f:
        names = f.readline().strip().split(",")
    time_column = next((n for n in names if n.startswith("time")), None)
    if time_column:
        display.XArrayName = time_column
        display.SeriesVisibility = [n for n in names if n != time_column]  # the series shown
    energy_unit = next((n[n.index("[") + 1:-1] for n in names if "[" in n and not n.startswith("time")), "")
    chart.LeftAxisTitle = title_of("energy", energy_unit)
    chart.BottomAxisTitle = time_column or "time"
    chart.ChartTitle = "energies"
    run.chart = chart
    run.energy = reader
    return reader


def open_run(path, field="von_mises", parts=True, max_part_items=200, energy=True, time=None):
    """Opens the run of `path` (NAME.hdf.series or its prefix NAME); returns a Run. The last state is shown
    unless `time` is given."""
    run = Run()
    run.series = series_path(os.path.abspath(path))
    run.prefix = run.series[: -len(".hdf.series")]
    name = os.path.basename(run.prefix)
    run.reader = pv.OpenDataFile(run.series)
    if run.reader is None:
        raise RuntimeError(f"ParaView found no reader for {run.series}")
    pv.RenameSource(name, run.reader)
    run.reader.UpdatePipelineInformation()
    times = list(run.reader.TimestepValues) if run.reader.TimestepValues else [0.0]
    scene = pv.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = times[-1] if time is None else time
    run.reader.UpdatePipeline(scene.AnimationTime)

    data = field_data(run.reader)
    run.units = dict(line.split("\t", 1) for line in text_lines(data, "units") if "\t" in line)
    ids = data.GetArray("part_ids")
    titles = text_lines(data, "part_titles")
    if ids is not None:
        run.parts = [(int(ids.GetValue(i)), titles[i] if i < len(titles) else str(ids.GetValue(i)))
                     for i in range(ids.GetNumberOfValues())]

    run.layout = pv.CreateLayout(name)  # a new tab in the GUI
    run.view = pv.CreateView("RenderView")
    if energy and os.path.isfile(run.prefix + "_energy.csv"):
        run.layout.SplitHorizontal(0, 0.62)
        run.layout.AssignView(1, run.view)
    else:
        run.layout.AssignView(0, run.view)
    pv.SetActiveView(run.view)
    if parts and 0 < len(run.parts) <= max_part_items:
        used = set()
        for part_id, title in run.parts:
            label = title if title and title.lower() not in used else f"{title} ({part_id})"
            used.add(label.lower())
            source = part_threshold(run.reader, part_id)
            pv.RenameSource(label, source)
            run.part_sources[label] = source
            run.displays[source] = pv.Show(source, run.view)
        pv.Hide(run.reader, run.view)
    else:
        run.displays[run.reader] = pv.Show(run.reader, run.view)
    arrays = list(run.reader.CellData.keys()) + list(run.reader.PointData.keys())
    chosen = field if field in arrays else "displacement"
    color_by(run, chosen)
    if energy:
        open_energy(run, run.layout)
    pv.SetActiveView(run.view)
    pv.SetActiveSource(run.reader)
    camera = run.view.GetActiveCamera()  # a three-quarter view: shells seen in plan show their bending too
    camera.Elevation(25)
    camera.Azimuth(30)
    run.view.ResetCamera()
    pv.Render(run.view)
    return run


def save_screenshot(run, path, resolution=(1200, 700)):
    """Saves the render view (with the energy chart beside it when there is one) to `path`."""
    pv.Render(run.view)
    if run.chart is not None:
        pv.SaveScreenshot(path, run.layout, ImageResolution=list(resolution))
    else:
        pv.SaveScreenshot(path, run.view, ImageResolution=list(resolution))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run", help="NAME.hdf.series, or the result prefix NAME")
    ap.add_argument("--field", default="von_mises", help="array to colour by (default von_mises)")
    ap.add_argument("--part", action="append", default=[], help="show only the part of this title (repeat)")
    ap.add_argument("--screenshot", help="save the views to this PNG")
    args = ap.parse_args(argv)
    run = open_run(args.run, field=args.field)
    if args.part:
        show_only_parts(run, args.part)
    if args.screenshot:
        save_screenshot(run, args.screenshot)
    print(f"{run.series}: coloured by {run.field} [{run.units.get(run.field, '?')}], parts "
          + ", ".join(f"{t} ({i})" for i, t in run.parts))
    return run


def run_as_gui_macro():
    """ParaView's Macros menu runs this file with no arguments: open the run of RADX_RUN, or of the file the
    active pipeline item reads (open NAME.hdf.series, select it, run the macro)."""
    path = os.environ.get("RADX_RUN")
    source = pv.GetActiveSource()
    if not path and source is not None:
        for prop in ("FileName", "FileNames"):
            if hasattr(source, prop):
                value = getattr(source, prop)
                value = value[-1] if isinstance(value, (list, tuple)) or hasattr(value, "__getitem__") and \
                    not isinstance(value, str) else value
                path = str(value)
                break
    if not path:
        print("radx_open: open NAME.hdf.series and select it, or set RADX_RUN, then run the macro again")
        return None
    if source is not None and not os.environ.get("RADX_RUN"):
        pv.Delete(source)  # open_run opens it again, with its parts
    return open_run(path)


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1:] != [""]:
        main(sys.argv[1:])
    else:
        run_as_gui_macro()
