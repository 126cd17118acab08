"""Draws the energy balance of a radx run (NAME_energy.csv) as a PNG chart.

radx embeds this file in its binary at build time (io/CMakeLists.txt) and runs it at the end of every
engine run as
    /usr/bin/python3 -I -c <this script> CSV PNG TITLE TIME_UNIT ENERGY_UNIT
so the engine needs no source tree. It also works stand-alone on a kept CSV:
    python3 io/listing/plot_energy.py run_energy.csv run_energy.png "my run" s J

The CSV has one header line, "time [s],kinetic [J],...", then one row of numbers per sample. Each energy
column becomes one line; the column named "total" is drawn bold and black so the balance stands out.

Exit codes, read by io/listing/energy_plot.cpp to word its warning: 0 drawn, 2 wrong arguments, 3 matplotlib
cannot be imported, 4 the CSV cannot be read; anything else is an unexpected failure (traceback on stderr).
"""

import csv
import math
import sys

EXIT_USAGE = 2
EXIT_NO_MATPLOTLIB = 3
EXIT_BAD_CSV = 4


def column_label(header):
    """'external_work [J]' -> 'external work': the unit is already on the axis."""
    name = header.split("[", 1)[0].strip()
    return name.replace("_", " ")


def read_columns(path):
    """Returns (labels, columns): one label per header field and one list of floats per column.

    Values that are not finite become NaN so matplotlib leaves a gap instead of stretching the axis to
    infinity.
    """
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError("empty file (no header line)")
    labels = [column_label(h) for h in rows[0]]
    columns = [[] for _ in labels]
    for line_no, row in enumerate(rows[1:], start=2):
        if not row:
            continue
        if len(row) != len(labels):
            raise ValueError("line %d has %d fields, the header has %d" % (line_no, len(row), len(labels)))
        for k, field in enumerate(row):
            v = float(field)
            columns[k].append(v if math.isfinite(v) else math.nan)
    return labels, columns


def main(argv):
    if len(argv) != 6:
        sys.stderr.write("usage: plot_energy.py CSV PNG TITLE TIME_UNIT ENERGY_UNIT\n")
        return EXIT_USAGE
    csv_path, png_path, title, time_unit, energy_unit = argv[1:]

    # Only pyplot is imported: start-up time is paid at the end of every run. The Agg backend draws
    # without a display (batch nodes, ssh sessions); radx also sets MPLBACKEND=Agg.
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        sys.stderr.write("cannot import matplotlib: %s\n" % e)
        return EXIT_NO_MATPLOTLIB

    try:
        labels, columns = read_columns(csv_path)
    except (OSError, ValueError) as e:
        sys.stderr.write("cannot read %s: %s\n" % (csv_path, e))
        return EXIT_BAD_CSV

    def with_unit(name, unit):
        return "%s [%s]" % (name, unit) if unit else name

    time = columns[0]
    # With one or two samples a line is hard to see: markers keep single points visible.
    marker = "o" if len(time) < 3 else None
    fig, ax = plt.subplots(figsize=(9.0, 5.5), dpi=100)
    for label, values in zip(labels[1:], columns[1:]):
        if label == "total":
            ax.plot(time, values, label=label, color="black", linewidth=2.6, marker=marker, zorder=3)
        else:
            ax.plot(time, values, label=label, linewidth=1.4, marker=marker)
    ax.set_xlabel(with_unit("time", time_unit))
    ax.set_ylabel(with_unit("energy", energy_unit))
    ax.set_title(title)
    ax.grid(True, alpha=0.4)
    ax.legend(loc="best")
    fig.tight_layout()
    # The format is given explicitly: radx writes to NAME_energy.png.part.png and renames it when complete.
    fig.savefig(png_path, format="png")
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
