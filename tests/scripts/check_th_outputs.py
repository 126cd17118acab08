"""Element and rigid-body time histories (/TH/BRIC, /TH/SH3N, /TH/RBODY) against their closed forms.

usage: /usr/bin/python3 check_th_outputs.py --radx RADX --case brick|sh3n|rbody
           --deck decks/verification/th_outputs/TH_<CASE>_0000.rad --out DIR

Runs the deck (radx run) and reads NAME_th.h5 with h5py. The models and closed forms are in
decks/verification/th_outputs/README.md; the constants below are the generator's (scripts/make_verification_decks.py,
JC, TRI, RB). Every check names its tolerance and what it stands for.
"""
import argparse
import math
import os

import h5py
import numpy as np

from results_common import check, finish, run_radx

JC = dict(H=10.0, RHO=7.85e-9, E=210000.0, NU=0.3, A=300.0, B=450.0, N=0.4, V=10.0)
TRI = dict(L=10.0, T=1.0, E=210000.0, NU=0.3, V=10.0)
RB = dict(H=10.0, RHO=7.85e-9, F=1e-3, G=9810.0)


def group(f, path):
    """(rows, {column name: index}, {column name: unit}) of a dataset."""
    d = f[path]
    cols = [str(c) for c in d.attrs["columns"]]
    return d[()], {c: k for k, c in enumerate(cols)}, dict(zip(cols, [str(u) for u in d.attrs["units"]]))


def within(got, want, atol, what):
    err = np.max(np.abs(np.asarray(got) - np.asarray(want)))
    check(err <= atol, "%s: worst error %.3e > %.3e" % (what, err, atol))
    return err


