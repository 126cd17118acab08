"""Shared pieces of the contact verification checks (tests/scripts/check_contact_*.py).

Not a test by itself. It holds:
  * a small fixed-column reader of the starter decks made by scripts/make_contact_decks.py, so that each
    check takes its parameters (masses, gap, stiffness, speeds) from the deck it runs, not from the generator;
  * the one-degree-of-freedom model of a rigid body on N identical TYPE7 pairs (docs/theory/type7-lagdt.md 4.3), used
    for the expected penetration and rebound speed when damping makes the energy equation of
    docs/theory/verification.md A.2 inexact; without damping it reduces to that equation (checked by self_test());
  * running radx (results_common.py) and reading its outputs (NAME_th.h5, NAME_summary.json, the animation
    states), with h5py;
  * what the checks share around that: the command line and the loop over the decks (main_per_deck), the
    moving body, the flat main plate, the penetrations, part speeds and contact forces from the time history,
    and the energy-error check.

Plain /usr/bin/python3 with Debian's numpy and h5py (imported where used: scripts/make_contact_decks.py imports
this module for rigid_impact with the standard library only).
"""
import argparse
import glob
import math
import os
import sys

from results_common import read_summary, run_radx  # noqa: F401  (part of this module's interface)

# ---------------------------------------------------------------------------------------------------
# Deck reading (fixed columns, docs/theory/deck-format.md); only what the contact decks use.


class Deck:
    """Keyword blocks of a starter deck: list of (keyword line, data lines without comments)."""

    def __init__(self, path):
        self.path = path
        self.blocks = []
        cur = None
        for raw in open(path, encoding="utf-8"):
            ln = raw.rstrip("\n")
            if ln.startswith("#") or ln.startswith("$"):
                continue
            if ln.startswith("/"):
                cur = (ln.strip(), [])
                self.blocks.append(cur)
            elif cur is not None:
                cur[1].append(ln)

    def of(self, prefix):
        """Blocks whose keyword starts with prefix, as (id, data lines); id = the field after prefix."""
        out = []
        for kw, data in self.blocks:
            if kw.upper().startswith(prefix.upper()):
                rest = kw[len(prefix):].strip("/").split("/")
                out.append((int(rest[0]) if rest and rest[0].strip().isdigit() else 0, data))
        return out


def cell(ln, a, b):
    return ln[a - 1:b].strip()


def real(ln, a, b, default=0.0):
    s = cell(ln, a, b)
    return float(s.replace("D", "E").replace("d", "e")) if s else default


def integer(ln, a, b, default=0):
    s = cell(ln, a, b)
    return int(s) if s else default


