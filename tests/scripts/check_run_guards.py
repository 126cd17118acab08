"""What guards a run's outputs: a refused or failed start leaves nothing of an earlier run, two
engines of one name never share a folder, a second stop signal of either kind ends the engine at once.

usage: /usr/bin/python3 check_run_guards.py --radx R --radx-starter S --radx-engine E --deck NAME_0000.rad --out DIR

Checks, each after a normal `radx run` of the deck in DIR (its summary says "normal", its states, energy CSV and
time history are there):
  * a `radx run` whose starter refuses the deck (`abc` in a /NODE field: exit 1, RX202) leaves no summary,
    state, index, time history or energy file (the starter removes the engine outputs of the name first);
  * an engine whose model file cannot be read (exit 1) leaves none either (the engine removes them before it
    reads anything, so a kill while it reads a big model leaves none);
  * a second engine of the same name in the same folder, while the first runs, exits 1 at once with an error
    naming the first one's pid, and writes nothing (the first run's summary still says "running");
  * `radx th NAME_th.h5 --recover` while that engine runs exits 1 naming it (a rewrite under a writer would
    lose rows);
  * SIGTERM then SIGINT, and SIGINT then SIGTERM: the engine ends at once, killed by a signal (the default
    action), not by the clean exit a single signal gives;
  * SIGTERM twice a millisecond apart (what `timeout` sends: to the engine, then to its process group) is one
    request: the engine stops cleanly with exit 143, an "interrupted" summary and a last state;
  * a restart deck (NAME_0002.rad, /RUN/NAME/2) is refused with exit 1 naming the restart run, and leaves every
    output of run 1 as it was (same files, same bytes);
  * a time-history interval of 1e-30 (below the resolution of the time at the end time, where adding it to the
    time changes nothing) is said when the deck is read and the run ends normally, a row every cycle: the
    schedule of outputs cannot stall a cycle.
"""
import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import time

