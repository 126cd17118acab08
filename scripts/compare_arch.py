#!/usr/bin/env python3
"""How far two builds of radx (two -march levels, docs/build-arch.md) differ on the sample and verification decks.

Reads the `radx regress --summary` JSON of each build run on the same decks (scripts/test.sh: the default
build's regression.decks test and the x86-64-v3 build's) and, for every deck both ran, prints the relative
difference of the final energies, internal (IE), kinetic (KE: translational plus rotational) and external
work (EXT), and of every quantity of the deck's NAME.ref as a share of that quantity's physical tolerance.
Fails (exit 1) when a deck's energies differ by more than --tol, or when the builds' difference in any .ref
quantity uses more than --share of its tolerance.

Relative difference of an energy: |a - b| / max(|a|, |b|, floor), the floor 1e-3 of the deck's largest
energy, so that an energy near zero (the external work of a free flight, the kinetic energy of a bar come to
rest) is compared with the deck's energy scale rather than with its own round-off.

Why the bars: the .ref energies are held to 1 % (some to 0.1 %) of the deck's energy, so a build-to-build
difference of 1e-3 of the energy scale would already be a tenth of the physics tolerance. Rounding
differences (an fma rounds once where a multiply then an add round twice, about 1e-16 relative) grow in a
run by the number of cycles and by any instability (contact detection, yield, failure, buckling); 1e-3
leaves room for that growth in the chaotic decks while catching a real difference, such as a kernel that
vectorised wrongly. --share 0.25 asks the two builds to agree with each other four times better than either
must agree with the reference.
Usage: compare_arch.py SUMMARY_A SUMMARY_B [--names A B] [--tol 1e-3] [--share 0.25] [--markdown]
"""
import argparse
import json
import sys


def load(path: str) -> dict:
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    return {d["deck"]: d for d in data["decks"]}


def energies(r: dict) -> dict:
    return {"IE": r["IENERGY"], "KE": r["KENERGYT"] + r["KENERGYR"], "EXT": r["EXTWORK"]}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("summary_a")
    ap.add_argument("summary_b")
    ap.add_argument("--names", nargs=2, default=["A", "B"], help="the builds' names for the table")
    ap.add_argument("--tol", type=float, default=1e-3, help="largest relative energy difference (default 1e-3)")
    ap.add_argument("--share", type=float, default=0.25,
                    help="largest difference in a .ref quantity, as a share of its tolerance (default 0.25)")
    ap.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    args = ap.parse_args()
    a, b = load(args.summary_a), load(args.summary_b)
    rows = []
    missing = []
    for deck in sorted(a):
        ra, rb = a[deck].get("radx"), b.get(deck, {}).get("radx")
        if ra is None and rb is None:
            continue  # starter-only and invalid decks: no run to compare
        if ra is None or rb is None:
            missing.append(deck)
            continue
        ea, eb = energies(ra), energies(rb)
        scale = max(abs(v) for v in list(ea.values()) + list(eb.values()))
        floor = 1e-3 * scale if scale > 0 else 1e-300
        rel = {k: abs(ea[k] - eb[k]) / max(abs(ea[k]), abs(eb[k]), floor) for k in ea}
        # The .ref quantities: the builds' difference over the tolerance the reference allows.
        checks_b = {c["quantity"]: c for c in b[deck].get("checks") or []}
        share, worst = 0.0, ""
        for c in a[deck].get("checks") or []:
            cb = checks_b.get(c["quantity"])
            if cb is None or c["radx"] is None or cb["radx"] is None or not c["allowed"]:
                continue
            s = abs(c["radx"] - cb["radx"]) / c["allowed"]
            if s > share:
                share, worst = s, c["quantity"]
        rows.append((deck, ra["cycles"], rb["cycles"], rel, max(rel.values()), share, worst))
    for d in sorted(b):
        if d not in a and b[d].get("radx") is not None:
            missing.append(d)

    n = args.names
    if args.markdown:
        print(f"| deck | cycles {n[0]} | cycles {n[1]} | IE | KE | EXT | largest .ref difference / tolerance |")
        print("|---|---:|---:|---:|---:|---:|---|")
        for deck, ca, cb, rel, _, share, worst in rows:
            print(f"| {deck} | {ca} | {cb} | {rel['IE']:.1e} | {rel['KE']:.1e} | {rel['EXT']:.1e} | "
                  f"{share:.1e}{' (' + worst + ')' if worst else ''} |")
    else:
        print(f"{'deck':58s} {'cycles ' + n[0]:>14s} {'cycles ' + n[1]:>14s} {'IE':>8s} {'KE':>8s} {'EXT':>8s}"
              f"  .ref diff/tol")
        for deck, ca, cb, rel, _, share, worst in rows:
            print(f"{deck:58s} {ca:14d} {cb:14d} {rel['IE']:8.1e} {rel['KE']:8.1e} {rel['EXT']:8.1e}"
                  f"  {share:.1e} {worst}")
    if not rows:
        print("no deck ran in both builds")
        return 1
    worst_e = max(rows, key=lambda r: r[4])
    worst_s = max(rows, key=lambda r: r[5])
    identical = sum(1 for r in rows if r[4] == 0.0 and r[5] == 0.0)
    print(f"{len(rows)} decks compared, {identical} identical to the last bit in every compared value; largest "
          f"energy difference {worst_e[4]:.2e} ({worst_e[0]}), bar {args.tol:g}; largest .ref difference "
          f"{worst_s[5]:.2e} of its tolerance ({worst_s[0]} {worst_s[6]}), bar {args.share:g}")
    failed = False
    if missing:
        print("ran in one build only: " + ", ".join(missing))
        failed = True
    for deck, _, _, rel, m, share, worst in rows:
        if m > args.tol:
            print(f"FAIL {deck}: the builds' energies differ by {m:.2e} relative (IE {rel['IE']:.1e}, KE "
                  f"{rel['KE']:.1e}, EXT {rel['EXT']:.1e}), more than {args.tol:g}")
            failed = True
        if share > args.share:
            print(f"FAIL {deck}: the builds differ in {worst} by {share:.2f} of its .ref tolerance, more than "
                  f"{args.share:g}")
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
