"""Reruns killed with SIGKILL, and stopped with SIGTERM and SIGINT, in the folder of a finished run.

usage: /usr/bin/python3 check_interrupt.py --radx-starter S --radx-engine E --deck NAME_0000.rad --out DIR
           [--mode sigkill|sigterm|sigint]...

docs/results.md section 4: a run that starts removes what an earlier run of the same name left, so no file
beside its outputs is older than it; SIGTERM (a batch system's wall-time limit) and SIGINT (Ctrl-C) stop the
run after a cycle, with a last state, a summary and the listing's termination lines.

First a normal run of the deck's own engine deck, with the energy chart (its summary says "normal", it leaves
NAME_energy.csv and the time history), then, a second later, for each mode a rerun with 20 times the end time
and a state every 1/10 of it, on one thread so that it lasts a few seconds, signalled once its index lists
states beyond the normal run's end time. Checks after each:
  * every file of the folder but the inputs (the decks, the starter's model file and listing) is younger than
    the rerun: nothing of the normal run is left (its summary, energy files, time history, states);
  * sigkill: the summary is absent or says "running"; no energy file;
  * sigterm, sigint: exit code 128 + the signal (143, 130); the rerun's own energy CSV and no chart (--no-plot
    leaves out the chart only); the summary says "interrupted" with the signal's
    name, at a time before the end time; the last state listed is at that time, and so is the time history's
    last row; the listing has the line of the last cycle, the INTERRUPTED TERMINATION heading with the
    reason and ends with the termination line; the reason is on standard error.
The `ls -l` of the folder after each rerun is printed.
"""
import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import h5py

from results_common import check, end_time, finish, listed_states, write_engine_deck

# Written by the starter or by this script: older than the reruns by design.
INPUT_SUFFIXES = ("_0000.hdf", "_0000.out", "_0001.rad")


def ls_l(out):
    return subprocess.run(["ls", "-l", "--time-style=+%H:%M:%S.%N", out], capture_output=True, text=True).stdout


