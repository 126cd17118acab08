"""Shared pieces of the scripts that run radx and check what it wrote (check_results_run.py, check_sigkill.py,
check_free_fall_th.py, check_run_outputs.py; check_contact_common.py takes run_radx and read_summary from here).

Not a test by itself: running radx, rewriting an engine deck's end time and output intervals (the signal and
time-history checks), reading NAME_summary.json and the state index NAME.hdf.series, running the ParaView
check, and collecting failures (check() prints each one, finish() exits 1 if there was any).

Plain /usr/bin/python3, standard library only.
"""
import json
import os
import subprocess
import sys

failures = []


def check(ok, msg):
    """Record and print a failure unless ok."""
    if not ok:
        failures.append(msg)
        print("FAIL: " + msg)


def finish(message):
    """Exit 1 if any check failed, else print "ok: " + message."""
    if failures:
        sys.exit(1)
    print("ok: " + message)


def data_line(lines, keyword):
    """Index of the first data line (not a comment) after the first line that starts with keyword."""
    k = next(i for i, l in enumerate(lines) if l.startswith(keyword))
    return next(i for i in range(k + 1, len(lines)) if not lines[i].startswith("#"))


def end_time(engine_deck):
    """The end time on the /RUN/ line of an engine deck."""
    lines = open(engine_deck).read().splitlines()
    return float(lines[data_line(lines, "/RUN/")].split()[0])


def write_engine_deck(source, path, t_stop=None, th_dt=None, anim_dt=None):
    """Copies the engine deck source to path with the values given replaced: the end time (/RUN/), the
    time-history interval (/TFILE) and the state interval (/ANIM/DT, states from time 0). Returns path."""
    lines = open(source).read().splitlines()
    if t_stop is not None:
        lines[data_line(lines, "/RUN/")] = "%20.6g" % t_stop
    if th_dt is not None:
        lines[data_line(lines, "/TFILE")] = "%20.6g" % th_dt
    if anim_dt is not None:
        lines[data_line(lines, "/ANIM/DT")] = "%20.6g%20.6g" % (0.0, anim_dt)
    open(path, "w").write("\n".join(lines) + "\n")
    return path


def run_radx(radx, deck, out, extra=()):
    """radx run DECK --out OUT --no-plot [extra arguments, e.g. ("--threads", "2")]; returns the run name (NAME
    of NAME_0000.rad). Exits on failure."""
    os.makedirs(out, exist_ok=True)
    r = subprocess.run([radx, "run", deck, "--out", out, "--no-plot", *extra], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("radx run %s failed (exit %d):\n%s\n%s" % (deck, r.returncode, r.stdout[-4000:], r.stderr[-4000:]))
    name = os.path.basename(deck)
    return name[:-len("_0000.rad")] if name.endswith("_0000.rad") else os.path.splitext(name)[0]


def read_summary(out, name):
    with open(os.path.join(out, name + "_summary.json")) as f:
        return json.load(f)


def listed_states(out, name):
    """(file name, time) of every state NAME.hdf.series lists, in its order; [] when it is missing or
    unreadable (e.g. being replaced)."""
    try:
        with open(os.path.join(out, name + ".hdf.series")) as f:
            return [(e["name"], e["time"]) for e in json.load(f)["files"]]
    except (OSError, ValueError):
        return []


def paraview_check(script, *args):
    """Runs pvpython SCRIPT ARGS... offscreen (check_results_paraview.py); returns the CompletedProcess."""
    return subprocess.run(["pvpython", script, *args], capture_output=True, text=True,
                          env=dict(os.environ, QT_QPA_PLATFORM="offscreen"))
