#!/usr/bin/env python3
"""The embedded default deck shows what radx is for: `radx run` with no deck must switch tens of LAGDT pairs
to Lagrange multipliers at impact, book friction work on them after the switch, close its energy balance within
1 %, and lose less than 5 % of the impact energy to hourglass, with no hourglass warning in the listing.

The impact energy is computed from the deck's own figures, not from the run: 1/2 M v0^2 with the block's mass
rho L^3 (2.7e-9 Mg/mm^3, 20 mm cube) and v0 = 10 m/s, 1080 mJ.

Usage: check_default_deck.py --radx RADX
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

RHO_BLOCK = 2.7e-9   # Mg/mm^3, the block's /MAT/LAW1 density
L_BLOCK = 20.0       # mm, the block's side
V0 = 1.0e4           # mm/s, the block's /INIVEL
IMPACT_ENERGY = 0.5 * RHO_BLOCK * L_BLOCK ** 3 * V0 ** 2  # mJ


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--radx", required=True)
    args = p.parse_args()
    failures = []
    with tempfile.TemporaryDirectory() as out:
        r = subprocess.run([args.radx, "run", "--out", out, "--no-plot"], capture_output=True, text=True)
        if r.returncode != 0:
            print(r.stdout[-3000:], r.stderr[-3000:])
            print("FAIL: radx run on the default deck exited %d" % r.returncode)
            return 1
        summaries = [f for f in os.listdir(out) if f.endswith("_summary.json")]
        if len(summaries) != 1:
            print("FAIL: expected one summary in %s, found %s" % (out, summaries))
            return 1
        with open(os.path.join(out, summaries[0])) as f:
            s = json.load(f)
        listing = open(os.path.join(out, summaries[0].replace("_summary.json", "_0001.out"))).read()
    e = s["energy"]
    switched = max((i["switched_pairs_max"] for i in s["interfaces"]), default=0)
    checks = [
        # the initial kinetic energy is the impact energy (the deck starts the block at v0): 1e-6 relative
        ("initial energy is 1/2 M v0^2 = %.1f mJ" % IMPACT_ENERGY,
         abs(e["initial_total"] - IMPACT_ENERGY) <= 1e-6 * IMPACT_ENERGY, e["initial_total"]),
        # "tens of pairs": the block's bottom face has 25 nodes; at least 10 must switch
        ("at least 10 LAGDT pairs switch at once", switched >= 10, switched),
        ("the multipliers do work (contact, Lagrange > 1 % of the impact energy)",
         e["contact_lagrange"] > 0.01 * IMPACT_ENERGY, e["contact_lagrange"]),
        # friction on the switched pairs: the penalty pairs of interface 1 never hold the block (they switch)
        ("friction work after the switch (> 0.5 % of the impact energy)",
         e["contact_friction"] > 0.005 * IMPACT_ENERGY, e["contact_friction"]),
        ("energy balance within 1 %", abs(e["error_percent"]) < 1.0, e["error_percent"]),
        ("hourglass under 5 % of the impact energy", e["hourglass"] < 0.05 * IMPACT_ENERGY, e["hourglass"]),
        ("no hourglass warning in the listing", "hourglass energy is" not in listing, None),
        ("normal termination", s["status"] == "normal", s["status"]),
    ]
    for what, ok, value in checks:
        print("%s  %s%s" % ("ok  " if ok else "FAIL", what, "" if value is None else " (%s)" % value))
        if not ok:
            failures.append(what)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