def brick(f):
    p = JC
    h, E, a, b, n, V = p["H"], p["E"], p["A"], p["B"], p["N"], p["V"]
    r, c, units = group(f, "brick/1")
    d, cd, _ = group(f, "brick/2")
    nd, cn, _ = group(f, "node/3")
    gl, cg, _ = group(f, "global")
    t = r[:, 0]
    col = lambda name: r[:, c["1:" + name]]
    u, v = nd[:, cn["8:DX"]], nd[:, cn["8:DZ"]]
    eps = np.log(1 + v / h)
    sz, plas = col("SZ"), col("PLAS")
    flow = a + b * np.abs(plas) ** n
    elastic, plastic = (plas == 0) & (t > 0), plas > 0
    check(elastic.sum() >= 2 and plastic.sum() > len(t) // 2, "%d elastic, %d plastic rows" % (elastic.sum(),
                                                                                              plastic.sum()))
    # Elastic: SZ = E eps, up to the lateral inertia stress (~0.1 MPa, README) on a stress of ~100 MPa: 1e-3.
    within(sz[elastic] / (E * eps[elastic]), 1.0, 1e-3, "SZ / (E ln(1 + v/h)) before yield")
    # Plastic: on the flow curve up to the explicit hardening lag of one cycle and the lateral stress: 1e-3.
    within(sz[plastic] / flow[plastic], 1.0, 1e-3, "SZ / (a + b PLAS^n)")
    # PLAS = total log strain - elastic strain SZ/E; the lateral stress changes the elastic part by nu 1e-3
    # of SZ/E (2e-6) and the strain increments follow the one-point geometry: 1e-5 absolute.
    within(plas[plastic], (eps - sz / E)[plastic], 1e-5, "PLAS = ln(1 + v/h) - SZ/E")
    flow_max = np.max(sz)
    for s in ("SX", "SY"):
        within(col(s), 0.0, 1e-3 * flow_max, s + " (free lateral faces)")
    for s in ("SXY", "SYZ", "SXZ"):
        within(col(s), 0.0, 1e-9 * flow_max, s + " (no shear)")
    # The cube stays a box: the one-point volume is exactly (h + u)^2 (h + v), to round-off.
    vol = (h + u) ** 2 * (h + v)
    within(col("VOL") / vol, 1.0, 1e-12, "VOL = (h + u)^2 (h + v)")
    within(col("DENS") * col("VOL") / (p["RHO"] * h ** 3), 1.0, 1e-12, "DENS VOL = rho0 V0")
    # IE per unit initial volume: elastic SZ^2/(2E) plus the area under the flow curve; the volume differs from
    # V0 by the elastic dilatation (1 - 2 nu) SZ / E < 1e-3 (README): 2e-3 relative.
    ie_ref = sz ** 2 / (2 * E) + np.where(plastic, a * plas + b * np.abs(plas) ** (n + 1) / (n + 1), 0.0)
    late = t > 0.01
    within(col("IE")[late] / ie_ref[late], 1.0, 2e-3, "IE = SZ^2/(2E) + a PLAS + b PLAS^(n+1)/(n+1)")
    # The brick is the only element: IE V0 is the global internal energy (the same sum), to round-off.
    within(col("IE") * h ** 3, gl[:, cg["IE"]], 1e-12 * np.max(gl[:, cg["IE"]]), "IE V0 = global IE")
    within(col("OFF"), 1.0, 0.0, "OFF")
    # Mean nodal velocity: four nodes at z = h move at V, four at 0 (exact); x = h nodes at the corner's VX.
    within(col("VZ"), V / 2, 1e-9 * V, "VZ = V/2")
    within(col("VX"), nd[:, cn["8:VX"]] / 2, 1e-9 * V, "VX = (corner VX)/2")
    within(col("VY"), nd[:, cn["8:VY"]] / 2, 1e-9 * V, "VY = (corner VY)/2")
    # Rates of the cycle (hex8_fb.cpp): the half-step velocities v^{n-1/2} = v - dt1/2 a on the geometry x^n.
    # The lateral contraction rings after yield, so the half step matters; dt1 is taken as the global DT (the
    # next step), which differs from it by ~1e-6 relative: 1e-6 relative on the rates. The last row is left
    # out: its DT is 0 (the end) and its dt1, cut to end at Tstop, is not in the file.
    dt = gl[:, cg["DT"]]
    w = nd[:, cn["8:VX"]] - 0.5 * dt * nd[:, cn["8:AX"]]
    dzz, dxx = V / (h + v), w / (h + u)
    plsr = np.sqrt(dzz ** 2 + 2 * dxx ** 2)
    rows = (t > 0) & (dt > 0)
    within(col("PLSR")[rows] / plsr[rows], 1.0, 1e-6, "PLSR = sqrt(Dzz^2 + 2 Dxx^2)")
    # Bulk viscosity where the volume shrinks (qa 1.1, qb 0.05 by default; c of the dilatational wave):
    # e is a difference of rates 1e3 times larger (1e-6 relative each), of a pressure that is 0 on most rows:
    # 1e-3 of the largest.
    nu, rho0 = p["NU"], p["RHO"]
    c_wave = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho0)
    ec = np.maximum(0.0, -(dzz + 2 * dxx))
    ell = col("VOL") ** (1.0 / 3.0)
    q = col("DENS") * ec * ell * (1.1 ** 2 * ell * ec + 0.05 * c_wave)
    check(np.max(q) > 0, "no row with a shrinking volume: BULK untested")
    within(col("BULK")[rows], q[rows], 1e-3 * np.max(q), "BULK = rho e l (qa^2 l e + qb c)")
    # /TH/BRICK DEF: the default set in OpenRadioss's order, the same values, TEMP 0.
    names = [k.split(":")[1] for k in sorted(cd, key=cd.get)[1:]]
    check(names == ["OFF", "SX", "SY", "SZ", "SXY", "SYZ", "SXZ", "IE", "DENS", "PLAS", "TEMP"], "DEF = %s" % names)
    for name in names[:-1]:
        check(np.array_equal(d[:, cd["1:" + name]], col(name)), "brick/2 %s differs from brick/1" % name)
    within(d[:, cd["1:TEMP"]], 0.0, 0.0, "TEMP")
    check(units["1:SZ"] == "MPa" and units["1:IE"] == "MPa" and units["1:DENS"] == "Mg/mm3" and
          units["1:VOL"] == "mm3" and units["1:PLSR"] == "1/s", "units %s" % units)
    check(str(f["brick/1"].attrs["object_kind"]) == "brick", "object_kind")
    return "%d rows: stresses on the flow curve, PLAS, VOL, DENS, IE, velocities, PLSR; DEF = TEMP 0" % len(t)


