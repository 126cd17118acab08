#!/usr/bin/env python3
"""Write the malformed starter decks of decks/invalid/ and their README table.

Every deck is the same tiny valid model (two shells, one brick, two parts, JC steel, elastic aluminium,
clamped plate nodes) with ONE fault put in (several_errors.rad has four). Lines of the base model carry tags;
a fault edits tagged lines, and the expected diagnostics name a tag, so the `# expect: RXnnn line N` headers
are computed, never counted by hand.

    python3 scripts/make_invalid_decks.py            # writes decks/invalid/*.rad, inc/*.rad, README.md
    python3 scripts/make_invalid_decks.py --out DIR  # elsewhere
    python3 scripts/make_invalid_decks.py --base F   # also write the fault-free base deck to F

Check the result with scripts/check_decks.py (an independent reader that re-derives the diagnostics).
Plain python3, standard library only.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from radx_deck_format import I, R, S, RULER, bcs_code, blank, ibc_code, line, names, write  # noqa: E402


class Deck:
    """Lines with optional tags. Tags are unique; edits address lines by tag."""

    def __init__(self):
        self.rows = []  # [text, tag]

    def add(self, text, tag=None):
        if tag is not None and any(r[1] == tag for r in self.rows):
            raise KeyError("duplicate tag %s" % tag)
        self.rows.append([text, tag])

    def extend(self, rows):
        for r in rows:
            self.add(*r) if isinstance(r, tuple) else self.add(r)

    def index(self, tag):
        for k, r in enumerate(self.rows):
            if r[1] == tag:
                return k
        raise KeyError(tag)

    def has(self, tag):
        return any(r[1] == tag for r in self.rows)

    def set(self, tag, text):
        self.rows[self.index(tag)][0] = text

    def insert_before(self, tag, rows):
        k = self.index(tag)
        new = Deck()
        new.extend(rows)
        self.rows[k:k] = new.rows

    def insert_after(self, tag, rows):
        k = self.index(tag) + 1
        new = Deck()
        new.extend(rows)
        self.rows[k:k] = new.rows

    def delete(self, first_tag, last_tag=None, keep_first=False):
        a = self.index(first_tag) + (1 if keep_first else 0)
        b = self.index(last_tag or first_tag)
        del self.rows[a:b + 1]

    def lineno(self, tag, offset):
        return offset + self.index(tag) + 1

    def texts(self):
        return [r[0] for r in self.rows]


# ---------------------------------------------------------------------------------------------------
# Line makers for the base model

NODES = [
    (1, 0.0, 0.0, 0.0), (2, 10.0, 0.0, 0.0), (3, 20.0, 0.0, 0.0),
    (4, 0.0, 10.0, 0.0), (5, 10.0, 10.0, 0.0), (6, 20.0, 10.0, 0.0),
    (11, 5.0, 1.0, 1.5), (12, 15.0, 1.0, 1.5), (13, 15.0, 9.0, 1.5), (14, 5.0, 9.0, 1.5),
    (15, 5.0, 1.0, 11.5), (16, 15.0, 1.0, 11.5), (17, 15.0, 9.0, 11.5), (18, 5.0, 9.0, 11.5),
]
SHELLS = [(1, 1, 2, 5, 4), (2, 2, 3, 6, 5)]
BRICK = (11, 11, 12, 13, 14, 15, 16, 17, 18)


def node_line(nid, x, y, z):
    return line(I(nid), R(x), R(y), R(z))


def shell_line(eid, n1, n2, n3, n4, phi=None, thick=None):
    return line(I(eid), I(n1), I(n2), I(n3), I(n4), blank(10), R(phi), R(thick))


def brick_line(*v):
    return line(*[I(x) for x in v])


def part_line(prop, mat):
    return line(I(prop), I(mat), I(0), R(0.0))


def psh_c1(ishell=1, ismstr=2, ish3n=2, idrill=0):
    return line(I(ishell), I(ismstr), I(ish3n), I(idrill), I(0), blank(10), R(0.0))


def psh_c2(hm=0.0):
    return line(R(hm), R(0.0), R(0.0), R(0.0), R(0.0))


def psh_c3(n=5, thick=1.0):
    return line(I(n), blank(10), R(thick), R(0.0), blank(10), I(1), I(1), I(0))


def pso_c1(isolid=1):
    return line(I(isolid), I(4), I(0), I(0), I(0), I(0), I(0), I(1), R(0.0))


def jc_c2(nu=0.3):
    return line(R(210000.0), R(nu), I(0), I(0), R(0.0))


def jc_c3(a=250.0, b=450.0, n=0.3, sigmax=0.0):
    return line(R(a), R(b), R(n), R(0.0), R(sigmax))


def jc_c4(c=0.0, eps0=0.0):
    return line(R(c), R(eps0), I(0), I(0), R(0.0), R(0.0))


def el_c2(e=70000.0, nu=0.33):
    return line(R(e), R(nu))


def units_line(m="Mg", length="mm", t="s"):
    return line(S(m, 20), S(length, 20), S(t, 20))


def law1_block(mid, tag_prefix, nu=0.33):
    return [("/MAT/LAW1/%d" % mid, tag_prefix + "_KW"), "Aluminium (elastic)",
            names(("RHO_I", 20), ("RHO_ref", 20)), (line(R(2.7e-9)), tag_prefix + "_C1"),
            names(("E", 20), ("nu", 20)), (el_c2(nu=nu), tag_prefix + "_C2")]


def base():
    d = Deck()
    d.add(RULER)
    d.add("/BEGIN", "BEGIN")
    d.add("TINY")
    d.add(names(("INVERS", 10)))
    d.add(line(I(2026)), "VERSION")
    d.add(names(("Input_mass", 20), ("Input_length", 20), ("Input_time", 20)))
    d.add(units_line(), "UNITS_IN")
    d.add(names(("Work_mass", 20), ("Work_length", 20), ("Work_time", 20)))
    d.add(units_line(), "UNITS_WORK")
    d.add(RULER, "AFTER_BEGIN")
    d.add("/TITLE", "TITLE_KW")
    d.add("Tiny model for the invalid-deck tests: two shells and one brick")
    d.add(RULER)
    d.add("/NODE", "NODE_KW")
    d.add(names(("node_ID", 10), ("Xc", 20), ("Yc", 20), ("Zc", 20)))
    for n in NODES:
        d.add(node_line(*n), "NODE_%d" % n[0])
    d.add(RULER)
    d.add("/SHELL/1", "SHELL_KW")
    d.add(names(("shell_ID", 10), ("node_ID1", 10), ("node_ID2", 10), ("node_ID3", 10), ("node_ID4", 10),
                ("", 10), ("PHI", 20), ("Thick", 20)))
    for e in SHELLS:
        d.add(shell_line(*e), "SHELL_%d" % e[0])
    d.add("/BRICK/2", "BRICK_KW")
    d.add(names(("brick_ID", 10), ("node_ID1", 10), ("node_ID2", 10), ("node_ID3", 10), ("node_ID4", 10),
                ("node_ID5", 10), ("node_ID6", 10), ("node_ID7", 10), ("node_ID8", 10)))
    d.add(brick_line(*BRICK), "BRICK_11")
    d.add(RULER)
    for pid, title in ((1, "Plate"), (2, "Block")):
        d.add("/PART/%d" % pid, "PART%d_KW" % pid)
        d.add(title)
        d.add(names(("prop_ID", 10), ("mat_ID", 10), ("subset_ID", 10), ("Thick", 20)))
        d.add(part_line(pid, pid), "PART%d" % pid)
    d.add(RULER, "AFTER_PARTS")
    d.add("/PROP/SHELL/1", "PSH_KW")
    d.add("Plate shell 1 mm")
    d.add(names(("Ishell", 10), ("Ismstr", 10), ("Ish3n", 10), ("Idrill", 10), ("Ipinch", 10), ("", 10),
                ("P_Thick_Fail", 20)))
    d.add(psh_c1(), "PSH_C1")
    d.add(names(("Hm", 20), ("Hf", 20), ("Hr", 20), ("Dm", 20), ("Dn", 20)))
    d.add(psh_c2(), "PSH_C2")
    d.add(names(("N", 10), ("", 10), ("Thick", 20), ("Ashear", 20), ("", 10), ("Ithick", 10), ("Iplas", 10),
                ("Ipos", 10)))
    d.add(psh_c3(), "PSH_C3")
    d.add("/PROP/SOLID/2", "PSO_KW")
    d.add("Block solid")
    d.add(names(("Isolid", 10), ("Ismstr", 10), ("Iale", 10), ("Icpre", 10), ("Itetra10", 10), ("Inpts", 10),
                ("Itetra4", 10), ("Iframe", 10), ("dn", 20)))
    d.add(pso_c1(), "PSO_C1")
    d.add(names(("qa", 20), ("qb", 20), ("h", 20), ("LAMBDA_V", 20), ("MU_V", 20)))
    d.add(line(R(0.0), R(0.0), R(0.0), R(0.0), R(0.0)), "PSO_C2")
    d.add(names(("dtmin", 20), ("vdef_min", 20), ("vdef_max", 20), ("ASP_max", 20), ("COL_min", 20)))
    d.add(line(R(0.0), R(0.0), R(0.0), R(0.0), R(0.0)), "PSO_C3")
    d.add(RULER)
    d.add("/MAT/PLAS_JOHNS/1", "JC_KW")
    d.add("Steel (Johnson-Cook)")
    d.add(names(("RHO_I", 20), ("RHO_ref", 20)))
    d.add(line(R(7.85e-9)), "JC_C1")
    d.add(names(("E", 20), ("nu", 20), ("Iflag", 10), ("flagVP", 10), ("Pmin", 20)))
    d.add(jc_c2(), "JC_C2")
    d.add(names(("a", 20), ("b", 20), ("n", 20), ("EPS_p_max", 20), ("SIG_max0", 20)))
    d.add(jc_c3(), "JC_C3")
    d.add(names(("c", 20), ("EPS_DOT_0", 20), ("ICC", 10), ("Fsmooth", 10), ("F_cut", 20), ("Chard", 20)))
    d.add(jc_c4(), "JC_C4")
    d.add(names(("m", 20), ("T_melt", 20), ("rhoC_p", 20), ("T_r", 20), ("T_max", 20)))
    d.add(line(R(0.0), R(0.0), R(0.0), R(0.0), R(0.0)), "JC_C5")
    d.extend(law1_block(2, "EL"))
    d.add(RULER, "AFTER_MATS")
    d.add("/GRNOD/NODE/1", "GRN1_KW")
    d.add("Plate nodes (clamped)")
    d.add(names(("node_ID1", 10), ("node_ID2", 10), ("node_ID3", 10), ("node_ID4", 10), ("node_ID5", 10),
                ("node_ID6", 10)))
    d.add(line(*[I(x) for x in (1, 2, 3, 4, 5, 6)]), "GRN1_L1")
    d.add("/BCS/1", "BCS_KW")
    d.add("Clamped plate")
    d.add(names(("Tra rot", 10), ("skew_ID", 10), ("grnod_ID", 10)))
    d.add(line(bcs_code("111", "111"), I(0), I(1)), "BCS_C1")
    d.add(RULER, "BEFORE_END")
    d.add("/END", "END")
    return d


def block_group():
    return [("/GRNOD/PART/2", "GRP2_KW"), "Block nodes", names(("part_ID1", 10)), (line(I(2)), "GRP2_L1")]


def type7(istf=4, igap=0, grnod=2, surf=1, stfac=1.0, tstart=0.0, tstop=0.0, inacti=0, ifric=0, ccards=(),
          lagdt=False, iid=1):
    """A TYPE7 (2026 layout) or LAGDT/TYPE7 interface, with /GRNOD/PART/2 and /SURF/PART/1 in front."""
    rows = block_group()
    rows += [("/SURF/PART/1", "SURF1_KW"), "Plate surface", names(("part_ID1", 10)), (line(I(1)), "SURF1_L1")]
    if lagdt:
        rows += [("/INTER/LAGDT/TYPE7/%d" % iid, "INT_KW"), "Block nodes on plate (LAGDT)",
                 names(("grnd_IDs", 10), ("surf_IDm", 10), ("Istf", 10), ("", 10), ("Igap", 10), ("", 10),
                       ("Ibag", 10), ("Idel", 10)),
                 (line(I(grnod), I(surf), I(istf), blank(10), I(igap), blank(10), I(0), I(0)), "INT_C1"),
                 names(("Fscalegap", 20), ("Gapmax", 20)), (line(R(0.0), R(0.0)), "INT_C2"),
                 names(("Stmin", 20), ("Stmax", 20)), (line(R(0.0), R(0.0)), "INT_C3"),
                 names(("Stfac", 20), ("Fric", 20), ("Gapmin", 20), ("Tstart", 20), ("Tstop", 20)),
                 (line(R(stfac), R(0.1), R(0.0), R(tstart), R(tstop)), "INT_C5"),
                 names(("IBC", 10), ("", 20), ("Inacti", 10), ("VISs", 20), ("VISf", 20), ("Bumult", 20)),
                 (line(ibc_code(0, 0, 0), blank(20), I(inacti), R(0.0), R(0.0), R(0.0)), "INT_C6"),
                 names(("Ifric", 10), ("Ifiltr", 10), ("Xfreq", 20), ("Iform", 10)),
                 (line(I(ifric), I(0), R(0.0), I(0)), "INT_C7")]
    else:
        rows += [("/INTER/TYPE7/%d" % iid, "INT_KW"), "Block nodes on plate",
                 names(("grnd_IDs", 10), ("surf_IDm", 10), ("Istf", 10), ("Ithe", 10), ("Igap", 10), ("", 10),
                       ("Ibag", 10), ("Idel", 10), ("Icurv", 10), ("Iadm", 10)),
                 (line(I(grnod), I(surf), I(istf), I(0), I(igap), blank(10), I(0), I(0), I(0), I(0)), "INT_C1"),
                 names(("Fscalegap", 20), ("Gap_max", 20), ("Fpenmax", 20), ("", 20), ("Itied", 10),
                       ("Ists", 10)),
                 (line(R(0.0), R(0.0), R(0.0), blank(20), I(0), I(0)), "INT_C2"),
                 names(("Stmin", 20), ("Stmax", 20), ("%mesh_size", 20), ("dtmin", 20), ("Irem_gap", 10),
                       ("Irem_i2", 10)),
                 (line(R(0.0), R(0.0), R(0.0), R(0.0), I(0), I(0)), "INT_C3"),
                 names(("Stfac", 20), ("Fric", 20), ("Gapmin", 20), ("Tstart", 20), ("Tstop", 20)),
                 (line(R(stfac), R(0.1), R(0.0), R(tstart), R(tstop)), "INT_C5"),
                 names(("IBC", 10), ("", 20), ("Inacti", 10), ("VISs", 20), ("VISf", 20), ("Bumult", 20)),
                 (line(ibc_code(0, 0, 0), blank(20), I(inacti), R(0.0), R(0.0), R(0.0)), "INT_C6"),
                 names(("Ifric", 10), ("Ifiltr", 10), ("Xfreq", 20), ("Iform", 10), ("sens_ID", 10),
                       ("fct_IDF", 10), ("AscaleF", 20), ("fric_ID", 10)),
                 (line(I(ifric), I(0), R(0.0), I(0), I(0), I(0), R(0.0), I(0)), "INT_C7")]
    if ccards:
        rows += [names(("C1", 20), ("C2", 20), ("C3", 20), ("C4", 20), ("C5", 20)),
                 (line(*[R(c) for c in ccards[:5]]), "INT_C8")]
        if len(ccards) > 5:
            rows += [names(("C6", 20)), (line(R(ccards[5])), "INT_C9")]
    return rows


def with_inter(d, **kw):
    d.insert_before("BEFORE_END", type7(**kw))
    return d


def funct_rows(fid, points, title="Function", tag="F"):
    rows = [("/FUNCT/%d" % fid, tag + "_KW"), title, names(("X", 20), ("Y", 20))]
    for k, (x, y) in enumerate(points, 1):
        rows.append((line(R(x), R(y)), "%s_P%d" % (tag, k)))
    return rows


# ---------------------------------------------------------------------------------------------------
# The faults. Each returns (deck, fault text, [(code, tag)], extra files {relpath: (Deck, [(code, tag)])}).

FAULTS = []


def fault(name):
    def reg(fn):
        FAULTS.append((name, fn))
        return fn
    return reg


@fault("truncated_card")
def _():
    d = base()
    d.delete("EL_C1", "EL_C2", keep_first=True)
    return d, "/MAT/LAW1/2 ends after its density card: the E, nu card is missing", [("RX502", "EL_KW")]


@fault("letters_in_number")
def _():
    d = base()
    d.set("PSH_C2", psh_c2(hm="0.O1"))
    return d, "/PROP/SHELL/1 Hm written 0.O1 (letter O for a zero) in a real field", [("RX202", "PSH_C2")]


@fault("letters_in_integer")
def _():
    d = base()
    d.set("PSO_C1", pso_c1(isolid="1x"))
    return d, "/PROP/SOLID/2 Isolid written 1x in an integer field", [("RX201", "PSO_C1")]


@fault("real_overflow")
def _():
    d = base()
    d.set("JC_C3", jc_c3(sigmax="1e400"))
    return d, "/MAT/PLAS_JOHNS/1 SIG_max0 = 1e400 overflows a double", [("RX203", "JC_C3")]


@fault("tab_in_fixed_field")
def _():
    d = base()
    text = node_line(2, 10.0, 0.0, 0.0)
    assert text[10] == " "
    d.set("NODE_2", text[:10] + "\t" + text[11:])
    return d, "node 2: a tab character in column 11 (first column of X)", [("RX104", "NODE_2")]


@fault("unknown_keyword")
def _():
    d = base()
    d.insert_after("AFTER_PARTS", [("/FOOBAR/1", "BAD_KW"), "Not a Radioss keyword", line(I(1), I(2))])
    return d, "/FOOBAR/1 is not a keyword (its block is skipped)", [("RX301", "BAD_KW")]


@fault("unsupported_keyword_law36")
def _():
    d = base()
    rows = [("/MAT/LAW36/3", "L36_KW"), "Tabulated steel (not supported by radx)",
            names(("RHO_I", 20), ("RHO_ref", 20)), line(R(7.85e-9)),
            names(("E", 20), ("nu", 20), ("Eps_p_max", 20), ("Eps_t", 20), ("Eps_m", 20)),
            line(R(210000.0), R(0.3), R(0.0), R(0.0), R(0.0)),
            names(("N_funct", 10), ("F_smooth", 10), ("C_hard", 20), ("F_cut", 20), ("Eps_f", 20), ("", 10),
                  ("VP", 10)),
            line(I(1), I(0), R(0.0), R(0.0), R(0.0), blank(10), I(0)),
            names(("fct_IDp", 10), ("Fscale", 20), ("Fct_IDE", 10), ("EInf", 20), ("CE", 20)),
            line(I(0), R(0.0), I(0), R(0.0), R(0.0)),
            names(("fct_ID1", 10)), line(I(1)),
            names(("Fscale1", 20)), line(R(1.0)),
            names(("Eps_dot1", 20)), line(R(0.0))]
    rows += funct_rows(1, [(0.0, 250.0), (0.1, 350.0), (1.0, 600.0)], "Yield stress vs plastic strain")
    d.insert_before("AFTER_MATS", rows)
    return d, "/MAT/LAW36/3 (with the /FUNCT/1 it names) is a real Radioss keyword radx does not read", \
        [("RX302", "L36_KW")]


@fault("include_loop_a")
def _():
    d = base()
    k0 = d.index("EL_KW")
    k1 = d.index("EL_C2")
    del d.rows[k0:k1 + 1]
    d.insert_before("AFTER_MATS", [("#include inc/include_loop_b.rad", "INC")])
    b = Deck()
    b.add("# Included by include_loop_a.rad. Holds /MAT/LAW1/2, then includes include_loop_a.rad again:")
    b.add("# the include loop closes here. Paths are relative to the file holding the #include.")
    b.extend(law1_block(2, "EL"))
    b.add("#include ../include_loop_a.rad", "LOOP")
    return d, "include_loop_a.rad includes inc/include_loop_b.rad, which includes include_loop_a.rad", \
        [("RX102", "LOOP", "inc/include_loop_b.rad")], {"inc/include_loop_b.rad": b}


@fault("missing_include")
def _():
    d = base()
    d.insert_before("BEFORE_END", [("#include inc/no_such_file.rad", "INC")])
    return d, "#include of a file that does not exist", [("RX103", "INC")]


@fault("no_end_truncated")
def _():
    d = base()
    d.delete("BEFORE_END", "END")
    return d, "the file stops after /BCS/1: no /END (error at the last line of the file)", [("RX106", "BCS_C1")]


@fault("missing_begin")
def _():
    d = base()
    d.delete("BEGIN", "AFTER_BEGIN")
    return d, "no /BEGIN (version and units missing); pointed at the first keyword line", \
        [("RX105", "TITLE_KW")]


@fault("unknown_unit")
def _():
    d = base()
    d.set("UNITS_IN", units_line(length="furlong"))
    return d, "/BEGIN input length unit 'furlong' is not a known unit", [("RX506", "UNITS_IN")]


@fault("duplicate_node_id")
def _():
    d = base()
    d.insert_after("NODE_18", [(node_line(3, 20.0, 0.0, 0.0), "DUP")])
    return d, "node 3 defined twice (same coordinates); the second line is the error", [("RX401", "DUP")]


@fault("duplicate_element_id")
def _():
    d = base()
    d.set("SHELL_2", shell_line(1, 2, 3, 6, 5))
    return d, "the second shell reuses element id 1", [("RX401", "SHELL_2")]


@fault("duplicate_mat_id")
def _():
    d = base()
    d.insert_before("AFTER_MATS", law1_block(2, "EL2"))
    return d, "/MAT/LAW1/2 defined twice; the second keyword line is the error", [("RX401", "EL2_KW")]


@fault("missing_reference_part_mat")
def _():
    d = base()
    d.set("PART2", part_line(2, 99))
    return d, "/PART/2 names material 99, which does not exist", [("RX402", "PART2")]


@fault("part_missing_property")
def _():
    d = base()
    d.set("PART2", part_line(99, 2))
    return d, "/PART/2 names property 99, which does not exist", [("RX402", "PART2")]


@fault("brick_missing_part")
def _():
    d = base()
    d.set("BRICK_KW", "/BRICK/7")
    return d, "/BRICK/7: the element block names part 7, which does not exist (id on the keyword line)", \
        [("RX402", "BRICK_KW")]


@fault("element_missing_node")
def _():
    d = base()
    d.insert_after("SHELL_2", [(shell_line(3, 3, 99, 6, 5), "SHELL_3")])
    return d, "shell 3 uses node 99, which does not exist", [("RX406", "SHELL_3")]


@fault("bcs_missing_group")
def _():
    d = base()
    d.set("BCS_C1", line(bcs_code("111", "111"), I(0), I(99)))
    return d, "/BCS/1 names node group 99, which does not exist", [("RX402", "BCS_C1")]


@fault("empty_group")
def _():
    d = base()
    d.delete("GRN1_L1")
    return d, "/GRNOD/NODE/1 (used by /BCS/1) lists no node", [("RX403", "GRN1_KW")]


@fault("surf_part_on_solid")
def _():
    d = base()
    d.insert_before("BEFORE_END", [("/SURF/PART/1", "SURF_KW"), "Block as a /SURF/PART (must be /SURF/PART/EXT)",
                                   names(("part_ID1", 10)), (line(I(2)), "SURF_L1")])
    return d, "/SURF/PART/1 lists part 2, a solid part (needs /SURF/PART/EXT)", [("RX407", "SURF_L1")]


@fault("degenerate_brick_zero_volume")
def _():
    d = base()
    for nid, x, y in ((15, 3.0, -1.0), (16, 17.0, -1.0), (17, 17.0, 11.0), (18, 3.0, 11.0)):
        d.set("NODE_%d" % nid, node_line(nid, x, y, 1.5))
    return d, "brick 11 is flat: its eight (distinct) nodes all lie in the plane z = 1.5", [("RX601", "BRICK_11")]


@fault("inverted_brick_negative_volume")
def _():
    d = base()
    d.set("BRICK_11", brick_line(11, 15, 16, 17, 18, 11, 12, 13, 14))
    return d, "brick 11 lists its top face first: negative volume", [("RX601", "BRICK_11")]


@fault("tangled_brick_positive_volume")
def _():
    d = base()
    # node 15 (n5) pushed through the bottom face n1-n4 (z = 1.5) to its middle, 2 mm below: the one-point
    # volume stays positive (about 0.45 of the box), but the corner at n5 is turned inside out
    d.set("NODE_15", node_line(15, 10.0, 5.0, -0.5))
    return d, "brick 11: node 15 (n5) pushed through the opposite face; positive volume, faces intersect " \
              "(a warning)", [("RX607", "BRICK_11")]


@fault("implausible_wave_speed")
def _():
    d = base()
    d.set("EL_C1", line(R(2700.0)))
    return d, "/MAT/LAW1/2 RHO_I = 2700 (kg/m3) in a Mg mm s deck: sqrt(E/RHO_I) = 0.005 m/s (a warning)", \
        [("RX512", "EL_C2")]


@fault("zero_area_shell")
def _():
    d = base()
    d.set("NODE_1", node_line(1, 10.0, -10.0, 0.0))
    d.set("NODE_4", node_line(4, 10.0, 20.0, 0.0))
    return d, "shell 1: nodes 1, 2, 5, 4 moved onto one line (x = 10): zero area", [("RX602", "SHELL_1")]


@fault("negative_thickness")
def _():
    d = base()
    d.set("PSH_C3", psh_c3(thick=-1.0))
    return d, "/PROP/SHELL/1 Thick = -1", [("RX504", "PSH_C3")]


@fault("zero_shell_thickness")
def _():
    d = base()
    d.set("PSH_C3", psh_c3(thick=0.0))
    d.set("SHELL_1", shell_line(1, 1, 2, 5, 4, thick=0.0))
    d.set("SHELL_2", shell_line(2, 2, 3, 6, 5, thick=1.0))
    return d, "shell 1 has Thick 0 on its element card and in /PROP/SHELL/1 (shell 2 gives 1.0 on its card)", \
        [("RX504", "SHELL_1")]


@fault("shell_n_over_10")
def _():
    d = base()
    d.set("PSH_C3", psh_c3(n=12))
    return d, "/PROP/SHELL/1 N = 12 integration points (0..10 allowed)", [("RX501", "PSH_C3")]


@fault("poisson_half")
def _():
    d = base()
    d.set("EL_C2", el_c2(nu=0.5))
    return d, "/MAT/LAW1/2 nu = 0.5 (Radioss silently uses 0.499)", [("RX503", "EL_C2")]


@fault("poisson_over_half")
def _():
    d = base()
    d.set("JC_C2", jc_c2(nu=0.6))
    return d, "/MAT/PLAS_JOHNS/1 nu = 0.6", [("RX503", "JC_C2")]


@fault("jc_c_without_epsdot0")
def _():
    d = base()
    d.set("JC_C4", jc_c4(c=0.014, eps0=0.0))
    return d, "/MAT/PLAS_JOHNS/1 c = 0.014 with EPS_DOT_0 = 0", [("RX502", "JC_C4")]


@fault("jc_n_over_one")
def _():
    d = base()
    d.set("JC_C3", jc_c3(n=1.5))
    return d, "/MAT/PLAS_JOHNS/1 hardening exponent n = 1.5 (must be <= 1)", [("RX501", "JC_C3")]


@fault("funct_not_increasing")
def _():
    d = base()
    rows = funct_rows(1, [(0.0, 0.0), (0.001, 1.0), (0.0005, 1.0), (0.01, 1.0)], "Gravity ramp")
    rows += [("/GRAV/1", "GRAV_KW"), "Gravity through /FUNCT/1",
             names(("funct_IDT", 10), ("DIR", 10), ("skew_ID", 10), ("sensor_ID", 10), ("grnod_ID", 10), ("", 10),
                   ("Ascale_x", 20), ("Fscale_y", 20)),
             line(I(1), S("Z", 10), I(0), I(0), I(0), blank(10), R(0.0), R(-9810.0))]
    d.insert_before("BEFORE_END", rows)
    return d, "/FUNCT/1: the third X (0.0005) is below the second (0.001)", [("RX505", "F_P3")]


def impvel_rows(funct, keyword="/IMPVEL", direction="Z", sensor=0):
    return block_group() + [
        ("%s/1" % keyword, "IMP_KW"), "Block pushed down",
        names(("funct_IDT", 10), ("Dir", 10), ("skew_ID", 10), ("sensor_ID", 10), ("grnod_ID", 10),
              ("frame_ID", 10), ("Icoor", 10)),
        (line(I(funct), S(direction, 10), I(0), I(sensor), I(2), I(0), I(0)), "IMP_C1"),
        names(("Ascale_x", 20), ("Fscale_y", 20), ("Tstart", 20), ("Tstop", 20)),
        (line(R(0.0), R(-1000.0), R(0.0), R(0.0)), "IMP_C2")]


@fault("impvel_no_function")
def _():
    d = base()
    d.insert_before("BEFORE_END", impvel_rows(0))
    return d, "/IMPVEL/1 with funct_IDT = 0 (a function is required)", [("RX502", "IMP_C1")]


@fault("impvel_missing_function")
def _():
    d = base()
    d.insert_before("BEFORE_END", impvel_rows(99))
    return d, "/IMPVEL/1 names function 99, which does not exist", [("RX402", "IMP_C1")]


@fault("impdisp_missing_function")
def _():
    d = base()
    d.insert_before("BEFORE_END", impvel_rows(99, "/IMPDISP"))
    return d, "/IMPDISP/1 names function 99, which does not exist", [("RX402", "IMP_C1")]


@fault("impdisp_rotation")
def _():
    d = base()
    d.insert_before("BEFORE_END", impvel_rows(7, "/IMPDISP", "ZZ")
                    + funct_rows(7, [(0.0, 0.0), (0.002, 0.1)], "Rotation angle"))
    return d, "/IMPDISP/1 Dir = ZZ: an imposed rotation angle (radx imposes translations only)", \
        [("RX510", "IMP_C1")]


def sensor_rows(sid, t_delay, t_stop=None, tag="SENS"):
    """/SENSOR/TIME/sid; card 1 carries TAG_C1, the Tstop card (when given) TAG_C2."""
    rows = [("/SENSOR/TIME/%d" % sid, tag + "_KW"), "Timer", names(("Tdelay", 20)), (line(R(t_delay)), tag + "_C1")]
    if t_stop is not None:
        rows += [names(("Tstop", 20)), (line(R(t_stop)), tag + "_C2")]
    return rows


@fault("sensor_missing")
def _():
    d = with_rows(impvel_rows(7, sensor=9), funct_rows(7, [(0.0, 0.0), (0.002, 1.0)], "Speed"))
    return d, "/IMPVEL/1 is started by sensor 9; the deck has no /SENSOR/9", [("RX402", "IMP_C1")]


@fault("sensor_unsupported_type")
def _():
    rows = [("/SENSOR/DIST/5", "SD_KW"), "Distance sensor", names(("Tdelay", 20)), line(R(0.0)),
            names(("node_ID1", 10), ("node_ID2", 10), ("Dmin", 20), ("Dmax", 20)), line(I(1), I(2), R(0.0), R(5.0))]
    return with_rows(rows), "/SENSOR/DIST/5: of the sensors radx reads /SENSOR/TIME only", [("RX302", "SD_KW")]


@fault("sensor_tstop_before_tdelay")
def _():
    d = with_rows(sensor_rows(3, 0.002, 0.001))
    return d, "/SENSOR/TIME/3 switches off (Tstop 0.001) before it switches on (Tdelay 0.002)", \
        [("RX507", "SENS_C2")]


@fault("rbody_sensor_tstop")
def _():
    rows = sensor_rows(4, 0.001, 0.002) + block_group() + [
        "/NODE", names(("node_ID", 10), ("Xc", 20), ("Yc", 20), ("Zc", 20)), node_line(99, 5.0, 5.0, 10.0),
        ("/RBODY/1", "RB_KW"), "Block released by sensor 4",
        names(("node_ID", 10), ("sens_ID", 10), ("skew_ID", 10), ("Ispher", 10), ("Mass", 20), ("grnd_ID", 10),
              ("Ikrem", 10), ("ICoG", 10), ("surf_ID", 10)),
        (line(I(99), I(4), I(0), I(0), R(0.0), I(2), I(0), I(0), I(0)), "RB_C1"),
        names(("Jxx", 20), ("Jyy", 20), ("Jzz", 20)), line(R(0.0), R(0.0), R(0.0)),
        names(("Jxy", 20), ("Jyz", 20), ("Jxz", 20)), line(R(0.0), R(0.0), R(0.0)),
        names(("Ioptoff", 10), ("Iexpams", 10), ("Ifail", 10)), line(I(0), I(0), I(0))]
    return with_rows(rows), \
        "/RBODY/1 is released by /SENSOR/TIME/4, which switches off again (Tstop): radx does not form the body again", \
        [("RX510", "RB_C1")]


@fault("inter_missing_surface")
def _():
    return with_inter(base(), surf=99), "/INTER/TYPE7/1 names surface 99, which does not exist", \
        [("RX402", "INT_C1")]


@fault("inter_missing_group")
def _():
    return with_inter(base(), grnod=99), "/INTER/TYPE7/1 names node group 99, which does not exist", \
        [("RX402", "INT_C1")]


@fault("istf_7")
def _():
    return with_inter(base(), istf=7), "/INTER/TYPE7/1 Istf = 7 (0..5 allowed)", [("RX501", "INT_C1")]


@fault("igap_3")
def _():
    return with_inter(base(), igap=3), "/INTER/TYPE7/1 Igap = 3 (0..2 allowed)", [("RX501", "INT_C1")]


@fault("istf1_stfac_zero")
def _():
    return with_inter(base(), istf=1, stfac=0.0), \
        "/INTER/TYPE7/1 Istf = 1 (stiffness given in Stfac) with Stfac = 0", [("RX502", "INT_C5")]


@fault("inter_tstop_before_tstart")
def _():
    return with_inter(base(), tstart=0.001, tstop=0.0005), "/INTER/TYPE7/1 Tstart = 0.001, Tstop = 0.0005", \
        [("RX507", "INT_C5")]


@fault("inacti_4")
def _():
    return with_inter(base(), inacti=4), "/INTER/TYPE7/1 Inacti = 4 (0, 1, 2, 3, 5, 6 allowed)", \
        [("RX501", "INT_C6")]


@fault("lagdt_inacti_4")
def _():
    return with_inter(base(), inacti=4, lagdt=True), \
        "/INTER/LAGDT/TYPE7/1 Inacti = 4 (0, 1, 2, 3, 5, 6 allowed)", [("RX501", "INT_C6")]


@fault("ifric_4")
def _():
    return with_inter(base(), ifric=4), \
        "/INTER/TYPE7/1 Ifric = 4 (0..3 allowed); no C1..C6 cards follow", [("RX501", "INT_C7")]


@fault("ifric3_c5_zero")
def _():
    return with_inter(base(), ifric=3, ccards=(0.2, 0.15, 0.3, 0.1, 0.0, 2.0)), \
        "/INTER/TYPE7/1 Renard friction (Ifric 3) with C5 = V_cr1 = 0", [("RX703", "INT_C8")]


def ctclaw_rows(law_lines, lid=3, inter=1):
    """A /CTCLAW/lid on interface `inter`; its law-string lines carry the tags CTC_L1, CTC_L2, ..."""
    rows = [("/CTCLAW/%d" % lid, "CTC_KW"), "Contact law", names(("inter_ID", 10)), (line(I(inter)), "CTC_C1")]
    rows += [(t, "CTC_L%d" % k) for k, t in enumerate(law_lines, 1)]
    return rows


def with_law(law_lines, extra=()):
    d = with_inter(base())
    d.insert_before("BEFORE_END", ctclaw_rows(law_lines) + list(extra))
    return d


@fault("ctclaw_unknown_parameter")
def _():
    return with_law(["n1s13{Kc1e3,Mu0.1,", "CtLin1e3,Foo3}"]), \
        "/CTCLAW/3 on /INTER/TYPE7/1: unknown parameter Foo on the second line of the law string", \
        [("RX704", "CTC_L2")]


@fault("ctclaw_missing_parameter")
def _():
    return with_law(["n1s2{Kc1e3,Mu0.2}"]), \
        "/CTCLAW/3: friction law s2 (linear regularised Coulomb) without its slope CtLin", [("RX704", "CTC_L1")]


@fault("ctclaw_lambda_and_pe")
def _():
    return with_law(["n2{pz1e5,lambda2e3,pe1e6}"]), \
        "/CTCLAW/3: exponential law n2 with both lambda and pe (exclusive)", [("RX704", "CTC_L1")]


@fault("ctclaw_negative_value")
def _():
    return with_law(["n1s1{Kc1e3,Mu-0.2}"]), "/CTCLAW/3: friction coefficient Mu = -0.2", \
        [("RX704", "CTC_L1")]


@fault("ctclaw_kcmax_below_initial")
def _():
    return with_law(["n2{pz1e5,lambda2e3,KcMax1e6}"]), \
        "/CTCLAW/3: KcMax = 1e6 below the initial stiffness lambda pz = 2e8", [("RX704", "CTC_L1")]


@fault("ctclaw_unknown_law")
def _():
    return with_law(["n7s13{Kc1,Mu0.1,CtLin1}"]), "/CTCLAW/3: normal law n7 (n1..n4 exist)", \
        [("RX704", "CTC_L1")]


@fault("ctclaw_missing_curve")
def _():
    return with_law(["n3s1{CurveID12,Mu0.1}"], funct_rows(11, [(-0.1, 100.0), (0.0, 0.0)], "Gap to pressure")), \
        "/CTCLAW/3: tabulated law n3 names /FUNCT/12; only /FUNCT/11 exists", [("RX704", "CTC_L1")]


@fault("ishell_24_qeph")
def _():
    d = base()
    d.set("PSH_C1", psh_c1(ishell=24))
    return d, "/PROP/SHELL/1 Ishell = 24 (QEPH) on the plate's 4-node shells: radx implements Ishell 1 only " \
        "(--allow-substitutions would run Ishell 1 and list it)", [("RX510", "PSH_C1")]


@fault("isolid_14_from_def_solid")
def _():
    d = base()
    d.insert_before("PSO_KW", ["/DEF_SOLID", names(("Isolid", 10), ("Ismstr", 10), ("Icpre", 10)),
                               line(I(14), I(0), I(0))])
    d.set("PSO_C1", pso_c1(isolid=0))
    return d, "/PROP/SOLID/2 leaves Isolid 0 and /DEF_SOLID sets 14 (HA8): the block's brick would run a " \
        "formulation radx lacks", [("RX510", "PSO_C1")]


@fault("solid_numerical_viscosity")
def _():
    d = base()
    d.set("PSO_C2", line(R(0.0), R(0.0), R(0.0), R(0.01), R(0.0)))
    return d, "/PROP/SOLID/2 numerical viscosity Lambda = 0.01: read but not implemented, and it changes " \
        "the physics", [("RX510", "PSO_C2")]


@fault("bcs_missing_skew")
def _():
    d = base()
    d.set("BCS_C1", line(bcs_code("111", "111"), I(5), I(1)))
    return d, "/BCS/1 names skew 5, and the deck has no /SKEW/FIX/5", [("RX402", "BCS_C1")]


@fault("skew_parallel_axes")
def _():
    d = base()
    d.insert_before("BCS_KW", [("/SKEW/FIX/5", "SKW_KW"), "Degenerate frame",
                               names(("Ox", 20), ("Oy", 20), ("Oz", 20)), line(R(0.0), R(0.0), R(0.0)),
                               names(("X1", 20), ("Y1", 20), ("Z1", 20)), line(R(0.0), R(0.0), R(2.0)),
                               names(("X2", 20), ("Y2", 20), ("Z2", 20)), (line(R(0.0), R(0.0), R(1.0)), "SKW_C3")])
    d.set("BCS_C1", line(bcs_code("111", "111"), I(5), I(1)))
    return d, "/SKEW/FIX/5 with Y' = (0, 0, 2) parallel to Z' = (0, 0, 1): no frame", [("RX507", "SKW_C3")]


def skew_mov_rows(n1, n2, n3, direction="", sid=5, title="Frame on plate nodes"):
    """/SKEW/MOV/<sid> (2019 layout and newer: N1 N2 N3 Dir); the card line is tagged SKM_C1."""
    return [("/SKEW/MOV/%d" % sid, "SKM_KW"), title,
            names(("N1", 10), ("N2", 10), ("N3", 10), ("Dir", 10)),
            (line(I(n1), I(n2), I(n3), S(direction, 10)), "SKM_C1")]


def with_moving_skew(n1, n2, n3, direction=""):
    """The base model with /SKEW/MOV/5 before /BCS/1, which holds the plate in it."""
    d = base()
    d.insert_before("BCS_KW", skew_mov_rows(n1, n2, n3, direction))
    d.set("BCS_C1", line(bcs_code("111", "111"), I(5), I(1)))
    return d


@fault("skew_mov_missing_node")
def _():
    return with_moving_skew(1, 2, 99), "/SKEW/MOV/5 names N3 = 99, which does not exist", [("RX402", "SKM_C1")]


@fault("skew_mov_repeated_node")
def _():
    return with_moving_skew(1, 2, 1), "/SKEW/MOV/5 with N3 = N1 = 1: three distinct nodes are needed", \
        [("RX507", "SKM_C1")]


@fault("skew_mov_coincident_nodes")
def _():
    d = with_moving_skew(1, 19, 4)
    d.insert_after("NODE_18", [node_line(19, 0.0, 0.0, 0.0)])
    return d, "/SKEW/MOV/5: N2 = 19 sits on N1 = 1 at (0, 0, 0), so N1 -> N2 has no direction", \
        [("RX507", "SKM_C1")]


@fault("skew_mov_collinear_nodes")
def _():
    return with_moving_skew(1, 2, 3), "/SKEW/MOV/5 on nodes 1, 2, 3, which lie on the line y = 0: no plane", \
        [("RX507", "SKM_C1")]


@fault("skew_mov_bad_dir")
def _():
    return with_moving_skew(1, 2, 4, "W"), "/SKEW/MOV/5 Dir = W (X, Y or Z, blank = X)", [("RX501", "SKM_C1")]


@fault("skew_duplicate_id")
def _():
    d = base()
    d.insert_before("BCS_KW", [("/SKEW/FIX/5", "SKW_KW"), "Fixed frame",
                               names(("Ox", 20), ("Oy", 20), ("Oz", 20)), line(R(0.0), R(0.0), R(0.0)),
                               names(("X1", 20), ("Y1", 20), ("Z1", 20)), line(R(0.0), R(1.0), R(0.0)),
                               names(("X2", 20), ("Y2", 20), ("Z2", 20)), line(R(0.0), R(0.0), R(1.0))]
                    + skew_mov_rows(1, 2, 4))
    d.set("BCS_C1", line(bcs_code("111", "111"), I(5), I(1)))
    return d, "/SKEW/FIX/5 and /SKEW/MOV/5: skews share one id space", [("RX401", "SKM_KW")]
def th_rows(path, title, variables, objects=(), records=None, obj_tag="TH_OBJ"):
    """A /TH group with id 1: title, variable names left-justified in 10-column cells, then the objects, one
    per line (records: "id" for /TH/BRIC, "id+skew" for /TH/SH3N) or ids 10 per line; the last object line is
    tagged obj_tag."""
    rows = [(path + "/1", "TH_KW"), title]
    if variables:
        rows += [names(*[("var_ID%d" % (k + 1), 10) for k in range(len(variables))]),
                 "".join(v.ljust(10) for v in variables).rstrip()]
    if records == "id":
        rows.append(names(("elem_ID", 10)))
        rows += [line(I(x)) for x in objects]
    elif records == "id+skew":
        rows.append(names(("elem_ID", 10), ("skew_ID", 10)))
        rows += [line(I(x), I(0)) for x in objects]
    elif objects:
        rows += [names(*[("obj_ID%d" % (k + 1), 10) for k in range(len(objects))]), line(*[I(x) for x in objects])]
    if objects:
        rows[-1] = (rows[-1], obj_tag)
    return rows


@fault("th_bric_missing_brick")
def _():
    d = base()
    d.insert_before("BEFORE_END", th_rows("/TH/BRIC", "Brick stresses", ["SX", "SY", "SZ"], [11, 99], "id"))
    return d, "/TH/BRIC/1 lists brick 11 and brick 99, which does not exist", [("RX402", "TH_OBJ")]


@fault("th_sh3n_missing_element")
def _():
    d = base()
    d.insert_before("BEFORE_END", th_rows("/TH/SH3N", "Triangles", ["DEF"], [1], "id+skew"))
    return d, "/TH/SH3N/1 lists element 1, a 4-node /SHELL: no /SH3N defines it", [("RX402", "TH_OBJ")]


@fault("th_node_missing_skew")
def _():
    d = base()
    d.insert_before("BEFORE_END", th_rows("/TH/NODE", "Plate corner in a skew", ["DEF"]) +
                    [names(("node_ID", 10), ("skew_ID", 10)), (line(I(1), I(7)), "TH_OBJ")])
    return d, "/TH/NODE/1 lists node 1 in skew 7, and the deck has no /SKEW/FIX/7 or /SKEW/MOV/7", \
        [("RX402", "TH_OBJ")]


@fault("th_shel_in_skew")
def _():
    d = base()
    d.insert_before("BEFORE_END", skew_mov_rows(1, 2, 4) + th_rows("/TH/SHEL", "Shell in a skew", ["DEF"]) +
                    [names(("elem_ID", 10), ("skew_ID", 10)), (line(I(1), I(5)), "TH_OBJ")])
    return d, "/TH/SHEL/1 lists shell 1 in skew 5: radx writes shell results in the element frame only", \
        [("RX509", "TH_OBJ")]


@fault("th_rbody_missing_rbody")
def _():
    d = base()
    d.insert_before("BEFORE_END", th_rows("/TH/RBODY", "Rigid bodies", ["DEF"], [5]))
    return d, "/TH/RBODY/1 lists rigid body 5, which does not exist (the deck has no /RBODY)", [("RX402", "TH_OBJ")]


@fault("th_bric_unknown_variable")
def _():
    d = base()
    d.insert_before("BEFORE_END", th_rows("/TH/BRIC", "Brick with a shell variable", ["SZ", "F1"], [11], "id"))
    return d, "/TH/BRIC/1 asks for F1, a shell variable, not a brick one (error at the keyword line)", \
        [("RX501", "TH_KW")]


@fault("th_rbody_no_variables")
def _():
    d = base()
    d.insert_before("BEFORE_END", th_rows("/TH/RBODY", "Rigid bodies without variables", []))
    return d, "/TH/RBODY/1 ends after its title: no variable line (and no object)", [("RX502", "TH_KW")]


@fault("rwall_sphere_no_diameter")
def _():
    d = base()
    d.insert_before("BEFORE_END", [("/RWALL/SPHER/1", "RWS_KW"), "Sphere without a diameter",
                                   names(("node_ID", 10), ("Slide", 10), ("grnd_ID1", 10), ("grnd_ID2", 10),
                                         ("Iform", 10)),
                                   line(I(0), I(0), I(1), I(0), I(0)),
                                   names(("d", 20), ("", 20), ("Diameter", 20)),
                                   (line(R(0.0), blank(20), R(0.0)), "RWS_C2"),
                                   names(("XM", 20), ("YM", 20), ("ZM", 20)), line(R(0.0), R(0.0), R(-50.0))])
    return d, "/RWALL/SPHER/1 with Diameter = 0: a sphere wall needs a diameter", [("RX502", "RWS_C2")]


def rwall_paral_rows(m2):
    """A fixed /RWALL/PARAL of corner M = (0, 0, -50) and edges to M1 = (100, 0, -50) and M2, on node group 1."""
    return [("/RWALL/PARAL/1", "RWP_KW"), "Parallelogram wall",
            names(("node_ID", 10), ("Slide", 10), ("grnd_ID1", 10), ("grnd_ID2", 10), ("Iform", 10)),
            line(I(0), I(0), I(1), I(0), I(0)),
            names(("d", 20)), line(R(0.0)),
            names(("XM", 20), ("YM", 20), ("ZM", 20)), line(R(0.0), R(0.0), R(-50.0)),
            names(("XM1", 20), ("YM1", 20), ("ZM1", 20)), line(R(100.0), R(0.0), R(-50.0)),
            names(("XM2", 20), ("YM2", 20), ("ZM2", 20)), (line(*[R(x) for x in m2]), "RWP_C5")]


@fault("rwall_paral_aligned_corners")
def _():
    d = base()
    d.insert_before("BEFORE_END", rwall_paral_rows((50.0, 0.0, -50.0)))
    return d, "/RWALL/PARAL/1: M2 on the line M M1, so the parallelogram has no area and no normal", \
        [("RX507", "RWP_C5")]


def fgeo_rows(part=0, node=2):
    """/IMPDISP/FGEO/1 through /FUNCT/1: the plate's node `node` to (12, 0, 0) and node 3 to (20, 0, 5)."""
    return funct_rows(1, [(0.0, 0.0), (0.01, 1.0)]) + [
        ("/IMPDISP/FGEO/1", "FG_KW"), "Final geometry",
        names(("fct_ID", 10), ("part_ID", 10), ("", 10), ("sens_ID", 10)),
        (line(I(1), I(part), blank(10), I(0)), "FG_C1"),
        names(("Ascale", 20), ("", 20), ("Tstart", 20), ("Tstop", 20)),
        line(R(1.0), blank(20), R(0.0), R(0.0)),
        names(("node_IDN", 10), ("Xn", 20), ("Yn", 20), ("Zn", 20)),
        (line(I(node), R(12.0), R(0.0), R(0.0)), "FG_N1"),
        (line(I(3), R(20.0), R(0.0), R(5.0)), "FG_N2")]


