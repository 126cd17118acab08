#!/usr/bin/env python3
"""Helper of bench/results_write.sh: edits the generated engine deck and reads what a run wrote.
Plain python3, standard library only.

    results_write_deck.py deck IN OUT [--tstop T | --cycles K --n N] [--anim-dt DT | --anim-states S]
                               [--tfile-dt DT] [--anim CARD ...]
        Copies the engine deck IN written by bench/gen_shell_plate.py to OUT with
          --tstop T        a new Tstop (the /TFILE interval becomes Tstop / 100, as the generator does);
          --cycles K --n N Tstop = K shell time steps 0.9 h / sqrt(E/rho) of the N x N plate (h = 1000 / N mm);
          --anim-dt DT     the /ANIM/DT interval (1e20: the first and the last state only; dT 0 is an input
                           error for the engine);
          --anim-states S  /ANIM/DT interval = Tstop / S;
          --tfile-dt DT    the /TFILE interval;
          --anim CARD      an /ANIM card to add (e.g. /ANIM/TENS/STRESS), each once.
        Prints "tstop=... anim_dt=... tfile_dt=..." (shell-sourceable).

    results_write_deck.py measure OUTDIR ROOT DECK
        Reads what the engine wrote in OUTDIR (listing ROOT_0001.out, ROOT_summary.json, ROOT.hdf.series) and
        prints one shell-sourceable line:
          eng_wall      the engine's wall time (summary, s: the timed loop, without reading the model, writing
                        the mesh file and what happens after the loop)
          write_pct     the listing's "writing time ... (X % of the wall time)"
          write_text    the listing's writing time as printed (0.1 s resolution)
          write_s       write_pct / 100 * eng_wall: the same figure with more digits
          states        states in the series; in_run: written inside the timed loop (counted in write_s);
                        after_run: written by the engine after the loop (not counted in write_s)
          cycles, cost (us per element per cycle), nodes, elements, status

    results_write_deck.py stats FILE
        FILE: lines of numbers; prints "best median worst" (min, median, max).

The in_run / after_run split replays the engine's state scheduling (apps/engine_outputs.cpp): a state on
the first cycle, then on the first cycle whose time reaches Tstart + k dT (k the next multiple after the
previous state), all inside the timed loop; after the loop, one more state at the final time unless the
last state already has that time. So the last state of the series was written after the loop exactly
when its time did not reach the next /ANIM/DT time computed from the state before it.
"""
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
import radx_cards as rc  # noqa: E402  (the engine card layouts)

E_STEEL, RHO_STEEL = 210000.0, 7.85e-9   # as in bench/gen_shell_plate.py


def is_comment(s):
    return s.startswith("#") or s.strip() == ""


def find_card(lines, key):
    for i, s in enumerate(lines):
        if s.rstrip() == key or s.startswith(key + "/"):
            return i
    raise SystemExit("results_write_deck.py: no %s card" % key)


def next_data(lines, i):
    j = i + 1
    while j < len(lines) and is_comment(lines[j]):
        j += 1
    return j