class Model:
    """Nodes, elements, parts, groups and the contact-relevant cards of a generated starter deck."""

    def __init__(self, path):
        d = Deck(path)
        self.deck = d
        self.nodes = {}
        for _, data in d.of("/NODE"):
            for ln in data:
                self.nodes[integer(ln, 1, 10)] = (real(ln, 11, 30), real(ln, 31, 50), real(ln, 51, 70))
        self.bricks, self.shells = {}, {}
        for pid, data in d.of("/BRICK"):
            for ln in data:
                self.bricks[integer(ln, 1, 10)] = (pid, [integer(ln, 11 + 10 * k, 20 + 10 * k) for k in range(8)])
        for pid, data in d.of("/SHELL"):
            for ln in data:
                self.shells[integer(ln, 1, 10)] = (pid, [integer(ln, 11 + 10 * k, 20 + 10 * k) for k in range(4)],
                                                   real(ln, 81, 100))
        self.parts = {pid: (integer(data[1], 1, 10), integer(data[1], 11, 20)) for pid, data in d.of("/PART")}
        self.shell_thickness = {pid: real(data[3], 21, 40) for pid, data in d.of("/PROP/SHELL")}
        self.rho = {}
        for prefix in ("/MAT/LAW1", "/MAT/PLAS_JOHNS", "/MAT/PLAS_TAB"):
            for mid, data in d.of(prefix):
                self.rho[mid] = real(data[1], 1, 20)
        self.groups = {}
        for gid, data in d.of("/GRNOD/NODE"):
            self.groups[gid] = [int(x) for ln in data[1:] for x in ln.split()]
        for gid, data in d.of("/GRNOD/PART"):
            parts = {int(x) for ln in data[1:] for x in ln.split()}
            self.groups[gid] = sorted({n for _, (pid, ns) in self.bricks.items() if pid in parts for n in ns} |
                                      {n for _, (pid, ns, _) in self.shells.items() if pid in parts for n in ns})
        self.inivel = [((real(data[1], 1, 20), real(data[1], 21, 40), real(data[1], 41, 60)), integer(data[1], 61, 70))
                       for _, data in d.of("/INIVEL/TRA")]
        self.grav = [(cell(data[1], 11, 20), integer(data[1], 41, 50), real(data[1], 81, 100))
                     for _, data in d.of("/GRAV")]
        self.interfaces = {iid: type7_fields(data) for iid, data in d.of("/INTER/TYPE7")}
        self.interfaces.update({iid: type7_fields(data, lagdt=True) for iid, data in d.of("/INTER/LAGDT/TYPE7")})
        # /SENSOR/TIME: (Tdelay, Tstop); Tstop (the 2023+ second card) 0 or absent = never.
        self.sensors = {sid: (real(data[1], 1, 20), (real(data[2], 1, 20) if len(data) > 2 else 0.0) or 1e30)
                        for sid, data in d.of("/SENSOR/TIME")}
        self.masses = self.lumped_masses()

    def window(self, iid):
        """[on, off) of interface iid: its Tstart and Tstop, narrowed to its sensor's [Tdelay, Tstop)."""
        it = self.interfaces[iid]
        on, off = it["Tstart"], it["Tstop"]
        if it["sens"]:
            t_delay, t_stop = self.sensors[it["sens"]]
            on, off = max(on, t_delay), min(off, t_stop)
        return on, off

    def lumped_masses(self):
        """Lumped nodal masses of regular meshes: a brick gives rho V / 8 to each node (V exact for a
        parallelepiped), a 4-node shell rho t A / 4 (A of a planar quadrilateral)."""
        m = {n: 0.0 for n in self.nodes}
        for pid, ns in self.bricks.values():
            p = [self.nodes[n] for n in ns]
            a, b, c = (sub(p[1], p[0]), sub(p[3], p[0]), sub(p[4], p[0]))
            vol = abs(dot(a, cross(b, c)))
            for n in ns:
                m[n] += self.rho[self.parts[pid][1]] * vol / 8
        for pid, ns, t_el in self.shells.values():
            p = [self.nodes[n] for n in ns]
            area = 0.5 * norm(cross(sub(p[2], p[0]), sub(p[3], p[1])))
            t = t_el if t_el else self.shell_thickness[self.parts[pid][0]]
            for n in ns:
                m[n] += self.rho[self.parts[pid][1]] * t * area / 4
        return m

    def moving_body(self):
        """The deck's only /INIVEL/TRA: (its group's nodes, their total mass, the velocity)."""
        (vel, gid), = self.inivel
        nodes = self.groups[gid]
        return nodes, sum(self.masses[n] for n in nodes), vel

    def brick_part(self):
        """The first part (in deck order) that has bricks."""
        return next(pid for pid in self.parts if any(b[0] == pid for b in self.bricks.values()))

    def flat_z(self, nodes, what):
        """The common z of nodes, asserting that they lie in one plane normal to Z (what: for the message)."""
        z = self.nodes[nodes[0]][2]
        assert all(self.nodes[n][2] == z for n in nodes), "%s must be flat, normal along Z" % what
        return z

    def initial_velocity(self, node):
        v = (0.0, 0.0, 0.0)
        for vel, gid in self.inivel:
            if node in self.groups[gid]:
                v = vel
        return v