@fault("impdisp_fgeo_missing_node")
def _():
    d = base()
    d.insert_before("BEFORE_END", fgeo_rows(node=99))
    return d, "/IMPDISP/FGEO/1 moves node 99, which does not exist", [("RX402", "FG_N1")]


@fault("impdisp_fgeo_spring_part")
def _():
    d = base()
    d.insert_before("BEFORE_END", fgeo_rows(part=2))
    return d, "/IMPDISP/FGEO/1 with part_ID = 2: the spring-part form needs /SPRING, which radx does not read", \
        [("RX509", "FG_C1")]


# Element groups and the surfaces and node groups built from them. The base model has shells 1 and 2
# (part 1), brick 11 (part 2) and no 3-node shell.


def id_list(head, tag, title, label, ids):
    """A keyword with a title and one line of ids; the ids line carries the tag TAG_L1."""
    return [(head, tag + "_KW"), title, names(*[("%s%d" % (label, k + 1), 10) for k in range(len(ids))]),
            (line(*[I(x) for x in ids]), tag + "_L1")]


def box_rows(bid, p1, p2, tag="BOX"):
    return [("/BOX/RECTA/%d" % bid, tag + "_KW"), "Box",
            names(("N1", 10), ("N2", 10), ("Iskew", 10)), line(I(0), I(0), I(0)),
            names(("Xp1", 20), ("Yp1", 20), ("Zp1", 20)), line(*[R(x) for x in p1]),
            names(("Xp2", 20), ("Yp2", 20), ("Zp2", 20)), line(*[R(x) for x in p2])]


