"""Shared pieces of the /CTCLAW solver-level checks (tests/scripts/check_ctclaw_*.py).

Not a test by itself. On top of check_contact_common (the deck reader, running radx, the time history), it
holds what the law checks need, each computed from the deck the check runs:
  * the /CTCLAW cards and /FUNCT curves of a deck, and a reader of the law string
    (docs/theory/contact-laws.md section 4);
  * the tributary area A_s of each secondary node by the starter's rule (contact/type7_prepare.hpp,
    tributary_areas): the surface patches are the shells and the outer brick faces (a face no other brick has);
    a node takes a quarter of each 4-node patch and a third of each 3-node patch around it whose nodes are all
    secondary nodes of the interface (the contact surface: a block's lower-face corner takes its share of the
    lower face, not of the block's sides), or, when it has no such patch, of every patch around it;
  * the normal laws P(u) of docs/theory/contact-laws.md section 2, written again here from the specification (the
    monotone cubic with the tangents that contact/ctclaw_laws.cpp states), their energy integral and the largest
    overclosure that absorbs a given energy;
  * the automatic stiffness density K / A_s that the starter listing prints for Kc = -1 or pe, to compare
    with the area computed here.

Plain /usr/bin/python3; the standard library only (scripts/make_ctclaw_decks.py imports it for the expected
values in the READMEs).
"""
import math
import re

# The exponential law's cut-off: no contact below P = 1e-12 pz (docs/theory/contact-laws.md 2.2).
EXP_CUTOFF = 1e-12

# ---------------------------------------------------------------------------------------------------
# The deck's /CTCLAW and /FUNCT cards


def ctclaws(deck):
    """{interface id: (law id, law string)} of the /CTCLAW cards of a check_contact_common.Deck: card 1 (after
    the title) is the interface, the lines after it the law string, joined with the blanks removed."""
    out = {}
    for lid, data in deck.of("/CTCLAW"):
        inter = int(data[1][:10])
        out[inter] = (lid, "".join("".join(ln.split()) for ln in data[2:]))
    return out


def functs(deck):
    """{function id: ([x], [y])} of the /FUNCT cards (title, then one (x, y) pair of 20-column reals a line)."""
    out = {}
    for fid, data in deck.of("/FUNCT"):
        xs, ys = [], []
        for ln in data[1:]:
            if ln.strip():
                xs.append(float(ln[0:20].replace("D", "E")))
                ys.append(float(ln[20:40].replace("D", "E")))
        out[fid] = (xs, ys)
    return out


def parse_urn(text):
    """The law string n<normal>s<friction>{name value, ...} as dict(normal (0: the interface's penalty),
    friction (0: none), params {lower-case name: value}, power [(m, kp_m)])."""
    t = "".join(text.split())
    m = re.fullmatch(r"(?:[nN](\d))?(?:[sS](\d+))?(?:\{(.*)\})?", t)
    if not m:
        raise ValueError("cannot read the law string %r" % text)
    law = dict(normal=int(m.group(1) or 0), friction=int(m.group(2) or 0), params={}, power=[])
    for item in filter(None, (m.group(3) or "").split(",")):
        pm = re.fullmatch(r"[kK][pP]([0-9.]+)=(.+)", item)
        if pm:
            law["power"].append((float(pm.group(1)), float(pm.group(2).replace("D", "E").replace("d", "e"))))
            continue
        nm = re.fullmatch(r"([A-Za-z]+)=?(.+)", item)
        if not nm:
            raise ValueError("cannot read the parameter %r of %r" % (item, text))
        law["params"][nm.group(1).lower()] = float(nm.group(2).replace("D", "E").replace("d", "e"))
    return law


# ---------------------------------------------------------------------------------------------------
# Tributary areas (the starter's rule)

BRICK_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))


def _polygon_area(pts):
    if len(pts) == 3:
        a, b, c = pts
        return 0.5 * _norm(_cross(_sub(b, a), _sub(c, a)))
    a, b, c, d = pts
    return 0.5 * _norm(_cross(_sub(c, a), _sub(d, b)))


def _distinct(ns):
    out = []
    for n in ns:
        if n not in out:
            out.append(n)
    return out


def tributary_areas(model, nodes):
    """{node id: A_s} of the secondary nodes `nodes` of a check_contact_common.Model by the starter's rule (see
    the module docstring)."""
    patches = [_distinct(ns) for _, ns, _ in model.shells.values()]
    faces = {}
    for _, ns in model.bricks.values():
        own = set()
        for f in BRICK_FACES:
            d = _distinct([ns[k] for k in f])
            if len(d) < 3:
                continue
            key = tuple(sorted(d))
            if key in own:
                continue
            own.add(key)
            faces.setdefault(key, []).append(d)
    patches += [found[0] for found in faces.values() if len(found) == 1]
    secondary = set(nodes)
    on_surface = {n: 0.0 for n in nodes}
    around = {n: 0.0 for n in nodes}
    for d in patches:
        if len(d) < 3:
            continue
        share = _polygon_area([model.nodes[n] for n in d]) / len(d)
        inside = all(n in secondary for n in d)
        for n in d:
            if n in secondary:
                around[n] += share
                if inside:
                    on_surface[n] += share
    return {n: on_surface[n] if on_surface[n] > 0 else around[n] for n in nodes}


