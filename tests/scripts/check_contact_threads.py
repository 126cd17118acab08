"""Thread determinism with contact: the same deck run with --threads 1 and --threads 2 gives bit-identical results.

usage: /usr/bin/python3 check_contact_threads.py --radx RADX
           --decks decks/verification/tube_crush/TUBE_CRUSH_0000.rad decks/block_on_plate/BLOCK_ON_PLATE_0000.rad
           --out DIR [--threads 1 2]

The element forces are computed by OpenMP threads over element groups and the TYPE7 contact scatters its forces
node by node in a fixed order (contact/type7_engine.cpp), so the thread count must not change a single bit of
the results. Each deck runs once per thread count; compared with the first count:

  * the summary: status, cycles, final time and step, every energy (kinetic, internal, hourglass, contact
    elastic, damping, friction, external work, error), the added mass, the momentum and each interface's
    active pairs and largest penetration: exactly equal (==); and `threads` must be the count asked for, so
    that the comparison is not between two one-thread runs;
  * the time history: every dataset of NAME_th.h5, bit for bit (np.array_equal on the float64 arrays);
  * the animation states: the same number of states, every state's Points (float64 coordinates) bit for bit,
    and the last state's point arrays (velocity, displacement, contact force) and cell arrays bit for bit.

There is no tolerance: any difference, even in the last bit, is a failure (a race or an order-dependent sum).
The decks: tube_crush (self-contact of a folding shell tube: many pairs, both sides of the contact moving,
Johnson-Cook shells in several element groups) and the default block_on_plate deck (two-pass contact with
Iform 1 and 2 friction and Inacti 6, shells and bricks).
"""
import glob
import os

import h5py
import numpy as np

import check_contact_common as cc


def state_files(out, name):
    return sorted(glob.glob(os.path.join(out, name + "_[0-9][0-9][0-9][0-9][0-9][0-9].hdf")))


def arrays(path):
    """{dataset path: array} of one state file's points, point data and cell data."""
    out = {}
    with h5py.File(path, "r") as f:
        def visit(p, obj):
            if isinstance(obj, h5py.Dataset) and (p == "VTKHDF/Points" or p.startswith("VTKHDF/PointData/") or
                                                  p.startswith("VTKHDF/CellData/")):
                out[p] = obj[()]
        f.visititems(visit)
    return out


def summary_key(s):
    keep = ("status", "message", "cycles", "time", "dt", "mass", "added_mass", "momentum", "energy", "interfaces")
    return {k: s[k] for k in keep if k in s}


def one_deck(radx, deck, out, checks, threads):
    runs = []
    for n in threads:
        o = os.path.join(out, "threads%d" % n)
        name = cc.run_radx(radx, deck, o, ("--threads", str(n)))
        runs.append((n, o, name))
    n0, o0, name = runs[0]
    s0 = cc.read_summary(o0, name)
    th0 = cc.read_th(o0, name)
    st0 = state_files(o0, name)
    print("%s: %d cycles, %d states, %d time-history groups" % (os.path.basename(deck), s0["cycles"], len(st0),
                                                               len(th0)))
    checks.check(s0["threads"] == n0, "the reference run used %d thread(s) (summary: %d)" % (n0, s0["threads"]))
    for n, o, _ in runs[1:]:
        s = cc.read_summary(o, name)
        checks.check(s["threads"] == n, "the run asked for %d threads used %d" % (n, s["threads"]))
        a, b = summary_key(s0), summary_key(s)
        diff = [k for k in a if a[k] != b.get(k)]
        checks.check(not diff, "%d vs %d threads: summary identical (energies, cycles, momentum, interfaces)%s"
                     % (n0, n, "" if not diff else "; differs in " + ", ".join(diff)))
        if "energy" in diff:
            for k in a["energy"]:
                if a["energy"][k] != b["energy"][k]:
                    print("    energy %s: %r vs %r" % (k, a["energy"][k], b["energy"][k]))
        th = cc.read_th(o, name)
        bad = [g for g in th0 if g not in th or th0[g][0].shape != th[g][0].shape or
               not np.array_equal(th0[g][0], th[g][0])]
        checks.check(set(th0) == set(th) and not bad, "%d vs %d threads: time history bit for bit (%d groups, %d rows)"
                     "%s" % (n0, n, len(th0), len(next(iter(th0.values()))[0]),
                             "" if not bad else "; differs in " + ", ".join(bad)))
        st = state_files(o, name)
        checks.check(len(st) == len(st0), "%d vs %d threads: %d and %d states" % (n0, n, len(st0), len(st)))
        first_bad = None
        for p0, p1 in zip(st0, st):
            a0, a1 = arrays(p0)["VTKHDF/Points"], arrays(p1)["VTKHDF/Points"]
            if a0.dtype != a1.dtype or not np.array_equal(a0, a1):
                first_bad = os.path.basename(p1)
                break
        checks.check(first_bad is None, "%d vs %d threads: Points of every state bit for bit%s"
                     % (n0, n, "" if first_bad is None else "; first difference in " + first_bad))
        if st0 and st:
            last0, last1 = arrays(st0[-1]), arrays(st[-1])
            bad = [k for k in last0 if k not in last1 or not np.array_equal(last0[k], last1[k])]
            checks.check(set(last0) == set(last1) and not bad, "%d vs %d threads: last state %s, %d arrays bit for "
                         "bit%s" % (n0, n, os.path.basename(st[-1]), len(last0),
                                    "" if not bad else "; differs in " + ", ".join(bad)))


if __name__ == "__main__":
    cc.main_per_deck(one_deck, options=[("--threads", dict(nargs="+", type=int, default=[1, 2]))])
