"""Section forces (/SECT, /TH/SECTIO) on a clamped brick bar, a truss bar and a beam cantilever pulled by a slow
ramp.

The forces and moments of /TH/SECTIO are means over the interval since the previous row (docs/results.md,
"Interval means"): they are checked against the mean of the load over each interval, which for the ramp is its
value at mid-interval, half a row interval (2.5 % of P) behind its value at the row's time; FNX_INST (the value of
the row's cycle) is checked against the load at the row's time.

usage: /usr/bin/python3 check_sections.py --radx RADX --deck decks/verification/sections/SECT_BAR_0000.rad --out DIR

Runs the deck (radx run) and reads SECT_BAR_th.h5 with h5py. The model and the closed form are in
decks/verification/sections/README.md; the constants below are the generator's (scripts/make_verification_decks.py,
SECT). A section cut through the bar reports the applied load: the pulled side pulls the cut with F = +P(t), the
held side with -P(t); section 1's moment about N1 is (0, h P/2, -h P/2).
"""
import argparse
import math
import os

import h5py
import numpy as np

from results_common import check, finish, run_radx

SECT = dict(H=10.0, NX=8, CUT=4, RHO=7.85e-9, E=210000.0, P=1000.0, T_RAMP=2e-3, BEAM_A=20.0, Q=100.0)


