"""Time history of the free-fall deck against its closed form, against the listing and against the summary.

usage: /usr/bin/python3 check_free_fall_th.py --radx RADX --deck decks/verification/free_fall/FREE_FALL_0000.rad
           --out DIR

The block (mass M, every node under the same gravity g along -Z, from rest) moves as a rigid body, and central
differences integrate a constant acceleration exactly: at the time t of each row
    DZ = -g t^2 / 2,  VZ = -g t,  AZ = -g,  DX = DY = VX = VY = 0,
    part and global: ZMOM = -M g t, KE = M g^2 t^2 / 2, MASS = M; global EXTW = KE, IE ~ 0.
Tolerances (what they mean):
  * positions and speeds: relative 1e-9 of the closed form: only round-off, summed over ~1,400 cycles;
  * accelerations: 1e-5 g absolute: the elements' stresses are round-off (the block is unstressed), and their
    forces divided by a node's mass give ~1e-6 g of noise;
  * IE: below 1e-9 of KE (round-off of an unstressed block);
  * rows every /TFILE dt_his: row k is at the first cycle with t >= k dt_his, i.e. within one time step.
The last row is the last cycle: its energies must equal NAME_summary.json's (the same report, printed with 17
digits: exact) and the listing's last line (printed with 6 digits: relative 5e-6).
"""
import argparse
import os

import h5py
import numpy as np

from results_common import check, finish, read_summary, run_radx

G, RHO, H = 9.81, 2700.0, 0.1  # decks/verification/free_fall/README.md


def columns(ds):
    return {str(c): k for k, c in enumerate(ds.attrs["columns"])}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    run_radx(a.radx, a.deck, a.out)
    M = RHO * H ** 3
    with h5py.File(os.path.join(a.out, "FREE_FALL_th.h5"), "r") as f:
        gl, node, part = f["global"], f["node/1"], f["part/2"]
        cg, cn, cp = columns(gl), columns(node), columns(part)
        g, n, p = gl[()], node[()], part[()]
        units = dict(zip([str(c) for c in gl.attrs["columns"]], [str(u) for u in gl.attrs["units"]]))
    t = g[:, 0]
    check(np.array_equal(t, n[:, 0]) and np.array_equal(t, p[:, 0]), "groups have different time columns")
    check(len(t) == 11, "%d rows, expected 11 (t = 0, every 0.001 s, the end 0.01 s)" % len(t))
    summary = read_summary(a.out, "FREE_FALL")
    dt = summary["time"] / summary["cycles"]  # the (constant) step of this unstressed block
    for k, tk in enumerate(t):
        check(0.001 * k <= tk * (1 + 1e-12) and tk < 0.001 * k + 2 * dt, "row %d at t = %.17g" % (k, tk))
    rel = 1e-9
    check(np.allclose(n[:, cn["27:DZ"]], -0.5 * G * t * t, rtol=rel, atol=1e-15), "DZ != -g t^2/2")
    check(np.allclose(n[:, cn["27:VZ"]], -G * t, rtol=rel, atol=1e-15), "VZ != -g t")
    check(np.allclose(n[:, cn["27:AZ"]], -G, atol=1e-5 * G, rtol=0), "AZ != -g")
    for c in ("27:DX", "27:DY"):
        check(np.max(np.abs(n[:, cn[c]])) < 1e-12 * H, c + " != 0")
    for arr, c in ((g, cg), (p, cp)):
        zmom = arr[:, c["ZMOM" if "ZMOM" in c else "1:ZMOM"]]
        ke = arr[:, c["KE" if "KE" in c else "1:KE"]]
        mass = arr[:, c["MASS" if "MASS" in c else "1:MASS"]]
        check(np.allclose(zmom, -M * G * t, rtol=rel, atol=1e-15), "ZMOM != -M g t")
        check(np.allclose(ke, 0.5 * M * G * G * t * t, rtol=rel, atol=1e-15), "KE != M g^2 t^2 / 2")
        check(np.allclose(mass, M, rtol=1e-12), "MASS != M")
    check(np.allclose(g[:, cg["EXTW"]], 0.5 * M * G * G * t * t, rtol=rel, atol=1e-15), "EXTW != KE")
    check(np.max(np.abs(g[:, cg["IE"]])) <= 1e-9 * np.max(g[:, cg["KE"]]), "IE not ~0")
    check(units["KE"] == "J" and units["ZMOM"] == "kg.m/s" and units["time"] == "s", "units %s" % units)

    # Against the summary (same report, 17 digits) and the listing's last line (6 digits).
    check(t[-1] == summary["time"], "last row at %.17g, run ended at %.17g" % (t[-1], summary["time"]))
    check(g[-1, cg["KE"]] == summary["energy"]["kinetic"],
          "last KE %.17g != summary %.17g" % (g[-1, cg["KE"]], summary["energy"]["kinetic"]))
    check(g[-1, cg["EXTW"]] == summary["energy"]["external_work"], "last EXTW != summary")
    check(g[-1, cg["ZMOM"]] == summary["momentum"][2], "last ZMOM != summary")
    listing = open(os.path.join(a.out, "FREE_FALL_0001.out")).read().splitlines()
    rows = [l.split() for l in listing if l.strip() and l.split()[0].isdigit() and len(l.split()) >= 8]
    last = rows[-1]
    check(abs(float(last[1]) - t[-1]) <= 5e-6 * t[-1], "listing's last time %s != %.6g" % (last[1], t[-1]))
    ke_text = "%.5E" % g[-1, cg["KE"]]
    check(ke_text in last, "listing's last line %s does not show KE %s" % (last, ke_text))
    finish("%d rows; DZ, VZ, AZ, ZMOM, KE, EXTW follow the free fall; last row = summary = listing" % len(t))


if __name__ == "__main__":
    main()