def type7_fields(data, lagdt=False):
    """/INTER/TYPE7 2019+ layout or /INTER/LAGDT/TYPE7 (lagdt: no Icurv, the same columns otherwise;
    docs/keywords.md): data[0] is the title."""
    c = data[1:]
    f = dict(grnd=integer(c[0], 1, 10), surf=integer(c[0], 11, 20), Istf=integer(c[0], 21, 30),
             Igap=integer(c[0], 41, 50), Icurv=0 if lagdt else integer(c[0], 81, 90), lagdt=lagdt)
    k = 3 + (1 if f["Icurv"] in (1, 2) else 0)
    f.update(Idel=integer(c[0], 71, 80))
    f.update(Stfac=real(c[k], 1, 20), Fric=real(c[k], 21, 40), Gapmin=real(c[k], 41, 60),
             Tstart=real(c[k], 61, 80), Tstop=real(c[k], 81, 100))
    f.update(IBC=tuple(integer(c[k + 1], col, col) for col in (8, 9, 10)))
    f.update(Inacti=integer(c[k + 1], 31, 40), VISs=real(c[k + 1], 41, 60), VISf=real(c[k + 1], 61, 80))
    f.update(Ifric=integer(c[k + 2], 1, 10), Iform=integer(c[k + 2], 41, 50),
             sens=0 if lagdt else integer(c[k + 2], 51, 60))
    # Two-stage defaults (docs/theory/type7-lagdt.md 3): 0 means the default.
    f["VISs"] = f["VISs"] or 0.05
    f["VISf"] = f["VISf"] or 1.0
    f["Iform"] = f["Iform"] or 1
    f["Tstop"] = f["Tstop"] or 1e30
    return f


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a):
    return math.sqrt(dot(a, a))


# ---------------------------------------------------------------------------------------------------
# TYPE7 normal law (docs/theory/type7-lagdt.md 4.3) and a rigid body on N identical pairs.


def penalty_force(K, g, p):
    return K * p * g / (g - p) if p > 0 else 0.0


def penalty_energy(K, g, p):
    x = p / g
    return K * g * g * (-x - math.log1p(-x)) if p > 0 else 0.0


def energy_equation_x(P):
    """x in [0, 1) with -x - ln(1 - x) = P (docs/theory/verification.md A.2), by bisection."""
    lo, hi = 0.0, 1.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if -mid - math.log1p(-mid) < P:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def rigid_impact(M, masses, K, g, vis_s, p0, vn0, quadratic=True, steps_per_t0=4000):
    """A rigid body of mass M moving along the normal of a fixed plane, held by len(masses) TYPE7 pairs that
    all have the same penetration p (secondary nodes on one flat face parallel to the plane). Each pair i
    (secondary nodal mass masses[i]) pushes with F(p) = K p g / (g - p) and damps with
        c_i = VISs sqrt(2 k m_i / r) + 0.32 m_i max(0, -v_n) / (g - p),   k = K g / (g - p),
        r = (g - p)/g while approaching (v_n < 0), else 1,
    the dashpot opposing v_n (docs/theory/type7-lagdt.md 4.3; quadratic=False leaves out the second term). So
        M dv_n/dt = N F(p) - sum_i c_i v_n,   dp/dt = -v_n.
    Starts at penetration p0 (negative: that far outside the gap) with normal speed vn0 < 0 and integrates
    with fixed-step RK4 (steps of t0 / steps_per_t0, t0 = sqrt(M / (N K))) until the pair opens again.
    Returns dict(p_max, v_rebound (v_n after the contact), t_contact (time in contact), t_max (time from the
    first contact to p_max), t_free (free flight before contact))."""
    n = len(masses)
    t_free = 0.0
    p, v = p0, vn0
    if p < 0:
        t_free = -p / -v
        p = 0.0
    acc = _rigid_acceleration(M, masses, K, g, vis_s, quadratic)
    h = math.sqrt(M / (n * K)) / steps_per_t0
    t, p_max, t_max = 0.0, p, 0.0
    for _ in range(1000 * steps_per_t0):
        # dp/dt = -v, dv/dt = acc(p, v)
        k1p, k1v = -v, acc(p, v)
        k2p, k2v = -(v + 0.5 * h * k1v), acc(p + 0.5 * h * k1p, v + 0.5 * h * k1v)
        k3p, k3v = -(v + 0.5 * h * k2v), acc(p + 0.5 * h * k2p, v + 0.5 * h * k2v)
        k4p, k4v = -(v + h * k3v), acc(p + h * k3p, v + h * k3v)
        p_new = p + h / 6 * (k1p + 2 * k2p + 2 * k3p + k4p)
        v_new = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
        if p_new <= 0 and v_new > 0:
            # Opened during this step: the force vanishes at p = 0, so v_n at the crossing is v_new to
            # within the step's change of speed over an interval where the force is ~0.
            frac = p / (p - p_new)
            return dict(p_max=p_max, v_rebound=v + frac * (v_new - v), t_contact=t + frac * h, t_max=t_max,
                        t_free=t_free)
        p, v, t = p_new, v_new, t + h
        if p > p_max:
            p_max, t_max = p, t
    raise RuntimeError("rigid_impact: the pair did not open")