def within(got, want, atol, what):
    err = np.max(np.abs(np.asarray(got) - np.asarray(want)))
    check(err <= atol, "%s: worst error %.3e > %.3e" % (what, err, atol))
    return err


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    name = run_radx(a.radx, a.deck, a.out)
    p = SECT
    h, P, L = p["H"], p["P"], p["NX"] * p["H"]
    with h5py.File(os.path.join(a.out, name + "_th.h5"), "r") as f:
        d = f["section/1"]
        cols = {str(c): k for k, c in enumerate(d.attrs["columns"])}
        units = dict(zip([str(c) for c in d.attrs["columns"]], [str(u) for u in d.attrs["units"]]))
        r = d[()]
    col = lambda s, v: r[:, cols["%d:%s" % (s, v)]]
    t = r[:, 0]
    check(len(t) >= 20, "%d rows, expected one every 1e-4 s over 2e-3 s" % len(t))
    T = p["T_RAMP"]
    ramp = np.minimum(t / T, 1.0)

    def ramp_integral(x):  # integral of min(s / T, 1) from 0 to x
        return np.where(x <= T, x * x / (2 * T), T / 2 + (x - T))

    # The mean of the ramp over (t_{k-1}, t_k]; the first row, which has no interval, the ramp's value there.
    mean_ramp = np.concatenate(([ramp[0]], np.diff(ramp_integral(t)) / np.diff(t)))
    load = P * mean_ramp
    # Tolerance: a ramp over T excites the bar's first axial mode with an amplitude P / (omega T) (omega = 2 pi c /
    # 4L), 0.5 % of P here (README); 1 % of P bounds it with the higher modes.
    c = math.sqrt(p["E"] / p["RHO"])
    tol = max(0.01, 2.0 / (2 * math.pi * c / (4 * L) * p["T_RAMP"])) * P
    within(col(1, "FNX"), load, tol, "section 1 (pulled side) FNX = +P(t), interval mean")
    within(col(1, "FNX_INST"), P * ramp, tol, "section 1 (pulled side) FNX_INST = +P(t) at the row's time")
    within(col(2, "FNX_INST"), -P * ramp, tol, "section 2 (held side) FNX_INST = -P(t) at the row's time")
    # What tells the two apart: on the ramp a mean lags the row's value by P dt_his / (2 T) = 2.5 % of P.
    check(np.max(np.abs(col(1, "FNX") - P * ramp)) > 1.5 * tol,
          "section 1 FNX should lag P(t) by half a row interval on the ramp")
    within(col(2, "FNX"), -load, tol, "section 2 (held side) FNX = -P(t)")
    within(col(1, "F3"), load, tol, "section 1 F3 (normal e3 = X) = P(t)")
    within(col(2, "F1"), -load, tol, "section 2 F1 (global X, Iframe 11) = -P(t)")
    # Nothing crosses the cut sideways: the lateral forces are round-off and Poisson ringing, far below 1e-3 P.
    for s in (1, 2):
        for v in ("FNY", "FNZ", "FTX", "FTY", "FTZ"):
            within(col(s, v), 0.0, 1e-3 * P, "section %d %s = 0" % (s, v))
    within(col(1, "F1"), 0.0, 1e-3 * P, "section 1 F1 (e1 = Y) = 0")
    within(col(1, "F2"), 0.0, 1e-3 * P, "section 1 F2 (e2 = Z) = 0")
    # Moment of section 1 about N1 = (40, 0, 0): the four cut nodes carry P/4 each at y, z in {0, h}, so
    # M = (0, h P/2, -h P/2) (global) and M1 = M.Y, M2 = M.Z, M3 = M.X; the arms change by the lateral strain
    # (nu sigma / E < 2e-5) and the force distribution follows the load within tol.
    within(col(1, "M1"), h * load / 2, h * tol / 2, "section 1 M1 = h P / 2 about N1")
    within(col(1, "M2"), -h * load / 2, h * tol / 2, "section 1 M2 = -h P / 2 about N1")
    within(col(1, "M3"), 0.0, 1e-3 * h * P, "section 1 M3 = 0 (no twist)")
    within(col(1, "MY"), h * load / 2, h * tol / 2, "section 1 MY = h P / 2")
    within(col(1, "MZ"), -h * load / 2, h * tol / 2, "section 1 MZ = -h P / 2")
    # Section 2 is taken about the cut's centre (Iframe 11): the uniform force has no moment there.
    for v in ("MX", "MY", "MZ", "M1", "M2", "M3"):
        within(col(2, v), 0.0, 1e-3 * h * P, "section 2 %s = 0 about the centre of the cut" % v)
    # Centres: N1 for section 1 (Iframe 0: N3 projected on N1 N2), the mean of the cut's nodes for section 2;
    # both follow the cut's displacement along X, P L_cut / (E A) < 0.01 mm.
    cut = p["CUT"] * h
    within(np.c_[col(1, "CX"), col(1, "CY"), col(1, "CZ")], np.array([cut, 0, 0]), 0.01, "section 1 centre = N1")
    within(np.c_[col(2, "CX"), col(2, "CY"), col(2, "CZ")], np.array([cut, h / 2, h / 2]), 0.01,
           "section 2 centre = mean of the cut's nodes")
    # Sections 3 and 4 (Iframe 11, global axes about the single cut node): the truss bar's pulled side pulls the
    # cut node with (P, 0, 0); the beam's with (P, 0, Q) and the moment of the tip load Q about the cut,
    # (0, -(L - x_cut) Q, 0), carried by the beams' nodal moments. The axial force follows P within tol as the
    # brick bar's does; the tip load Q excites the cantilever's first bending mode, omega_b = 1.875^2
    # sqrt(E I / (rho A L^4)), by Q / (omega_b T): the beam's Z force and moment are checked within twice that.
    arm = L - p["CUT"] * h
    q_load = p["Q"] * mean_ramp
    a = p["BEAM_A"]
    omega_b = 1.875 ** 2 * math.sqrt(p["E"] * a ** 4 / 12 / (p["RHO"] * a * a * L ** 4))
    tol_q = max(0.01, 2.0 / (omega_b * p["T_RAMP"])) * p["Q"]
    for s in (3, 4):
        within(col(s, "FNX") + col(s, "FTX"), load, tol, "section %d F.X = +P(t)" % s)
        within(col(s, "FNY") + col(s, "FTY"), 0.0, 1e-3 * P, "section %d F.Y = 0" % s)
        within(col(s, "MX"), 0.0, 1e-3 * h * P, "section %d MX = 0" % s)
        within(col(s, "MZ"), 0.0, 1e-3 * h * P, "section %d MZ = 0" % s)
    within(col(3, "FNZ") + col(3, "FTZ"), 0.0, 1e-3 * P, "section 3 (trusses) F.Z = 0")
    within(col(3, "MY"), 0.0, 1e-3 * h * P, "section 3 (trusses) MY = 0: the cut node is the centre")
    within(col(4, "FNZ") + col(4, "FTZ"), q_load, tol_q, "section 4 (beams) F.Z = +Q(t)")
    within(col(4, "MY"), -arm * q_load, arm * tol_q, "section 4 (beams) MY = -(L - x_cut) Q(t)")
    check(units["1:FNX"] == "N" and units["1:M1"] in ("N.mm", "mJ") and units["1:CX"] == "mm",
          "units %s %s %s" % (units["1:FNX"], units["1:M1"], units["1:CX"]))
    finish("section forces follow P(t) = %g N within %.3g N; moments and centres as in the README" % (P, tol))


if __name__ == "__main__":
    main()
