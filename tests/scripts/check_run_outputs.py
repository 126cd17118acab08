"""The energy chart of a run, and the last state of a run that stops on an error.

usage: /usr/bin/python3 check_run_outputs.py --radx RADX --decks DECKS_DIR --out DIR

1. decks/verification/free_fall run as a user runs it (no --no-plot): NAME_energy.csv has one header line with
   names and units and one row per report; its last row is the end of the run and equals NAME_summary.json
   (both print 17 significant digits of the same values: exact); total = kinetic + internal + hourglass +
   contact on every row (relative 1e-12: the sum of four doubles); NAME_energy.png is a PNG (signature, IHDR
   size at least 400 x 300) and no temporary file is left.
2. decks/verification/jc_single_brick with /STOP Emax = 1e-9 % added: the run stops with an error at its first
   listing cycle after the start (the energy error exceeds 1e-9 %); it still writes its last state: the
   series' last state is at the summary's final time, and the states before it are the /ANIM/DT ones due
   before the stop; the reason is on standard error too.
"""
import argparse
import csv
import glob
import os
import shutil
import struct
import subprocess

from results_common import check, finish, listed_states, read_summary


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--decks", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)

    # 1. Energy CSV and chart.
    out = os.path.join(a.out, "plot")
    r = subprocess.run([a.radx, "run", os.path.join(a.decks, "verification/free_fall/FREE_FALL_0000.rad"), "--out",
                        out], capture_output=True, text=True)
    check(r.returncode == 0, "free fall run failed: " + r.stderr[-2000:])
    check("warning" not in r.stderr, "a warning while plotting: " + r.stderr[-2000:])
    s = read_summary(out, "FREE_FALL")
    rows = list(csv.reader(open(os.path.join(out, "FREE_FALL_energy.csv"))))
    check(rows[0] == ["time [s]", "kinetic [J]", "internal [J]", "hourglass [J]", "contact [J]",
                      "external_work [J]", "total [J]"], "CSV header %s" % rows[0])
    values = [[float(x) for x in row] for row in rows[1:]]
    check(len(values) >= 10, "only %d CSV rows" % len(values))
    for v in values:
        check(abs(v[6] - (v[1] + v[2] + v[3] + v[4])) <= 1e-12 * max(1e-300, abs(v[6])), "total != sum: %s" % v)
    last = values[-1]
    e = s["energy"]
    check(last[0] == s["time"], "last CSV time %.17g != summary %.17g" % (last[0], s["time"]))
    check(last[1] == e["kinetic"] and last[2] == e["internal"] and last[3] == e["hourglass"] and
          last[5] == e["external_work"], "last CSV row %s != summary %s" % (last, e))
    png = open(os.path.join(out, "FREE_FALL_energy.png"), "rb").read()
    check(png[:8] == b"\x89PNG\r\n\x1a\n" and png[12:16] == b"IHDR", "not a PNG")
    if len(png) > 24:
        w, h = struct.unpack(">II", png[16:24])
        check(w >= 400 and h >= 300, "PNG %d x %d" % (w, h))
    check(not glob.glob(os.path.join(out, "*.part*")) and not glob.glob(os.path.join(out, "*.tmp")),
          "temporary files left")

    # 2. Error stop still writes its last state.
    out = os.path.join(a.out, "stop")
    os.makedirs(out)
    src = os.path.join(a.decks, "verification/jc_single_brick")
    shutil.copy(os.path.join(src, "JC_SINGLE_BRICK_0000.rad"), out)
    engine = open(os.path.join(src, "JC_SINGLE_BRICK_0001.rad")).read().replace(
        "\n/END", "\n/STOP\n#               Emax                Mmax                Nmax\n"
                  "               1e-09                   0                   0\n/END")
    open(os.path.join(out, "JC_SINGLE_BRICK_0001.rad"), "w").write(engine)
    r = subprocess.run([a.radx, "run", os.path.join(out, "JC_SINGLE_BRICK_0000.rad"), "--out", out, "--no-plot"],
                       capture_output=True, text=True)
    check(r.returncode == 1, "the /STOP run exited with %d, expected 1" % r.returncode)
    s = read_summary(out, "JC_SINGLE_BRICK")
    check(s["status"] == "error" and "/STOP" in s["message"], "summary %s: %s" % (s["status"], s["message"]))
    # The reason also on standard error, not only in the listing and on standard output.
    check("radx-engine: error termination: " + s["message"] in r.stderr,
          "the reason of the error termination is not on stderr: " + r.stderr[-2000:])
    series = listed_states(out, "JC_SINGLE_BRICK")
    times = [t for _, t in series]
    check(times[-1] == s["time"], "last state at %.17g, the run stopped at %.17g" % (times[-1], s["time"]))
    check(0 < s["time"] < 0.1, "stop time %g" % s["time"])
    due = [k * 0.005 for k in range(0, 100) if k * 0.005 < s["time"]]  # /ANIM/DT 0 0.005 in the deck
    check(len(times) == len(due) + 1, "%d states, expected %d due before the stop and the last" %
          (len(times), len(due) + 1))
    for name, _ in series:
        check(os.path.exists(os.path.join(out, name)), name + " listed but missing")
    finish("energy CSV and PNG match the summary; the /STOP run wrote %d states, the last at %.6g s" %
          (len(times), times[-1]))


if __name__ == "__main__":
    main()
