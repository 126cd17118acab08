"""Moving skews (/SKEW/MOV) on a spinning rigid cube, used by /CLOAD, /BCS, /IMPVEL, /GRAV, /INIVEL, /ACCEL and
/TH/NODE, against closed forms.

usage: /usr/bin/python3 check_skew_mov.py --radx RADX --deck decks/verification/skew_mov/SKEW_MOV_0000.rad --out DIR

Runs the deck (radx run) and reads SKEW_MOV_th.h5 with h5py. The model and the closed forms are in
decks/verification/skew_mov/README.md; the constants below are the generator's (scripts/make_verification_decks.py,
SKM). theta = w t is the angle of the cube, and of every skew, at time t. Every check names its tolerance and what
it stands for.
"""
import argparse
import math
import os

import h5py
import numpy as np

from results_common import check, finish, read_summary, run_radx

P = dict(H=1.0, W=2 * math.pi, M=2.0, F=1.0, V0=1.0, V=1.0, G=2.0, R=3.0, DT=1e-4, T_STOP=1.0)


def within(got, want, atol, what):
    err = np.max(np.abs(np.asarray(got) - np.asarray(want)))
    check(err <= atol, "%s: worst error %.3e > %.3e" % (what, err, atol))
    return err


def group(f, path):
    """(time, value(object index, variable)) of a /TH dataset: columns are object-major."""
    d = f[path]
    rows = d[()]
    names = [str(v) for v in d.attrs["variables"]]
    return rows[:, 0], lambda k, v: rows[:, 1 + k * len(names) + names.index(v)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    name = run_radx(a.radx, a.deck, a.out, ("--threads", "1"))
    p = P
    w, m, r, dt, h = p["W"], p["M"], p["R"], p["DT"], p["H"]
    with h5py.File(os.path.join(a.out, name + "_th.h5"), "r") as f:
        # The skews each /TH/NODE object is written in are recorded with the dataset.
        check(list(f["node/1"].attrs["skews"]) == [1, 2, 3, 0], "node/1 skews %s" % list(f["node/1"].attrs["skews"]))
        check("skews" not in f["node/2"].attrs, "node/2 is on the global axes: no skews attribute")
        t, col = group(f, "node/1")
        check(abs(t[-1] - p["T_STOP"]) < 1e-9 and len(t) == 101, "rows to Tstop: %d, last %g" % (len(t), t[-1]))
        c, s = np.cos(w * t), np.sin(w * t)
        # 1. The skews turn with the cube. The rigid body turns its corners by the exact rotation R(w dt) each cycle
        # and the skews are rebuilt from the corners, so the angle is w t to round-off over 10^4 cycles (1e-11 of r).
        for k, (ex, ey) in enumerate(((r * c, -r * s), (r * s, r * c), (r * c, -r * s), (r + 0 * t, 0 * t))):
            within(col(k, "X"), ex, 1e-11 * r, "point at rest, X in skew %d" % [1, 2, 3, 0][k])
            within(col(k, "Y"), ey, 1e-11 * r, "point at rest, Y in skew %d" % [1, 2, 3, 0][k])
            within(col(k, "Z"), 0.0, 1e-11 * r, "point at rest, Z in skew %d" % [1, 2, 3, 0][k])

        t, col = group(f, "node/2")
        c, s = np.cos(w * t), np.sin(w * t)
        # 2. /CLOAD along x' of skew 1 on node 21 (object 0): a force of constant size turning at w. Central
        # differences integrate it to second order: the errors are (w dt)^2 = 4e-7 of the scales F/(m w) and
        # F/(m w^2): 1e-6 of them.
        vs, xs = p["F"] / (m * w), p["F"] / (m * w * w)
        within(col(0, "VX"), vs * s, 1e-6 * vs, "CLOAD point VX = F/(m w) sin wt")
        within(col(0, "VY"), vs * (1 - c), 1e-6 * vs, "CLOAD point VY = F/(m w) (1 - cos wt)")
        within(col(0, "DX"), xs * (1 - c), 1e-6 * xs, "CLOAD point DX = F/(m w^2) (1 - cos wt)")
        within(col(0, "DY"), xs * (w * t - s), 1e-6 * xs, "CLOAD point DY = F/(m w^2) (wt - sin wt)")
        # 3. /BCS holding y' and z' of skew 1 on node 22 (object 1), launched at V0 along y' of skew 2 (= X at t = 0,
        # /INIVEL in a moving skew at t = 0): each cycle keeps the velocity's part along the new x', cos(w dt) of it,
        # so the speed is V0 cos(w dt)^(t/dt) = V0 exp(-w^2 dt t / 2) to (w dt)^4 (1e-12); the point runs on the
        # circle of radius V0/w, off by the speed lost (2e-3 after the turn) and half a step: 3e-3 of V0/w.
        speed = np.hypot(col(1, "VX"), col(1, "VY"))
        within(speed, p["V0"] * np.exp(-w * w * dt * t / 2), 1e-9 * p["V0"], "BCS point speed")
        within(col(1, "VZ"), 0.0, 0.0, "BCS point VZ (z' held)")
        # The velocity lies along x' = (cos, sin, 0) of the cycle: its component along y' is round-off.
        within(-s * col(1, "VX") + c * col(1, "VY"), 0.0, 1e-12 * p["V0"], "BCS point velocity along y'")
        rv = p["V0"] / w
        within(col(1, "DX"), rv * s, 3e-3 * rv, "BCS point DX = (V0/w) sin wt")
        within(col(1, "DY"), rv * (1 - c), 3e-3 * rv, "BCS point DY = (V0/w) (1 - cos wt)")
        # 4. /IMPVEL V along x' of skew 3 with y' and z' held there, node 23 (object 2): v^{n+1/2} = V x'(t_n), the
        # circle of radius V/w, which the steps follow half a step behind: V dt = 6e-4 of V/w; 1e-3 of it. The
        # full-step velocity (the mean of two half-step ones, w dt apart) is V cos(w dt / 2), after t = 0 when the
        # point starts from rest: 1e-6 of V.
        rv = p["V"] / w
        within(col(2, "DX"), rv * s, 1e-3 * rv, "IMPVEL point DX = (V/w) sin wt")
        within(col(2, "DY"), rv * (1 - c), 1e-3 * rv, "IMPVEL point DY = (V/w) (1 - cos wt)")
        within(np.hypot(col(2, "VX"), col(2, "VY"))[1:], p["V"], 1e-6 * p["V"], "IMPVEL point speed")
        # 5. /GRAV g along y' of skew 2 (Dir Y: y' = (cos, sin, 0)) on node 24 (object 3): as the /CLOAD with g for
        # F/m.
        vs = p["G"] / w
        within(col(3, "VX"), vs * s, 1e-6 * vs, "GRAV point VX = (g/w) sin wt")
        within(col(3, "VY"), vs * (1 - c), 1e-6 * vs, "GRAV point VY = (g/w) (1 - cos wt)")
        within(col(3, "DZ"), 0.0, 0.0, "GRAV point DZ")

        # 6. /TH/NODE in skew 1: the /CLOAD point's acceleration is F/m along x', exactly (a = F x'/m of the same
        # cycle); its velocity F/(m w) (sin wt, cos wt - 1, 0) to 1e-6 as above. Corner 2 sits at (h/2, -h/2, -h/2)
        # on the skew's axes (round-off) and moves at (w h/2, w h/2, 0) there, up to the full-step velocity of a point
        # on a circle, the mean of two chords: (w dt)^2 / 6 = 7e-8 relative; 1e-7.
        t, col = group(f, "node/3")
        c, s = np.cos(w * t), np.sin(w * t)
        fm = p["F"] / m
        within(col(0, "AX"), fm, 1e-12 * fm, "CLOAD point AX in skew 1 = F/m")
        within(col(0, "AY"), 0.0, 1e-12 * fm, "CLOAD point AY in skew 1 = 0")
        within(col(0, "AZ"), 0.0, 1e-12 * fm, "CLOAD point AZ in skew 1 = 0")
        vs = fm / w
        within(col(0, "VX"), vs * s, 1e-6 * vs, "CLOAD point VX in skew 1 = F/(m w) sin wt")
        within(col(0, "VY"), vs * (c - 1), 1e-6 * vs, "CLOAD point VY in skew 1 = F/(m w) (cos wt - 1)")
        for v, want in (("X", h / 2), ("Y", -h / 2), ("Z", -h / 2)):
            within(col(1, v), want, 1e-12 * h, "corner 2 %s in skew 1" % v)
        for v, want in (("VX", w * h / 2), ("VY", w * h / 2), ("VZ", 0.0)):
            within(col(1, v)[1:], want, 1e-7 * w * h, "corner 2 %s in skew 1" % v)

        # 7. /ACCEL in skew 1 on the /CLOAD point: AX = F/m, AY = AZ = 0 (round-off); WX, integrated over the cycles
        # up to the next half step, F/m (t + DT/2) with DT the next step (0 on the last row, at Tstop).
        t, col = group(f, "accel/4")
        _, glob = group(f, "global")
        within(col(0, "AX"), fm, 1e-12 * fm, "ACCEL AX = F/m")
        within(col(0, "AY"), 0.0, 1e-12 * fm, "ACCEL AY")
        within(col(0, "AZ"), 0.0, 1e-12 * fm, "ACCEL AZ")
        within(col(0, "WX"), fm * (t + glob(0, "DT") / 2), 1e-9 * fm, "ACCEL WX = F/m (t + DT/2)")

    # The energy balance closes: the point held by the /BCS loses 0.2 % of its 1 J (the projection), against the
    # cube's 79 J of rotation: 1e-2 %.
    s = read_summary(a.out, name)
    err = abs(s["energy"]["error_percent"])
    check(err < 1e-2, "energy error %.3g %%" % err)
    finish("one turn of the moving skews: the point at rest in skews 1 2 3, /CLOAD, /BCS, /IMPVEL, /GRAV, "
           "/INIVEL, /ACCEL and /TH/NODE in them against their closed forms")


if __name__ == "__main__":
    main()