def sh3n(f):
    p = TRI
    L, T, E = p["L"], p["T"], p["E"]
    r, c, units = group(f, "sh3n/1")
    nd, cn, _ = group(f, "node/2")
    t = r[:, 0]
    for plate, (along, diag), node in ((1, (1, 2), 3), (2, (11, 12), 13)):
        col = lambda e, name: r[:, c["%d:%s" % (e, name)]]
        u = nd[:, cn["%d:DX" % node]]
        sigma = E * np.log(1 + u / L)
        tf = T * sigma
        scale = np.max(tf)
        # The lateral stress of the lateral inertia is below 1e-3 of the axial one (0.16 of 419 N/mm at the end);
        # F1 follows sigma to the same 1e-3; tf > 0 after the first row.
        k = t > 0
        within(col(along, "F1")[k] / tf[k], 1.0, 1e-3, "plate %d triangle %d F1 = t sigma" % (plate, along))
        within(col(along, "F2"), 0.0, 1e-3 * scale, "plate %d triangle %d F2 = 0" % (plate, along))
        within(col(along, "F12"), 0.0, 1e-9 * scale, "plate %d triangle %d F12 = 0" % (plate, along))
        # Along the diagonal: the same stress seen at 45 degrees (element y axis at 135 degrees). The lumped masses
        # differ between nodes (corners 1 and 3 carry two triangles, 2 and 4 one), so the stress is uniform only
        # to ~1e-3 (0.16 MPa lateral and 0.4 MPa shear of 419 MPa at the end): 2e-3 of t sigma.
        for name, factor in (("F1", 0.5), ("F2", 0.5), ("F12", -0.5)):
            within(col(diag, name), factor * tf, 2e-3 * scale,
                   "plate %d triangle %d %s = %g t sigma" % (plate, diag, name, factor))
        for e in (along, diag):
            for name in ("M1", "M2", "M12", "IEB", "EMIN", "EMAX"):
                within(col(e, name), 0.0, 1e-9 * scale * T, "triangle %d %s" % (e, name))
            within(col(e, "OFF"), 1.0, 0.0, "triangle %d OFF" % e)
            # Energy of a linear elastic membrane: A t sigma^2 / (2E), A = L^2/2 (the area grows by 1e-3): 3e-3.
            iem = 0.5 * L * L * T * sigma ** 2 / (2 * E)
            within(col(e, "IEM")[k] / iem[k], 1.0, 3e-3, "triangle %d IEM = A t sigma^2/(2E)" % e)
    # Both plates see the same stress (N = 0 resultants and N = 5 points give one elastic membrane): 1e-9.
    for name in ("F1", "F2", "F12", "IEM"):
        for e1, e2 in ((1, 11), (2, 12)):
            within(r[:, c["%d:%s" % (e1, name)]], r[:, c["%d:%s" % (e2, name)]],
                   1e-9 * np.max(np.abs(r[:, c["%d:%s" % (e1, name)]])) + 1e-12, "%s of %d and %d" % (name, e1, e2))
    check(units["1:F1"] == "N/mm" and units["1:IEM"] == "mJ", "units %s" % units)
    check(str(f["sh3n/1"].attrs["object_kind"]) == "3-node shell", "object_kind")
    # THIC: the thickness the element tracks (Ithick 0 only keeps it out of the mechanics), of uniaxial plane
    # stress: e_zz = -nu e_xx, t = T (1 + u/L)^-nu; 1e-5 T is 2 % of its change at the end (the lateral
    # inertia). EPSD: the equivalent rate of docs/theory/elements.md 1.3,
    # sqrt(4/3 (e_xx^2 + e_yy^2 + e_xx e_yy)), of uniaxial stress (e_yy = -nu e_xx) at e_xx = V/(L + u): 1e-2
    # for the lateral inertia and the central difference of the rate against the node's displacement.
    r3, c3, units3 = group(f, "sh3n/3")
    nu = p["NU"]
    for e, node in ((1, 3), (11, 13)):
        u = nd[:, cn["%d:DX" % node]]
        k = r3[:, 0] > 0
        within(r3[:, c3["%d:THIC" % e]], T * (1 + u / L) ** (-nu), 1e-5 * T, "triangle %d THIC = T (1 + u/L)^-nu" % e)
        rate = math.sqrt(4.0 / 3.0 * (1 - nu + nu * nu)) * p["V"] / (L + u)
        within(r3[k, c3["%d:EPSD" % e]] / rate[k], 1.0, 1e-2, "triangle %d EPSD = equivalent strain rate" % e)
    check(units3["1:THIC"] == "mm" and units3["1:EPSD"] == "1/s", "units %s" % units3)
    return "%d rows, 4 triangles: F1 F2 F12 in the element frames, M = 0, IEM, OFF" % len(t)