def _rigid_acceleration(M, masses, K, g, vis_s, quadratic):
    """dv_n/dt(p, v_n) of rigid_impact's body (the law and damping of docs/theory/type7-lagdt.md 4.3)."""
    n = len(masses)
    sum_m = sum(masses)
    sum_sqrt = sum(math.sqrt(m) for m in masses)

    def acc(p, v):
        if p <= 0:
            return 0.0
        rem = g - p
        k = K * g / rem
        r = rem / g if v < 0 else 1.0
        c = vis_s * math.sqrt(2 * k / r) * sum_sqrt
        if quadratic:
            c += 0.32 * max(0.0, -v) / rem * sum_m
        return (n * K * p * g / rem - c * v) / M

    return acc


def rigid_state(M, masses, K, g, vis_s, p0, vn0, t_end, quadratic=True, steps_per_t0=4000):
    """rigid_impact's body (same law, damping and start) at the time t_end after the start: (p, v_n), by
    the same fixed-step RK4 (the last step shortened to land on t_end). Free flight before contact
    (p < 0) and after it are exact."""
    acc = _rigid_acceleration(M, masses, K, g, vis_s, quadratic)
    p, v, t = p0, vn0, 0.0
    if p < 0 and v < 0:
        t_c = -p / -v
        if t_c >= t_end:
            return p - v * t_end, v
        p, t = 0.0, t_c
    h0 = math.sqrt(M / (len(masses) * K)) / steps_per_t0
    while t < t_end:
        h = min(h0, t_end - t)
        k1p, k1v = -v, acc(p, v)
        k2p, k2v = -(v + 0.5 * h * k1v), acc(p + 0.5 * h * k1p, v + 0.5 * h * k1v)
        k3p, k3v = -(v + 0.5 * h * k2v), acc(p + 0.5 * h * k2p, v + 0.5 * h * k2v)
        k4p, k4v = -(v + h * k3v), acc(p + h * k3p, v + h * k3v)
        p += h / 6 * (k1p + 2 * k2p + 2 * k3p + k4p)
        v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
        t += h
    return p, v


def self_test():
    """Without damping the integrator must reproduce the energy equation (relative 1e-6 on x) and a rebound
    at the impact speed (1e-6): guards the expected values of the checks against a broken integrator."""
    M, K, g, v0 = 9.0, 1e6, 1e-3, 1.0
    masses = [0.25] * 9
    r = rigid_impact(M, masses, K, g, 0.0, 0.0, -v0, quadratic=False)
    x = energy_equation_x(M * v0 * v0 / (2 * len(masses) * K * g * g))
    assert abs(r["p_max"] / g - x) <= 1e-6 * x, (r["p_max"] / g, x)
    assert abs(r["v_rebound"] - v0) <= 1e-6 * v0, r["v_rebound"]