def listing_automatic_stiffness(listing_text):
    """The range (lo, hi) of the automatic stiffness density K / A_s (Pa/m) that the starter listing prints
    for a law with Kc = -1 or pe ("Kc automatic, K/A_s from X [to Y]" or "Kc_auto = K/A_s from X [to Y]"),
    or None when it prints none."""
    m = re.search(r"K/A_s from ([-+0-9.eE]+)(?: to ([-+0-9.eE]+))?", listing_text)
    if not m:
        return None
    lo = float(m.group(1))
    return lo, float(m.group(2)) if m.group(2) else lo


# ---------------------------------------------------------------------------------------------------
# Normal laws (docs/theory/contact-laws.md section 2), per pair: the law string's parameters resolved with the pair's K
# and A_s as the specification says (Kc = -1: K / A_s; lambda = (K / A_s) / pe).


def _monotone_tangent(d0, d1, h0, h1):
    if d0 * d1 <= 0:
        return 0.0
    w1, w2 = 2 * h1 + h0, h1 + 2 * h0
    return (w1 + w2) / (w1 / d0 + w2 / d1)


class NormalLaw:
    """P(u) (Pa) of one pair; u the overclosure (m), positive inside the gap."""

    def __init__(self, law, K, area, curves=None):
        self.kind = law["normal"]
        prm = law["params"]
        kc_auto = K / area
        self.breaks = []  # overclosures where P or its slope has a kink (integration break points)
        if self.kind == 1:
            self.kc = kc_auto if prm["kc"] == -1 else prm["kc"]
            self.breaks = [0.0]
        elif self.kind == 2:
            self.pz = prm["pz"]
            self.lam = prm["lambda"] if "lambda" in prm else kc_auto / prm["pe"]
            self.kc_max = prm.get("kcmax", 0.0)
            self.u_knee = (math.log(self.kc_max / (self.pz * self.lam)) / self.lam if self.kc_max > 0
                           else math.inf)
            self.u_cut = math.log(EXP_CUTOFF) / self.lam
            self.breaks = [self.u_cut] + ([self.u_knee] if self.kc_max > 0 else [])
        elif self.kind == 3:
            x, y = curves[int(prm["curveid"])]
            self.x, self.y = list(x), list(y)
            self.cubic = bool(prm.get("cubic", 0))
            self.breaks = sorted(-g for g in self.x)
        elif self.kind == 4:
            self.power = list(law["power"])
            self.breaks = [0.0]
        else:
            raise ValueError("no normal law in %r" % law)

    def onset(self):
        """The overclosure where the law starts acting (P > 0 above it)."""
        if self.kind == 2:
            return self.u_cut
        if self.kind == 3:
            # Pressures do not rise with the gap; the first gap at which P reaches 0 (a point, or the last
            # segment's extrapolation).
            for k in range(len(self.x)):
                if not self.y[k] > 0:
                    return -self.x[k]
            s = (self.y[-1] - self.y[-2]) / (self.x[-1] - self.x[-2])
            return -(self.x[-1] - self.y[-1] / s)
        return 0.0

    def pressure(self, u):
        if self.kind == 1:
            return self.kc * u if u > 0 else 0.0
        if self.kind == 2:
            if u > self.u_knee:
                return self.kc_max / self.lam + self.kc_max * (u - self.u_knee)
            p = self.pz * math.exp(self.lam * u)
            return p if p >= EXP_CUTOFF * self.pz else 0.0
        if self.kind == 3:
            return max(0.0, self._table(-u))
        if self.kind == 4:
            return sum(k * u ** m for m, k in self.power) if u > 0 else 0.0

    def _table(self, g):
        x, y, n = self.x, self.y, len(self.x)
        if g >= x[-1]:
            k = n - 2
        elif g > x[0]:
            k = max(i for i in range(n - 1) if x[i] <= g)
        else:
            k = 0
        h = x[k + 1] - x[k]
        d = (y[k + 1] - y[k]) / h
        if not self.cubic or g <= x[0] or g >= x[-1]:
            return y[k] + d * (g - x[k])

        def sec(j):
            return (y[j + 1] - y[j]) / (x[j + 1] - x[j])

        m0 = d if k == 0 else _monotone_tangent(sec(k - 1), d, x[k] - x[k - 1], h)
        m1 = d if k + 2 == n else _monotone_tangent(d, sec(k + 1), h, x[k + 2] - x[k + 1])
        t = (g - x[k]) / h
        return ((2 * t ** 3 - 3 * t ** 2 + 1) * y[k] + (t ** 3 - 2 * t ** 2 + t) * h * m0 +
                (-2 * t ** 3 + 3 * t ** 2) * y[k + 1] + (t ** 3 - t ** 2) * h * m1)

    def work(self, u1):
        """Integral of P du (J/m^2) from where the law starts acting up to u1: the closed form for the exponential
        law, else composite Simpson (400 intervals) between the law's break points (kinks), exact to round-off
        for these piecewise polynomials of degree <= 3 (a power law of a higher or fractional degree: within
        ~1e-9)."""
        u0 = self.onset()
        if u1 <= u0:
            return 0.0
        if self.kind == 2:  # closed form: (pz / lambda) (exp(lambda u) - 1e-12), then the line beyond the knee
            ue = min(u1, self.u_knee)
            w = self.pz / self.lam * (math.exp(self.lam * ue) - EXP_CUTOFF)
            if u1 > self.u_knee:
                d = u1 - self.u_knee
                w += self.kc_max / self.lam * d + self.kc_max * d * d / 2
            return w
        pts = [u0] + [b for b in sorted(self.breaks) if u0 < b < u1] + [u1]
        total = 0.0
        for a, b in zip(pts[:-1], pts[1:]):
            n = 400
            h = (b - a) / n
            s = self.pressure(a) + self.pressure(b)
            s += sum((4 if k % 2 else 2) * self.pressure(a + k * h) for k in range(1, n))
            total += s * h / 3
        return total


