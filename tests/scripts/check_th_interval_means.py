"""Interface forces in the time history are interval means (docs/results.md, "Interval means"): on
decks/block_on_plate (a 20 mm aluminium block dropped at 10 m/s on a clamped plate, its README.md) the impulses
they carry add up to the block's momentum change.

usage: /usr/bin/python3 check_th_interval_means.py --radx RADX --deck decks/block_on_plate/BLOCK_ON_PLATE_0000.rad
       --out DIR

The block (part 2) is free but for gravity and the two interfaces: interface 1 pushes its nodes (the secondary
nodes) with F1 = FN + FT, interface 2 pushes the plate's nodes with F2 and so the block with -F2. Its elements'
forces add up to zero over its nodes. So its momentum at the full step, which /TH/PART writes, changes between the
first row t_0 and the last t_K by
    P(t_K) - P(t_0) = sum_k (F1_k - F2_k) (t_k - t_{k-1}) + M g (t_K - t_0)
exactly when F_k is the mean of the interval (t_{k-1}, t_k] taken as radx takes it (the trapezoid rule over the
cycles, which is how the central-difference scheme moves the momentum); the sampled values (FNZ_INST...) hold
one cycle in about ten and miss it by the contact's ringing.
"""
import argparse
import os

import h5py
import numpy as np

from results_common import check, finish, run_radx

G = -9810.0  # mm/s^2 along Z (/GRAV/1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    name = run_radx(a.radx, a.deck, a.out)
    with h5py.File(os.path.join(a.out, name + "_th.h5"), "r") as f:
        inter, part = f["interface/3"], f["part/2"]
        icols = {str(c): k for k, c in enumerate(inter.attrs["columns"])}
        pcols = {str(c): k for k, c in enumerate(part.attrs["columns"])}
        ri, rp = inter[()], part[()]
    t = ri[:, 0]
    check(np.array_equal(t, rp[:, 0]), "interface and part rows at the same times")
    check(len(t) > 150, "%d rows, expected one every 1e-5 s over 2e-3 s" % len(t))
    dt = np.diff(t)
    mass = rp[0, pcols["2:MASS"]]
    worst = 0.0
    for axis in "XYZ":
        f1 = ri[:, icols["1:FN" + axis]] + ri[:, icols["1:FT" + axis]]
        f2 = ri[:, icols["2:FN" + axis]] + ri[:, icols["2:FT" + axis]]
        mom = rp[:, pcols["2:" + axis + "MOM"]]
        impulse = np.sum((f1 - f2)[1:] * dt) + (mass * G * (t[-1] - t[0]) if axis == "Z" else 0.0)
        # Round-off: the sums of ~2000 cycles' forces in double precision, far below 1e-9 of the initial momentum
        # M 10000 mm/s; 1e-6 of it leaves room for the order of the sums and nothing for a missing half step
        # (one cycle's impulse at the peak contact force is about 1e-2 of it).
        scale = mass * 10000.0
        err = abs((mom[-1] - mom[0]) - impulse)
        worst = max(worst, err / scale)
        check(err <= 1e-6 * scale, "%s: momentum change %.9g, impulse of the interval means %.9g (error %.3g of M v0)"
              % (axis, mom[-1] - mom[0], impulse, err / scale))
        # The same sum from the sampled values misses it: the check above can tell the two apart.
        f1s = ri[:, icols["1:FN%s_INST" % axis]] + ri[:, icols["1:FT%s_INST" % axis]]
        f2s = ri[:, icols["2:FN%s_INST" % axis]] + ri[:, icols["2:FT%s_INST" % axis]]
        if axis == "Z":
            sampled = np.sum((f1s - f2s)[1:] * dt) + mass * G * (t[-1] - t[0])
            check(abs((mom[-1] - mom[0]) - sampled) > 1e-4 * scale,
                  "Z: the sampled forces' impulse %.9g should miss the momentum change %.9g" % (sampled, mom[-1] - mom[0]))
    # The first row has no interval: it holds the value of its cycle.
    for v in ("FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ"):
        for i in (1, 2):
            check(ri[0, icols["%d:%s" % (i, v)]] == ri[0, icols["%d:%s_INST" % (i, v)]],
                  "first row: %d:%s equals %d:%s_INST" % (i, v, i, v))
    # DEF asks for the six forces: each has its _INST column, and nothing else does.
    check(sorted(c for c in icols if c.endswith("_INST")) == sorted(c + "_INST" for c in icols
                                                                  if c != "time" and not c.endswith("_INST")),
          "one _INST column per force: %s" % sorted(icols))
    finish("the interval means' impulses give the block's momentum change to %.2g of M v0" % worst)


if __name__ == "__main__":
    main()