# ---------------------------------------------------------------------------------------------------
# Running radx and reading its outputs


def read_th(out, name):
    """{group path: (rows [n, 1 + c] float64, {column name: index})} of NAME_th.h5."""
    import h5py
    groups = {}
    with h5py.File(os.path.join(out, name + "_th.h5"), "r") as f:
        def visit(path, obj):
            if isinstance(obj, h5py.Dataset):
                cols = [c.decode() if isinstance(c, bytes) else str(c) for c in obj.attrs["columns"]]
                groups[path] = (obj[()], {c: k for k, c in enumerate(cols)})
        f.visititems(visit)
    return groups


def th_column(th, name):
    """(time, values) of the column `name` (e.g. "101:DZ") in whichever group of read_th() holds it."""
    for rows, cols in th.values():
        if name in cols:
            return rows[:, 0], rows[:, cols[name]]
    raise KeyError("no time-history column %s (groups: %s)" % (name, ", ".join(th)))


def has_column(th, name):
    return any(name in cols for _, cols in th.values())


def part_velocity(th, pid, axis="Z"):
    """(time, mean velocity of part pid along axis: <axis>MOM / MASS) from the time history."""
    t, mom = th_column(th, "%d:%sMOM" % (pid, axis))
    return t, mom / th_column(th, "%d:MASS" % pid)[1]


def contact_forces(th, iid):
    """(time, [FNX, FNY, FNZ] as a [3, rows] array) of interface iid from the time history: the forces of each
    row's cycle (FNX_INST..), which the checks compare with that cycle's state; FNX.. are the means over the
    interval since the previous row (docs/results.md, "Interval means")."""
    import numpy as np
    t, _ = th_column(th, "%d:FNZ_INST" % iid)
    return t, np.array([th_column(th, "%d:FN%s_INST" % (iid, a))[1] for a in "XYZ"])


def penetrations(m, th, nodes, g, z_plate):
    """Penetration g - (z - z_plate) of each node into the gap g of a flat plane at z_plate, at every
    time-history row ([len(nodes), rows]; z from the deck's position and the time history's DZ)."""
    import numpy as np
    z0 = np.array([m.nodes[n][2] for n in nodes])
    return np.array([g - (z0[k] + th_column(th, "%d:DZ" % n)[1] - z_plate) for k, n in enumerate(nodes)])


def engine_card(deck, keyword):
    """The numbers of the first data line after `keyword` (e.g. "/DT/INTER/CST") in the engine deck beside the
    starter deck (NAME_0001.rad, free format), or None when the card is absent."""
    path = deck[:-len("_0000.rad")] + "_0001.rad" if deck.endswith("_0000.rad") else deck
    lines = [ln.rstrip("\n") for ln in open(path, encoding="utf-8")]
    for k, ln in enumerate(lines):
        if ln.strip().upper() == keyword.upper():
            for data in lines[k + 1:]:
                if data.startswith("#") or data.startswith("$") or not data.strip():
                    continue
                return [float(x.replace("D", "E").replace("d", "e")) for x in data.replace(",", " ").split()]
    return None


def read_listing(out, name):
    """The engine listing NAME_0001.out as text (for its warnings and summary rows)."""
    with open(os.path.join(out, name + "_0001.out"), encoding="utf-8", errors="replace") as f:
        return f.read()


def listing_rows(text):
    """The cycle lines of an engine listing: list of dict(cycle, time, dt, added_mass) (docs: the columns
    CYCLE, TIME, TIME-STEP, ..., MASS ADDED; the last column is the mass added so far)."""
    rows = []
    for ln in text.splitlines():
        f = ln.split()
        if len(f) >= 12 and f[0].isdigit() and any(x.endswith("%") for x in f):
            try:
                rows.append(dict(cycle=int(f[0]), time=float(f[1]), dt=float(f[2]), added_mass=float(f[-1])))
            except ValueError:
                pass
    return rows


