"""A run whose time step has fallen for good says so, --stop-if-runaway or /DT/INTER/STOP stop it, and a fall
that passes says nothing (apps/runaway_watch.hpp, docs/engine.md "A run that will not end").

usage: /usr/bin/python3 check_step_runaway.py --starter RADX_STARTER --engine RADX_ENGINE
           --deck-drop decks/verification/ctclaw_drop/CTCLAW_DROP_N1_0000.rad --out DIR

Resting (the decks are written by scripts/make_ctclaw_decks.py's sliding_deck, as ctclaw_sliding's): the
sliding cube (M = 9 kg, lower-face nodes of m_s = 0.5625 kg) rests from the first cycle on a legal but steep
bilinear /CTCLAW law, Kc = 4e18 Pa/m, a pair stiffness Kc A_s = 1e16 N/m (A_s = 0.0025 m^2): each pair votes
the spring step 0.9 sqrt(2 m_s / (Kc A_s)) = 9.5e-9 s, 1/800 of the bricks' 7.6e-6 s, for the whole run (end
time 1e-4 s, about 1e4 cycles; the starter's estimate is about 13). Three runs:
  * plain: it runs to its end and warns once (listing, standard error, summary warnings) on the first listing
    cycle at least 1000 cycles into the fall (cycle 2000, /PRINT 2000), naming interface 1 and a lower-face node,
    with that step (within 5 %: the pair votes its damping too), the cycles left ((t_stop - t) / dt within 1 %,
    the message's 3 digits) beyond 100 times the estimate, and a projected wall time;
  * --stop-if-runaway: an error termination (exit code 1, summary status "error" and its message) at that
    cycle, before the end time;
  * /DT/INTER/STOP with Tmin = 1e-7 s (above the pairs' step, below the bricks'): an error termination at the
    first cycle naming the interface, the node and the minimum.
Passing (ctclaw_drop's N1 cube, its law made 1e12 times steeper): the impact drops the step to 2.5e-10 s, which
would leave 2e7 cycles, and the step grows back within a few hundred cycles: the run ends normally in under
2000 cycles and says nothing (a projection from the dip would have been a false alarm).
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))

import make_ctclaw_decks as mk  # noqa: E402  (the sliding cube's decks)
import make_verification_decks as v  # noqa: E402

KC = 4e18          # Pa/m
T_STOP = 1e-4      # s
DROP_FACTOR = 1e12


class Checks:
    def __init__(self):
        self.failures = 0

    def check(self, ok, msg):
        print(("ok   " if ok else "FAIL ") + msg)
        self.failures += 0 if ok else 1
        return ok


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=600)
    return p.returncode, p.stderr


def with_dt(engine_lines, card):
    """The engine deck with its /DT card (keyword, comment, values) replaced by `card` (lines), if given."""
    if not card:
        return engine_lines
    k = engine_lines.index("/DT")
    return engine_lines[:k] + card + engine_lines[k + 3:]


def resting_decks(out, name, card):
    p = dict(mk.SLIDE, K=KC * 0.0025, T_STOP=T_STOP)
    D, E, _ = mk.sliding_deck(name, "n1s11{Kc%g,Mu0.3}" % KC, "X", "steep bilinear law, exact Coulomb", False, p)
    v.write(os.path.join(out, name + "_0000.rad"), D)
    v.write(os.path.join(out, name + "_0001.rad"), with_dt(E, card))


def drop_decks(deck, out, name):
    base = os.path.basename(deck)[:-len("_0000.rad")]
    with open(deck) as f:
        text = f.read()
    kc = re.search(r"n1\{Kc([0-9.eE+-]+)\}", text)
    text = text.replace(kc.group(0), "n1{Kc%g}" % (float(kc.group(1)) * DROP_FACTOR)).replace(base, name)
    with open(os.path.join(out, name + "_0000.rad"), "w") as f:
        f.write(text)
    with open(deck.replace("_0000.rad", "_0001.rad")) as f:
        eng = f.read().replace(base, name)
    with open(os.path.join(out, name + "_0001.rad"), "w") as f:
        f.write(eng)


def run_case(c, a, name, extra):
    rc, _ = run([a.starter, name + "_0000.rad"], a.out)
    c.check(rc == 0, "%s: starter exit code %d" % (name, rc))
    rc, err = run([a.engine, name + "_0001.rad", "--threads", "1", "--no-plot"] + extra, a.out)
    with open(os.path.join(a.out, name + "_summary.json")) as f:
        s = json.load(f)
    with open(os.path.join(a.out, name + "_0001.out")) as f:
        listing = f.read()
    return rc, err, s, listing


def check_warning(c, rc, err, s, listing, dt_pair):
    c.check(rc == 0 and s["status"] == "normal", "plain: normal termination (exit code %d, %s)" % (rc, s["status"]))
    warned = [w for w in s["warnings"] if "will not end" in w]
    c.check(len(warned) == 1, "plain: one runaway warning in the summary (%d)" % len(warned))
    c.check(err.count("will not end") == 1, "plain: one runaway warning on standard error")
    c.check(listing.count("will not end") == 1, "plain: one runaway warning in the listing")
    if not warned:
        return
    w = warned[0]
    print("  " + w)
    m = re.search(r"cycle (\d+): .*fallen to ([0-9.e+-]+) s \(since cycle (\d+)\), set by interface 1 \(secondary "
                  r"node (\d+)\); the ([0-9.e+-]+) s left to the end time take about ([0-9.e+-]+) more cycles, "
                  r"([0-9.e+-]+) times the starter's estimate of the whole run \(([0-9.e+-]+) cycles\); at the "
                  r"([0-9.e+-]+) us per cycle measured so far that is ([0-9.e+-]+) (s|min|h|days|years) of wall time",
                  w)
    if not c.check(m is not None, "plain: the warning names interface 1, a secondary node, the step, the cycles "
                   "left, the estimate and the wall time"):
        return
    cycle, dt, since, node = int(m.group(1)), float(m.group(2)), int(m.group(3)), int(m.group(4))
    left_t, left, est = float(m.group(5)), float(m.group(6)), float(m.group(8))
    c.check(cycle - since >= 1000, "plain: said at cycle %d, %d cycles into the fall (at least 1000)"
            % (cycle, cycle - since))
    c.check(101 <= node <= 104, "plain: node %d is one of the cube's lower-face nodes 101..104" % node)
    c.check(abs(dt / dt_pair - 1) <= 0.05, "plain: the step %.4g s is the pair's 0.9 sqrt(2 m_s / (Kc A_s)) = "
            "%.4g s within 5 %%" % (dt, dt_pair))
    c.check(abs(left / (left_t / dt) - 1) <= 0.01, "plain: cycles left %.4g = (t_stop - t) / dt = %.4g within 1 %%"
            % (left, left_t / dt))
    c.check(left > 100 * est, "plain: cycles left %.3g beyond 100 times the estimate %.3g" % (left, est))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--starter", required=True)
    ap.add_argument("--engine", required=True)
    ap.add_argument("--deck-drop", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    a.starter, a.engine = os.path.abspath(a.starter), os.path.abspath(a.engine)
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    c = Checks()
    dt_pair = 0.9 * math.sqrt(2 * 0.5625 / (KC * 0.0025))

    resting_decks(a.out, "RESTING", None)
    check_warning(c, *run_case(c, a, "RESTING", []), dt_pair)

    resting_decks(a.out, "RESTING_STOP", None)
    rc, err, s, _ = run_case(c, a, "RESTING_STOP", ["--stop-if-runaway"])
    c.check(rc == 1 and s["status"] == "error", "--stop-if-runaway: error termination (exit code %d, %s)"
            % (rc, s["status"]))
    c.check(s["message"].startswith("stopped by --stop-if-runaway at cycle ") and "interface 1" in s["message"],
            "--stop-if-runaway: the summary says why: %s" % s["message"][:140])
    c.check(s["time"] < 0.5 * T_STOP, "--stop-if-runaway: stopped at %.4g s, before the end %g s"
            % (s["time"], T_STOP))

    resting_decks(a.out, "RESTING_INTER_STOP", ["/DT/INTER/STOP", "#             Tscale                Tmin",
                                                 "                 0.0                1e-7"])
    rc, err, s, _ = run_case(c, a, "RESTING_INTER_STOP", [])
    c.check(rc == 1 and s["status"] == "error", "/DT/INTER/STOP: error termination (exit code %d, %s)"
            % (rc, s["status"]))
    m = re.search(r"interface 1 \(secondary node (\d+)\) has the step ([0-9.e+-]+), below the /DT/INTER/STOP "
                  r"minimum 1e-07 \(cycle 0,", s["message"])
    c.check(m is not None, "/DT/INTER/STOP: at cycle 0, naming the interface, the node and the minimum: %s"
            % s["message"])

    drop_decks(a.deck_drop, a.out, "PASSING")
    rc, err, s, listing = run_case(c, a, "PASSING", [])
    c.check(rc == 0 and s["status"] == "normal", "passing fall: normal termination (exit code %d, %s)"
            % (rc, s["status"]))
    c.check(s["cycles"] < 2000, "passing fall: the run took %d cycles (under 2000)" % s["cycles"])
    c.check("will not end" not in listing + err + json.dumps(s["warnings"]), "passing fall: no runaway warning")

    if c.failures:
        print("%d check(s) failed" % c.failures)
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
