"""Long runs: the time history is appended in place with memory independent of the run
length, survives SIGKILL with every flushed row, and the state indexes stay valid after every state.

usage: /usr/bin/python3 check_th_stream.py --radx-starter S --radx-engine E --deck FREE_FALL_0000.rad --out DIR

The engine deck is the free-fall deck's own with a time-history row every cycle (/TFILE 0) and, for the kill,
a state every 300 cycles and an end time of 1e30. One thread, so the cycle count per second stays steady.
Checks:
  * memory: the maximum resident set size (/usr/bin/time) of a 60,000-cycle run exceeds the 1,000-cycle
    run's by less than 6 MB (at most about 2 MiB of rows and 1 MiB of energy samples are held; rows held
    whole cost some 20 MB more: 40 doubles a row);
  * the energy CSV of the 60,000-cycle run holds at most 16,384 samples and the last, times increasing from 0
    to the run's end;
  * SIGKILL, three times at different moments: P_th.h5 opens with h5py, every group has the same number of
    rows, times never go back, every value is finite, no row read from the file during the run is lost
    (read before the kill: the file is closed between flushes, so it can be read while the engine runs), and
    a run killed more than a second after its start has rows after the first (flushed once a second);
  * after each kill the .xmf parses as XML and the .hdf.series as JSON, and they list the same states (the
    .xmf one ahead at most: it is written first).
"""
import argparse
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

import h5py

from results_common import check, finish, write_engine_deck

DT = 0.01 / 1381  # the free fall's stable time step, constant (rigid motion)


def run_rss_kb(engine, deck, out):
    """Runs the engine to its end; returns its maximum resident set size in kB. Through /usr/bin/time: a child
    forked from this Python process would count Python's own pages (h5py, numpy) in its maximum."""
    env = dict(os.environ, OMP_NUM_THREADS="1")
    rss_file = os.path.join(out, "max_rss_kb")
    r = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", rss_file, engine, deck, "--out", out, "--no-plot"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    if r.returncode != 0:
        sys.exit("the engine failed (exit %d) on %s" % (r.returncode, deck))
    return int(open(rss_file).read().split()[-1])


def read_th(path):
    """{group path: rows} of the time history, or None while the writer holds the file (HDF5 refuses it: its
    "open for writing" flag is set during a flush)."""
    try:
        with h5py.File(path, "r") as h:
            return {g: h[g][()] for g in h.attrs["groups"]}
    except OSError:
        return None


