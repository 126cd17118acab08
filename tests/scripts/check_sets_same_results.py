"""A /SET/GENERAL that holds what the group it replaces holds gives the same results, to the bit.

usage: /usr/bin/python3 check_sets_same_results.py --radx RADX --groups DECK --sets DECK... --out DIR

The decks describe one model: --groups with /GRNOD and /SURF (decks/block_on_plate), each --sets deck with the
same node groups and surfaces written as sets: decks/block_on_plate_sets (the clamped edge nodes as two
/SET/COLLECT of one id, a NODE_G and a NODE clause; one PART set per part that is both its node group and its
contact surface) and decks/verification/set_operations (the block as sets 20 or 21 intersected with set 22,
the plate as ALL less the block). A set is resolved in the starter into the same node groups and segments
(docs/sets.md), so the engine cannot tell the runs apart; OpenRadioss gives these decks the same energies at
every printed cycle too. Each runs with radx run and is compared with the groups run without tolerance:

  * the summary: status, cycles, final time and step, mass, momentum, every energy and each interface's pairs
    and largest penetration, exactly equal (==);
  * the time history: every dataset of NAME_th.h5, bit for bit (np.array_equal).

Any difference, even in the last bit, is a failure: a set that resolved to other members or another order.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_contact_common as cc  # noqa: E402


def summary_key(s):
    keep = ("status", "message", "cycles", "time", "dt", "mass", "added_mass", "momentum", "energy", "interfaces")
    return {k: s[k] for k in keep if k in s}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--groups", required=True)
    ap.add_argument("--sets", nargs="+", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    og = os.path.join(a.out, "groups")
    ng = cc.run_radx(a.radx, a.groups, og)
    sg, tg = cc.read_summary(og, ng), cc.read_th(og, ng)
    all_checks = []
    for deck in a.sets:
        ns = os.path.basename(deck).replace("_0000.rad", "")
        checks = cc.Checks(ns + " vs groups")
        os_ = os.path.join(a.out, ns)
        cc.run_radx(a.radx, deck, os_)
        ss, ts = cc.read_summary(os_, ns), cc.read_th(os_, ns)
        ka, kb = summary_key(sg), summary_key(ss)
        diff = [k for k in ka if ka[k] != kb.get(k)]
        checks.check(not diff, "summary identical (%d cycles, energies, momentum, interfaces)%s"
                     % (sg["cycles"], "" if not diff else "; differs in " + ", ".join(diff)))
        bad = [g for g in tg if g not in ts or tg[g][0].shape != ts[g][0].shape or
               not np.array_equal(tg[g][0], ts[g][0])]
        checks.check(set(tg) == set(ts) and not bad, "time history bit for bit (%d groups, %d rows)%s"
                     % (len(tg), len(next(iter(tg.values()))[0]), "" if not bad else "; differs in " + ", ".join(bad)))
        all_checks.append(checks)
    cc.finish(all_checks)


if __name__ == "__main__":
    main()