from results_common import check, data_line, end_time, finish, listed_states, write_engine_deck


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--radx-starter", required=True)
    ap.add_argument("--radx-engine", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    out = os.path.abspath(a.out)
    base = os.path.basename(a.deck).replace("_0000.rad", "")
    env = dict(os.environ, OMP_NUM_THREADS="1")
    engine_outputs = lambda: sorted(f for f in os.listdir(out) if f.startswith(base) and (  # noqa: E731
        f.endswith(("_0001.out", "_summary.json", "_th.h5", "_energy.csv", "_energy.png", ".xmf", ".hdf.series",
                    ".mesh.hdf"))
        or f[len(base) + 1:-4].isdigit() and len(f) == len(base) + 11))

    def normal_run():
        r = subprocess.run([a.radx, "run", a.deck, "--out", out], capture_output=True, text=True, env=env)
        if r.returncode != 0 or json.load(open(os.path.join(out, base + "_summary.json")))["status"] != "normal":
            sys.exit("the normal run failed:\n" + r.stdout[-2000:] + r.stderr[-2000:])
        if not os.path.exists(os.path.join(out, base + "_energy.csv")) or not listed_states(out, base):
            sys.exit("the normal run left no energy CSV or no state")

    # A refused starter deck, in a folder of its own beside the decks (the engine deck is found beside it).
    bad_dir = os.path.join(out, "bad_deck")
    os.makedirs(bad_dir)
    lines = open(a.deck).read().splitlines()
    k = data_line(lines, "/NODE")
    lines[k] = lines[k][:10] + "%20s" % "abc" + lines[k][30:]
    bad = os.path.join(bad_dir, os.path.basename(a.deck))
    open(bad, "w").write("\n".join(lines) + "\n")
    shutil.copy(a.deck.replace("_0000.rad", "_0001.rad"), bad_dir)
    normal_run()
    r = subprocess.run([a.radx, "run", bad, "--out", out], capture_output=True, text=True, env=env)
    check(r.returncode == 1 and "RX202" in r.stdout + r.stderr, "the refused deck: exit %d, %s" % (
        r.returncode, (r.stdout + r.stderr)[-1000:]))
    left = engine_outputs()
    check(not left, "a run refused by its starter leaves the earlier run's %s" % left)

    # An engine that cannot read its model file.
    normal_run()
    engine_deck = os.path.join(out, base + "_0001.rad")
    shutil.copy(a.deck.replace("_0000.rad", "_0001.rad"), engine_deck)
    r = subprocess.run([a.radx_engine, engine_deck, "--out", out, "--model", os.path.join(out, "missing.hdf")],
                       capture_output=True, text=True, env=env)
    check(r.returncode == 1, "an engine without its model file: exit %d" % r.returncode)
    left = engine_outputs()
    check(not left, "an engine that cannot read its model leaves the earlier run's %s" % left)

    # A long run for the lock and the signals: 50 times the end time, on one thread.
    normal_run()
    source = a.deck.replace("_0000.rad", "_0001.rad")
    write_engine_deck(source, engine_deck, t_stop=50 * end_time(source))
    summary = os.path.join(out, base + "_summary.json")

    def start_long():
        start = time.time()
        p = subprocess.Popen([a.radx_engine, engine_deck, "--out", out, "--no-plot"], stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL, env=env)
        deadline = time.time() + 60
        while p.poll() is None and time.time() < deadline:
            try:
                # This run's summary (a killed run before it leaves one saying "running" too).
                if (os.stat(summary).st_mtime >= start - 0.01 and json.load(open(summary))["status"] == "running"
                        and len(listed_states(out, base)) >= 2):
                    break
            except (OSError, ValueError):
                pass
            time.sleep(0.01)
        if p.poll() is not None:
            sys.exit("the long run ended (exit %s) before it could be used" % p.returncode)
        return p

    first = start_long()
    second = subprocess.run([a.radx_engine, engine_deck, "--out", out, "--no-plot"], capture_output=True,
                            text=True, env=env, timeout=60)
    check(second.returncode == 1 and ("pid %d" % first.pid) in second.stderr,
          "a second engine of the same name: exit %d, %r" % (second.returncode, second.stderr[-500:]))
    check(first.poll() is None and json.load(open(summary))["status"] == "running",
          "the second engine disturbed the first one's summary")
    recover = subprocess.run([a.radx, "th", os.path.join(out, base + "_th.h5"), "--recover"], capture_output=True,
                             text=True, env=env, timeout=60)
    check(recover.returncode == 1 and ("pid %d" % first.pid) in recover.stderr,
          "radx th --recover under a running engine: exit %d, %r" % (recover.returncode, recover.stderr[-500:]))

    for one, two in ((signal.SIGTERM, signal.SIGINT), (signal.SIGINT, signal.SIGTERM)):
        p = first if one == signal.SIGTERM else start_long()
        # Back to back: a clean stop of this small run takes only milliseconds, and a pause could let it
        # finish before the second signal. Both may then be pending when the engine next runs, and the kernel
        # delivers the lower-numbered first (SIGINT), so the one that kills may be either: the check is that
        # a signal killed the engine, not the clean 143/130 exit of a first signal alone.
        p.send_signal(one)
        p.send_signal(two)
        p.wait(timeout=60)
        check(p.returncode in (-one, -two), "%s then %s: the engine exits with %s, not killed by the second"
              % (one.name, two.name, p.returncode))
    p = start_long()
    p.send_signal(signal.SIGTERM)
    time.sleep(0.001)
    p.send_signal(signal.SIGTERM)
    p.wait(timeout=60)
    status = json.load(open(summary))["status"]
    check(p.returncode == 128 + signal.SIGTERM and status == "interrupted",
          "SIGTERM twice within a millisecond: exit %s and status %r, not one clean stop (143, interrupted)"
          % (p.returncode, status))
    check_restart_refused(a, out, base, env, normal_run)
    check_tiny_th_interval(a, out, base, env, engine_deck, source)
    finish("a refused or failed start leaves no earlier output; one engine a name; a second signal ends the run; "
           "a restart deck touches nothing; a tiny output interval does not stall")


def snapshot(out, base):
    """The bytes of every file of the run in out."""
    return {f: open(os.path.join(out, f), "rb").read() for f in sorted(os.listdir(out))
            if f.startswith(base) and os.path.isfile(os.path.join(out, f))}


def check_restart_refused(a, out, base, env, normal_run):
    normal_run()
    before = snapshot(out, base)
    restart = os.path.join(out, base + "_0002.rad")
    lines = open(a.deck.replace("_0000.rad", "_0001.rad")).read().splitlines()
    k = next(i for i, line in enumerate(lines) if line.startswith("/RUN/"))
    lines[k] = "/RUN/%s/2" % base
    open(restart, "w").write("\n".join(lines) + "\n")
    before.pop(os.path.basename(restart), None)
    r = subprocess.run([a.radx_engine, restart, "--out", out, "--no-plot"], capture_output=True, text=True,
                       env=env, timeout=60)
    check(r.returncode == 1 and "run number 2 is a restart run" in r.stderr,
          "a restart deck: exit %d, %r" % (r.returncode, r.stderr[-800:]))
    after = snapshot(out, base)
    after.pop(os.path.basename(restart), None)
    changed = sorted(f for f in set(before) | set(after) if before.get(f) != after.get(f))
    check(not changed, "a refused restart deck changed or removed run 1's %s" % changed)
    os.remove(restart)


def check_tiny_th_interval(a, out, base, env, engine_deck, source):
    write_engine_deck(source, engine_deck, th_dt=1e-30)
    try:
        r = subprocess.run([a.radx_engine, engine_deck, "--out", out, "--no-plot"], capture_output=True, text=True,
                           env=env, timeout=120)
    except subprocess.TimeoutExpired:
        check(False, "an engine with /TFILE 1e-30 did not end within 120 s (a stalled output schedule)")
        return
    status = json.load(open(os.path.join(out, base + "_summary.json")))["status"]
    check(r.returncode == 0 and status == "normal", "/TFILE 1e-30: exit %d, status %r, %r"
          % (r.returncode, status, r.stderr[-800:]))
    check("below the time resolution" in r.stderr and "a row every cycle" in r.stderr,
          "/TFILE 1e-30 was not said when the deck was read: %r" % r.stderr[-800:])


if __name__ == "__main__":
    main()