def older_files(out, since):
    return sorted(f for f in os.listdir(out)
                  if not f.endswith(INPUT_SUFFIXES) and os.stat(os.path.join(out, f)).st_mtime < since)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx-starter", required=True)
    ap.add_argument("--radx-engine", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--mode", action="append", choices=["sigkill", "sigterm", "sigint"])
    a = ap.parse_args()
    modes = a.mode or ["sigkill", "sigterm", "sigint"]
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    base = os.path.basename(a.deck).replace("_0000.rad", "")
    s = subprocess.run([a.radx_starter, a.deck, "--out", a.out], capture_output=True, text=True)
    if s.returncode != 0:
        sys.exit("starter failed:\n" + s.stdout[-2000:] + s.stderr[-2000:])
    source = a.deck.replace("_0000.rad", "_0001.rad")
    t_stop = end_time(source)
    deck = os.path.join(a.out, base + "_0001.rad")
    env = dict(os.environ, OMP_NUM_THREADS="1")
    summary_path = os.path.join(a.out, base + "_summary.json")
    energy = [os.path.join(a.out, base + e) for e in ("_energy.csv", "_energy.png")]
    listing_path = os.path.join(a.out, base + "_0001.out")

    for mode in modes:
        # The earlier run: a normal one, with the energy chart.
        write_engine_deck(source, deck, t_stop=t_stop / 4, anim_dt=t_stop / 20)
        r = subprocess.run([a.radx_engine, deck, "--out", a.out], capture_output=True, text=True, env=env)
        if r.returncode != 0:
            sys.exit("the normal run failed:\n" + r.stdout[-2000:] + r.stderr[-2000:])
        if json.load(open(summary_path))["status"] != "normal" or not os.path.exists(energy[0]):
            sys.exit("the normal run left no normal summary or no energy CSV")
        time.sleep(1.1)  # every file of the normal run is then more than a second older than the rerun

        write_engine_deck(source, deck, t_stop=20 * t_stop, anim_dt=t_stop / 10)
        start = time.time()
        # Standard error to a file: a pipe read only at the end could fill and stall the engine.
        err_file = tempfile.TemporaryFile(mode="w+")
        p = subprocess.Popen([a.radx_engine, deck, "--out", a.out, "--no-plot"], stdout=subprocess.DEVNULL,
                             stderr=err_file, text=True, env=env)
        deadline = time.time() + 120
        # The normal run's index lists states up to t_stop / 4: the rerun's own index is the one beyond.
        while (len([t for _, t in listed_states(a.out, base) if t > t_stop / 4 * 1.001]) < 2 and p.poll() is None
               and time.time() < deadline):
            time.sleep(0.005)
        if p.poll() is not None:
            sys.exit("the engine ended (exit %s) before it could be signalled: make the run longer" % p.returncode)
        signo = {"sigkill": signal.SIGKILL, "sigterm": signal.SIGTERM, "sigint": signal.SIGINT}[mode]
        time.sleep(0.02)  # most often between two states, so the last state is one the stop adds
        p.send_signal(signo)
        try:
            p.wait(timeout=120)
        except subprocess.TimeoutExpired:
            p.kill()
            sys.exit("%s: the engine did not stop within 120 s" % mode)
        err_file.seek(0)
        stderr = err_file.read()
        print("--- ls -l after the %s rerun (signalled after %.2f s):\n%s" % (mode, time.time() - start, ls_l(a.out)))

        old = older_files(a.out, start - 0.5)
        check(not old, "%s: files of the earlier run are left beside the rerun's: %s" % (mode, old))
        if mode == "sigkill":
            check(p.returncode == -signal.SIGKILL, "the engine was not killed by SIGKILL (%s)" % p.returncode)
            if os.path.exists(summary_path):
                status = json.load(open(summary_path))["status"]
                check(status == "running", "the killed rerun's summary says %r, not \"running\"" % status)
            for f in energy:
                check(not os.path.exists(f), "the killed rerun left %s" % os.path.basename(f))
            continue

        name = signal.Signals(signo).name
        check(p.returncode == 128 + signo, "%s: exit code %s, expected %d" % (mode, p.returncode, 128 + signo))
        summary = json.load(open(summary_path))
        check(summary["status"] == "interrupted", "%s: summary status %r" % (mode, summary["status"]))
        check(summary["message"].startswith("interrupted by " + name), "%s: message %r" % (mode, summary["message"]))
        check(0 < summary["time"] < 20 * t_stop, "%s: stopped at t = %r" % (mode, summary["time"]))
        states = listed_states(a.out, base)
        check(states and states[-1][1] == summary["time"],
              "%s: the last state is at %r, the run stopped at %r" % (mode, states[-1][1] if states else None,
                                                                     summary["time"]))
        for f, _ in states:
            check(os.path.exists(os.path.join(a.out, f)), "%s: %s listed but missing" % (mode, f))
        with h5py.File(os.path.join(a.out, base + "_th.h5"), "r") as th:
            last = float(th["global"][-1, 0])
        check(last == summary["time"], "%s: the time history ends at %r, the run at %r" % (mode, last,
                                                                                          summary["time"]))
        listing = open(listing_path).read()
        check(listing.endswith("  INTERRUPTED TERMINATION\n"), "%s: the listing ends with %r" % (mode, listing[-200:]))
        check("  INTERRUPTED TERMINATION\n" in listing[:-30] and "  " + summary["message"] + "\n" in listing,
              "%s: no INTERRUPTED TERMINATION heading with the reason in the listing" % mode)
        check(any(l.split()[:1] == [str(summary["cycles"])] for l in listing.splitlines()),
              "%s: no listing line of the last cycle %d" % (mode, summary["cycles"]))
        check(summary["message"] in stderr, "%s: the reason is not on stderr: %r" % (mode, stderr[-2000:]))
        # --no-plot leaves out the chart only: the stopped rerun writes its own energy CSV (younger than the
        # rerun, checked above) and no chart.
        check(os.path.exists(energy[0]), "%s: the rerun wrote no %s" % (mode, os.path.basename(energy[0])))
        check(not os.path.exists(energy[1]), "%s: the rerun (--no-plot) left %s" % (mode, os.path.basename(energy[1])))
    finish("reruns %s: nothing of the earlier run left; SIGTERM and SIGINT stop with a last state, an "
           "\"interrupted\" summary and the termination lines" % ", ".join(modes))


if __name__ == "__main__":
    main()