def cylinder_rows(bid, p1, p2, diameter, tag="CYL"):
    return [("/BOX/CYLIN/%d" % bid, tag + "_KW"), "Cylinder box",
            names(("N1", 10), ("N2", 10), ("", 10), ("Diameter", 20)),
            (line(I(0), I(0), blank(10), R(diameter)), tag + "_C1"),
            names(("Xp1", 20), ("Yp1", 20), ("Zp1", 20)), line(*[R(x) for x in p1]),
            names(("Xp2", 20), ("Yp2", 20), ("Zp2", 20)), (line(*[R(x) for x in p2]), tag + "_C3")]


def sphere_rows(bid, centre, diameter, tag="SPH"):
    return [("/BOX/SPHER/%d" % bid, tag + "_KW"), "Sphere box",
            names(("N1", 10), ("", 20), ("Diameter", 20)), (line(I(0), blank(20), R(diameter)), tag + "_C1"),
            names(("Xp1", 20), ("Yp1", 20), ("Zp1", 20)), line(*[R(x) for x in centre])]


def with_rows(*groups):
    d = base()
    for rows in groups:
        d.insert_before("BEFORE_END", rows)
    return d


# Sections: a cut at the plate's nodes (node group 1), frame nodes 1, 2, 4.


def sect_rows(grshel, frame=0, tag="SECT"):
    """/SECT/1 summing shell group `grshel` on node group 1; card 1 carries TAG_C1, card 3 TAG_C3."""
    return [("/SECT/1", tag + "_KW"), "Cut",
            names(("node_ID1", 10), ("node_ID2", 10), ("node_ID3", 10), ("grnod_ID", 10), ("I_SAVE", 10),
                  ("Frame_ID", 10), ("Dt", 20), ("alpha", 20)),
            (line(I(1), I(2), I(4), I(1), I(0), I(frame), R(0.0), R(0.0)), tag + "_C1"),
            "# File name", "",
            names(("grbric_ID", 10), ("", 10), ("grshel_ID", 10), ("grtrus_ID", 10), ("grbeam_ID", 10),
                  ("grsprg_ID", 10), ("grtria_ID", 10), ("Ninter", 10), ("", 10), ("Iframe", 10)),
            (line(I(0), blank(10), I(grshel), I(0), I(0), I(0), I(0), I(0), blank(10), I(0)), tag + "_C3")]