def read_states(out, name):
    """Mesh and animation states: dict(node_id [N] int64, cells [list of node-index lists], cell_part [C],
    states [list of (time, points [N, 3] float64)]), states in time order."""
    import h5py
    import numpy as np
    with h5py.File(os.path.join(out, name + ".mesh.hdf"), "r") as m:
        v = m["VTKHDF"]
        node_id = v["PointData/node_id"][()]
        conn, offs = v["Connectivity"][()], v["Offsets"][()]
        cells = [conn[offs[k]:offs[k + 1]].tolist() for k in range(len(offs) - 1)]
        cell_part = v["CellData/part_id"][()]
    states = []
    for path in sorted(glob.glob(os.path.join(out, name + "_[0-9][0-9][0-9][0-9][0-9][0-9].hdf"))):
        with h5py.File(path, "r") as f:
            states.append((float(f["VTKHDF/FieldData/TimeValue"][()][0]), np.array(f["VTKHDF/Points"][()],
                                                                                dtype=np.float64)))
    states.sort(key=lambda s: s[0])
    return dict(node_id=node_id, cells=cells, cell_part=cell_part, states=states)


class Checks:
    """Collects failures; every check prints one line saying what was compared and how close it came."""

    def __init__(self, label=""):
        self.failures = []
        self.label = label

    def check(self, ok, msg):
        print(("ok   " if ok else "FAIL ") + (self.label + ": " if self.label else "") + msg)
        if not ok:
            self.failures.append(msg)
        return ok

    def close(self, value, expected, rel, what):
        err = abs(value - expected) / abs(expected) if expected else abs(value)
        return self.check(err <= rel, "%s = %.6g, expected %.6g (off by %.3g %%, allowed %.3g %%)"
                          % (what, value, expected, 100 * err, 100 * rel))


def check_energy_error(checks, summary, detail=""):
    """The run's energy error (summary) within 1 % (docs/theory/verification.md C); detail is added to the message."""
    err = summary["energy"]["error_percent"]
    return checks.check(abs(err) <= 1.0, "energy error %.3g %% (allowed 1 %%%s)" % (err, detail))


def check_all_pairs_switched(checks, summary, n_pairs):
    """An /INTER/LAGDT/TYPE7 with Tmin far above the pair steps: each of its n_pairs pairs is a multiplier row at
    every cycle, cycle 0 included (the summary's first interface)."""
    si = summary["interfaces"][0]
    rows = n_pairs * (summary["cycles"] + 1)
    return checks.check(si["switched_pairs_total"] == rows and si["switched_pairs_max"] == n_pairs,
                        "every pair switched at every cycle: %d pair-cycles (expected %d), at most %d in a cycle"
                        % (si["switched_pairs_total"], rows, si["switched_pairs_max"]))


def finish(all_checks):
    bad = [f for c in all_checks for f in c.failures]
    if bad:
        print("%d check(s) failed" % len(bad))
        sys.exit(1)
    print("all checks passed")


def main_per_deck(one_deck, self_test_first=False, options=()):
    """The command line of a check that runs decks one after another: --radx RADX --decks DECK... --out DIR,
    plus options ((flag, add_argument keywords) pairs). Runs self_test() first if asked, then
    one_deck(radx, deck, OUT/<run name>, checks, <options by name>) for every deck, each with its own Checks
    labelled with the run name (NAME of NAME_0000.rad), and finish()."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--decks", nargs="+", required=True)
    ap.add_argument("--out", required=True)
    dests = [ap.add_argument(flag, **kw).dest for flag, kw in options]
    a = ap.parse_args()
    if self_test_first:
        self_test()
    all_checks = []
    for deck in a.decks:
        label = os.path.basename(deck).replace("_0000.rad", "")
        c = Checks(label)
        one_deck(a.radx, deck, os.path.join(a.out, label), c, **{d: getattr(a, d) for d in dests})
        all_checks.append(c)
    finish(all_checks)
