"""Initial penetrations treated when an interface starts at Tstart > 0 (docs/theory/type7-lagdt.md 4.6).

usage: /usr/bin/python3 check_contact_inacti_tstart.py --radx RADX --decks DIR --out DIR

The initial_penetration decks (decks/verification/initial_penetration, README) start with tile A's nodes
closer than the gap. Each Inacti deck is run twice: as written (Tstart 0: the starter treats the penetrations)
and with Tstart = 1e-9 s (a few thousandths of the first step: the interface starts on the second cycle,
when the engine must find and treat the same penetrations from the current coordinates). In that time the
tiles move by v t = 1e-6 mm, far below the 1e-3 mm of resolution asked of the comparison, so:
  * both runs must give the same closest approach and final speed of tile A, within 1e-3 of the gap and of v0
    (the tiles moved 1e-6 mm, the reduced gaps differ by that much);
  * the Tstart run's listing must report the penetrations found when the interface starts, with the Inacti
    value applied.
Inacti 1 (node off), 2 (segment off) and 5 (reduced gap) are checked; 0 and 6 follow the same path.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

import h5py
import numpy as np

from results_common import check, finish


def run(radx, deck, out):
    r = subprocess.run([radx, "run", deck, "--out", out, "--no-plot"], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("radx run %s failed:\n%s%s" % (deck, r.stdout[-2000:], r.stderr[-2000:]))
    return r.stdout + r.stderr


def tile_a(out, root):
    """Lowest DZ and final VZ over the /TH/NODE columns of the time history (tile A's nodes)."""
    with h5py.File(os.path.join(out, root + "_th.h5"), "r") as f:
        for path in f.attrs["groups"]:
            if str(path).startswith("node/"):
                d = f[path]
                cols = [str(c) for c in d.attrs["columns"]]
                dz = [k for k, c in enumerate(cols) if c.endswith(":DZ")]
                vz = [k for k, c in enumerate(cols) if c.endswith(":VZ")]
                a = d[()]
                return float(np.min(a[:, dz])), float(a[-1, vz[0]])
    sys.exit("no /TH/NODE group in " + root)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--decks", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    gap, v0 = 1.0, 1000.0  # mm, mm/s (the decks' README)
    for inacti in (1, 2, 5):
        root = "INITIAL_PENETRATION_INACTI%d" % inacti
        src = os.path.join(a.decks, root + "_0000.rad")
        ref_out = os.path.join(a.out, "t0_%d" % inacti)
        run(a.radx, src, ref_out)
        late = os.path.join(a.out, "late_%d" % inacti)
        os.makedirs(late)
        text = open(src).read().splitlines()
        k = next(i for i, l in enumerate(text) if l.startswith("#") and "Tstart" in l and "Gapmin" in l)
        line = text[k + 1]
        text[k + 1] = line[:60] + "%20s" % "1e-9" + line[80:]
        open(os.path.join(late, root + "_0000.rad"), "w").write("\n".join(text) + "\n")
        shutil.copy(src.replace("_0000.rad", "_0001.rad"), late)
        log = run(a.radx, os.path.join(late, root + "_0000.rad"), late)
        z0, v_0 = tile_a(ref_out, root)
        z1, v_1 = tile_a(late, root)
        check(abs(z1 - z0) <= 1e-3 * gap, "Inacti %d: lowest DZ %.9g with Tstart > 0, %.9g from t = 0" % (inacti, z1, z0))
        check(abs(v_1 - v_0) <= 1e-3 * v0, "Inacti %d: final VZ %.9g with Tstart > 0, %.9g from t = 0" % (inacti, v_1, v_0))
        check(re.search(r"starts at t = \S+ \(Tstart\) with \d+ secondary node\(s\) closer than the gap.*Inacti %d applied"
                        % inacti, log) is not None, "Inacti %d: no message about the penetrations at Tstart" % inacti)
    finish("Inacti 1, 2, 5 at Tstart > 0 match the treatment from t = 0")


if __name__ == "__main__":
    main()
