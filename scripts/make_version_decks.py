#!/usr/bin/env python3
"""Write one small model as starter decks in the layouts of several Radioss deck formats.

The same model (a clamped Johnson-Cook plate hit by an elastic block held by a rigid body, with a TYPE7 and a
LAGDT/TYPE7 interface, a rigid wall, gravity, an imposed velocity and time histories) is written once per
deck version (/BEGIN INVERS) into decks/versions/VERSIONS_<version>_0000.rad. Every field sits at the columns
of its version's layout, every card the layout has is written (fields it lacks are left out), and the values
are the same in every version, so every deck must give the same model: the ctest decks.versions_same_model
runs the starter on each and compares the model files with the 2026 one.

The layouts of 90 to 140 are those OpenRadioss reads each keyword with (the FORMAT block of the highest
version at or below the deck's), restated here from the format facts, not from radx's declarations; those of
2026 follow docs/theory/deck-format.md. Edit this script and regenerate rather than editing the decks by hand.

    python3 scripts/make_version_decks.py              # into decks/versions/
    python3 scripts/make_version_decks.py --out /tmp/x

Plain python3, standard library only.
"""
import argparse
import os
import sys

from radx_deck_format import RULER, fmt_real, write

VERSIONS = (90, 100, 110, 120, 130, 140, 2026)
RUN = "VERSIONS"

# ---------------------------------------------------------------------------------------------------
# Cards: a field is (name, first column, last column, value, first version, last version); the value is an
# int, a float, a str, or None for a blank field. A card is written with the fields of the deck's version.

ANY, LAST = 0, 9999


def fld(name, a, b, value, since=ANY, until=LAST):
    return (name, a, b, value, since, until)


def text_of(value, width):
    if value is None:
        return ""
    if isinstance(value, float):
        s = fmt_real(value)
    else:
        s = str(value)
    if len(s) > width:
        raise ValueError("%r does not fit in %d columns" % (s, width))
    return s


def card_lines(v, fields, names=True):
    """The field-name comment line (optional) and the data line of one card in version v."""
    present = [f for f in fields if f[4] <= v <= f[5]]
    data = [" "] * 100
    head = [" "] * 100
    for name, a, b, value, _, _ in present:
        s = text_of(value, b - a + 1).rjust(b - a + 1)
        data[a - 1:b] = list(s)
        label = name[:b - a + 1].rjust(b - a + 1)
        head[a - 1:b] = list(label)
    out = []
    if names and present:
        h = "".join(head).rstrip()
        if h[0] != " ":
            raise ValueError("field name fills column 1: %r" % h)
        out.append("#" + h[1:])
    out.append("".join(data).rstrip())
    return out


# ---------------------------------------------------------------------------------------------------
# Geometry (mm): a 40 x 40 plate of 4 x 4 shells at z = 0 and a 20 mm cube of 2 x 2 x 2 bricks above it.

PN = 4
PITCH = 10.0
BN = 2
BLOCK_Z0 = 1.5


def plate_node(i, j):
    return 1 + i + (PN + 1) * j


def block_node(i, j, k):
    return 101 + i + (BN + 1) * j + (BN + 1) ** 2 * k


def nodes():
    out = []
    for j in range(PN + 1):
        for i in range(PN + 1):
            out.append((plate_node(i, j), (i - PN / 2) * PITCH, (j - PN / 2) * PITCH, 0.0))
    for k in range(BN + 1):
        for j in range(BN + 1):
            for i in range(BN + 1):
                out.append((block_node(i, j, k), (i - BN / 2) * PITCH, (j - BN / 2) * PITCH, BLOCK_Z0 + k * PITCH))
    return out


def shells():
    return [(1 + i + PN * j, plate_node(i, j), plate_node(i + 1, j), plate_node(i + 1, j + 1), plate_node(i, j + 1))
            for j in range(PN) for i in range(PN)]


def bricks():
    out = []
    for k in range(BN):
        for j in range(BN):
            for i in range(BN):
                b = [block_node(i, j, k), block_node(i + 1, j, k), block_node(i + 1, j + 1, k), block_node(i, j + 1, k)]
                t = [block_node(i, j, k + 1), block_node(i + 1, j, k + 1), block_node(i + 1, j + 1, k + 1),
                     block_node(i, j + 1, k + 1)]
                out.append((101 + i + BN * j + BN * BN * k, *b, *t))
    return out