def deck(argv):
    import argparse
    p = argparse.ArgumentParser(prog="results_write_deck.py deck")
    p.add_argument("src")
    p.add_argument("dst")
    p.add_argument("--tstop", type=float)
    p.add_argument("--cycles", type=float)
    p.add_argument("--n", type=int)
    p.add_argument("--anim-dt", type=float)
    p.add_argument("--anim-states", type=float)
    p.add_argument("--tfile-dt", type=float)
    p.add_argument("--anim", action="append", default=[])
    a = p.parse_args(argv)
    lines = open(a.src).read().splitlines()
    i_t = next_data(lines, find_card(lines, "/RUN"))
    tstop = float(lines[i_t].strip())
    if a.cycles is not None:
        if not a.n:
            p.error("--cycles needs --n")
        dt = 0.9 * (1000.0 / a.n) / math.sqrt(E_STEEL / RHO_STEEL)
        tstop = float("%.6g" % (a.cycles * dt))
    elif a.tstop is not None:
        tstop = a.tstop
    lines[i_t] = rc.data("/RUN", engine=True, Tstop=tstop)
    i_tf = next_data(lines, find_card(lines, "/TFILE"))
    tfile = a.tfile_dt if a.tfile_dt is not None else float("%.6g" % (tstop / 100))
    lines[i_tf] = rc.data("/TFILE", engine=True, dt_his=tfile)
    i_an = next_data(lines, find_card(lines, "/ANIM/DT"))
    anim = rc.read("/ANIM/DT", lines[i_an], engine=True)
    t0, dT = anim["Tstart"], anim["dT"]
    if a.anim_dt is not None:
        dT = a.anim_dt
    elif a.anim_states is not None:
        dT = float("%.6g" % (tstop / a.anim_states))
    else:
        dT = float(dT)
    lines[i_an] = rc.data("/ANIM/DT", engine=True, Tstart=float(t0 or 0.0), dT=dT)
    present = {s.strip() for s in lines if s.startswith("/ANIM/")}
    i_after = max(i for i, s in enumerate(lines) if s.startswith("/ANIM/"))
    extra = [c for c in dict.fromkeys(a.anim) if c not in present]
    lines[i_after + 1:i_after + 1] = extra
    with open(a.dst, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("tstop=%r anim_dt=%r tfile_dt=%r" % (tstop, dT, tfile))


def split_states(series, deck_path):
    """(states, in_run, after_run) of a run, see the module documentation."""
    times = [float(f["time"]) for f in json.load(open(series))["files"]]
    lines = open(deck_path).read().splitlines()
    anim = rc.read("/ANIM/DT", lines[next_data(lines, find_card(lines, "/ANIM/DT"))], engine=True)
    start, dT = float(anim["Tstart"] or 0.0), float(anim["dT"] or 0.0)
    in_run = 1 if times else 0
    for k in range(1, len(times)):
        prev = times[k - 1]
        nxt = math.inf
        if dT > 0:
            nxt = start
            if prev >= nxt:
                nxt += dT * (math.floor((prev - start) / dT) + 1.0)
        if times[k] >= nxt:
            in_run += 1
    return len(times), in_run, len(times) - in_run


def measure(argv):
    if len(argv) != 3:
        raise SystemExit("usage: results_write_deck.py measure OUTDIR ROOT DECK")
    out, root, deck_path = argv
    listing = open(os.path.join(out, root + "_0001.out")).read()
    summary = json.load(open(os.path.join(out, root + "_summary.json")))
    m = re.search(r"^ +writing time +(.*?) \(([0-9.]+) % of the wall time\)", listing, re.M)
    if not m:
        raise SystemExit("results_write_deck.py: no writing time in %s_0001.out" % root)
    write_text, pct = m.group(1), float(m.group(2))
    wall = float(summary["wall_seconds"])
    states, in_run, after = split_states(os.path.join(out, root + ".hdf.series"), deck_path)
    print("eng_wall=%.4f write_pct=%.1f write_text='%s' write_s=%.4f states=%d in_run=%d after_run=%d "
          "cycles=%d cost=%.4f nodes=%d elements=%d status=%s" %
          (wall, pct, write_text, pct / 100.0 * wall, states, in_run, after, summary["cycles"],
           summary["us_per_element_cycle"], summary["nodes"], summary["elements"], summary["status"]))


def stats(argv):
    v = sorted(float(x) for x in open(argv[0]).read().split())
    if not v:
        print("nan nan nan")
        return
    n = len(v)
    med = v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])
    print("%.4f %.4f %.4f" % (v[0], med, v[-1]))


def main(argv):
    cmds = {"deck": deck, "measure": measure, "stats": stats}
    if not argv or argv[0] not in cmds:
        print(__doc__, file=sys.stderr)
        return 2
    cmds[argv[0]](argv[1:])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
