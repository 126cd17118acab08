"""Square tube crushed axially with TYPE7 self-contact: it must fold, and no node may pass through a segment.

usage: /usr/bin/python3 check_contact_tube_crush.py --radx RADX
           --deck decks/verification/tube_crush/TUBE_CRUSH_0000.rad --out DIR [--states-only]

(--states-only skips the run and checks the states already in DIR.)

Pass-through test, on the animation states (float64 coordinates of every node):
  * every quadrangle segment is split into four triangles around its centroid (the contact geometry of
    docs/theory/type7-lagdt.md 4.3); a node is never tested against the triangles of a segment that contains it;
  * for two consecutive states A and B, node and triangle vertices are taken to move on straight lines between
    them. The signed distance of the node to the triangle's plane is s_A in state A and s_B in state B (each
    with its own state's normal). A pass-through is a strict sign change (s_A s_B < 0, both above 1e-9 of the
    tube width, so round-off at a node lying in a plane does not count) whose crossing point lies inside the
    triangle: at lambda = s_A / (s_A - s_B) the interpolated node, projected on the interpolated triangle's
    plane, has barycentric coordinates all >= -1e-6. A node crossing exactly on a shared edge is inside one of
    the two triangles, so nothing is missed at the seams;
  * candidates: only (node, triangle) pairs closer than the triangle's circumradius plus the largest motion of
    any node between the two states (plus 1 % of the width) can cross, found with a k-d tree (scipy), so the
    test costs O(N log N) per pair of states, not O(N M).
The states are written every dT of the engine deck; the deck keeps the crush per state below the gap, and a
node that moves more than the gap between states would be reported as a warning (the linear path is then only
an approximation, and the test can miss a pass-through and come back).

Also checked:
  * the run reaches its end time and the moving end has travelled the imposed distance (0.5 % of it);
  * the tube folded: some node moved sideways by more than three thicknesses;
  * the self-contact acted: contact energy (elastic + damping + friction) above 0.1 % of the external work;
  * energy error within 1 % (docs/theory/verification.md C).
"""
import argparse
import os

import numpy as np
from scipy.spatial import cKDTree

import check_contact_common as cc


def triangles(cells, points):
    """The four triangles of each 4-node cell around its centroid: returns (quads [Q, 4] node indices,
    tri [T, 3] indices into the points extended by the centroids (extend(): centroid of quad c is point N + c),
    owner [T] the quad of each triangle)."""
    n = len(points)
    quads = np.array([c for c in cells if len(c) == 4], dtype=np.int64)
    tri = []
    owner = []
    for ci, q in enumerate(quads):
        for k in range(4):
            tri.append((q[k], q[(k + 1) % 4], n + ci))
            owner.append(ci)
    return quads, np.array(tri, dtype=np.int64), np.array(owner, dtype=np.int64)


def extend(points, quads):
    return np.vstack([points, points[quads].mean(axis=1)])


def plane(pts, tri):
    a, b, c = pts[tri[:, 0]], pts[tri[:, 1]], pts[tri[:, 2]]
    nrm = np.cross(b - a, c - a)
    length = np.linalg.norm(nrm, axis=1)
    return a, nrm / np.maximum(length, 1e-300)[:, None]


def barycentric(p, a, b, c):
    v0, v1, v2 = b - a, c - a, p - a
    d00, d01, d11 = (v0 * v0).sum(1), (v0 * v1).sum(1), (v1 * v1).sum(1)
    d20, d21 = (v2 * v0).sum(1), (v2 * v1).sum(1)
    den = d00 * d11 - d01 * d01
    v = (d11 * d20 - d01 * d21) / den
    w = (d00 * d21 - d01 * d20) / den
    return np.stack([1 - v - w, v, w], axis=1)