@fault("sect_missing_shell_group")
def _():
    d = with_rows(sect_rows(5))
    return d, "/SECT/1 sums /GRSHEL group 5, which does not exist", [("RX402", "SECT_C3")]


@fault("sect_moving_frame")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", "shell_ID", [1, 2]), sect_rows(1, frame=3))
    return d, "/SECT/1 asks for a moving frame (Frame_ID 3), which radx does not implement", \
        [("RX510", "SECT_C1")]


# Accelerometers: /ACCEL/1 on a node, in a skew, with a cut-off frequency.


def accel_rows(node, skew=0, fcut=0.0):
    """/ACCEL/1 on `node`; its card carries ACCEL_C1."""
    return [("/ACCEL/1", "ACCEL_KW"), "Accelerometer",
            names(("node_ID", 10), ("skew_ID", 10), ("", 10), ("Fcut", 20)),
            (line(I(node), I(skew), blank(10), R(fcut)), "ACCEL_C1")]


@fault("accel_missing_node")
def _():
    d = with_rows(accel_rows(99))
    return d, "/ACCEL/1 sits on node 99, which does not exist", [("RX402", "ACCEL_C1")]


@fault("accel_negative_fcut")
def _():
    d = with_rows(accel_rows(1, fcut=-100.0))
    return d, "/ACCEL/1 has a negative cut-off frequency", [("RX501", "ACCEL_C1")]


