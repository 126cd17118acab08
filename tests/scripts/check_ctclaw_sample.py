"""The /CTCLAW sample deck (decks/block_on_plate_ctclaw) runs with its laws and closes its energy balance.

usage: /usr/bin/python3 check_ctclaw_sample.py --radx RADX --deck BLOCK_ON_PLATE_CTCLAW_0000.rad --out DIR

Checks, from the run's NAME_summary.json and starter listing:
  * every /CTCLAW of the deck (read here from the deck's own text) is echoed in the starter listing with its law
    string, so the laws were read and attached to their interfaces;
  * the laws acted: the contact energies (elastic, damping, friction) add up to more than 1 % of the initial
    energy (the block's impact is carried by interface 1's law);
  * the energy balance closes within 1 %, as on the law decks (the error is the engine's E / (E0 + W) - 1 with
    contact energies included, docs/theory/verification.md C).
"""
import argparse
import json
import os
import re
import subprocess
import sys


def ctclaws(deck):
    """(law id, law string) of every /CTCLAW in the deck: the first data line after the interface card."""
    lines = [l.rstrip("\n") for l in open(deck) if not l.startswith("#")]
    out = []
    for k, l in enumerate(lines):
        m = re.match(r"/CTCLAW/(\d+)", l)
        if m:
            out.append((int(m.group(1)), lines[k + 3].replace(" ", "")))
    return out


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--radx", required=True)
    p.add_argument("--deck", required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    run = subprocess.run([a.radx, "run", os.path.abspath(a.deck), "--out", a.out], capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout[-3000:], run.stderr[-3000:])
        return 1
    name = os.path.basename(a.deck)[:-len("_0000.rad")]
    listing = open(os.path.join(a.out, name + "_0000.out")).read()
    summary = json.load(open(os.path.join(a.out, name + "_summary.json")))
    failures = []
    laws = ctclaws(a.deck)
    if not laws:
        failures.append("the deck has no /CTCLAW")
    for law_id, text in laws:
        if "/CTCLAW/%d  %s" % (law_id, text) not in listing:
            failures.append("/CTCLAW/%d (%s) is not echoed in the starter listing" % (law_id, text))
    e = summary["energy"]
    contact = e["contact_elastic"] + e["contact_damping"] + e["contact_friction"]
    print("contact energies %.6g of E0 %.6g; energy error %.4f %%" % (contact, e["initial_total"], e["error_percent"]))
    if not contact > 0.01 * e["initial_total"]:
        failures.append("the contact energies (%g) are not above 1 %% of E0: the laws did not act" % contact)
    if not abs(e["error_percent"]) <= 1.0:
        failures.append("energy error %.4f %% is beyond 1 %%" % e["error_percent"])
    for f in failures:
        print("FAILED:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