def peak_overclosure(laws_areas, energy, hi):
    """The largest overclosure u_max at which the pairs [(NormalLaw, A_s)] moving together have absorbed
    `energy` (J): sum A_s * work(u_max) = energy, by bisection on [max onset, hi]."""
    lo = max(law.onset() for law, _ in laws_areas)

    def f(u):
        return sum(a * law.work(u) for law, a in laws_areas) - energy

    if f(hi) < 0:
        raise ValueError("the laws do not absorb %g J before the overclosure %g" % (energy, hi))
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if f(mid) < 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def damped_linear_impact(M, ks, cs, v0):
    """A rigid body of mass M hitting at v0 a set of linear springs ks (N/m) with dashpots cs (N s/m) in
    parallel, active while the overclosure is positive (a Kelvin-Voigt contact): xi = sum c / (2 sqrt(M sum k)),
    omega = sqrt(sum k / M). Returns dict(xi, t_contact = pi / omega_d, restitution
    exp(-xi pi / sqrt(1 - xi^2)), u_max = (v0 / omega) exp(-xi / sqrt(1 - xi^2) atan(sqrt(1 - xi^2) / xi)))."""
    k, c = sum(ks), sum(cs)
    w = math.sqrt(k / M)
    xi = c / (2 * math.sqrt(k * M))
    s = math.sqrt(1 - xi * xi)
    u_max = v0 / w * (math.exp(-xi / s * math.atan2(s, xi)) if xi > 0 else 1.0)
    return dict(xi=xi, omega=w, t_contact=math.pi / (w * s), restitution=math.exp(-xi * math.pi / s), u_max=u_max)


def self_test():
    """The law integrals against their closed forms (relative 1e-8), and the peak overclosure of a linear law
    against v0 sqrt(M / k): guards the expected values of the checks."""
    def close(a, b, what):
        assert abs(a - b) <= 1e-8 * abs(b), (what, a, b)

    lin = NormalLaw(dict(normal=1, params=dict(kc=3e9), power=[]), 1e6, 0.005)
    close(lin.work(4e-4), 3e9 * 4e-4 ** 2 / 2, "bilinear work")
    ex = NormalLaw(dict(normal=2, params=dict(pz=1500.0, **{"lambda": 2e4}), power=[]), 1e6, 0.005)
    simpson = sum((1 if k in (0, 40000) else 4 if k % 2 else 2) * ex.pressure(ex.u_cut + k * (4e-4 - ex.u_cut) / 40000)
                  for k in range(40001)) * (4e-4 - ex.u_cut) / 40000 / 3
    close(ex.work(4e-4), simpson, "exponential work")
    exk = NormalLaw(dict(normal=2, params=dict(pz=1500.0, kcmax=1e10, **{"lambda": 2e4}), power=[]), 1e6, 0.005)
    uk, pk = exk.u_knee, 1e10 / 2e4
    close(exk.work(4e-4), 1500.0 / 2e4 * (math.exp(2e4 * uk) - EXP_CUTOFF) + pk * (4e-4 - uk) +
          1e10 * (4e-4 - uk) ** 2 / 2, "exponential work beyond the knee")
    pw = NormalLaw(dict(normal=4, params={}, power=[(1.0, 1e9), (3.0, 2e16)]), 1e6, 0.005)
    close(pw.work(4e-4), 1e9 * 4e-4 ** 2 / 2 + 2e16 * 4e-4 ** 4 / 4, "power work")
    tab = NormalLaw(dict(normal=3, params=dict(curveid=1), power=[]), 1e6, 0.005,
                    {1: ([-1e-3, -5e-4, 0.0], [4e6, 1e6, 0.0])})
    close(tab.work(8e-4), 0.5 * 1e6 * 5e-4 + (1e6 + 1e6 + 3e6 * 3e-4 / 5e-4) / 2 * 3e-4, "table work")
    u = peak_overclosure([(lin, 0.005)] * 4, 4.5, 1e-2)
    close(u, 1.0 * math.sqrt(9.0 / (4 * 3e9 * 0.005)), "peak overclosure")


# ---------------------------------------------------------------------------------------------------


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _norm(a):
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