def rbody(f):
    p = RB
    h, F, G = p["H"], p["F"], p["G"]
    M = p["RHO"] * h ** 3
    I = M * h * h / 2  # eight corner masses M/8 at (+-h/2, +-h/2, +-h/2) about the centre
    r, c, units = group(f, "rbody/1")
    nd, cn, _ = group(f, "node/2")
    t = r[:, 0]
    col = lambda name: r[:, c["1:" + name]]
    names = [k.split(":")[1] for k in sorted(c, key=c.get)[1:]]
    check(names[:9] == ["FX", "FY", "FZ", "MX", "MY", "MZ", "RX", "RY", "RZ"], "DEF first: %s" % names)
    # Force of the secondary nodes: the load alone; element forces of the rigid cube are round-off.
    within(col("FX"), F, 1e-9 * F, "FX = F")
    within(col("FY"), 0.0, 1e-9 * F, "FY = 0")
    within(col("FZ"), 0.0, 1e-9 * F, "FZ = 0 (the weight acts at the main node)")
    # Moment about the main node: (x8 - x9) x (F, 0, 0) with the positions of the same row.
    rr = np.stack([nd[:, cn["8:" + a]] - col(a) for a in ("X", "Y", "Z")], axis=1)
    mom = np.cross(rr, np.array([F, 0.0, 0.0]))
    for k, a in enumerate(("MX", "MY", "MZ")):
        within(col(a), mom[:, k], 1e-9 * F * h, a + " = ((x8 - x9) x F)")
    # Constant accelerations, integrated exactly by central differences (round-off: 1e-9).
    within(col("AX"), F / M, 1e-9 * F / M, "AX = F/M")
    within(col("AY"), 0.0, 1e-9 * F / M, "AY = 0")
    within(col("AZ"), -G, 1e-9 * G, "AZ = -g")
    within(col("DX"), 0.5 * F / M * t * t, 1e-9 * F / M * t[-1] ** 2, "DX = F t^2 / (2M)")
    within(col("DZ"), -0.5 * G * t * t, 1e-9 * G * t[-1] ** 2, "DZ = -g t^2/2")
    within(col("VX"), F / M * t, 1e-9 * F / M * t[-1], "VX = F t / M")
    within(col("VZ"), -G * t, 1e-9 * G * t[-1], "VZ = -g t")
    within(col("X"), h / 2 + col("DX"), 1e-12 * h, "X = x0 + DX")
    within(col("MASS"), M, 1e-12 * M, "MASS = rho h^3")
    for a in ("IXX", "IYY", "IZZ"):
        within(col(a), I, 1e-12 * I, a + " = M h^2/2")
    for a in ("IXY", "IYZ", "IZX"):
        within(col(a), 0.0, 1e-12 * I, a + " = 0")
    # Spherical inertia: alpha = moment / I, no gyroscopic term (1e-9).
    alpha = F * h / 2 / I
    for a, m in (("ARX", "MX"), ("ARY", "MY"), ("ARZ", "MZ")):
        within(col(a), col(m) / I, 1e-9 * alpha, a + " = " + m + " / I")
    # Rotation: the moment arm turns with the body, which changes the moment by the angle itself (relative, 6.4e-4
    # rad at the end), so RY = -RZ = alpha t^2 / 2 and VRY = alpha t hold to 1e-3 of their final values.
    theta = 0.5 * alpha * t * t
    within(col("RY"), theta, 1e-3 * theta[-1], "RY = alpha t^2/2")
    within(col("RZ"), -theta, 1e-3 * theta[-1], "RZ = -alpha t^2/2")
    within(col("RX"), 0.0, 1e-9 * theta[-1], "RX = 0")
    within(col("VRY"), alpha * t, 1e-3 * alpha * t[-1], "VRY = alpha t")
    # RX RY RZ against the geometry: node 8 has turned about the main node by R(theta); the small-rotation form
    # r0 + theta x r0 is off by theta^2 |r0| / 2 (3.2e-4 of theta |r0| at the end): 1e-3 of theta |r0|.
    r0 = np.array([h / 2, h / 2, h / 2])
    rot = np.stack([col("RX"), col("RY"), col("RZ")], axis=1)
    within(rr - r0, np.cross(rot, r0), 1e-3 * theta[-1] * np.linalg.norm(r0), "x8 - x9 = r0 + R x r0")
    within(col("STATUS"), 1.0, 0.0, "STATUS")
    for a in ("FXI", "FYI", "FZI", "MXI", "MYI", "MZI"):
        within(col(a), 0.0, 0.0, a)
    check(units["1:FX"] == "N" and units["1:MASS"] == "Mg" and units["1:IXX"] == "Mg.mm2" and
          units["1:ARY"] == "1/s2", "units %s" % units)
    check(str(f["rbody/1"].attrs["object_kind"]) == "rigid body", "object_kind")
    return "%d rows: F, M = r x F, accelerations, motion, mass, inertia, rotation, STATUS" % len(t)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--case", required=True, choices=("brick", "sh3n", "rbody"))
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    name = run_radx(a.radx, a.deck, a.out)
    with h5py.File(os.path.join(a.out, name + "_th.h5"), "r") as f:
        message = {"brick": brick, "sh3n": sh3n, "rbody": rbody}[a.case](f)
    finish(message)


if __name__ == "__main__":
    main()
