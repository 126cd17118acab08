#!/usr/bin/env python3
"""`radx th --filter CFCnnn` from the command line, on a real time history (decks/block_impact):

* a constant channel (the model's mass) comes out unchanged: a phaseless Butterworth passes a constant with
  gain 1 (to round-off, 1e-12 relative);
* a channel that rises (the plate's internal energy) is filtered, not copied: CFC60 (F_H = 100 Hz) on a 2 ms
  run must change it;
* a note says when the rows are sampled below SAE J211's 10 F_H (F_H = 5/3 CFC): written every 1e-4 s
  (10 kHz), CFC1000 (16.7 kHz needed) gets the note and CFC60 (1 kHz needed) does not; written every 1e-5 s
  (100 kHz) neither does.

Usage: check_th_filter.py --radx RADX --root SOURCE_ROOT --out DIR
"""
import argparse
import csv
import os
import shutil
import subprocess

from results_common import check, finish, run_radx, write_engine_deck


def th_csv(radx, th, var, cfc, out_csv):
    args = [radx, "th", th, "--csv", "--var", var, "-o", out_csv] + (["--filter", cfc] if cfc else [])
    r = subprocess.run(args, capture_output=True, text=True)
    check(r.returncode == 0, "radx th %s exited %d: %s" % (" ".join(args[2:]), r.returncode, r.stderr))
    with open(out_csv) as f:
        rows = list(csv.reader(f))
    return [[float(x) for x in row] for row in rows[1:]], r.stderr


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--radx", required=True)
    p.add_argument("--root", required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args()
    deck_dir = os.path.join(a.root, "decks", "block_impact")
    for th_dt in (1e-5, 1e-4):
        work = os.path.join(a.out, "dt%g" % th_dt)
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        shutil.copy(os.path.join(deck_dir, "BLOCK_IMPACT_0000.rad"), work)
        write_engine_deck(os.path.join(deck_dir, "BLOCK_IMPACT_0001.rad"), os.path.join(work, "BLOCK_IMPACT_0001.rad"),
                          th_dt=th_dt)
        run_radx(a.radx, os.path.join(work, "BLOCK_IMPACT_0000.rad"), work)
        th = os.path.join(work, "BLOCK_IMPACT_th.h5")
        mass, _ = th_csv(a.radx, th, "global:MASS", None, os.path.join(work, "mass.csv"))
        mass_f, _ = th_csv(a.radx, th, "global:MASS", "CFC60", os.path.join(work, "mass_f.csv"))
        worst = max(abs(f[1] - r[1]) / abs(r[1]) for f, r in zip(mass_f, mass))
        check(worst < 1e-12, "dt %g: the constant mass moved by %g (relative) through CFC60" % (th_dt, worst))
        ie, _ = th_csv(a.radx, th, "part/2:1:IE", None, os.path.join(work, "ie.csv"))
        ie_f, note60 = th_csv(a.radx, th, "part/2:1:IE", "CFC60", os.path.join(work, "ie_f.csv"))
        change = max(abs(f[1] - r[1]) for f, r in zip(ie_f, ie))
        check(change > 1e-3 * max(abs(r[1]) for r in ie), "dt %g: CFC60 left the plate's IE unchanged" % th_dt)
        _, note1000 = th_csv(a.radx, th, "part/2:1:IE", "CFC1000", os.path.join(work, "ie_f1000.csv"))
        coarse = th_dt > 1.0 / (10 * 5.0 / 3.0 * 1000)
        check(("10 F_H" in note1000) == coarse,
              "dt %g: CFC1000's note on the sampling is %s" % (th_dt, "missing" if coarse else "wrongly there"))
        check("10 F_H" not in note60, "dt %g: CFC60 (1 kHz needed) got the coarse-sampling note" % th_dt)
    finish("CFC filtering from radx th: unit DC gain, a real change, the J211 sampling note")


if __name__ == "__main__":
    main()