@fault("accel_missing_skew")
def _():
    d = with_rows(accel_rows(1, skew=3))
    return d, "/ACCEL/1 measures in skew 3, which does not exist", [("RX402", "ACCEL_C1")]


@fault("th_accel_missing_accelerometer")
def _():
    d = with_rows(accel_rows(1), th_rows("/TH/ACCEL", "Sensors", ["DEF"], [2]))
    return d, "/TH/ACCEL/1 lists accelerometer 2; the deck has only /ACCEL/1", [("RX402", "TH_OBJ")]


@fault("th_sectio_missing_section")
def _():
    d = with_rows(th_rows("/TH/SECTIO", "Cuts", ["DEF"], [7]))
    return d, "/TH/SECTIO/1 lists section 7; the deck has no /SECT", [("RX402", "TH_OBJ")]


@fault("grshel_shel_missing_element")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", "shell_ID", [1, 2, 99]))
    return d, "/GRSHEL/SHEL/1 lists shell 99, which does not exist", [("RX402", "G1_L1")]


@fault("grshel_shel_negative_id")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", "shell_ID", [1, -2]))
    return d, "/GRSHEL/SHEL/1 lists element -2: element ids are positive (Radioss finds no element -2 either)", \
        [("RX402", "G1_L1")]


@fault("grsh3n_sh3n_missing_element")
def _():
    d = with_rows(id_list("/GRSH3N/SH3N/1", "G1", "Triangles", "tria_ID", [7]))
    return d, "/GRSH3N/SH3N/1 lists 3-node shell 7; the deck has no /SH3N", [("RX402", "G1_L1")]


