"""radx diff (docs/results.md, "Comparing two runs"): a run against itself passes; a run whose loads are scaled by
1 + eps is reported past a relative tolerance below what the scaling predicts, and within one above it; bad input
exits 2.

usage: /usr/bin/python3 check_run_diff.py --radx RADX --deck decks/verification/sections/SECT_BAR_0000.rad --out DIR

The deck (decks/verification/sections/README.md) is a linear elastic bar, truss and beam pulled by loads that
follow one ramp /FUNCT/1. Run B scales the ramp by 1 + eps (eps = 1 %): the response is linear in the load to the
strains' order (5e-5), so every force, moment, displacement and momentum of B is (1 + eps) times A's, and every
energy (1 + eps)^2 times. Against the tolerance max(rel |A|, floor), the floor rel times the largest magnitude in
either run of the channel's group and unit (of the figure's family), the largest score is an energy's at the
largest energy E:
    ((1 + eps)^2 - 1) E / (rel (1 + eps)^2 E) = (2 eps + eps^2) / (rel (1 + eps)^2)
that is 3.94 for rel = eps / 2 (past) and 0.49 for rel = 4 eps (within); a force's is eps / (rel (1 + eps)).
"""
import argparse
import os
import re
import subprocess

import h5py
import numpy as np

from results_common import check, finish, run_radx

EPS = 0.01


def scaled_deck(source, path, factor):
    """The starter deck with /FUNCT/1's ordinates multiplied by factor (its loads scale with them)."""
    lines = open(source).read().splitlines()
    k = next(i for i, l in enumerate(lines) if l.startswith("/FUNCT/1"))
    i = k + 1
    while not lines[i].startswith("/"):
        f = lines[i].split()
        if not lines[i].startswith("#") and len(f) == 2:
            lines[i] = "%20.6g%20.10g" % (float(f[0]), float(f[1]) * factor)
        i += 1
    open(path, "w").write("\n".join(lines) + "\n")


def diff(radx, *args):
    r = subprocess.run([radx, "diff", *args], capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr


def scores(text):
    """(score, quantity) of every row of the deviation table."""
    rows = []
    for line in text.splitlines():
        m = re.match(r"^  (inf|[0-9.e+-]+)\s+(\S+)", line)
        if m and not line.startswith("  score"):
            rows.append((float(m.group(1)), m.group(2)))
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    dir_a, dir_b = os.path.join(a.out, "a"), os.path.join(a.out, "b")
    os.makedirs(dir_b, exist_ok=True)
    name = run_radx(a.radx, a.deck, dir_a)
    engine = a.deck.replace("_0000.rad", "_0001.rad")
    deck_b = os.path.join(dir_b, os.path.basename(a.deck))
    scaled_deck(a.deck, deck_b, 1 + EPS)
    with open(engine) as src, open(os.path.join(dir_b, os.path.basename(engine)), "w") as dst:
        dst.write(src.read())
    run_radx(a.radx, deck_b, dir_b)
    run_a, run_b = os.path.join(dir_a, name), os.path.join(dir_b, name)

    code, out, err = diff(a.radx, run_a, run_a)
    check(code == 0, "A against itself: exit %d, expected 0\n%s%s" % (code, out, err))
    check(all(s == 0 for s, _ in scores(out)), "A against itself: every score 0")
    check(re.search(r"summary figures, [1-9][0-9]* time-history channels", out) is not None,
          "A against itself: the channels are compared\n" + out)

    predicted = lambda rel: (2 * EPS + EPS ** 2) / (rel * (1 + EPS) ** 2)
    rel = EPS / 2
    code, out, err = diff(a.radx, run_a, dir_b, "--rel", str(rel), "--top", "400")
    rows = scores(out)
    check(code == 1, "B (loads x 1.01) against A at rel %g: exit %d, expected 1\n%s%s" % (rel, code, out, err))
    # The strains' order (5e-5) and the interpolation of B's rows at A's times (their steps differ by as little)
    # bound what departs from the linear prediction: 2 % of it.
    if rows:
        top, what = rows[0]
        check(abs(top - predicted(rel)) <= 0.02 * predicted(rel),
              "largest score %.4g (%s), predicted %.4g for an energy" % (top, what, predicted(rel)))
        energy = [s for s, q in rows if q.startswith("energy.")]
        check(energy and abs(max(energy) - predicted(rel)) <= 0.02 * predicted(rel),
              "largest energy figure's score %s, predicted %.4g" % (max(energy) if energy else None, predicted(rel)))
        # Section 1's FNX: |B - A| = eps |a| against max(rel |a|, rel (1 + eps) N), N the largest force (N) of the
        # section group in A; its largest score, from A's rows alone.
        with h5py.File(run_a + "_th.h5", "r") as f:
            d = f["section/1"]
            cols = [str(c) for c in d.attrs["columns"]]
            units = [str(u) for u in d.attrs["units"]]
            r = d[()]
        peak = max(np.max(np.abs(r[:, k])) for k, u in enumerate(units) if u == "N")
        fnx = r[:, cols.index("1:FNX")]
        want = np.max(EPS * np.abs(fnx) / np.maximum(rel * np.abs(fnx), rel * (1 + EPS) * peak))
        force = [s for s, q in rows if q == "th:section/1:1:FNX"]
        check(force and abs(force[0] - want) <= 0.02 * want,
              "section 1 FNX score %s, predicted %.4g" % (force[0] if force else None, want))
        same = [s for s, q in rows if q in ("cycles", "time", "initial_mass")]
        check(len(same) == 3 and max(same) == 0, "cycles, time and initial mass agree: %s" % same)
    else:
        check(False, "no deviation table:\n" + out)
    rel = 4 * EPS
    code, out, err = diff(a.radx, run_a + "_summary.json", run_b, "--rel", str(rel))
    check(code == 0, "B against A at rel %g: exit %d, expected 0 (largest score %.3g predicted)\n%s%s"
          % (rel, code, predicted(rel), out, err))

    code, out, err = diff(a.radx, run_a, os.path.join(a.out, "missing"))
    check(code == 2 and "no run summary" in err, "a missing run: exit %d, expected 2 with a message\n%s" % (code, err))
    code, out, err = diff(a.radx, run_a, run_b, "--rel", "-1")
    check(code == 2, "a negative tolerance: exit %d, expected 2" % code)
    finish("radx diff: a run passes against itself; loads x %g give the predicted score %.3g past rel %g"
           % (1 + EPS, predicted(EPS / 2), EPS / 2))


if __name__ == "__main__":
    main()
