"""An output interval smaller than the spacing of doubles at the run's times ends, with an output every cycle.

usage: /usr/bin/python3 check_tiny_output_interval.py --radx R --deck NAME_0000.rad --out DIR

The deck runs with /ANIM/DT dT = 1e-30 s and /TFILE dt_his = 1e-30 s (its own engine deck otherwise). At a time
t of a few microseconds, t + 1e-30 is t itself: an output scheduler that steps its next time by the interval
until it passes t never gets there (the engine hung, and as it never finished a cycle it never saw SIGTERM
either). What must hold:
  * the run ends normally well within the time limit (60 s: the deck's own run takes about a second);
  * a state is written at time 0 and at every cycle after it, each later than the one before: cycles + 1
    states, the most an interval below the step can ask for;
  * the time history has a row at time 0 and at every cycle after it: cycles + 1 rows in every group.
"""
import argparse
import os
import shutil
import subprocess
import sys

import h5py

from results_common import check, finish, listed_states, read_summary, write_engine_deck


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    out = os.path.abspath(a.out)
    name = os.path.basename(a.deck)[:-len("_0000.rad")]
    deck = os.path.join(out, name + "_0000.rad")
    shutil.copy(a.deck, deck)
    write_engine_deck(a.deck.replace("_0000.rad", "_0001.rad"), os.path.join(out, name + "_0001.rad"), th_dt=1e-30,
                      anim_dt=1e-30)
    run = subprocess.Popen([a.radx, "run", deck, "--out", os.path.join(out, "run"), "--no-plot"],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        log = run.communicate(timeout=60)[0]
    except subprocess.TimeoutExpired:
        run.kill()
        run.communicate()
        sys.exit("FAIL: the run with output intervals of 1e-30 s still runs after 60 s (an endless scheduling loop)")
    if run.returncode != 0:
        sys.exit("FAIL: the run exits %d, not 0:\n%s" % (run.returncode, log[-3000:]))
    summary = read_summary(os.path.join(out, "run"), name)
    check(summary["status"] == "normal", "the summary says normal (%s)" % summary["status"])
    cycles = summary["cycles"]
    times = [t for _, t in listed_states(os.path.join(out, "run"), name)]
    check(len(times) == cycles + 1, "%d states for %d cycles: one at time 0 and one each cycle" % (len(times), cycles))
    check(all(b > a for a, b in zip(times, times[1:])), "the state times increase strictly")
    with h5py.File(os.path.join(out, "run", name + "_th.h5"), "r") as h:
        for group in h.attrs["groups"]:
            rows = h[group].shape[0]
            check(rows == cycles + 1, "time history %s: %d rows for %d cycles" % (group, rows, cycles))
    finish("%d cycles: %d states and %d time-history rows, each cycle once" % (cycles, len(times), cycles + 1))


if __name__ == "__main__":
    main()
