"""Redundant Lagrange-multiplier rows at engine level (decks/verification/lagdt_redundant,
scripts/make_contact_decks.py): a stiff cube falling flat on a fixed plate with every LAGDT pair that may switch
solved with multipliers (Tmin of /DT/INTER/CST far above every pair's step).

usage: /usr/bin/python3 check_lagdt_redundant.py --radx RADX
           --deck-shared decks/verification/lagdt_redundant/LAGDT_SHARED_NODES_0000.rad
           --deck-rigid decks/verification/lagdt_redundant/LAGDT_RIGID_BODY_0000.rad --out DIR

LAGDT_SHARED_NODES: each lower-face node over a vertex shared by four coplanar segments, two identical
interfaces (the same secondary nodes on the same surface), the plate fully fixed.
  * normal termination, no regularisation: after merging, each row holds a different node's translations
    (the plate's are fixed), so the system has full rank and needs no beta;
  * every row of interface 2 is merged into interface 1's: merged rows = interface 2's switched pair-cycles,
    and the rows solved = interface 1's (exact counts);
  * no lower-face node inside the gap by more than 1e-3 of it, in any time-history row (every cycle);
  * after the impact the cube moves up no faster than it came (|ZMOM| <= M v0: no energy created), and does
    move up (the rows released it);
LAGDT_RIGID_BODY: the cube is a rigid body.
  * its pairs stay on the penalty path: no switched pair, and one warning naming a lower-face node;
  * the penalty stops it inside the gap (largest penetration between 0 and the gap);
Both: energy balance within 1 % (docs/theory/verification.md C).
"""
import argparse
import os
import re
import sys

import numpy as np

import check_contact_common as cc


def shared(radx, deck, out, c):
    m = cc.Model(deck)
    name = cc.run_radx(radx, deck, out)
    s = cc.read_summary(out, name)
    c.check(s["status"] == "normal", "normal termination (%s)" % s["status"])
    lag = s["lagrange_solver"]
    i1, i2 = s["interfaces"]
    c.check(lag["regularisations"] == 0, "no regularisation (%d)" % lag["regularisations"])
    c.check(i2["switched_pairs_total"] > 0 and lag["merged_rows"] == i2["switched_pairs_total"] and
            lag["rows_total"] == i1["switched_pairs_total"],
            "rows merged: %d (interface 2's pair-cycles %d), rows solved %d (interface 1's %d)"
            % (lag["merged_rows"], i2["switched_pairs_total"], lag["rows_total"], i1["switched_pairs_total"]))
    it = m.interfaces[1]
    gap = it["Gapmin"]
    secondary = m.groups[it["grnd"]]
    z_plate = m.flat_z([n for _, ns, _ in m.shells.values() for n in ns], "the main plate")
    th = cc.read_th(out, name)
    pen = cc.penetrations(m, th, secondary, gap, z_plate)
    c.check(pen.max() <= 1e-3 * gap, "largest penetration into the gap %.3g m (allowed 1e-3 of the gap %g m)"
            % (pen.max(), gap))
    _, M, vel = m.moving_body()
    p0 = M * vel[2]
    p_end = s["momentum"][2]
    c.check(0 < p_end <= abs(p0) * (1 + 1e-9), "momentum along Z %.6g -> %.6g (the cube moves up, no faster "
            "than it came)" % (p0, p_end))
    cc.check_energy_error(c, s)


def rigid(radx, deck, out, c):
    m = cc.Model(deck)
    name = cc.run_radx(radx, deck, out)
    s = cc.read_summary(out, name)
    c.check(s["status"] == "normal", "normal termination (%s)" % s["status"])
    (i1,) = s["interfaces"]
    c.check(i1["switched_pairs_total"] == 0, "no pair switched (%d pair-cycles)" % i1["switched_pairs_total"])
    it = m.interfaces[1]
    warnings = re.findall(r"node (\d+) has an imposed velocity, a rigid body or a rigid wall: LAGDT pairs on "
                          r"such nodes stay on the penalty path", cc.read_listing(out, name))
    c.check(len(warnings) == 1 and int(warnings[0]) in m.groups[it["grnd"]],
            "one warning naming a lower-face node (%s)" % ", ".join(warnings))
    gap = it["Gapmin"]
    c.check(0 < i1["max_penetration"] < gap, "the penalty stops the body inside the gap: largest penetration "
            "%.4g m (gap %g m)" % (i1["max_penetration"], gap))
    cc.check_energy_error(c, s)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--deck-shared", required=True)
    ap.add_argument("--deck-rigid", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    c1, c2 = cc.Checks("LAGDT_SHARED_NODES"), cc.Checks("LAGDT_RIGID_BODY")
    shared(a.radx, a.deck_shared, os.path.join(a.out, "shared"), c1)
    rigid(a.radx, a.deck_rigid, os.path.join(a.out, "rigid"), c2)
    cc.finish([c1, c2])


if __name__ == "__main__":
    sys.exit(main())