@fault("grbric_bric_missing_element")
def _():
    d = with_rows(id_list("/GRBRIC/BRIC/1", "G1", "Bricks", "brick_ID", [11, 12]))
    return d, "/GRBRIC/BRIC/1 lists brick 12, which does not exist", [("RX402", "G1_L1")]


@fault("grshel_part_missing_part")
def _():
    d = with_rows(id_list("/GRSHEL/PART/1", "G1", "Shells of parts", "part_ID", [1, 9]))
    return d, "/GRSHEL/PART/1 lists part 9, which does not exist", [("RX402", "G1_L1")]


@fault("grbric_subset_missing_subset")
def _():
    d = with_rows(id_list("/GRBRIC/SUBSET/1", "G1", "Bricks of a subset", "subs_ID", [4]))
    return d, "/GRBRIC/SUBSET/1 lists subset 4; the deck has no /SUBSET", [("RX402", "G1_L1")]


@fault("grshel_mat_missing_material")
def _():
    d = with_rows(id_list("/GRSHEL/MAT/1", "G1", "Shells of a material", "mat_ID", [1, 7]))
    return d, "/GRSHEL/MAT/1 lists material 7, which does not exist", [("RX402", "G1_L1")]


@fault("grbric_prop_missing_property")
def _():
    d = with_rows(id_list("/GRBRIC/PROP/1", "G1", "Bricks of a property", "prop_ID", [2, 7]))
    return d, "/GRBRIC/PROP/1 lists property 7, which does not exist", [("RX402", "G1_L1")]


@fault("grshel_box_missing_box")
def _():
    d = with_rows(id_list("/GRSHEL/BOX/1", "G1", "Shells in a box", "box_ID", [3]))
    return d, "/GRSHEL/BOX/1 names box 3; the deck has no /BOX", [("RX402", "G1_L1")]


@fault("box_cylinder_no_axis")
def _():
    d = with_rows(cylinder_rows(1, (5.0, 5.0, 0.0), (5.0, 5.0, 0.0), 4.0))
    return d, "/BOX/CYLIN/1 with P1 = P2: the cylinder has no axis", [("RX507", "CYL_C3")]


@fault("box_sphere_no_diameter")
def _():
    d = with_rows(sphere_rows(1, (10.0, 5.0, 0.0), 0.0))
    return d, "/BOX/SPHER/1 with Diameter = 0: a sphere box needs a diameter", [("RX502", "SPH_C1")]


@fault("grshel_box_sphere_empty")
def _():
    # The sphere of centre (10, 5, 0) and diameter 12 holds the plate's middle nodes 2 and 5, no whole shell.
    d = with_rows(sphere_rows(2, (10.0, 5.0, 0.0), 12.0),
                  id_list("/GRSHEL/BOX/1", "G1", "Shells in the sphere", "box_ID", [2]))
    return d, "/GRSHEL/BOX/1: box 2 (a sphere) holds no whole shell", [("RX403", "G1_KW")]


@fault("grbric_box_duplicate_box_id")
def _():
    # /BOX/RECTA/1 and /BOX/CYLIN/1: one id space for every box shape.
    d = with_rows(box_rows(1, (0.0, 0.0, 0.0), (20.0, 10.0, 20.0)),
                  cylinder_rows(1, (10.0, 5.0, 0.0), (10.0, 5.0, 20.0), 30.0),
                  id_list("/GRBRIC/BOX/1", "G1", "Bricks in the box", "box_ID", [1]))
    return d, "/BOX/RECTA/1 and /BOX/CYLIN/1: two boxes with one id", [("RX401", "CYL_KW")]


