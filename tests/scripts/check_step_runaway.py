"""A run whose time step collapses mid-run says so, and --stop-if-runaway or /DT/INTER/STOP stop it
(apps/runaway_watch.hpp, docs/engine.md "A run that will not end").

usage: /usr/bin/python3 check_step_runaway.py --starter RADX_STARTER --engine RADX_ENGINE
           --deck decks/verification/ctclaw_drop/CTCLAW_DROP_N1_0000.rad --out DIR

The deck is ctclaw_drop's cube falling at v0 = 1 m/s onto a plate through the bilinear /CTCLAW law; the check
makes its slope Kc 1e12 times steeper (a legal law): the cube flies free for about 2.5 ms at its bricks' step
(the starter's estimate of the whole run is about 1e3 cycles), then as its pairs close each votes the contact
spring's step 0.9 sqrt(2 m_s / (Kc A_s)), m_s = 0.5625 kg, A_s = 0.0025 m^2: 2.5e-10 s, which would leave
~2e7 cycles to the end time, 2e4 times the estimate. Three runs:
  * plain: the run goes on and warns once, at the cycle the step collapses (listing, standard error, summary
    warnings), naming interface 1 and a lower-face node, with that step (within 5 %: the pair votes its
    reach stiffness and damping too), the cycles left ((t_stop - t) / dt within 1 %, the message's 3 digits)
    and a projected wall time;
  * --stop-if-runaway: an error termination at that cycle (exit code 1, summary status "error" and its
    message), far from the end time;
  * /DT/INTER/STOP with Tmin = 1e-8 s (between the free flight's interface steps, none, and the collapsed one):
    an error termination naming the interface, the node and the minimum, at the same time within one step of
    the free flight.
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys

KC_FACTOR = 1e12


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


class Checks:
    def __init__(self):
        self.failures = 0

    def check(self, ok, msg):
        print(("ok   " if ok else "FAIL ") + msg)
        self.failures += 0 if ok else 1
        return ok


def prepare(deck, out, name, engine_cards):
    """The steep copy of the deck in out/name: Kc times KC_FACTOR, the run named `name`, the engine deck's /DT
    card replaced by `engine_cards` (a list of lines) when given."""
    os.makedirs(out, exist_ok=True)
    base = os.path.basename(deck)[:-len("_0000.rad")]
    with open(deck) as f:
        text = f.read()
    kc = re.search(r"n1\{Kc([0-9.eE+-]+)\}", text)
    steep = float(kc.group(1)) * KC_FACTOR
    text = text.replace(kc.group(0), "n1{Kc%g}" % steep).replace(base, name)
    with open(os.path.join(out, name + "_0000.rad"), "w") as f:
        f.write(text)
    with open(deck.replace("_0000.rad", "_0001.rad")) as f:
        eng = f.read().replace(base, name)
    if engine_cards:
        eng = re.sub(r"/DT\n#.*\n.*\n", "\n".join(engine_cards) + "\n", eng)
    with open(os.path.join(out, name + "_0001.rad"), "w") as f:
        f.write(eng)
    return steep


def summary(out, name):
    with open(os.path.join(out, name + "_summary.json")) as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--starter", required=True)
    ap.add_argument("--engine", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    a.starter, a.engine = os.path.abspath(a.starter), os.path.abspath(a.engine)
    shutil.rmtree(a.out, ignore_errors=True)
    c = Checks()
    m_s, area = 0.5625, 0.0025
    t_stop = None
    runs = {}
    for name, cards, extra in (("RUNAWAY", None, []), ("RUNAWAY_STOP", None, ["--stop-if-runaway"]),
                               ("RUNAWAY_INTER_STOP", ["/DT/INTER/STOP", "0.9 1e-8"], [])):
        kc = prepare(a.deck, a.out, name, cards)
        rc, _, err = run([a.starter, name + "_0000.rad"], a.out)
        c.check(rc == 0, "%s: starter exit code %d" % (name, rc))
        rc, _, err = run([a.engine, name + "_0001.rad", "--threads", "1", "--no-plot"] + extra, a.out)
        runs[name] = (rc, err, summary(a.out, name))
        with open(os.path.join(a.out, name + "_0001.rad")) as f:
            t_stop = float(re.search(r"/RUN/\S+\n(?:#.*\n)?\s*([0-9.eE+-]+)", f.read()).group(1))
    dt_pair = 0.9 * math.sqrt(2 * m_s / (kc * area))

    rc, err, s = runs["RUNAWAY"]
    c.check(rc == 0 and s["status"] == "normal", "plain run: normal termination (exit code %d, %s)" % (rc, s["status"]))
    warned = [w for w in s["warnings"] if "will not end" in w]
    c.check(len(warned) == 1, "plain run: one runaway warning in the summary (%d)" % len(warned))
    c.check(err.count("will not end") == 1, "plain run: one runaway warning on standard error")
    with open(os.path.join(a.out, "RUNAWAY_0001.out")) as f:
        c.check(f.read().count("will not end") == 1, "plain run: one runaway warning in the listing")
    if warned:
        w = warned[0]
        print("  " + w)
        m = re.search(r"cycle (\d+): .*fallen to ([0-9.e+-]+) s, set by interface 1 \(secondary node (\d+)\); the "
                      r"([0-9.e+-]+) s left to the end time take about ([0-9.e+-]+) more cycles, ([0-9.e+-]+) times "
                      r"the starter's estimate of the whole run \(([0-9.e+-]+) cycles\); at the ([0-9.e+-]+) us per "
                      r"cycle measured so far that is ([0-9.e+-]+) (s|min|h|days|years) of wall time", w)
        if c.check(m is not None, "plain run: the warning names interface 1, a secondary node, the step, the cycles "
                   "left, the estimate and the wall time"):
            dt, node, left_t, left, est = (float(m.group(2)), int(m.group(3)), float(m.group(4)),
                                           float(m.group(5)), float(m.group(7)))
            c.check(101 <= node <= 104, "the node %d is one of the cube's lower-face nodes 101..104" % node)
            c.check(abs(dt / dt_pair - 1) <= 0.05, "the step %.4g s is the pair's 0.9 sqrt(2 m_s / (Kc A_s)) = "
                    "%.4g s within 5 %%" % (dt, dt_pair))
            c.check(abs(left / (left_t / dt) - 1) <= 0.01, "cycles left %.4g = (t_stop - t) / dt = %.4g within 1 %%"
                    % (left, left_t / dt))
            c.check(left > 100 * est, "cycles left %.3g beyond 100 times the estimate %.3g" % (left, est))
    rc, err, s = runs["RUNAWAY_STOP"]
    c.check(rc == 1 and s["status"] == "error", "--stop-if-runaway: error termination (exit code %d, %s)"
            % (rc, s["status"]))
    c.check(s["message"].startswith("stopped by --stop-if-runaway at cycle ") and "interface 1" in s["message"],
            "--stop-if-runaway: the summary says why: %s" % s["message"][:120])
    c.check(s["time"] < 0.5 * t_stop, "--stop-if-runaway: stopped at %.4g s, far before the end %g s"
            % (s["time"], t_stop))
    stop_time = s["time"]
    rc, err, s = runs["RUNAWAY_INTER_STOP"]
    c.check(rc == 1 and s["status"] == "error", "/DT/INTER/STOP: error termination (exit code %d, %s)"
            % (rc, s["status"]))
    m = re.search(r"interface 1 \(secondary node (\d+)\) has the step ([0-9.e+-]+), below the /DT/INTER/STOP "
                  r"minimum 1e-08", s["message"])
    c.check(m is not None, "/DT/INTER/STOP: the message names the interface, the node and the minimum: %s"
            % s["message"])
    c.check(abs(s["time"] - stop_time) <= 2e-5, "/DT/INTER/STOP: stopped at %.6g s, the collapse at %.6g s "
            "(within two steps of the free flight)" % (s["time"], stop_time))
    if c.failures:
        print("%d check(s) failed" % c.failures)
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