def edge_nodes():
    return [plate_node(i, j) for j in range(PN + 1) for i in range(PN + 1) if i in (0, PN) or j in (0, PN)]


def top_nodes():
    return [block_node(i, j, BN) for j in range(BN + 1) for i in range(BN + 1)]


MAIN_NODE = block_node(1, 1, BN)  # centre of the block's top face: the rigid body's main node


# ---------------------------------------------------------------------------------------------------
# The deck


def id_lines(ids):
    return ["".join(str(x).rjust(10) for x in ids[k:k + 10]) for k in range(0, len(ids), 10)]


def deck(v):
    L = []

    def kw(header, title=None):
        L.append(RULER)
        L.append(header)
        if title is not None:
            L.append(title)

    def c(*fields):
        L.extend(card_lines(v, fields))

    L.append("#RADIOSS STARTER")
    L.append("# One model in the deck format %d; generated by scripts/make_version_decks.py (do not edit)." % v)
    kw("/BEGIN")
    L.append(RUN)
    c(fld("INVERS", 1, 10, v), fld("IRUN", 11, 20, 0, until=2020))
    if v >= 100:
        c(fld("Input_mass", 1, 20, "Mg"), fld("Input_length", 21, 40, "mm"), fld("Input_time", 41, 60, "s"))
        c(fld("Work_mass", 1, 20, "Mg"), fld("Work_length", 21, 40, "mm"), fld("Work_time", 41, 60, "s"))
    else:
        # Version 90: no unit cards; the global units are keywords of their own.
        for q, u in (("MASS", "Mg"), ("LENGTH", "mm"), ("TIME", "s")):
            kw("/UNIT/%s/%s" % (q, u))
    kw("/TITLE")
    L.append("A clamped plate hit by a block held by a rigid body; the same model in every deck format")
    kw("/IOFLAG")
    c(fld("Ipri", 1, 10, 3), fld("Igtyp", 21, 30, 0, until=140), fld("Ioutp", 31, 40, 0),
      fld("Outyy", 41, 50, 0, since=100), fld("Irootyy", 51, 60, 0, since=100), fld("Irot", 61, 70, 0, since=100))
    kw("/SPMD")
    c(fld("Domdec", 1, 10, 0), fld("Nspmd", 11, 20, 0), fld("Dkword", 31, 40, 0), fld("Nthread", 51, 60, 0, 110))
    kw("/DEF_SHELL")
    c(fld("Ishell", 1, 10, 0), fld("Ismstr", 11, 20, 0), fld("Ithick", 21, 30, 0), fld("Iplas", 31, 40, 0),
      fld("Istrain", 41, 50, 0), fld("Ioffset", 51, 60, 0, since=2024), fld("Ish3n", 71, 80, 0),
      fld("Idrill", 81, 90, 0, since=110), fld("Ithin_dr", 91, 100, 0, since=2026))
    kw("/DEF_SOLID")
    c(fld("Isolid", 1, 10, 0), fld("Ismstr", 11, 20, 0), fld("Icpre", 21, 30, 0, since=2021),
      fld("Istrain", 31, 40, 0, 100, 2020), fld("Itetra4", 41, 50, 0, since=2019), fld("Itetra10", 51, 60, 0, 2019),
      fld("Imas", 61, 70, 0, since=120), fld("Iframe", 71, 80, 0), fld("Icontrol", 81, 90, 0, since=2025))
    kw("/NODE")
    c(fld("node_ID", 1, 10, None), fld("X", 11, 30, None), fld("Y", 31, 50, None), fld("Z", 51, 70, None))
    L.pop()  # the name line only
    for n in nodes():
        L.extend(card_lines(v, [fld("id", 1, 10, n[0]), fld("X", 11, 30, float(n[1])), fld("Y", 31, 50, float(n[2])),
                                fld("Z", 51, 70, float(n[3]))], names=False))
    kw("/SHELL/1")
    for e in shells():
        L.extend(card_lines(v, [fld("id", 1, 10, e[0])] + [fld("n", 11 + 10 * k, 20 + 10 * k, e[1 + k])
                                                          for k in range(4)], names=False))
    kw("/BRICK/2")
    for e in bricks():
        L.extend(card_lines(v, [fld("id", 1, 10, e[0])] + [fld("n", 11 + 10 * k, 20 + 10 * k, e[1 + k])
                                                          for k in range(8)], names=False))
    for pid, title in ((1, "Plate"), (2, "Block")):
        kw("/PART/%d" % pid, title)
        c(fld("prop_ID", 1, 10, pid), fld("mat_ID", 11, 20, pid), fld("subset_ID", 21, 30, 0), fld("Thick", 31, 50, 0.0))
    kw("/PROP/SHELL/1", "Plate shell")
    c(fld("Ishell", 1, 10, 0), fld("Ismstr", 11, 20, 0), fld("Ish3n", 21, 30, 0), fld("Idrill", 31, 40, 0, since=110),
      fld("Ipinch", 41, 50, 0, since=2020), fld("P_Thick_Fail", 61, 80, 0.0, since=2018))
    c(fld("Hm", 1, 20, 0.02), fld("Hf", 21, 40, 0.03), fld("Hr", 41, 60, 0.04), fld("Dm", 61, 80, 0.0),
      fld("Dn", 81, 100, 0.0))
    c(fld("N", 1, 10, 5), fld("Istrain", 11, 20, 0, until=2023), fld("Thick", 21, 40, 1.2), fld("Ashear", 41, 60, 0.0),
      fld("Ithick", 71, 80, 1), fld("Iplas", 81, 90, 1), fld("Ipos", 91, 100, 0, since=2024))
    kw("/PROP/SOLID/2", "Block solid")
    c(fld("Isolid", 1, 10, 0), fld("Ismstr", 11, 20, 0), fld("Iale", 21, 30, 0, since=2022), fld("Icpre", 31, 40, 0),
      fld("Itetra10", 41, 50, 0, since=2019), fld("Inpts", 51, 60, 0), fld("Itetra4", 61, 70, 0, since=100),
      fld("Iframe", 71, 80, 0), fld("dn", 81, 100, 0.0))
    c(fld("qa", 1, 20, 1.2), fld("qb", 21, 40, 0.06), fld("h", 41, 60, 0.12), fld("Lambda", 61, 80, 0.0, since=120),
      fld("Mu", 81, 100, 0.0, since=120))
    c(fld("dtmin", 1, 20, 0.0), fld("Istrain", 21, 30, 0, 100, 2022), fld("Ihkt", 31, 40, 0, 120, 2022),
      fld("vdef_min", 21, 40, 0.0, since=2023), fld("vdef_max", 41, 60, 0.0, since=2023),
      fld("ASP_max", 61, 80, 0.0, since=2023), fld("COL_min", 81, 100, 0.0, since=2023))
    kw("/MAT/PLAS_JOHNS/1", "Steel (Johnson-Cook)")
    # RHO_I right-justified: columns 11-20 hold text, so the 90-130 layouts read RHO_ref as well.
    c(fld("RHO_I", 1, 20, 7.85e-9), fld("RHO_ref", 21, 40, 7.8e-9))
    c(fld("E", 1, 20, 210000.0), fld("nu", 21, 40, 0.3), fld("Iflag", 41, 50, 0, since=140),
      fld("flagVP", 51, 60, 0, since=2023), fld("Pmin", 61, 80, 0.0, since=2025))
    c(fld("a", 1, 20, 250.0), fld("b", 21, 40, 450.0), fld("n", 41, 60, 0.3), fld("EPS_p_max", 61, 80, 0.0),
      fld("SIG_max0", 81, 100, 0.0))
    c(fld("c", 1, 20, 0.014), fld("EPS_DOT_0", 21, 40, 1.0), fld("ICC", 41, 50, 0), fld("Fsmooth", 51, 60, 0),
      fld("F_cut", 61, 80, 0.0), fld("Chard", 81, 100, 0.0, since=100))
    c(fld("m", 1, 20, 0.0), fld("T_melt", 21, 40, 0.0), fld("rhoC_p", 41, 60, 0.0), fld("T_r", 61, 80, 0.0),
      fld("T_max", 81, 100, 0.0, since=2025))
    kw("/MAT/LAW1/2", "Aluminium (elastic)")
    c(fld("RHO_I", 1, 20, 2.7e-9))
    c(fld("E", 1, 20, 70000.0), fld("nu", 21, 40, 0.33))
    for gid, path, title, ids in ((1, "NODE", "Plate edges", edge_nodes()), (2, "PART", "Block nodes", [2]),
                                  (3, "PART", "Plate nodes", [1]), (4, "NODE", "Block top face", top_nodes()),
                                  (5, "NODE", "Rigid body main node", [MAIN_NODE])):
        kw("/GRNOD/%s/%d" % (path, gid), title)
        L.extend(id_lines(ids))
    kw("/SURF/PART/1", "Plate surface")
    L.extend(id_lines([1]))
    kw("/SURF/PART/EXT/2", "Block outer faces")
    L.extend(id_lines([2]))
    kw("/BCS/1", "Clamped plate edges")
    L.append("   111 111" + "0".rjust(10) + "1".rjust(10))
    kw("/INIVEL/TRA/1", "Block moving down at 5 m/s")
    c(fld("Vx", 1, 20, 0.0), fld("Vy", 21, 40, 0.0), fld("Vz", 41, 60, -5000.0), fld("grnod_ID", 61, 70, 2),
      fld("skew_ID", 71, 80, 0))
    if v >= 2025:
        c(fld("Tstart", 1, 20, 0.0), fld("sensor_ID", 21, 30, 0))
    kw("/GRAV/1", "Gravity")
    c(fld("funct_IDT", 1, 10, 0), fld("DIR", 11, 20, "Z"), fld("skew_ID", 21, 30, 0), fld("sensor_ID", 31, 40, 0),
      fld("grnod_ID", 41, 50, 0), fld("Ascale_x", 61, 80, 0.0), fld("Fscale_y", 81, 100, -9810.0))
    kw("/FUNCT/1", "Velocity ramp")
    for x, y in ((0.0, 1.0), (0.001, 0.5), (1.0, 0.5)):
        L.extend(card_lines(v, [fld("X", 1, 20, x), fld("Y", 21, 40, y)], names=False))
    kw("/IMPVEL/1", "Rigid body pushed down")
    c(fld("funct_IDT", 1, 10, 1), fld("Dir", 11, 20, "Z"), fld("skew_ID", 21, 30, 0), fld("sensor_ID", 31, 40, 0),
      fld("grnod_ID", 41, 50, 5), fld("frame_ID", 51, 60, 0), fld("Icoor", 61, 70, 0, since=120))
    c(fld("Ascale_x", 1, 20, 0.0), fld("Fscale_y", 21, 40, -5000.0), fld("Tstart", 41, 60, 0.0),
      fld("Tstop", 61, 80, 0.0))
    kw("/RBODY/1", "Block top face")
    c(fld("node_ID", 1, 10, MAIN_NODE), fld("sens_ID", 11, 20, 0), fld("skew_ID", 21, 30, 0), fld("Ispher", 31, 40, 0),
      fld("Mass", 41, 60, 0.0), fld("grnd_ID", 61, 70, 4), fld("Ikrem", 71, 80, 0), fld("ICoG", 81, 90, 3),
      fld("surf_ID", 91, 100, 0))
    c(fld("Jxx", 1, 20, 0.0), fld("Jyy", 21, 40, 0.0), fld("Jzz", 41, 60, 0.0))
    c(fld("Jxy", 1, 20, 0.0), fld("Jyz", 21, 40, 0.0), fld("Jxz", 41, 60, 0.0))
    if v >= 110:
        c(fld("Ioptoff", 1, 10, 0), fld("Iexpams", 11, 20, 0, since=2017), fld("Ifail", 21, 30, 0, since=2021))
    kw("/RWALL/PLANE/1", "Floor under the plate")
    c(fld("node_ID", 1, 10, 0), fld("Slide", 11, 20, 0), fld("grnd_ID1", 21, 30, 3), fld("grnd_ID2", 31, 40, 1),
      fld("Iform", 41, 50, 0, since=2026))
    c(fld("d", 1, 20, 100.0))
    c(fld("XM", 1, 20, 0.0), fld("YM", 21, 40, 0.0), fld("ZM", 41, 60, -5.0))
    c(fld("XM1", 1, 20, 0.0), fld("YM1", 21, 40, 0.0), fld("ZM1", 41, 60, 1.0))
    type7(v, c, kw)
    lagdt(v, c, kw)
    kw("/TH/NODE/1", "Plate centre and main node")
    L.append("DEF")
    for nid, name in ((plate_node(PN // 2, PN // 2), "plate centre"), (MAIN_NODE, "main node")):
        L.extend(card_lines(v, [fld("id", 1, 10, nid), fld("skew", 11, 20, 0)], names=False))
        L[-1] = L[-1].ljust(21) + name  # a blank after the 20 columns keeps the name apart
    kw("/TH/PART/2", "Both parts")
    L.append("DEF")
    L.extend(id_lines([1, 2]))
    kw("/TH/INTER/3", "Both interfaces")
    L.append("DEF")
    L.extend(id_lines([1, 2]))
    kw("/TH/SHEL/4", "Two shells")
    L.append("F1        F2        M12")
    for eid, name in ((1, "corner shell"), (6, "inner shell")):
        # no skew_ID (columns 11-20 blank) before the 140 layout
        L.extend(card_lines(v, [fld("id", 1, 10, eid), fld("skew", 11, 20, 0, since=140)], names=False))
        L[-1] = L[-1].ljust(21) + name  # a blank after the 20 columns keeps the name apart
    L.append(RULER)
    L.append("/END")
    return L


def type7(v, c, kw):
    kw("/INTER/TYPE7/1", "Block nodes on the plate")
    c(fld("grnd_IDs", 1, 10, 2), fld("surf_IDm", 11, 20, 1), fld("Istf", 21, 30, 4), fld("Ithe", 31, 40, 0),
      fld("Igap", 41, 50, 0), fld("Multimp", 51, 60, 0, until=110), fld("Ibag", 61, 70, 0), fld("Idel", 71, 80, 0),
      fld("Icurv", 81, 90, 0), fld("Iadm", 91, 100, 0))
    c(fld("Fscalegap", 1, 20, 0.0), fld("Gap_max", 21, 40, 0.0), fld("Fpenmax", 41, 60, 0.0, since=120),
      fld("Itied", 81, 90, 0, since=2020), fld("Ists", 91, 100, 0, since=2026))
    c(fld("Stmin", 1, 20, 0.0), fld("Stmax", 21, 40, "1E30"), fld("%mesh_size", 41, 60, 0.0, since=110),
      fld("dtmin", 61, 80, 0.0, since=120), fld("Irem_gap", 81, 90, 0, since=120),
      fld("Irem_i2", 91, 100, 0, since=130))
    c(fld("Stfac", 1, 20, 1.0), fld("Fric", 21, 40, 0.1), fld("Gapmin", 41, 60, 0.5), fld("Tstart", 61, 80, 0.0),
      fld("Tstop", 81, 100, 0.0))
    c(fld("IBCX", 8, 8, 0), fld("IBCY", 9, 9, 0), fld("IBCZ", 10, 10, 0), fld("Inacti", 31, 40, 6),
      fld("VISs", 41, 60, 0.05), fld("VISf", 61, 80, 1.0), fld("Bumult", 81, 100, 0.0))
    c(fld("Ifric", 1, 10, 0), fld("Ifiltr", 11, 20, 0), fld("Xfreq", 21, 40, 0.0), fld("Iform", 41, 50, 1),
      fld("sens_ID", 51, 60, 0, since=120), fld("fct_IDF", 61, 70, 0, since=140),
      fld("AscaleF", 71, 90, 0.0, since=140), fld("fric_ID", 91, 100, 0, since=2018))


def lagdt(v, c, kw):
    kw("/INTER/LAGDT/TYPE7/2", "Plate nodes on the block's outer faces")
    c(fld("grnd_IDs", 1, 10, 3), fld("surf_IDm", 11, 20, 2), fld("Istf", 21, 30, 0), fld("Igap", 41, 50, 0),
      fld("Multimp", 51, 60, 0, until=130), fld("Ibag", 61, 70, 0), fld("Idel", 71, 80, 0))
    c(fld("Fscalegap", 1, 20, 0.0), fld("Gapmax", 21, 40, 0.0))
    c(fld("Stmin", 1, 20, 0.0), fld("Stmax", 21, 40, 0.0))
    c(fld("Stfac", 1, 20, 1.0), fld("Fric", 21, 40, 0.2), fld("Gapmin", 41, 60, 0.0), fld("Tstart", 61, 80, 0.0),
      fld("Tstop", 81, 100, 0.0))
    c(fld("IBCX", 8, 8, 0), fld("IBCY", 9, 9, 0), fld("IBCZ", 10, 10, 0), fld("Inacti", 31, 40, 0),
      fld("VISs", 41, 60, 0.0), fld("VISf", 61, 80, 1.0), fld("Bumult", 81, 100, 0.0))
    c(fld("Ifric", 1, 10, 0), fld("Ifiltr", 11, 20, 0), fld("Xfreq", 21, 40, 0.0), fld("Iform", 41, 50, 2))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--out", default=os.path.join(here, "..", "decks", "versions"))
    a = ap.parse_args(argv)
    for v in VERSIONS:
        write(os.path.join(a.out, "%s_%d_0000.rad" % (RUN, v)), deck(v), report=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