@fault("grbric_grbric_missing_group")
def _():
    d = with_rows(id_list("/GRBRIC/BRIC/1", "G1", "Bricks", "brick_ID", [11]),
                  id_list("/GRBRIC/GRBRIC/2", "G2", "Union", "grbr_ID", [1, 5]))
    return d, "/GRBRIC/GRBRIC/2 lists brick group 5, which does not exist", [("RX402", "G2_L1")]


@fault("grshel_grshel_loop")
def _():
    d = with_rows(id_list("/GRSHEL/GRSHEL/1", "G1", "First", "grsh_ID", [2]),
                  id_list("/GRSHEL/GRSHEL/2", "G2", "Second", "grsh_ID", [1]))
    return d, "/GRSHEL/GRSHEL/1 lists group 2, which lists group 1: a loop (reported at the group met again)", \
        [("RX507", "G1_KW")]


@fault("grshel_duplicate_group_id")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", "shell_ID", [1]),
                  id_list("/GRSHEL/PART/1", "G2", "Shells of part 1", "part_ID", [1]))
    return d, "/GRSHEL/SHEL/1 and /GRSHEL/PART/1: two 4-node shell groups with id 1", [("RX401", "G2_KW")]


@fault("grbric_box_partly_inside")
def _():
    d = with_rows(box_rows(1, (0.0, 0.0, 0.0), (20.0, 10.0, 6.5)),
                  id_list("/GRBRIC/BOX/1", "G1", "Bricks wholly in the box", "box_ID", [1]),
                  id_list("/GRBRIC/BOX2/2", "G2", "Bricks with a node in the box", "box_ID", [1]))
    return d, "box 1 holds the lower four nodes of brick 11 only: /GRBRIC/BOX/1 (all nodes inside) is empty, " \
        "/GRBRIC/BOX2/2 (one node inside) holds the brick", [("RX403", "G1_KW")]


@fault("grsh3n_part_empty")
def _():
    d = with_rows(id_list("/GRSH3N/PART/1", "G1", "Triangles of the plate", "part_ID", [1]))
    return d, "/GRSH3N/PART/1 lists part 1, which has 4-node shells only: no 3-node shell", [("RX403", "G1_KW")]


@fault("grshel_grshel_removes_all")
def _():
    d = with_rows(id_list("/GRSHEL/PART/1", "G1", "Plate", "part_ID", [1]),
                  id_list("/GRSHEL/GRSHEL/2", "G2", "Plate minus plate", "grsh_ID", [1, -1]))
    return d, "/GRSHEL/GRSHEL/2 adds group 1 and removes it again: empty", [("RX403", "G2_KW")]


@fault("surf_grshel_missing_group")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", "shell_ID", [1, 2]),
                  id_list("/SURF/GRSHEL/1", "S1", "Surface of shell groups", "grsh_ID", [1, 3]))
    return d, "/SURF/GRSHEL/1 lists shell group 3, which does not exist", [("RX402", "S1_L1")]


@fault("surf_grsh3n_missing_group")
def _():
    d = with_rows(id_list("/SURF/GRSH3N/1", "S1", "Surface of 3-node shell groups", "grsh_ID", [4]))
    return d, "/SURF/GRSH3N/1 lists 3-node shell group 4; the deck has none", [("RX402", "S1_L1")]


@fault("surf_grbric_ext_missing_group")
def _():
    d = with_rows(id_list("/GRBRIC/PART/1", "G1", "Block", "part_ID", [2]),
                  id_list("/SURF/GRBRIC/EXT/1", "S1", "Outer faces", "grbr_ID", [1, 2]))
    return d, "/SURF/GRBRIC/EXT/1 lists brick group 2, which does not exist", [("RX402", "S1_L1")]


@fault("surf_grbric_without_ext")
def _():
    d = with_rows(id_list("/GRBRIC/PART/1", "G1", "Block", "part_ID", [2]),
                  id_list("/SURF/GRBRIC/1", "S1", "Faces of a brick group", "grbr_ID", [1]))
    return d, "/SURF/GRBRIC/1 without /EXT or /FREE: Radioss builds no surface from it either", \
        [("RX407", "S1_KW")]


@fault("surf_part_all_missing_part")
def _():
    d = with_rows(id_list("/SURF/PART/ALL/1", "S1", "All faces", "part_ID", [2, 5]))
    return d, "/SURF/PART/ALL/1 lists part 5, which does not exist", [("RX402", "S1_L1")]


@fault("surf_part_all_empty")
def _():
    d = base()
    d.insert_before("AFTER_PARTS", [("/PART/3", "PART3_KW"), "Part without elements",
                                    names(("prop_ID", 10), ("mat_ID", 10), ("subset_ID", 10), ("Thick", 20)),
                                    (part_line(1, 1), "PART3")])
    d.insert_before("BEFORE_END", id_list("/SURF/PART/ALL/1", "S1", "All faces of part 3", "part_ID", [3]))
    return d, "/SURF/PART/ALL/1 lists part 3, which has no element: no segment", [("RX403", "S1_KW")]


@fault("grnod_grshel_missing_group")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", "shell_ID", [1]),
                  id_list("/GRNOD/GRSHEL/3", "N3", "Nodes of shell groups", "grsh_ID", [1, 2]))
    return d, "/GRNOD/GRSHEL/3 lists shell group 2, which does not exist", [("RX402", "N3_L1")]


@fault("grnod_grbric_negative_only")
def _():
    d = with_rows(id_list("/GRBRIC/PART/1", "G1", "Block", "part_ID", [2]),
                  id_list("/GRNOD/GRBRIC/3", "N3", "Nodes of brick groups", "grbr_ID", [-1]))
    return d, "/GRNOD/GRBRIC/3 lists only -1: a negative id is ignored there (a warning), as in Radioss, so the " \
        "group holds no node", [("RX403", "N3_KW")]


# Added masses, initial velocities, gravity and concentrated loads: their references and values.


def admas_rows(mass, grnod, path="/ADMAS/0"):
    return [(path + "/1", "ADM_KW"), "Added mass", names(("MASS", 20), ("grnod_ID", 10)),
            (line(R(mass), I(grnod)), "ADM_C1")]


@fault("admas_missing_group")
def _():
    d = with_rows(admas_rows(1e-6, 99))
    return d, "/ADMAS/0/1 adds mass to node group 99, which does not exist", [("RX402", "ADM_C1")]


@fault("admas_negative_mass")
def _():
    d = with_rows(admas_rows(-1e-6, 1, "/ADMAS/1"))
    return d, "/ADMAS/1/1 adds a negative mass", [("RX501", "ADM_C1")]


@fault("inivel_rot_missing_group")
def _():
    d = with_rows([("/INIVEL/ROT/1", "IV_KW"), "Spin",
                   names(("Vx", 20), ("Vy", 20), ("Vz", 20), ("grnod_ID", 10), ("skew_ID", 10)),
                   (line(R(0.0), R(0.0), R(100.0), I(42), I(0)), "IV_C1")])
    return d, "/INIVEL/ROT/1 spins node group 42, which does not exist", [("RX402", "IV_C1")]


@fault("grav_missing_function")
def _():
    d = with_rows([("/GRAV/1", "GR_KW"), "Gravity",
                   names(("funct_IDT", 10), ("DIR", 10), ("skew_ID", 10), ("sensor_ID", 10), ("grnod_ID", 10),
                         ("", 10), ("Ascale_x", 20), ("Fscale_y", 20)),
                   (line(I(8), S("Z", 10), I(0), I(0), I(1), blank(10), R(0.0), R(-9810.0)), "GR_C1")])
    return d, "/GRAV/1 follows function 8, which does not exist", [("RX402", "GR_C1")]


@fault("cload_missing_group")
def _():
    d = with_rows([("/CLOAD/1", "CL_KW"), "Force",
                   names(("funct_IDT", 10), ("Dir", 10), ("skew_ID", 10), ("sensor_ID", 10), ("grnod_ID", 10),
                         ("Itypfun", 10), ("Ascale_x", 20), ("Fscale_y", 20)),
                   (line(I(5), S("X", 10), I(0), I(0), I(77), I(0), R(0.0), R(1.0)), "CL_C1")]
                  + funct_rows(5, [(0.0, 1.0), (1.0, 1.0)], "Constant"))
    return d, "/CLOAD/1 pushes node group 77, which does not exist", [("RX402", "CL_C1")]


@fault("mat_law_not_in_radx")
def _():
    d = with_rows([("/MAT/LAW51/9", "ML_KW"), "Multi-material ALE law", line(R(1e-9))])
    return d, "/MAT/LAW51: a Radioss material law radx does not implement (not an unknown keyword)", \
        [("RX302", "ML_KW")]


# Random perturbation of the coordinates.


def random_rows(path, xalea, tag):
    return [(path, tag + "_KW"), names(("XALEA", 20), ("SEED", 20)), (line(R(xalea), R(0.0)), tag + "_C1")]


@fault("random_negative_xalea")
def _():
    d = with_rows(random_rows("/RANDOM", -0.01, "RA"))
    return d, "/RANDOM with a negative largest perturbation XALEA", [("RX501", "RA_C1")]


@fault("random_grnod_missing_group")
def _():
    d = with_rows(random_rows("/RANDOM/GRNOD/9", 0.01, "RG"))
    return d, "/RANDOM/GRNOD/9 perturbs node group 9, which does not exist", [("RX402", "RG_KW")]


@fault("random_both_kinds")
def _():
    d = with_rows(random_rows("/RANDOM", 0.01, "RA") + random_rows("/RANDOM/GRNOD/1", 0.01, "RG"))
    return d, "/RANDOM (all nodes) and /RANDOM/GRNOD together: Radioss then perturbs nothing", \
        [("RX507", "RG_C1")]


# Model assembly: //SUBMODEL, /TRANSFORM, /MOVE_FUNCT
def submodel_head(sid=5, offsets=(0,), tag="SUB"):
    return [("//SUBMODEL/%d" % sid, tag + "_KW"), "Block as a submodel",
            names(("off_def", 10), ("off_nod", 10), ("off_ele", 10), ("off_part", 10), ("off_mat", 10),
                  ("off_type", 10), ("off_sub", 10)),
            (line(*[I(x) for x in offsets]), tag + "_C1")]