def pass_throughs(res, width):
    """List of (state index, time A, time B, node id, cell index) for every pass-through found, and the largest
    node motion between states."""
    node_id = res["node_id"]
    quads, tri, owner = triangles(res["cells"], res["states"][0][1])
    contains = [set(q.tolist()) for q in quads]
    found, largest = [], 0.0
    for k in range(len(res["states"]) - 1):
        (ta, xa), (tb, xb) = res["states"][k], res["states"][k + 1]
        move = np.linalg.norm(xb - xa, axis=1)
        largest = max(largest, move.max())
        pa, pb = extend(xa, quads), extend(xb, quads)
        oa, na = plane(pa, tri)
        ob, nb = plane(pb, tri)
        cen = pa[tri].mean(axis=1)
        rad = np.linalg.norm(pa[tri] - cen[:, None, :], axis=2).max(axis=1)
        reach = rad.max() + 2 * move.max() + 0.01 * width
        pairs = cKDTree(xa).query_ball_point(cen, reach)
        ti = np.array([t for t, ns in enumerate(pairs) for _ in ns], dtype=np.int64)
        ni = np.array([n for ns in pairs for n in ns], dtype=np.int64)
        if len(ti) == 0:
            continue
        keep = np.array([n not in contains[owner[t]] for t, n in zip(ti, ni)])
        ti, ni = ti[keep], ni[keep]
        sa = ((xa[ni] - oa[ti]) * na[ti]).sum(1)
        sb = ((xb[ni] - ob[ti]) * nb[ti]).sum(1)
        tiny = 1e-9 * width
        cross = (sa * sb < 0) & (np.abs(sa) > tiny) & (np.abs(sb) > tiny)
        if not cross.any():
            continue
        ti, ni, sa, sb = ti[cross], ni[cross], sa[cross], sb[cross]
        lam = (sa / (sa - sb))[:, None]
        p = xa[ni] + lam * (xb[ni] - xa[ni])
        verts = [pa[tri[ti, j]] + lam * (pb[tri[ti, j]] - pa[tri[ti, j]]) for j in range(3)]
        o, nrm = verts[0], np.cross(verts[1] - verts[0], verts[2] - verts[0])
        nrm /= np.linalg.norm(nrm, axis=1)[:, None]
        proj = p - ((p - o) * nrm).sum(1)[:, None] * nrm
        inside = (barycentric(proj, *verts) >= -1e-6).all(axis=1)
        for t, n in zip(ti[inside], ni[inside]):
            found.append((k, ta, tb, int(node_id[n]), int(owner[t])))
    return found, largest


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--states-only", action="store_true")
    a = ap.parse_args()
    m = cc.Model(a.deck)
    (it,) = m.interfaces.values()
    gap = it["Gapmin"]
    thick = next(iter(m.shell_thickness.values()))
    xs = [p[0] for p in m.nodes.values()]
    width = max(xs) - min(xs)
    name = os.path.basename(a.deck)[:-len("_0000.rad")]
    if not a.states_only:
        cc.run_radx(a.radx, a.deck, a.out)
    checks = cc.Checks("tube")
    s = cc.read_summary(a.out, name)
    checks.check(s["status"] == "normal", "run status %s: %s" % (s["status"], s["message"]))
    res = cc.read_states(a.out, name)
    states = res["states"]
    checks.check(len(states) >= 10, "%d animation states" % len(states))
    x0, xl = states[0][1], states[-1][1]
    # The imposed crush: the moving end's /IMPVEL (ramp, then constant) integrated over the run.
    deck = cc.Deck(a.deck)
    (_, impvel), = deck.of("/IMPVEL")
    (_, funct), = deck.of("/FUNCT")
    fscale = cc.real(impvel[2], 21, 40)
    pts = [(cc.real(ln, 1, 20), cc.real(ln, 21, 40)) for ln in funct[1:]]
    t_end = s["time"]
    tt = np.linspace(0.0, t_end, 200001)
    crush = abs(fscale) * np.trapz(np.interp(tt, [p[0] for p in pts], [p[1] for p in pts]), tt)
    top = x0[:, 2] >= x0[:, 2].max() - 1e-9
    checks.close(float(np.mean(x0[top, 2] - xl[top, 2])), crush, 0.005, "crush of the moving end (mm)")
    lateral = max(float(np.max(np.hypot(x[:, 0] - x0[:, 0], x[:, 1] - x0[:, 1]))) for _, x in states)
    checks.check(lateral > 3 * thick, "folded: largest sideways motion %.3g mm (needs > 3 t = %.3g mm)"
                 % (lateral, 3 * thick))
    e = s["energy"]
    ce = e["contact_elastic"] + e["contact_damping"] + e["contact_friction"]
    checks.check(ce > 1e-3 * e["external_work"], "self-contact acted: contact energy %.4g (external work %.4g)"
                 % (ce, e["external_work"]))
    cc.check_energy_error(checks, s)
    found, largest = pass_throughs(res, width)
    if largest > gap:
        print("warning: a node moved %.3g mm between two states, more than the gap %g mm" % (largest, gap))
    for k, ta, tb, nid, cell in found[:20]:
        print("  node %d through cell %d between states %d and %d (t = %.6g to %.6g)"
              % (nid, cell, k, k + 1, ta, tb))
    checks.check(not found, "no node passes through a segment: %d pass-through(s) in %d state intervals "
                 "(largest node motion between states %.3g mm)" % (len(found), len(states) - 1, largest))
    cc.finish([checks])


if __name__ == "__main__":
    main()
