"""Kills the engine with SIGKILL in the middle of a run and checks what a user is left with.

usage: /usr/bin/python3 check_sigkill.py --radx-starter S --radx-engine E --deck NAME_0000.rad --out DIR
           --paraview-check check_results_paraview.py

docs/theory/results-format.md section 5: a crash at any point leaves a consistent, readable result set, and the next run
cleans up. The engine deck is the deck's own with a longer end time and frequent states (written here), run
on one thread so that it lasts a few seconds; the engine is killed once the index lists at least 3 states.
Checks:
  * every state the .hdf.series lists exists and is a complete HDF5 file (h5py opens it and reads its
    TimeValue, equal to the listed time); the .xmf lists the same number of grids;
  * ParaView (pvpython) opens the .hdf.series and the .xmf and sees exactly the listed states and times;
  * a stray .part file (left by the kill, or planted here if the kill fell between two states) is removed by
    the next run, which replaces the whole result set: its index lists only its own states, every file it
    names exists, and no state file of the killed run beyond them is left.
"""
import argparse
import glob
import os
import re
import shutil
import signal
import subprocess
import sys
import time

import h5py

from results_common import check, end_time, finish, listed_states, paraview_check, write_engine_deck


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx-starter", required=True)
    ap.add_argument("--radx-engine", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--paraview-check", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    base = os.path.basename(a.deck).replace("_0000.rad", "")
    s = subprocess.run([a.radx_starter, a.deck, "--out", a.out], capture_output=True, text=True)
    if s.returncode != 0:
        sys.exit("starter failed:\n" + s.stdout[-2000:] + s.stderr[-2000:])
    # The engine deck with 20 times the end time and a state every 1/200 of it.
    source = a.deck.replace("_0000.rad", "_0001.rad")
    t_stop = 20 * end_time(source)
    engine_deck = write_engine_deck(source, os.path.join(a.out, base + "_0001.rad"), t_stop=t_stop,
                                    anim_dt=t_stop / 200)

    env = dict(os.environ, OMP_NUM_THREADS="1")
    p = subprocess.Popen([a.radx_engine, engine_deck, "--out", a.out, "--no-plot"], stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL, env=env)
    deadline = time.time() + 120
    while len(listed_states(a.out, base)) < 3 and p.poll() is None and time.time() < deadline:
        time.sleep(0.005)
    if p.poll() is not None:
        sys.exit("the engine ended (exit %s) before it could be killed: make the run longer" % p.returncode)
    p.send_signal(signal.SIGKILL)
    p.wait()
    check(p.returncode == -signal.SIGKILL, "the engine was not killed by SIGKILL (%s)" % p.returncode)

    listed = listed_states(a.out, base)
    check(len(listed) >= 3, "the index lists %d states after the kill" % len(listed))
    for name, t in listed:
        try:
            with h5py.File(os.path.join(a.out, name), "r") as h:
                check(float(h["/VTKHDF/FieldData/TimeValue"][0]) == t, "%s: TimeValue != listed %r" % (name, t))
                h["/VTKHDF/PointData/displacement"][()]
        except OSError as e:
            check(False, "%s listed but unreadable: %s" % (name, e))
    # The two indexes are replaced one after the other (the .xmf first), so a kill between the two renames
    # leaves the .xmf one state ahead of the series: each must be complete on its own.
    xmf = open(os.path.join(a.out, base + ".xmf")).read()
    xmf_times = [float(t) for t in re.findall(r'<Time Value="([^"]+)"', xmf)]
    xmf_files = re.findall(r"(" + re.escape(base) + r"_\d{6}\.hdf):/VTKHDF/Points", xmf)
    check(xmf_times[:len(listed)] == [t for _, t in listed] and len(xmf_times) - len(listed) in (0, 1),
          "the .xmf lists times %s, the series %s" % (xmf_times, [t for _, t in listed]))
    check(xmf_files == [n for n, _ in listed] + xmf_files[len(listed):] and len(xmf_files) == len(xmf_times),
          "the .xmf reads files %s" % xmf_files)
    for name in xmf_files:
        check(os.path.exists(os.path.join(a.out, name)), "the .xmf names %s, which does not exist" % name)
    with h5py.File(os.path.join(a.out, base + "_0000.hdf"), "r") as m:
        ncells = int(m["/VTKHDF/NumberOfCells"][0])
    for index, entries in (("--series", listed), ("--xmf", list(zip(xmf_files, xmf_times)))):
        path = os.path.join(a.out, base + (".hdf.series" if index == "--series" else ".xmf"))
        pv = paraview_check(a.paraview_check, index, path, "--expect-states", str(len(entries)),
                            "--expect-cells", str(ncells), "--expect-arrays", "displacement,velocity,element_status",
                            "--expect-times", ",".join("%.17g" % t for _, t in entries),
                            "--last-displacement-from", os.path.join(a.out, entries[-1][0]))
        print(pv.stdout[-2000:])
        check(pv.returncode == 0, "ParaView does not read the killed run's states through %s:\n%s" %
              (path, pv.stdout[-2000:]))

    # The next run cleans up: plant a stray .part and a state beyond what the next run writes.
    stray = os.path.join(a.out, base + "_%06d.hdf.part" % (len(listed) + 1))
    open(stray, "w").write("half a state")
    far = os.path.join(a.out, base + "_%06d.hdf" % 999)
    shutil.copy(os.path.join(a.out, listed[0][0]), far)
    write_engine_deck(engine_deck, engine_deck, t_stop=t_stop / 40)  # 6 states: t = 0 .. t_stop/40 every t_stop/200
    r = subprocess.run([a.radx_engine, engine_deck, "--out", a.out, "--no-plot"], capture_output=True, text=True)
    check(r.returncode == 0, "the next run failed: " + r.stderr[-2000:])
    check(not glob.glob(os.path.join(a.out, "*.part")), "a .part file survived the next run")
    check(not os.path.exists(far), "a state file of the earlier run survived the next run")
    again = listed_states(a.out, base)
    files = sorted(os.path.basename(f) for f in glob.glob(os.path.join(a.out, base + "_[0-9]" * 1 + "*.hdf"))
                   if re.fullmatch(re.escape(base) + r"_\d{6}\.hdf", os.path.basename(f)))
    check([n for n, _ in again] == files, "after the next run the index lists %s, the folder has %s" %
          ([n for n, _ in again], files))
    check(len(again) == 6, "the next run wrote %d states, expected 6 (t = 0 and every t_stop/200 up to t_stop/40)"
          % len(again))
    finish("killed with %d states listed, all readable in ParaView; the next run cleaned up" % len(listed))


if __name__ == "__main__":
    main()