def transform_rows(kind, grnod=1, v=(0.0, 0.0, 0.0), n1=0, n2=0, sub=0, card2=None, tag="TR"):
    rows = [("/TRANSFORM/%s/1" % kind, tag + "_KW"), "Move",
            names(("grnod_ID", 10), ("X", 20), ("Y", 20), ("Z", 20), ("node_ID1", 10), ("node_ID2", 10),
                  ("sub_ID", 10)),
            (line(I(grnod), R(v[0]), R(v[1]), R(v[2]), I(n1) if n1 else blank(10), I(n2) if n2 else blank(10),
                  I(sub) if sub else blank(10)), tag + "_C1")]
    if card2 is not None:
        rows += [names(("", 10), ("X_point_2", 20), ("Y_point_2", 20), ("Z_point_2", 20), ("Angle", 20)),
                 (line(blank(10), *[R(x) for x in card2]), tag + "_C2")]
    return rows


def with_brick_submodel(d, offsets=(0,), close=True):
    """The brick block (/BRICK/2) inside //SUBMODEL/5."""
    d.insert_before("BRICK_KW", submodel_head(offsets=offsets))
    if close:
        d.insert_after("BRICK_11", [("//ENDSUB", "ENDSUB")])
    return d


@fault("transform_missing_group")
def _():
    d = base()
    d.insert_before("BEFORE_END", transform_rows("TRA", grnod=99, v=(0.0, 0.0, 5.0)))
    return d, "/TRANSFORM/TRA/1 moves node group 99, which does not exist", [("RX402", "TR_C1")]


@fault("transform_missing_submodel")
def _():
    d = base()
    d.insert_before("BEFORE_END", transform_rows("TRA", grnod=0, v=(0.0, 0.0, 5.0), sub=9))
    return d, "/TRANSFORM/TRA/1 moves submodel 9, which does not exist", [("RX402", "TR_C1")]


@fault("transform_group_and_submodel")
def _():
    d = with_brick_submodel(base())
    d.insert_before("BEFORE_END", transform_rows("TRA", grnod=1, v=(0.0, 0.0, 5.0), sub=5))
    return d, "/TRANSFORM/TRA/1 names both node group 1 and submodel 5: a transform moves one of them", \
        [("RX507", "TR_C1")]


@fault("transform_one_node")
def _():
    d = base()
    d.insert_before("BEFORE_END", transform_rows("TRA", grnod=1, n1=1))
    return d, "/TRANSFORM/TRA/1 gives node_ID1 without node_ID2 (both or neither)", [("RX404", "TR_C1")]


@fault("transform_degenerate_axis")
def _():
    d = base()
    d.insert_before("BEFORE_END", transform_rows("ROT", grnod=1, v=(5.0, 5.0, 0.0), card2=(5.0, 5.0, 0.0, 90.0)))
    return d, "/TRANSFORM/ROT/1 turns 90 degrees about an axis from (5, 5, 0) to the same point", \
        [("RX605", "TR_C2")]


@fault("move_funct_missing_function")
def _():
    d = base()
    d.insert_before("BEFORE_END", [("/MOVE_FUNCT/9", "MF_KW"), "Moved",
                                   names(("Ascalex", 20), ("Fscaley", 20), ("Ashiftx", 20), ("Fshifty", 20)),
                                   (line(R(2.0), R(1.0), R(0.0), R(0.0)), "MF_C1")])
    return d, "/MOVE_FUNCT/9: there is no /FUNCT/9 to move", [("RX402", "MF_KW")]


@fault("endsub_without_submodel")
def _():
    d = base()
    d.insert_before("BEFORE_END", [("//ENDSUB", "ENDSUB")])
    return d, "//ENDSUB with no //SUBMODEL open", [("RX312", "ENDSUB")]


@fault("submodel_not_closed")
def _():
    return with_brick_submodel(base(), close=False), "//SUBMODEL/5 is never closed by an //ENDSUB", \
        [("RX312", "SUB_KW")]


@fault("submodel_include_missing_node")
def _():
    d = base()
    k = d.index("BRICK_KW")
    inc = Deck()
    inc.add("# Included by submodel_include_missing_node.rad inside //SUBMODEL/5, whose node offset is 100:")
    inc.add("# the brick's nodes 11..18 are read as 111..118, which do not exist.")
    for text, tag in d.rows[k:d.index("BRICK_11") + 1]:
        inc.add(text, tag)
    d.delete("BRICK_KW", "BRICK_11")
    d.insert_before("RULER_AFTER_ELEMENTS" if d.has("RULER_AFTER_ELEMENTS") else "PART1_KW",
                    submodel_head(offsets=(0, 100)) + [("#include inc/submodel_brick.rad", "INC"),
                                                       ("//ENDSUB", "ENDSUB")])
    return d, "inside //SUBMODEL/5 (node offset 100) the included brick names nodes 11..18, read as 111..118", \
        [("RX406", "BRICK_11", "inc/submodel_brick.rad")], {"inc/submodel_brick.rad": inc}


@fault("several_errors")
def _():
    d = base()
    d.insert_after("NODE_18", [(node_line(3, 20.0, 0.0, 0.0), "DUP")])
    d.insert_after("AFTER_PARTS", [("/FOOBAR/1", "BAD_KW"), "Not a Radioss keyword", line(I(1), I(2))])
    d.set("EL_C2", el_c2(nu=0.6))
    d.insert_before("BEFORE_END", funct_rows(5, [(0.0, 0.0), (0.002, 1.0), (0.002, 2.0)], "Bad function"))
    return d, "four independent errors: duplicate node 3, unknown /FOOBAR, nu = 0.6 on /MAT/LAW1/2, " \
        "/FUNCT/5 X not increasing", [("RX401", "DUP"), ("RX301", "BAD_KW"), ("RX503", "EL_C2"),
                                      ("RX505", "F_P3")]


# ---------------------------------------------------------------------------------------------------


def wrap(text, width=96):
    out, cur = [], ""
    for w in text.split():
        if cur and len(cur) + 1 + len(w) > width:
            out.append(cur)
            cur = w
        else:
            cur = (cur + " " + w) if cur else w
    if cur:
        out.append(cur)
    return out


def render(name, d, what, expects, extras):
    """Returns (lines, [(code, line, file or None)]). Expected lines are computed from tags."""
    nexp = len(expects)
    fault_lines = ["# fault: " + x for x in wrap(what, 90)]
    head_len = nexp + len(fault_lines)
    resolved = []
    for e in expects:
        code, tag = e[0], e[1]
        if len(e) > 2:
            resolved.append((code, extras[e[2]].index(tag) + 1, e[2]))
        else:
            resolved.append((code, d.index(tag) + head_len + 1, None))
    resolved.sort(key=lambda r: (r[2] or "", r[1], r[0]))
    head = []
    for code, ln, f in resolved:
        head.append("# expect: %s line %d%s" % (code, ln, (" file " + f) if f else ""))
    lines = head + fault_lines + d.texts()
    for code, ln, f in resolved:
        if f is None:
            assert 1 <= ln <= len(lines)
    return lines, resolved


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--out", default=os.path.join(here, "..", "decks", "invalid"))
    p.add_argument("--base", help="also write the fault-free base deck to this file")
    args = p.parse_args(argv)
    out = os.path.normpath(args.out)
    table = []
    for name, fn in FAULTS:
        res = fn()
        d, what, expects = res[0], res[1], res[2]
        extras = res[3] if len(res) > 3 else {}
        lines, resolved = render(name, d, what, expects, extras)
        write(os.path.join(out, name + ".rad"), lines)
        for rel, deck in extras.items():
            write(os.path.join(out, rel), deck.texts())
        table.append((name, what, resolved, sorted(extras)))
    if args.base:
        write(args.base, base().texts())
    write(os.path.join(out, "README.md"), readme(table))
    print("wrote %d invalid decks into %s" % (len(table), out))
    return 0


def readme(table):
    L = ["# Invalid starter decks",
         "",
         "Each `.rad` file here is a small starter deck (format 2026, units Mg mm s) that must be REJECTED. It is",
         "the same tiny valid model every time (two 4-node shells of part 1 with Johnson-Cook steel, one brick",
         "of part 2 with elastic aluminium, plate nodes clamped by `/BCS`) with one fault put in, so that it",
         "should produce only the diagnostics listed (`several_errors.rad` has four independent faults, and",
         "all four must be reported).",
         "",
         "The first lines of each deck state what the reader must report, one line per error:",
         "",
         "```",
         "# expect: RX402 line 37",
         "# expect: RX102 line 5 file inc/include_loop_b.rad",
         "# fault: free text describing the fault",
         "```",
         "",
         "* the code is a `Diag` of `parser/diagnostics.hpp`; the line is 1-based, in the deck itself unless",
         "  `file` names another file (relative to this folder);",
         "* the line is the data line that holds the bad value or the bad reference; the keyword line for",
         "  keyword-level faults (unknown or unsupported keyword, empty group, a block that ends before a",
         "  required card, an id given on the keyword line); the last line of the file for a missing `/END`;",
         "  the `#include` line that closes the loop, or that names a missing file;",
         "* only errors are listed. Warnings and notes are not part of the expectation.",
         "",
         "Files that are only included sit in `inc/`: they are not decks and must not be run on their own.",
         "`#include` paths are relative to the folder of the file that holds the `#include` line.",
         "",
         "The decks are generated by `scripts/make_invalid_decks.py` (edit the script, not the decks) and",
         "checked by `scripts/check_decks.py`, an independent reader that re-derives the expected",
         "diagnostics from the deck text.",
         "",
         "| file | fault | expected |",
         "|---|---|---|"]
    for name, what, resolved, extras in table:
        exp = "<br>".join("%s line %d%s" % (c, ln, (" of " + f) if f else "") for c, ln, f in resolved)
        files = "`%s.rad`" % name + "".join(" + `%s`" % x for x in extras)
        L.append("| %s | %s | %s |" % (files, what.replace("|", "\\|"), exp))
    L += ["", "%d decks." % len(table), ""]
    return L


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