def refused_as_killed(path):
    """True when HDF5 refuses the file because its writer was killed inside a flush (check_th_kill_sweep.py
    checks what radx th reads and recovers then)."""
    try:
        h5py.File(path, "r").close()
        return False
    except OSError as e:
        return "open for write" in str(e)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx-starter", required=True)
    ap.add_argument("--radx-engine", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    base = os.path.basename(a.deck).replace("_0000.rad", "")
    src = a.deck.replace("_0000.rad", "_0001.rad")

    rss = {}
    for cycles in (1000, 60000):
        out = os.path.join(a.out, "cycles_%d" % cycles)
        os.makedirs(out)
        s = subprocess.run([a.radx_starter, a.deck, "--out", out], capture_output=True, text=True)
        if s.returncode != 0:
            sys.exit("starter failed:\n" + s.stdout[-2000:] + s.stderr[-2000:])
        deck = write_engine_deck(src, os.path.join(out, os.path.basename(src)), t_stop=(cycles - 0.5) * DT,
                                 th_dt=0.0, anim_dt=1e30)
        rss[cycles] = run_rss_kb(a.radx_engine, deck, out)
        with h5py.File(os.path.join(out, base + "_th.h5"), "r") as h:
            rows = h["global"].shape[0]
        check(abs(rows - cycles) <= cycles // 100 + 2, "%d cycles wrote %d rows" % (cycles, rows))
    print("max RSS: %d kB for 1,000 cycles, %d kB for 60,000" % (rss[1000], rss[60000]))

    # The energy chart's samples are thinned: the 60,000 cycles (a sample each) give at most 16,384 and the
    # last, from t = 0 to the end. Run again with the chart (its CSV is written only then), apart from the
    # memory measurement, which would count the plotting Python.
    out = os.path.join(a.out, "cycles_60000")
    r = subprocess.run([a.radx_engine, os.path.join(out, os.path.basename(src)), "--out", out],
                       capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    check(r.returncode == 0, "the 60,000-cycle run with the chart failed: " + r.stderr[-2000:])
    with h5py.File(os.path.join(out, base + "_th.h5"), "r") as h:
        t_end = float(h["global"][-1, 0])
    times = [float(l.split(",")[0]) for l in open(os.path.join(out, base + "_energy.csv")).read().splitlines()[1:]]
    check(2000 < len(times) <= 16385 and times[0] == 0.0 and times[-1] == t_end and
          all(times[i] < times[i + 1] for i in range(len(times) - 1)),
          "the energy CSV has %d samples from %s to %s (the run ends at %r)"
          % (len(times), times[:1], times[-1:], t_end))
    check(rss[60000] - rss[1000] < 6144, "60,000 cycles take %d kB more memory than 1,000" % (rss[60000] - rss[1000]))

    out = os.path.join(a.out, "killed")
    os.makedirs(out)
    s = subprocess.run([a.radx_starter, a.deck, "--out", out], capture_output=True, text=True)
    if s.returncode != 0:
        sys.exit("starter failed:\n" + s.stdout[-2000:] + s.stderr[-2000:])
    deck = write_engine_deck(src, os.path.join(out, os.path.basename(src)), t_stop=1e30, th_dt=0.0,
                             anim_dt=300 * DT)
    th = os.path.join(out, base + "_th.h5")
    for delay in (0.3, 1.7, 3.1):
        env = dict(os.environ, OMP_NUM_THREADS="1")
        err = open(os.path.join(out, "engine_stderr_%.1f.txt" % delay), "w")
        p = subprocess.Popen([a.radx_engine, deck, "--out", out, "--no-plot"], stdout=subprocess.DEVNULL,
                             stderr=err, env=env)
        deadline = time.time() + 60
        while not os.path.exists(th) and p.poll() is None and time.time() < deadline:
            time.sleep(0.01)
        seen = None  # rows read from the file during the run
        t_kill = time.time() + delay
        while time.time() < t_kill and p.poll() is None:
            # Two reads in a row that agree count (a read during a flush is refused).
            got, again = read_th(th), read_th(th)
            if got is not None and again is not None and all(
                    got[g].shape == again[g].shape and (got[g] == again[g]).all() for g in got):
                seen = got
            time.sleep(0.05)
        if p.poll() is not None:
            sys.exit("the engine ended (exit %s) before it could be killed:\n%s"
                     % (p.returncode, open(err.name).read()[-2000:]))
        p.send_signal(signal.SIGKILL)
        p.wait()
        groups = read_th(th)
        if groups is None and refused_as_killed(th):
            print("killed at %.1f s inside a flush: the file is refused as being written" % delay)
            continue
        check(groups is not None, "after a kill at %.1f s the time history does not open" % delay)
        if groups is None:
            continue
        n = {len(v) for v in groups.values()}
        check(len(n) == 1, "after a kill at %.1f s the groups have different row counts %s" % (delay, n))
        t = groups["global"][:, 0]
        check(len(t) > 0 and all(t[i] <= t[i + 1] for i in range(len(t) - 1)),
              "after a kill at %.1f s the times go back or there is no row" % delay)
        check(all(math.isfinite(x) for v in groups.values() for x in v.flat),
              "after a kill at %.1f s a value is not finite" % delay)
        # Rows are flushed at least once a second: a run killed later than that has rows after the first.
        if delay > 1.2:
            check(len(t) > 1, "killed at %.1f s, the file has only the first row" % delay)
        if seen is not None:
            m = len(seen["global"])
            check(len(t) >= m and (groups["global"][:m] == seen["global"]).all(),
                  "after a kill at %.1f s the file has %d rows, %d were read from it during the run"
                  % (delay, len(t), m))
        print("killed at %.1f s: %d rows (%s read during the run)" % (delay, len(t), seen and len(seen["global"])))

        try:
            xmf = ET.parse(os.path.join(out, base + ".xmf")).getroot()
            grids = [g for g in xmf.iter("Grid") if g.get("GridType") == "Uniform"]
            series = json.load(open(os.path.join(out, base + ".hdf.series")))["files"]
            check(len(grids) - len(series) in (0, 1) and len(series) >= 1,
                  "after a kill at %.1f s the .xmf lists %d states, the series %d" % (delay, len(grids), len(series)))
        except (ET.ParseError, ValueError) as e:
            check(False, "after a kill at %.1f s an index does not parse: %s" % (delay, e))
    finish("memory independent of the run length; the time history and the indexes survive SIGKILL")


if __name__ == "__main__":
    main()
