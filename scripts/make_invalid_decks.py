#!/usr/bin/env python3
"""Write the malformed starter decks of decks/invalid/ and their README table.

Every deck is the same tiny valid model (two shells, one brick, two parts, JC steel, elastic aluminium,
clamped plate nodes) with ONE fault put in (several_errors.rad has four). The cards are written by
scripts/radx_cards.py; each keyword block carries a tag, and its lines carry names derived from the tag and
what radx_cards.marked() says each line holds: TAG_KW the keyword line, TAG.field the data line holding that
field (TAG.field.2 the second line holding it: a law string's continuation, the second row of a list),
TAG.ids the first line of an id list, TAG.rows.k the k-th row (or the row tags given). A fault writes a block
again with other values (Deck.update) or edits tagged lines, and the expected diagnostics name a tag, so the
`# expect: RXnnn line N` headers are computed, never counted by hand.

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
import radx_cards as rc  # noqa: E402  (the card layouts and their writer)
from radx_deck_format import RULER, bcs_code, ibc_code, write  # noqa: E402


class Spec:
    """What wrote a keyword block: its tag, rc.marked()'s arguments and the row tags."""

    def __init__(self, tag, keyword, ident, title, row_tags, kw):
        self.tag, self.keyword, self.ident, self.title, self.row_tags, self.kw = \
            tag, keyword, ident, title, row_tags, kw


def _render(spec):
    """The (text, names, spec) rows of a block: names from the tag and each line's mark."""
    out, seen, k_row = [], {}, 0
    for text, mark in rc.marked(spec.keyword, spec.ident, spec.title, **spec.kw):
        names = []
        if mark == "keyword":
            names.append(spec.tag + "_KW")
        elif isinstance(mark, tuple):
            for key in mark:
                n = seen[key] = seen.get(key, 0) + 1
                names.append("%s.%s" % (spec.tag, key) if n == 1 else "%s.%s.%d" % (spec.tag, key, n))
            if mark == ("rows",) and spec.row_tags:
                names.append(spec.row_tags[k_row])
                k_row += 1
        out.append((text, tuple(names), spec))
    return out


def block(tag, keyword, ident=None, title=None, row_tags=None, **kw):
    """The tagged rows of one keyword written by radx_cards (kw: rc.card()'s values, rows, ids ...)."""
    return _render(Spec(tag, keyword, ident, title, row_tags, kw))


class Deck:
    """Lines with optional names. Names are unique; edits address lines by name (a block's by its tag)."""

    def __init__(self):
        self.rows = []  # [text, names, spec or None]

    def add(self, text, tag=None, spec=None):
        names = () if tag is None else (tag,) if isinstance(tag, str) else tuple(tag)
        for n in names:
            if self.has(n):
                raise KeyError("duplicate tag %s" % n)
        self.rows.append([text, names, spec])

    def extend(self, rows):
        for r in rows:
            self.add(*r) if isinstance(r, tuple) else self.add(r)

    def index(self, tag):
        for k, r in enumerate(self.rows):
            if tag in r[1]:
                return k
        raise KeyError(tag)

    def has(self, tag):
        return any(tag in r[1] for r in self.rows)

    def set(self, tag, text):
        self.rows[self.index(tag)][0] = text

    def update(self, tag, **kw):
        """Write block `tag` again with these values changed (row_tags too)."""
        at = [k for k, r in enumerate(self.rows) if r[2] is not None and r[2].tag == tag]
        if not at or at != list(range(at[0], at[-1] + 1)):
            raise KeyError("no block %s" % tag)
        old = self.rows[at[0]][2]
        row_tags = kw.pop("row_tags", old.row_tags)
        new = Deck()
        new.extend(_render(Spec(tag, old.keyword, old.ident, old.title, row_tags, dict(old.kw, **kw))))
        self.rows[at[0]:at[-1] + 1] = new.rows

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
# The base model

NODES = [
    (1, 0.0, 0.0, 0.0), (2, 10.0, 0.0, 0.0), (3, 20.0, 0.0, 0.0),
    (4, 0.0, 10.0, 0.0), (5, 10.0, 10.0, 0.0), (6, 20.0, 10.0, 0.0),
    (11, 5.0, 1.0, 1.5), (12, 15.0, 1.0, 1.5), (13, 15.0, 9.0, 1.5), (14, 5.0, 9.0, 1.5),
    (15, 5.0, 1.0, 11.5), (16, 15.0, 1.0, 11.5), (17, 15.0, 9.0, 11.5), (18, 5.0, 9.0, 11.5),
]
SHELLS = [(1, 1, 2, 5, 4), (2, 2, 3, 6, 5)]
BRICK = (11, 11, 12, 13, 14, 15, 16, 17, 18)
PSH = dict(Ishell=1, Ismstr=2, Ish3n=2, N=5, Thick=1.0, Ithick=1, Iplas=1, fill=0)
PSO = dict(Isolid=1, Ismstr=4, Iframe=1, fill=0)
JC = dict(RHO_I=7.85e-9, RHO_ref=None, E=210000.0, nu=0.3, a=250.0, b=450.0, n=0.3, fill=0)


def node_line(nid, x, y, z):
    return rc.row_line("/NODE", (nid, x, y, z))


def shell_line(eid, n1, n2, n3, n4, phi=None, thick=None):
    return rc.row_line("/SHELL", (eid, n1, n2, n3, n4, phi, thick))


def brick_line(*v):
    return rc.row_line("/BRICK", v)


def part(pid, title, prop, mat):
    return block("PART%d" % pid, "/PART", pid, title, prop_ID=prop, mat_ID=mat, subset_ID=0, Thick=0.0)


def law1(mid, tag, nu=0.33):
    return block(tag, "/MAT/LAW1", mid, "Aluminium (elastic)", RHO_I=2.7e-9, E=70000.0, nu=nu)


def base():
    d = Deck()
    d.add(RULER)
    d.extend(block("BEGIN", "/BEGIN", RUNNAME="TINY", INVERS=rc.VERSION, Input_mass="Mg", Input_length="mm",
                   Input_time="s", Work_mass="Mg", Work_length="mm", Work_time="s"))
    d.add(RULER, "AFTER_BEGIN")
    d.extend(block("TITLE", "/TITLE", title="Tiny model for the invalid-deck tests: two shells and one brick"))
    d.add(RULER)
    d.extend(block("NODE", "/NODE", rows=NODES, row_tags=["NODE_%d" % n[0] for n in NODES]))
    d.add(RULER)
    d.extend(block("SHELL", "/SHELL", 1, rows=SHELLS, row_tags=["SHELL_%d" % e[0] for e in SHELLS]))
    d.extend(block("BRICK", "/BRICK", 2, rows=[BRICK], row_tags=["BRICK_11"]))
    d.add(RULER)
    d.extend(part(1, "Plate", 1, 1))
    d.extend(part(2, "Block", 2, 2))
    d.add(RULER, "AFTER_PARTS")
    d.extend(block("PSH", "/PROP/SHELL", 1, "Plate shell 1 mm", **PSH))
    d.extend(block("PSO", "/PROP/SOLID", 2, "Block solid", **PSO))
    d.add(RULER)
    d.extend(block("JC", "/MAT/PLAS_JOHNS", 1, "Steel (Johnson-Cook)", **JC))
    d.extend(law1(2, "EL"))
    d.add(RULER, "AFTER_MATS")
    d.extend(block("GRN1", "/GRNOD/NODE", 1, "Plate nodes (clamped)", ids=[1, 2, 3, 4, 5, 6]))
    d.extend(block("BCS", "/BCS", 1, "Clamped plate", Tra_rot=bcs_code("111", "111"), skew_ID=0, grnod_ID=1))
    d.add(RULER, "BEFORE_END")
    d.add("/END", "END")
    return d


def block_group():
    return block("GRP2", "/GRNOD/PART", 2, "Block nodes", ids=[2])


def type7(istf=4, igap=0, grnod=2, surf=1, stfac=1.0, tstart=0.0, tstop=0.0, inacti=0, ifric=0, ccards=(),
          lagdt=False, iid=1):
    """A TYPE7 (2026 layout) or LAGDT/TYPE7 interface (tag INT), with /GRNOD/PART/2 and /SURF/PART/1 in front."""
    rows = block_group() + block("SURF1", "/SURF/PART", 1, "Plate surface", ids=[1])
    friction = {"C%d" % (k + 1): c for k, c in enumerate(ccards)}
    values = dict(grnd_IDs=grnod, surf_IDm=surf, Istf=istf, Igap=igap, Stfac=stfac, Fric=0.1, Tstart=tstart,
                  Tstop=tstop, IBC=ibc_code(0, 0, 0), Inacti=inacti, Ifric=ifric, fill=0, **friction)
    if lagdt:
        return rows + block("INT", "/INTER/LAGDT/TYPE7", iid, "Block nodes on plate (LAGDT)", **values)
    return rows + block("INT", "/INTER/TYPE7", iid, "Block nodes on plate", **values)


def with_inter(d, **kw):
    d.insert_before("BEFORE_END", type7(**kw))
    return d


def funct_rows(fid, points, title="Function", tag="F"):
    """/FUNCT/fid; its points carry the tags TAG_P1, TAG_P2 ..."""
    return block(tag, "/FUNCT", fid, title, rows=points, row_tags=["%s_P%d" % (tag, k + 1) for k in range(len(points))])


def foreign(*cards):
    """The field-name and data lines of cards of keywords radx does not read (so radx_cards declares no layout
    for them): (rc.Card, values in field order, None for a gap) pairs."""
    out = []
    for c, values in cards:
        out += [rc.name_line(c.columns), rc.data_line(c.columns, values)]
    return out


def tag_last(rows, name):
    """rows with `name` added to the names of the last one."""
    text, names, spec = rows[-1]
    return rows[:-1] + [(text, names + (name,), spec)]


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
    d.delete("EL.RHO_I", "EL.nu", keep_first=True)
    return d, "/MAT/LAW1/2 ends after its density card: the E, nu card is missing", [("RX502", "EL_KW")]


@fault("letters_in_number")
def _():
    d = base()
    d.update("PSH", Hm="0.O1")
    return d, "/PROP/SHELL/1 Hm written 0.O1 (letter O for a zero) in a real field", [("RX202", "PSH.Hm")]


@fault("letters_in_integer")
def _():
    d = base()
    d.update("PSO", Isolid="1x")
    return d, "/PROP/SOLID/2 Isolid written 1x in an integer field", [("RX201", "PSO.Isolid")]


@fault("real_overflow")
def _():
    d = base()
    d.update("JC", SIG_max0="1e400")
    return d, "/MAT/PLAS_JOHNS/1 SIG_max0 = 1e400 overflows a double", [("RX203", "JC.SIG_max0")]


@fault("tab_in_fixed_field")
def _():
    d = base()
    text = node_line(2, 10.0, 0.0, 0.0)
    assert text[10] == " "
    d.set("NODE_2", text[:10] + "\t" + text[11:])
    return d, "node 2: a tab character in column 11 (first column of X), read as one blank column as Radioss " \
        "reads it (a warning)", [("RX104 warning", "NODE_2")]


@fault("tab_separated_ids")
def _():
    d = base()
    d.insert_before("BEFORE_END", [("/GRNOD/NODE/7", "TG_KW"), "Ids separated by tabs", ("         4\t5\t6", "TG_IDS")])
    return d, "/GRNOD/NODE/7 lists 4, then '<tab>5<tab>6' in the second 10-column cell (a tab is one column): " \
        "Radioss reads only id 5 there and drops 6, radx refuses it", [("RX104 warning", "TG_IDS"),
                                                                      ("RX201", "TG_IDS")]


@fault("end_in_include")
def _():
    d = base()
    d.delete("EL_KW", "EL.nu")
    d.insert_before("AFTER_MATS", [("#include inc/end_in_include.rad", "INC")])
    b = Deck()
    b.add("# Included by end_in_include.rad. Holds /MAT/LAW1/2, then an /END that ends this file only (as")
    b.add("# Radioss reads it); the keyword after it is not read.")
    b.extend(law1(2, "EL"))
    b.add("/END", "INC_END")
    b.extend(FOOBAR)
    return d, "inc/end_in_include.rad ends with /END then /FOOBAR/1: the /END ends that file only (a warning), " \
        "the deck goes on", [("RX108 warning", "INC_END", "inc/end_in_include.rad")], \
        {"inc/end_in_include.rad": b}


@fault("include_double_quoted")
def _():
    d = base()
    d.delete("EL_KW", "EL.nu")
    d.insert_before("AFTER_MATS", [('#include "inc/include_double_quoted.rad"', "INC")])
    b = Deck()
    b.add("# Included by include_double_quoted.rad with a double-quoted name, which OpenRadioss does not read.")
    b.extend(law1(2, "EL"))
    return d, "#include with a double-quoted name: radx reads it, OpenRadioss does not (a warning)", \
        [("RX109 warning", "INC")], {"inc/include_double_quoted.rad": b}


@fault("slash_include")
def _():
    d = base()
    d.insert_before("BEFORE_END", [("/INCLUDE", "SI_KW"), "inc/no_such_file.rad"])
    return d, "/INCLUDE is not how Radioss includes a file (OpenRadioss skips it)", [("RX302", "SI_KW")]


@fault("inter_without_id")
def _():
    d = with_inter(base())
    d.set("INT_KW", "/INTER/TYPE7")
    return d, "/INTER/TYPE7 written without its id: read as interface 1, the id OpenRadioss gives it (a warning)", \
        [("RX508 warning", "INT_KW")]


@fault("convec_unsupported")
def _():
    d = base()
    d.insert_before("BEFORE_END", [("/CONVEC/1", "CV_KW"), "Convection", "         1         0"])
    return d, "/CONVEC/1, a Radioss thermal keyword radx does not implement", [("RX302", "CV_KW")]


FOOBAR = [("/FOOBAR/1", "BAD_KW"), "Not a Radioss keyword", "         1         2"]


@fault("unknown_keyword")
def _():
    d = base()
    d.insert_after("AFTER_PARTS", FOOBAR)
    return d, "/FOOBAR/1 is not a keyword (its block is skipped)", [("RX301", "BAD_KW")]


@fault("unsupported_keyword_law44")
def _():
    d = base()
    rows = [("/MAT/LAW44/3", "L44_KW"), "Cowper-Symonds steel (not supported by radx)"] + foreign(
        (rc.Card(rc.r("RHO_I"), rc.r("RHO_ref")), [7.85e-9]),
        (rc.Card(rc.r("E"), rc.r("nu")), [210000.0, 0.3]),
        (rc.Card(rc.r("a"), rc.r("b"), rc.r("n"), rc.r("EPS_p_max"), rc.r("SIG_max0")), [250.0, 450.0, 0.3, 0.0, 0.0]),
        (rc.Card(rc.r("c"), rc.r("p"), rc.i("ICC"), rc.i("Fsmooth"), rc.r("F_cut")), [40.0, 5.0, 0, 0, 0.0]))
    d.insert_before("AFTER_MATS", rows)
    return d, "/MAT/LAW44/3 is a real Radioss keyword radx does not read", [("RX302", "L44_KW")]


@fault("include_loop_a")
def _():
    d = base()
    d.delete("EL_KW", "EL.nu")
    d.insert_before("AFTER_MATS", [("#include inc/include_loop_b.rad", "INC")])
    b = Deck()
    b.add("# Included by include_loop_a.rad. Holds /MAT/LAW1/2, then includes include_loop_a.rad again:")
    b.add("# the include loop closes here. Paths are relative to the file holding the #include.")
    b.extend(law1(2, "EL"))
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
    return d, "the file stops after /BCS/1: no /END (error at the last line of the file)", \
        [("RX106", "BCS.grnod_ID")]


@fault("missing_begin")
def _():
    d = base()
    d.delete("BEGIN_KW", "AFTER_BEGIN")
    return d, "no /BEGIN (version and units missing); pointed at the first keyword line", \
        [("RX105", "TITLE_KW")]


@fault("unknown_unit")
def _():
    d = base()
    d.update("BEGIN", Input_length="furlong")
    return d, "/BEGIN input length unit 'furlong' is not a known unit", [("RX506", "BEGIN.Input_length")]


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
    d.insert_before("AFTER_MATS", law1(2, "EL2"))
    return d, "/MAT/LAW1/2 defined twice; the second keyword line is the error", [("RX401", "EL2_KW")]


@fault("missing_reference_part_mat")
def _():
    d = base()
    d.update("PART2", mat_ID=99)
    return d, "/PART/2 names material 99, which does not exist", [("RX402", "PART2.mat_ID")]


@fault("part_missing_property")
def _():
    d = base()
    d.update("PART2", prop_ID=99)
    return d, "/PART/2 names property 99, which does not exist", [("RX402", "PART2.prop_ID")]


@fault("brick_missing_part")
def _():
    d = base()
    d.set("BRICK_KW", "/BRICK/7")
    return d, "/BRICK/7: the element block names part 7, which does not exist (id on the keyword line)", \
        [("RX402", "BRICK_KW")]


@fault("element_missing_node")
def _():
    d = base()
    d.update("SHELL", rows=SHELLS + [(3, 3, 99, 6, 5)], row_tags=["SHELL_1", "SHELL_2", "SHELL_3"])
    return d, "shell 3 uses node 99, which does not exist", [("RX406", "SHELL_3")]


@fault("bcs_missing_group")
def _():
    d = base()
    d.update("BCS", grnod_ID=99)
    return d, "/BCS/1 names node group 99, which does not exist", [("RX402", "BCS.grnod_ID")]


def set_rows(sid, clauses, title="Set", tag=None):
    """/SET/GENERAL/sid (tag SETsid) with clause rows; row k carries the tag TAG_Ck (k from 1)."""
    tag = tag or "SET%d" % sid
    return block(tag, "/SET/GENERAL", sid, title, rows=clauses,
                 row_tags=["%s_C%d" % (tag, k + 1) for k in range(len(clauses))])


@fault("set_missing_part")
def _():
    # Radioss leaves a missing part out of a set with a warning (its message 1902) and warns of the empty group.
    d = base()
    d.insert_before("BEFORE_END", set_rows(5, [("PART", 99)], "Parts of the plate (part 99 does not exist)"))
    d.update("BCS", grnod_ID=5)
    return d, "/SET/GENERAL/5 (the node group of /BCS/1) lists part 99, which does not exist: left out, the set is " \
        "empty (two warnings, as in Radioss)", [("RX402 warning", "SET5_C1"), ("RX403 warning", "SET5_KW")]


@fault("set_unknown_clause")
def _():
    # SH4N is no Radioss clause (4-node shells are SHELL): OpenRadioss drops it without a word, radx stops.
    d = base()
    d.insert_before("BEFORE_END", set_rows(5, [("SH4N", 1, 2)], "Plate shells written as SH4N"))
    d.update("BCS", grnod_ID=5)
    return d, "/SET/GENERAL/5 has a clause SH4N, which is not a /SET clause (SHELL is)", [("RX507", "SET5_C1")]


@fault("set_unsupported_clause")
def _():
    d = base()
    d.insert_before("BEFORE_END", set_rows(5, [("SEG", 1, 1, 2, 5, 4)], "A segment clause"))
    d.update("BCS", grnod_ID=5)
    return d, "/SET/GENERAL/5 has a SEG clause, which radx does not build (refused by name)", \
        [("RX510", "SET5_C1")]


@fault("set_unsupported_option")
def _():
    d = base()
    d.insert_before("BEFORE_END", set_rows(5, [("PART_E", 1)], "Outer nodes of the plate"))
    d.update("BCS", grnod_ID=5)
    return d, "/SET/GENERAL/5 has PART_E (only the nodes of outer faces and free edges), an option radx does not " \
        "apply (refused by name)", [("RX510", "SET5_C1")]


@fault("set_includes_itself")
def _():
    d = base()
    d.insert_before("BEFORE_END", set_rows(5, [("SET", 6)], "Set 6") + set_rows(6, [("SET", 5)], "Set 5"))
    d.update("BCS", grnod_ID=5)
    return d, "/SET/GENERAL/5 takes set 6, which takes set 5", [("RX507", "SET5_KW")]


@fault("set_empty_tie_surface")
def _():
    # A set of nodes only has no segment: as a TYPE2 main surface it leaves nothing to tie to, an error.
    d = with_type2(base(), surf=7)
    d.insert_before("BEFORE_END", set_rows(7, [("NODE", 1, 2, 3)], "Plate nodes (no element: no segment)"))
    return d, "/INTER/TYPE2/1 names /SET/GENERAL/7 as its main surface; the set holds nodes only, so no segment " \
        "(a warning at the set, an error at the tie)", [("RX403 warning", "SET7_KW"), ("RX403", "T2.surf_IDm")]


@fault("empty_group")
def _():
    d = base()
    d.delete("GRN1.ids")
    return d, "/GRNOD/NODE/1 (used by /BCS/1) lists no node: /BCS/1 acts on nothing (a warning, as in Radioss)", \
        [("RX403 warning", "GRN1_KW")]


@fault("surf_part_on_solid")
def _():
    d = base()
    d.insert_before("BEFORE_END", block("SURF", "/SURF/PART", 1, "Block as a /SURF/PART (must be /SURF/PART/EXT)",
                                        ids=[2]))
    return d, "/SURF/PART/1 lists part 2, a solid part (needs /SURF/PART/EXT)", [("RX407", "SURF.ids")]


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
              "(a warning)", [("RX607 warning", "BRICK_11")]


def with_tetra(d, row=(21, 11, 14, 12, 15), part_prop=2, itetra4=None):
    """d with /TETRA4/3 (one tetrahedron on four of the brick's nodes, positive as written: the right-hand
    normal of n1 n2 n3 points away from n4, tag TETRA_21) in part 3 of property part_prop (a /PROP/SOLID/3
    with Itetra4 = itetra4 when given)."""
    d.insert_before("AFTER_PARTS", block("TETRA", "/TETRA4", 3, rows=[row], row_tags=["TETRA_21"]) +
                    part(3, "Tetra", 3 if itetra4 is not None else part_prop, 2))
    if itetra4 is not None:
        d.insert_before("AFTER_MATS", block("PSO3", "/PROP/SOLID", 3, "Tetra solid", **dict(PSO, Itetra4=itetra4)))
    return d


SPR = dict(M=1e-6, sens_ID=0, Isflag=0, Ileng=0, K=1000.0, C=0.0, A=0.0, B=0.0, D=0.0, fct_ID1=0, H=0, fct_ID2=0,
           fct_ID3=0, fct_ID4=0, delta_min=0.0, delta_max=0.0, F=0.0, E=0.0, Ascale=0.0, Hscale=0.0)


def with_spring(d, row=(31, 3, 6, 0), **prop):
    """d with /SPRING/4 (spring 31 between the plate's nodes 3 and 6, tag SPRING_31) in part 4 (no material) of
    /PROP/SPRING/4 (tag PSPR: M 1e-6, K 1000, the given values on top)."""
    d.insert_before("AFTER_PARTS", block("SPRING", "/SPRING", 4, rows=[row], row_tags=["SPRING_31"]) +
                    part(4, "Spring", 4, 0))
    d.insert_before("AFTER_MATS", block("PSPR", "/PROP/SPRING", 4, "Spring", **dict(SPR, **prop)))
    return d


@fault("spring_zero_mass")
def _():
    d = with_spring(base(), M=0.0)
    return d, "/PROP/SPRING/4 has M = 0: a spring needs a mass > 0 (its step is sqrt(M/K))", [("RX501", "PSPR.M")]


@fault("spring_negative_stiffness")
def _():
    d = with_spring(base(), K=-5.0)
    return d, "/PROP/SPRING/4 has K = -5", [("RX501", "PSPR.K")]


@fault("spring_missing_function")
def _():
    d = with_spring(base(), fct_ID1=99)
    return d, "/PROP/SPRING/4 names the force curve fct_ID1 = 99, which no /FUNCT defines", \
        [("RX402", "PSPR.fct_ID1")]


@fault("spring_zero_stiffness_hardening")
def _():
    # K = 0 with a curve is the nonlinear elastic spring for H = 0 (read, the step from the curve's slope); H 1
    # unloads with the slope K, which is then 0.
    d = with_spring(base(), K=0.0, fct_ID1=7, H=1)
    d.insert_before("AFTER_MATS", funct_rows(7, [(-1.0, -1000.0), (0.0, 0.0), (1.0, 1000.0)], "Spring force", "F7"))
    return d, "/PROP/SPRING/4 K = 0 with a force curve and H = 1: that law unloads with the slope K", \
        [("RX501", "PSPR.K")]


@fault("spring_zero_stiffness_flat_curve")
def _():
    d = with_spring(base(), K=0.0, fct_ID1=7)
    d.insert_before("AFTER_MATS", funct_rows(7, [(-1.0, 0.0), (1.0, 0.0)], "Flat force", "F7"))
    return d, "/PROP/SPRING/4 K = 0 with a flat force curve: no force and no time step", [("RX501", "PSPR.K")]


@fault("spring_missing_node")
def _():
    d = with_spring(base(), row=(31, 3, 999, 0))
    return d, "spring 31 joins node 3 to node 999, which does not exist", [("RX406", "SPRING_31")]


@fault("spring_hardening_needs_curve")
def _():
    d = with_spring(base(), fct_ID1=7, H=4)
    d.insert_before("AFTER_MATS", funct_rows(7, [(-1.0, -1000.0), (0.0, 0.0), (1.0, 1000.0)], "Spring force", "F7"))
    return d, "/PROP/SPRING/4 asks for H = 4 (kinematic hardening) without fct_ID3, its lower yield curve", \
        [("RX502", "PSPR.fct_ID3")]


def with_truss(d, row=(31, 3, 6), mat=2, **prop):
    """d with /TRUSS/4 (truss 31 between the plate's nodes 3 and 6, tag TRUSS_31) in part 4 (tag PART4, material
    `mat`: 2 the elastic law 1) of /PROP/TRUSS/4 (tag PTRUSS: Area 10, the given values on top)."""
    d.insert_before("AFTER_PARTS", block("TRUSS", "/TRUSS", 4, rows=[row], row_tags=["TRUSS_31"]) +
                    part(4, "Truss", 4, mat))
    d.insert_before("AFTER_MATS", block("PTRUSS", "/PROP/TRUSS", 4, "Truss", **dict(dict(Area=10.0, Gap=0.0),
                                                                                   **prop)))
    return d


@fault("ale_bcs_on_lagrangian_nodes")
def _():
    d = base()
    d.insert_before("BEFORE_END", block("ALEBCS", "/ALE/BCS", 5, "Fixed grid velocity",
                                        Code=bcs_code("111", "000"), skew_ID=0, grnod_ID=1))
    return d, "/ALE/BCS on the plate's nodes: it fixes ALE grid velocities, which act on nothing on radx's " \
        "Lagrangian nodes, as in Radioss (a warning)", [("RX509 warning", "ALEBCS.grnod_ID")]


@fault("truss_gap")
def _():
    d = with_truss(base(), Gap=1.0)
    return d, "/PROP/TRUSS/4 Gap = 1: a gap truss (no force until it shortens by Gap), which radx does not " \
        "implement", [("RX510", "PTRUSS.Gap")]


@fault("truss_zero_area")
def _():
    d = with_truss(base(), Area=-1.0)
    return d, "/PROP/TRUSS/4 Area = -1: a truss needs a cross-section > 0", [("RX501", "PTRUSS.Area")]


@fault("truss_same_nodes")
def _():
    d = with_truss(base(), row=(31, 3, 3))
    return d, "truss 31 joins node 3 to itself", [("RX604", "TRUSS_31")]


@fault("truss_law_not_run")
def _():
    d = with_truss(base(), mat=3)
    d.insert_before("AFTER_MATS", block("VOID3", "/MAT/VOID", 3, "Void"))
    return d, "part 4's trusses have the void material (law 0): radx's trusses run laws 1 and 2 only", \
        [("RX510", "PART4.mat_ID")]


BEAMP = dict(Ismstr=0, Dm=0.0, Df=0.0, Area=100.0, Iyy=833.0, Izz=833.0, Ixx=1406.0, Wdof="000 000", Ishear=0)


def with_beam(d, row=(31, 3, 6, 0), mat=2, **prop):
    """d with /BEAM/4 (beam 31 between the plate's nodes 3 and 6, tag BEAM_31) in part 4 (tag PART4, material
    `mat`: 2 the elastic law 1) of /PROP/BEAM/4 (tag PBEAM: a 10 mm square section, the given values on
    top)."""
    d.insert_before("AFTER_PARTS", block("BEAM", "/BEAM", 4, rows=[row], row_tags=["BEAM_31"]) +
                    part(4, "Beam", 4, mat))
    d.insert_before("AFTER_MATS", block("PBEAM", "/PROP/BEAM", 4, "Beam", **dict(BEAMP, **prop)))
    return d


@fault("beam_small_strain")
def _():
    d = with_beam(base(), Ismstr=1)
    return d, "/PROP/BEAM/4 Ismstr = 1: small strain (the initial length in the strains), not implemented for " \
        "beams", [("RX510", "PBEAM.Ismstr")]


@fault("beam_zero_inertia")
def _():
    d = with_beam(base(), Iyy=-1.0)
    return d, "/PROP/BEAM/4 Iyy = -1: a second moment of area must be > 0", [("RX501", "PBEAM.Iyy")]


@fault("beam_orientation_on_axis")
def _():
    d = with_beam(base(), row=(31, 1, 3, 2))
    return d, "beam 31 from node 1 to node 3 with its orientation node 2 on that line: no y axis", \
        [("RX603", "BEAM_31")]


@fault("beam_law_not_run")
def _():
    d = with_beam(base(), mat=3)
    d.insert_before("AFTER_MATS", block("VOID3", "/MAT/VOID", 3, "Void"))
    return d, "part 4's beams have the void material (law 0): radx's type-3 beams run laws 1 and 2 only", \
        [("RX510", "PART4.mat_ID")]


SPR8 = dict(M=1e-6, Inertia=0.0, skew_ID=0, sens_ID=0, Isflag=0, Ifail=0, Ifail2=0, Iequil=0, Fsmooth=0, Fcut=0.0,
            **{k + d: v for d in "123456" for k, v in (("K", 0.0), ("C", 0.0), ("A", 0.0), ("B", 0.0), ("D", 0.0),
                                                      ("fct_ID1", 0), ("H", 0), ("fct_ID2", 0), ("fct_ID3", 0),
                                                      ("fct_ID4", 0), ("delta_min", 0.0), ("delta_max", 0.0),
                                                      ("F", 0.0), ("E", 0.0), ("Ascale", 0.0), ("Hscale", 0.0))})


def with_spring8(d, **prop):
    """d with /SPRING/4 (spring 31 between the plate's nodes 3 and 6, tag SPRING_31) in part 4 (no material) of
    /PROP/SPR_GENE/4 (tag PSPR8: M 1e-6, K1 1000, the given values on top)."""
    d.insert_before("AFTER_PARTS", block("SPRING", "/SPRING", 4, rows=[(31, 3, 6, 0)], row_tags=["SPRING_31"]) +
                    part(4, "Spring", 4, 0))
    d.insert_before("AFTER_MATS", block("PSPR8", "/PROP/SPR_GENE", 4, "General spring",
                                        **dict(SPR8, K1=1000.0, **prop)))
    return d


@fault("spring8_rotation_without_inertia")
def _():
    d = with_spring8(base(), K4=50.0)
    return d, "/PROP/SPR_GENE/4 gives the rotation about X a stiffness K4 = 50 but no Inertia: the rotation would " \
        "have no time step and the node no inertia", [("RX501", "PSPR8.Inertia")]


@fault("spring8_negative_damping")
def _():
    d = with_spring8(base(), C3=-1.0)
    return d, "/PROP/SPR_GENE/4 has a negative damping C3 = -1", [("RX501", "PSPR8.C3")]


@fault("spring8_hardening_refused")
def _():
    d = with_spring8(base(), fct_ID12=7, H2=8, K2=1000.0)
    d.insert_before("AFTER_MATS", funct_rows(7, [(-1.0, -1000.0), (0.0, 0.0), (1.0, 1000.0)], "Spring force", "F7"))
    return d, "/PROP/SPR_GENE/4 asks for H2 = 8 (force of the total length) on its Y law, which radx does not " \
        "implement for TYPE8: refused by name", [("RX510", "PSPR8.H2")]


@fault("spring8_iequil_refused")
def _():
    d = with_spring8(base(), Iequil=1)
    return d, "/PROP/SPR_GENE/4 asks for Iequil = 1 (moment equilibrium of the shear forces), which radx does not " \
        "implement", [("RX510", "PSPR8.Iequil")]


SPR13 = dict({k: v for k, v in SPR8.items() if k not in ("Iequil", "Fsmooth", "Fcut")}, Ileng=0, Vo=0.0, Wo=0.0,
             Asrate=0.0, Israte=0,
             **{k + d: 0.0 for d in "123456" for k in ("c", "n", "alpha", "beta")})


def with_spring13(d, **prop):
    """d with /SPRING/4 (spring 31 between the plate's nodes 3 and 6, tag SPRING_31) in part 4 (no material) of
    /PROP/SPR_BEAM/4 (tag PSPR13: M 1e-6, K1 1000, the given values on top)."""
    d.insert_before("AFTER_PARTS", block("SPRING", "/SPRING", 4, rows=[(31, 3, 6, 0)], row_tags=["SPRING_31"]) +
                    part(4, "Spring", 4, 0))
    d.insert_before("AFTER_MATS", block("PSPR13", "/PROP/SPR_BEAM", 4, "Beam spring",
                                        **dict(SPR13, K1=1000.0, **prop)))
    return d


@fault("spring13_shear_without_inertia")
def _():
    d = with_spring13(base(), K2=50.0)
    return d, "/PROP/SPR_BEAM/4 gives the Y shear a stiffness K2 = 50 but no Inertia: its end moments would turn " \
        "nodes without inertia", [("RX501", "PSPR13.Inertia")]


@fault("spring13_ileng_refused")
def _():
    d = with_spring13(base(), Ileng=1)
    return d, "/PROP/SPR_BEAM/4 asks for Ileng = 1 (values per unit length), which radx does not implement for " \
        "TYPE13", [("RX510", "PSPR13.Ileng")]


@fault("tetra_zero_volume")
def _():
    d = with_tetra(base(), row=(21, 11, 12, 13, 14))
    return d, "tetrahedron 21 on nodes 11 12 13 14, which all lie in the plane z = 1.5: zero volume", \
        [("RX601", "TETRA_21")]


@fault("tetra_repeated_node")
def _():
    d = with_tetra(base(), row=(21, 11, 14, 11, 15))
    return d, "tetrahedron 21 lists node 11 twice (n1 and n3)", [("RX604", "TETRA_21")]


@fault("tetra_negative_volume_renumbered")
def _():
    d = with_tetra(base(), row=(21, 11, 12, 14, 15))
    return d, "tetrahedron 21 turns n1 n2 n3 towards n4 (negative volume): n2 and n4 swapped as Radioss does " \
              "(a warning)", [("RX608 warning", "TETRA_21")]


@fault("tetra_id_of_a_brick")
def _():
    d = with_tetra(base(), row=(11, 11, 14, 12, 15))
    return d, "tetrahedron 11 takes the id of brick 11: solid elements share one id space", \
        [("RX401", "TETRA_21")]


@fault("tetra_missing_node")
def _():
    d = with_tetra(base(), row=(21, 11, 14, 12, 99))
    return d, "tetrahedron 21 uses node 99, which does not exist", [("RX406", "TETRA_21")]


@fault("tetra_in_shell_part")
def _():
    d = with_tetra(base(), part_prop=1)
    return d, "/TETRA4/3 is in part 3, whose property /PROP/SHELL/1 is a shell property", [("RX407", "TETRA_KW")]


@fault("tetra_itetra4_nodal_pressure")
def _():
    d = with_tetra(base(), itetra4=1)
    return d, "/PROP/SOLID/3 Itetra4 = 1 (nodal pressure) for tetrahedron 21: refused by name", \
        [("RX510", "PSO3.Itetra4")]


@fault("tetra_corotational_shared_property")
def _():
    d = with_tetra(base())
    d.update("PSO", Iframe=2)
    return d, "/PROP/SOLID/2 Iframe = 2 (co-rotational) is shared by brick 11 and tetrahedron 21: radx's " \
              "tetrahedron runs the Jaumann rate only (OpenRadioss's runs co-rotational): refused by name", \
        [("RX510", "PSO.Iframe")]


# A 20-node brick: a 10 mm cube at x = 30..40, corners then mid-side nodes in /BRIC20's order (ids 101-120).
BRIC20_NAT = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1),
              (0, -1, -1), (1, 0, -1), (0, 1, -1), (-1, 0, -1), (-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0),
              (0, -1, 1), (1, 0, 1), (0, 1, 1), (-1, 0, 1)]
BRIC20_NODES = [(101 + k, 35.0 + 5.0 * a, 5.0 + 5.0 * b, 6.5 + 5.0 * c) for k, (a, b, c) in enumerate(BRIC20_NAT)]


def with_bric20(d, nodes=None, isolid=16, inpts=0, eid=31, lines=3):
    """d with the nodes 101-120 and /BRIC20/3 (element eid on them, its first line tagged BRIC20_<eid>; only its
    first `lines` lines) in part 3 of /PROP/SOLID/3 (tag PSO20: Isolid isolid, Inpts inpts), law 1."""
    nodes = nodes or list(range(101, 121))
    d.insert_before("AFTER_PARTS", block("NODE20", "/NODE", rows=BRIC20_NODES,
                                         row_tags=["NODE_%d" % n[0] for n in BRIC20_NODES]))
    rows = rc.bric20_rows(3, [(eid, *nodes)])
    tagged = [(rows[0], "BRIC20_KW")] + [(r, None) for r in rows[1:4]]
    tagged.append((rows[4], "BRIC20_%d" % eid))
    tagged += [(r, None) for r in rows[5:4 + lines]]
    d.insert_before("AFTER_PARTS", [(t, g) if g else t for t, g in tagged] + part(3, "Quadratic", 3, 2))
    d.insert_before("AFTER_MATS", block("PSO20", "/PROP/SOLID", 3, "Quadratic solid",
                                        **dict(PSO, Isolid=isolid, Inpts=inpts)))
    return d


@fault("bric20_isolid_one_point")
def _():
    d = with_bric20(base(), isolid=1)
    return d, "/PROP/SOLID/3 Isolid = 1 on 20-node brick 31: OpenRadioss runs it with one Gauss point and no " \
              "hourglass control; refused by name (radx runs 16, 14 and 17)", [("RX510", "PSO20.Isolid")]


@fault("bric20_inpts_one_point")
def _():
    d = with_bric20(base(), inpts=122)
    return d, "/PROP/SOLID/3 Inpts = 122 on 20-node brick 31: one point along a direction leaves zero-energy " \
              "modes; radx builds 2 or 3 points per direction", [("RX510", "PSO20.Inpts")]


@fault("bric20_repeated_node")
def _():
    d = with_bric20(base(), nodes=[101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116,
                                   117, 118, 119, 117])
    return d, "20-node brick 31 lists node 117 twice (n17 and n20)", [("RX604", "BRIC20_31")]


@fault("bric20_inverted")
def _():
    d = with_bric20(base(), nodes=[105, 106, 107, 108, 101, 102, 103, 104, 117, 118, 119, 120, 113, 114, 115, 116,
                                   109, 110, 111, 112])
    return d, "20-node brick 31 lists its top face first: non-positive Jacobian", [("RX601", "BRIC20_31")]


@fault("bric20_id_of_a_brick")
def _():
    d = with_bric20(base(), eid=11)
    return d, "20-node brick 11 takes the id of brick 11: solid elements share one id space", \
        [("RX401", "BRIC20_11")]


@fault("bric20_missing_line")
def _():
    d = with_bric20(base(), lines=2)
    return d, "/BRIC20/3 ends after two of element 31's three lines", [("RX304", "BRIC20_31")]


@fault("bric20_free_format")
def _():
    d = with_bric20(base())
    d.set("BRIC20_31", "31, 101, 102, 103, 104, 105, 106, 107, 108")
    return d, "/BRIC20/3 element 31 written comma-separated: /BRIC20 is read in fixed 10-column fields only", \
        [("RX201", "BRIC20_31")]


@fault("bric20_group_surface")
def _():
    d = with_bric20(base())
    d.insert_before("BEFORE_END", block("GRB", "/GRBRIC/PART", 4, "Quadratic part's bricks", ids=[3]) +
                    block("SURF", "/SURF/GRBRIC/EXT", 1, "Their skin", ids=[4]))
    return d, "/SURF/GRBRIC/EXT/1 of brick group 4, which holds 20-node brick 31: their faces are not built", \
        [("RX510", "SURF.ids")]


@fault("bric20_surface")
def _():
    d = with_bric20(base())
    d.insert_before("BEFORE_END", block("SURF", "/SURF/PART/EXT", 1, "Quadratic part's skin", ids=[3]))
    return d, "/SURF/PART/EXT/1 lists part 3 of 20-node bricks: their faces are not built (OpenRadioss gives " \
              "them no segment either)", [("RX510", "SURF.ids")]


@fault("implausible_wave_speed")
def _():
    d = base()
    d.update("EL", RHO_I=2700.0)
    return d, "/MAT/LAW1/2 RHO_I = 2700 (kg/m3) in a Mg mm s deck: sqrt(E/RHO_I) = 0.005 m/s (a warning)", \
        [("RX512 warning", "EL.nu")]


@fault("zero_area_shell")
def _():
    d = base()
    d.set("NODE_1", node_line(1, 10.0, -10.0, 0.0))
    d.set("NODE_4", node_line(4, 10.0, 20.0, 0.0))
    return d, "shell 1: nodes 1, 2, 5, 4 moved onto one line (x = 10): zero area", [("RX602", "SHELL_1")]


@fault("negative_thickness")
def _():
    d = base()
    d.update("PSH", Thick=-1.0)
    return d, "/PROP/SHELL/1 Thick = -1", [("RX504", "PSH.Thick")]


@fault("zero_shell_thickness")
def _():
    d = base()
    d.update("PSH", Thick=0.0)
    d.set("SHELL_1", shell_line(1, 1, 2, 5, 4, thick=0.0))
    d.set("SHELL_2", shell_line(2, 2, 3, 6, 5, thick=1.0))
    return d, "shell 1 has Thick 0 on its element card and in /PROP/SHELL/1 (shell 2 gives 1.0 on its card)", \
        [("RX504", "SHELL_1")]


@fault("shell_n_over_10")
def _():
    d = base()
    d.update("PSH", N=12)
    return d, "/PROP/SHELL/1 N = 12 integration points (0..10 allowed)", [("RX501", "PSH.N")]


@fault("poisson_half")
def _():
    d = base()
    d.update("EL", nu=0.5)
    return d, "/MAT/LAW1/2 nu = 0.5 (Radioss silently uses 0.499)", [("RX503", "EL.nu")]


@fault("poisson_over_half")
def _():
    d = base()
    d.update("JC", nu=0.6)
    return d, "/MAT/PLAS_JOHNS/1 nu = 0.6", [("RX503", "JC.nu")]


@fault("jc_c_without_epsdot0")
def _():
    d = base()
    d.update("JC", c=0.014, EPS_DOT_0=0.0)
    return d, "/MAT/PLAS_JOHNS/1 c = 0.014 with EPS_DOT_0 = 0", [("RX502", "JC.c")]


@fault("jc_n_over_one")
def _():
    d = base()
    d.update("JC", n=1.5)
    return d, "/MAT/PLAS_JOHNS/1 hardening exponent n = 1.5 (must be <= 1)", [("RX501", "JC.n")]


def plas_tab(n=1, fids=(7,), scales=(1.0,), rates=(0.0,), **kw):
    """/MAT/PLAS_TAB/3 (tag TAB, curves on /FUNCT/7) and its function, before AFTER_MATS; no part uses it."""
    values = dict(RHO_I=7.85e-9, E=210000.0, nu=0.3, N_funct=n, **kw)
    for k in range(n):
        values["fct_ID%d" % (k + 1)] = fids[k]
        values["Fscale%d" % (k + 1)] = scales[k]
        values["Eps_dot%d" % (k + 1)] = rates[k]
    return (block("TAB", "/MAT/PLAS_TAB", 3, "Steel (tabulated)", **values) +
            funct_rows(7, [(0.0, 250.0), (1.0, 700.0)], "Yield curve", tag="F7"))


@fault("plas_tab_missing_function")
def _():
    d = base()
    d.insert_before("AFTER_MATS", plas_tab(fids=(99,)))
    return d, "/MAT/PLAS_TAB/3 fct_ID1 = 99 names no /FUNCT", [("RX402", "TAB.fct_ID1")]


@fault("plas_tab_rates_decreasing")
def _():
    d = base()
    d.insert_before("AFTER_MATS", plas_tab(n=2, fids=(7, 7), scales=(1.0, 1.2), rates=(100.0, 50.0)))
    return d, "/MAT/PLAS_TAB/3 strain rates 100 then 50 (must increase)", [("RX507", "TAB.Eps_dot2")]


@fault("plas_tab_plastic_rate")
def _():
    d = base()
    d.insert_before("AFTER_MATS", plas_tab(VP=1))
    return d, "/MAT/PLAS_TAB/3 VP = 1 (plastic strain rate, not implemented)", [("RX510", "TAB.VP")]


def plas_brit(mid=3, **kw):
    """/MAT/PLAS_BRIT (tag PB; the LOI27 QA aluminium with a crack at 14 %); no part uses it unless a fault says."""
    values = dict(RHO_I=2.8e-9, E=71000.0, nu=0.33, a=290.0, b=562.3, n=0.63, SIG_max0=425.0, EPS_t1=0.14,
                  EPS_m1=0.15, d_max1=0.999, EPS_f1=0.151, fill=0)
    values.update(kw)
    return block("PB", "/MAT/PLAS_BRIT", mid, "Aluminium (brittle)", **values)


@fault("plas_brit_no_damage_slope")
def _():
    d = base()
    d.insert_before("AFTER_MATS", plas_brit(EPS_t1=0.15, EPS_m1=0.14))
    return d, "/MAT/PLAS_BRIT/3 EPS_m1 = 0.14 below EPS_t1 = 0.15 (the damage needs EPS_m1 > EPS_t1)", \
        [("RX507", "PB.EPS_m1")]


@fault("plas_brit_damage_one")
def _():
    d = base()
    d.insert_before("AFTER_MATS", plas_brit(d_max1=1.0))
    return d, "/MAT/PLAS_BRIT/3 d_max1 = 1 (the largest damage must be below 1)", [("RX501", "PB.d_max1")]


@fault("plas_brit_on_brick")
def _():
    d = base()
    d.insert_before("AFTER_MATS", plas_brit())
    d.update("PART2", mat_ID=3)
    return d, "/MAT/PLAS_BRIT/3 on the brick part 2 (law 27 is a shell law)", [("RX510", "PB_KW")]


@fault("plas_brit_global_plasticity")
def _():
    d = base()
    d.insert_before("AFTER_MATS", plas_brit())
    d.update("PART1", mat_ID=3)
    d.update("PSH", N=0)
    return d, "/MAT/PLAS_BRIT/3 on shells of N = 0 (law 27 needs integration points)", [("RX510", "PSH.N")]
def ogden(mid=3, **kw):
    """/MAT/OGDEN (tag OG; the rubber of OpenRadioss's law42 QA deck); no part uses it unless a fault says."""
    values = dict(RHO_I=9.4e-10, nu=0.495, mu_1=0.8276, mu_2=0.055, alpha_1=2.0, alpha_2=-2.0, fill=0)
    values.update(kw)
    return block("OG", "/MAT/OGDEN", mid, "Rubber (Ogden)", **values)


@fault("ogden_prony")
def _():
    d = base()
    d.insert_before("AFTER_MATS", ogden(M=2))
    return d, "/MAT/OGDEN/3 M = 2 Prony terms (the visco-elastic part is not implemented)", [("RX510", "OG.M")]


@fault("ogden_bulk_function")
def _():
    d = base()
    d.insert_before("AFTER_MATS", ogden(fct_IDbulk=5))
    return d, "/MAT/OGDEN/3 fct_IDbulk = 5 (the tabulated bulk modulus is not implemented)", \
        [("RX510", "OG.fct_IDbulk")]


@fault("ogden_no_shear")
def _():
    d = base()
    d.insert_before("AFTER_MATS", ogden(mu_1=0.8, alpha_1=2.0, mu_2=0.9, alpha_2=-2.0))
    return d, "/MAT/OGDEN/3 sum mu_p alpha_p = 1.6 - 1.8 < 0 (no initial shear stiffness)", [("RX507", "OG.mu_1")]


@fault("ogden_zero_exponent")
def _():
    d = base()
    d.insert_before("AFTER_MATS", ogden(mu_3=0.1, alpha_3=0.0))
    return d, "/MAT/OGDEN/3 mu_3 = 0.1 with alpha_3 = 0 (undefined energy mu_p / alpha_p)", [("RX507", "OG.alpha_3")]


@fault("ogden_incompressible")
def _():
    d = base()
    d.insert_before("AFTER_MATS", ogden(nu=0.5))
    return d, "/MAT/OGDEN/3 nu = 0.5 (infinite bulk modulus; radx asks for the value meant)", [("RX503", "OG.nu")]


@fault("ogden_on_shells")
def _():
    d = base()
    d.insert_before("AFTER_MATS", ogden())
    d.update("PART1", mat_ID=3)
    return d, "/MAT/OGDEN/3 on the shell part 1 (law 42 runs on one-point bricks only)", [("RX510", "OG_KW")]


@fault("ogden_heph")
def _():
    d = base()
    d.insert_before("AFTER_MATS", ogden())
    d.update("PART2", mat_ID=3)
    d.update("PSO", Isolid=24)
    return d, "/MAT/OGDEN/3 on bricks of Isolid 24 (law 42 runs on Isolid 1 and 2 only)", [("RX510", "PSO.Isolid")]


def foam(mid=3, load=((7, 0.0, 1.0),), unload=(), points=((0.0, 0.0), (0.5, 0.2), (0.8, 1.0)), **kw):
    """/MAT/FOAM_TAB/mid (tag FO; loading curves on /FUNCT/7, tag F7) before AFTER_MATS; no part uses it."""
    values = dict(RHO_I=5e-11, E0=20.0, nu=0.0, E_max=0.0, Eps_max=0.0, Nload=len(load), Nunload=len(unload),
                  Iflag=0, fill=0)
    for k, (fid, rate, scale) in enumerate(load):
        values.update({"fct_L%d" % (k + 1): fid, "rate_L%d" % (k + 1): rate, "scale_L%d" % (k + 1): scale})
    for k, (fid, rate, scale) in enumerate(unload):
        values.update({"fct_U%d" % (k + 1): fid, "rate_U%d" % (k + 1): rate, "scale_U%d" % (k + 1): scale})
    values.update(kw)
    return (block("FO", "/MAT/FOAM_TAB", mid, "Foam (tabulated)", **values) +
            funct_rows(7, list(points), "Foam loading curve", tag="F7"))


@fault("foam_on_shells")
def _():
    d = base()
    d.insert_before("AFTER_MATS", foam())
    d.update("PART1", mat_ID=3)
    return d, "/MAT/FOAM_TAB/3 on the shell part 1 (law 70 runs on one-point bricks only)", [("RX510", "FO_KW")]


@fault("foam_heph")
def _():
    d = base()
    d.insert_before("AFTER_MATS", foam())
    d.update("PART2", mat_ID=3)
    d.update("PSO", Isolid=24)
    return d, "/MAT/FOAM_TAB/3 on bricks of Isolid 24 (law 70 runs on Isolid 1 and 2 only)", [("RX510", "PSO.Isolid")]


@fault("foam_same_rates")
def _():
    d = base()
    d.insert_before("AFTER_MATS", foam(load=((7, 0.0, 1.0), (7, 0.0, 2.0))))
    return d, "/MAT/FOAM_TAB/3 two loading curves at the same strain rate 0", [("RX507", "FO.rate_L2")]


@fault("foam_missing_function")
def _():
    d = base()
    d.insert_before("AFTER_MATS", foam(load=((99, 0.0, 1.0),)))
    return d, "/MAT/FOAM_TAB/3 fct_L1 = 99 names no /FUNCT", [("RX402", "FO.fct_L1")]


@fault("rigid_no_density")
def _():
    d = base()
    d.insert_before("AFTER_MATS", block("RIG", "/MAT/RIGID", 3, "Rigid steel", RHO_I=0.0, E=210000.0, nu=0.3))
    return d, "/MAT/RIGID/3 RHO_I = 0 (its rigid body would have no mass)", [("RX502", "RIG.RHO_I")]


@fault("rigid_no_young")
def _():
    d = base()
    d.insert_before("AFTER_MATS", block("RIG", "/MAT/RIGID", 3, "Rigid steel", RHO_I=7.85e-9, E=0.0, nu=0.3))
    return d, "/MAT/RIGID/3 E = 0 (OpenRadioss refuses it too: the contact stiffness)", [("RX502", "RIG.E")]


@fault("void_poisson_half")
def _():
    d = base()
    d.insert_before("AFTER_MATS", block("VOID", "/MAT/VOID", 3, "Void", RHO_I=0.0, E=1000.0, nu=0.5))
    return d, "/MAT/VOID/3 nu = 0.5 (its contact bulk modulus E/3(1-2nu) would be infinite)", [("RX503", "VOID.nu")]


@fault("fail_johnson_on_elastic")
def _():
    d = base()
    d.insert_before("AFTER_MATS", block("FJ", "/FAIL/JOHNSON", 2, D1=0.1, D2=0.2, D3=-1.5))
    return d, "/FAIL/JOHNSON/2 on the elastic /MAT/LAW1/2 (radx: laws 2 and 36 only)", [("RX510", "FJ_KW")]


@fault("fail_johnson_twice")
def _():
    d = base()
    d.insert_before("AFTER_MATS", block("FJA", "/FAIL/JOHNSON", 1, D1=0.1) + block("FJB", "/FAIL/JOHNSON", 1, D1=0.2))
    return d, "two /FAIL/JOHNSON on /MAT/PLAS_JOHNS/1", [("RX401", "FJB_KW")]


def fail_tab(mid=1, tag="FT", **kw):
    """/FAIL/TAB/mid (tag FT) with one eps_f(triaxiality) function /FUNCT/8 (tag F8) unless the values say
    otherwise, before AFTER_MATS."""
    values = dict(Ifail_sh=1, Ifail_so=1, N_rate=1, Dcrit=1.0, n=1.0, fct_ID1=8, Fscale1=1.0, Epsdot1=0.0)
    values.update(kw)
    return (block(tag, "/FAIL/TAB", mid, **values) +
            funct_rows(8, [(-1.0, 0.5), (1.0, 0.2)], "Failure strain", tag="F8"))


@fault("fail_tab_on_elastic")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_tab(2))
    return d, "/FAIL/TAB/2 on the elastic /MAT/LAW1/2 (radx: laws 2 and 36 only)", [("RX510", "FT_KW")]


@fault("fail_tab_missing_function")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_tab(fct_ID1=99))
    return d, "/FAIL/TAB/1 fct_ID1 = 99 names no /FUNCT", [("RX402", "FT.fct_ID1")]


@fault("fail_tab_missing_size_function")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_tab(fct_IDel=98, EI_ref=1.0))
    return d, "/FAIL/TAB/1 fct_IDel = 98 (element size factor) names no /FUNCT", [("RX402", "FT.fct_IDel")]


@fault("fail_tab_temperature")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_tab(fct_IDt=9) +
                    funct_rows(9, [(0.0, 1.0), (1000.0, 0.5)], "Temperature factor", tag="F9"))
    return d, ("/FAIL/TAB/1 with a temperature factor that varies (radx has no temperature: a constant "
               "function only)"), [("RX510", "FT.fct_IDt")]


@fault("fail_tab_solid_exponent")
def _():
    d = base()
    d.update("PART2", mat_ID=1)
    d.insert_before("AFTER_MATS", fail_tab(n=2.0))
    return d, ("/FAIL/TAB/1 with n = 2 on the brick's part (OpenRadioss's solids take n D^(1-1/n) with the "
               "card's D)"), [("RX510", "FT.n")]


@fault("fail_tab_xfem")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_tab(Ixfem=1))
    return d, "/FAIL/TAB/1 Ixfem = 1 (XFEM crack)", [("RX510", "FT.Ixfem")]


@fault("fail_tab_negative_thickness")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_tab(P_thickfail=-0.5, Ifail_sh=2))
    return d, "/FAIL/TAB/1 P_thickfail < 0 (a fraction of failed points)", [("RX510", "FT.P_thickfail")]


@fault("fail_tab_twice")
def _():
    d = base()
    d.insert_before("AFTER_MATS", block("FJ", "/FAIL/JOHNSON", 1, D1=0.1) + fail_tab())
    return d, "/FAIL/JOHNSON and /FAIL/TAB on /MAT/PLAS_JOHNS/1 (one failure model per material)", \
        [("RX401", "FT_KW")]


def fail_biquad(mid=1, tag="FB", **kw):
    """/FAIL/BIQUAD/mid (tag FB) with C1..C5 given (S_Flag 2) unless the values say otherwise, before
    AFTER_MATS."""
    values = dict(C1=0.9, C2=0.45, C3=0.3, C4=0.2, C5=0.35, P_thickfail=0.0, M_Flag=0, S_Flag=0, Inst_start=0.0)
    values.update(kw)
    return block(tag, "/FAIL/BIQUAD", mid, **values)


def size_function():
    return funct_rows(8, [(0.0, 1.2), (10.0, 0.8)], "Element size factor", tag="F8")


@fault("fail_biquad_on_elastic")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_biquad(2))
    return d, "/FAIL/BIQUAD/2 on the elastic /MAT/LAW1/2 (radx: laws 2 and 36 only)", [("RX510", "FB_KW")]


@fault("fail_biquad_s_flag_range")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_biquad(S_Flag=5))
    return d, "/FAIL/BIQUAD/1 S_Flag = 5 (accepted: 0 to 3)", [("RX501", "FB.S_Flag")]


@fault("fail_biquad_softening")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_biquad(ICOUP=1, DCRIT=0.5, EXP=2.0))
    return d, "/FAIL/BIQUAD/1 ICOUP = 1 (stress softening from DCRIT)", [("RX510", "FB.ICOUP")]


@fault("fail_biquad_necking_softening")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_biquad(S_Flag=3, Inst_start=0.1, ICOUP=2, EXP=2.0))
    return d, ("/FAIL/BIQUAD/1 ICOUP = 2 with S_Flag 3 (stress softening from the necking instability)"), \
        [("RX510", "FB.ICOUP")]


@fault("fail_biquad_dcrit")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_biquad(DCRIT=0.5))
    return d, "/FAIL/BIQUAD/1 DCRIT = 0.5 with ICOUP 0 (Radioss then softens with ICOUP 1)", \
        [("RX510", "FB.DCRIT")]


@fault("fail_biquad_ireg")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_biquad(Ireg=2, fct_IDel=8, EI_ref=1.0) + size_function())
    return d, "/FAIL/BIQUAD/1 Ireg = 2 (the size factor weighted by the triaxiality)", [("RX510", "FB.Ireg")]


@fault("fail_biquad_negative_thickness")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_biquad(P_thickfail=-0.5))
    return d, "/FAIL/BIQUAD/1 P_thickfail < 0 (a fraction of failed points)", [("RX510", "FB.P_thickfail")]


@fault("fail_biquad_missing_size_function")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_biquad(fct_IDel=98, EI_ref=1.0))
    return d, "/FAIL/BIQUAD/1 fct_IDel = 98 (element size factor) names no /FUNCT", [("RX402", "FB.fct_IDel")]


@fault("fail_biquad_solid_size")
def _():
    d = base()
    d.update("PART2", mat_ID=1)
    d.insert_before("AFTER_MATS", fail_biquad(fct_IDel=8, EI_ref=1.0) + size_function())
    return d, "/FAIL/BIQUAD/1 with an element size function on the brick's part (radx: shells only)", \
        [("RX510", "FB.fct_IDel")]


@fault("fail_biquad_twice")
def _():
    d = base()
    d.insert_before("AFTER_MATS", fail_tab() + fail_biquad())
    return d, "/FAIL/TAB and /FAIL/BIQUAD on /MAT/PLAS_JOHNS/1 (one failure model per material)", \
        [("RX401", "FB_KW")]


@fault("funct_not_increasing")
def _():
    d = base()
    rows = funct_rows(1, [(0.0, 0.0), (0.001, 1.0), (0.0005, 1.0), (0.01, 1.0)], "Gravity ramp")
    rows += block("GRAV", "/GRAV", 1, "Gravity through /FUNCT/1", funct_IDT=1, DIR="Z", Fscale_y=-9810.0, fill=0)
    d.insert_before("BEFORE_END", rows)
    return d, "/FUNCT/1: the third X (0.0005) is below the second (0.001)", [("RX505", "F_P3")]


def impvel_rows(funct, keyword="/IMPVEL", direction="Z", sensor=0):
    return block_group() + block("IMP", keyword, 1, "Block pushed down", funct_IDT=funct, Dir=direction,
                                 sensor_ID=sensor, grnod_ID=2, Fscale_y=-1000.0, fill=0)


@fault("impvel_no_function")
def _():
    d = base()
    d.insert_before("BEFORE_END", impvel_rows(0))
    return d, "/IMPVEL/1 with funct_IDT = 0 (a function is required)", [("RX502", "IMP.funct_IDT")]


@fault("impvel_missing_function")
def _():
    d = base()
    d.insert_before("BEFORE_END", impvel_rows(99))
    return d, "/IMPVEL/1 names function 99, which does not exist", [("RX402", "IMP.funct_IDT")]


@fault("impdisp_missing_function")
def _():
    d = base()
    d.insert_before("BEFORE_END", impvel_rows(99, "/IMPDISP"))
    return d, "/IMPDISP/1 names function 99, which does not exist", [("RX402", "IMP.funct_IDT")]


@fault("impdisp_rotation")
def _():
    d = base()
    d.insert_before("BEFORE_END", impvel_rows(7, "/IMPDISP", "ZZ")
                    + funct_rows(7, [(0.0, 0.0), (0.002, 0.1)], "Rotation angle"))
    return d, "/IMPDISP/1 Dir = ZZ: an imposed rotation angle (radx imposes translations only)", \
        [("RX510", "IMP.Dir")]


def sensor_rows(sid, t_delay, t_stop, tag="SENS"):
    """/SENSOR/TIME/sid (tag SENS)."""
    return block(tag, "/SENSOR/TIME", sid, "Timer", Tdelay=t_delay, Tstop=t_stop)


@fault("sensor_missing")
def _():
    d = with_rows(impvel_rows(7, sensor=9), funct_rows(7, [(0.0, 0.0), (0.002, 1.0)], "Speed"))
    return d, "/IMPVEL/1 is started by sensor 9; the deck has no /SENSOR/9", [("RX402", "IMP.sensor_ID")]


@fault("sensor_unsupported_type")
def _():
    rows = [("/SENSOR/DIST/5", "SD_KW"), "Distance sensor"] + foreign(
        (rc.Card(rc.r("Tdelay")), [0.0]),
        (rc.Card(rc.i("node_ID1"), rc.i("node_ID2"), rc.r("Dmin"), rc.r("Dmax")), [1, 2, 0.0, 5.0]))
    return with_rows(rows), "/SENSOR/DIST/5: of the sensors radx reads /SENSOR/TIME only", [("RX302", "SD_KW")]


@fault("sensor_tstop_before_tdelay")
def _():
    d = with_rows(sensor_rows(3, 0.002, 0.001))
    return d, "/SENSOR/TIME/3 switches off (Tstop 0.001) before it switches on (Tdelay 0.002)", \
        [("RX507", "SENS.Tstop")]


@fault("rbody_sensor_tstop")
def _():
    rows = sensor_rows(4, 0.001, 0.002) + block_group() + block("N99", "/NODE", rows=[(99, 5.0, 5.0, 10.0)])
    rows += block("RB", "/RBODY", 1, "Block released by sensor 4", node_ID=99, sens_ID=4, grnd_ID=2, fill=0)
    return with_rows(rows), \
        "/RBODY/1 is released by /SENSOR/TIME/4, which switches off again (Tstop): radx does not form the body again", \
        [("RX510", "RB.sens_ID")]


@fault("rbody_ioptoff")
def _():
    rows = block_group() + block("N99", "/NODE", rows=[(99, 5.0, 5.0, 10.0)])
    rows += block("RB", "/RBODY", 1, "Block whose elements would be switched off", node_ID=99, grnd_ID=2,
                  Ioptoff=1, fill=0)
    return with_rows(rows), \
        "/RBODY/1 asks Ioptoff = 1 (its elements not computed), which radx does not implement", \
        [("RX510", "RB.Ioptoff")]


@fault("rbody_no_inertia")
def _():
    rows = block("N99", "/NODE", rows=[(99, 5.0, 5.0, 10.0)])
    rows += block("G7", "/GRNOD/NODE", 7, "The main node only", ids=[99])
    rows += block("RB", "/RBODY", 1, "Main node alone", node_ID=99, Mass=1e-3, grnd_ID=7, fill=0)
    return with_rows(rows), \
        "/RBODY/1's group holds only its main node (a warning): no secondary node, no added inertia and a main " \
        "node of no element, so it cannot turn (Radioss's error 274)", \
        [("RX403 warning", "RB.grnd_ID"), ("RX502", "RB.grnd_ID")]


@fault("inter_missing_surface")
def _():
    return with_inter(base(), surf=99), "/INTER/TYPE7/1 names surface 99, which does not exist", \
        [("RX402", "INT.surf_IDm")]


@fault("inter_missing_group")
def _():
    return with_inter(base(), grnod=99), "/INTER/TYPE7/1 names node group 99, which does not exist", \
        [("RX402", "INT.grnd_IDs")]


def type2(grnod=3, surf=1, spotflag=0, tag="T2", iid=1, group=True, idel2=0):
    """A /INTER/TYPE2 (tag T2) tying the block's bottom nodes (/GRNOD/NODE/3: 11 12 13 14, 1.5 mm above the
    plate) to the plate surface (/SURF/PART/1), with those two in front (group=False: not again)."""
    rows = []
    if group:
        rows += block("GRN3", "/GRNOD/NODE", 3, "Block bottom nodes", ids=[11, 12, 13, 14])
        rows += block("SURF1", "/SURF/PART", 1, "Plate surface", ids=[1])
    return rows + block(tag, "/INTER/TYPE2", iid, "Block bottom tied to plate", grnd_IDs=grnod, surf_IDm=surf,
                        Ignore=0, Spotflag=spotflag, Level=0, Isearch=0, Idel2=idel2, Dsearch=0.0)


def with_type2(d, **kw):
    d.insert_before("BEFORE_END", type2(**kw))
    return d


@fault("type2_missing_group")
def _():
    return with_type2(base(), grnod=99), "/INTER/TYPE2/1 names node group 99, which does not exist", \
        [("RX402", "T2.grnd_IDs")]


@fault("type2_missing_surface")
def _():
    return with_type2(base(), surf=99), "/INTER/TYPE2/1 names surface 99, which does not exist", \
        [("RX402", "T2.surf_IDm")]


@fault("type2_spotflag_7")
def _():
    return with_type2(base(), spotflag=7), "/INTER/TYPE2/1 Spotflag = 7 (not a TYPE2 formulation)", \
        [("RX501", "T2.Spotflag")]


@fault("type2_spotflag_3")
def _():
    return with_type2(base(), spotflag=3), \
        "/INTER/TYPE2/1 Spotflag = 3 (the rigid tie with its own mass update, refused by name; radx runs 1)", \
        [("RX510", "T2.Spotflag")]


@fault("type2_spotflag_1_idel2")
def _():
    return with_type2(base(), spotflag=1, idel2=1), \
        "/INTER/TYPE2/1 Spotflag = 1 (the rigid tie, run) with Idel2 = 1 (release on deletion, refused by name)", \
        [("RX510", "T2.Idel2")]


@fault("type2_node_tied_twice")
def _():
    d = with_type2(base())
    d.insert_before("BEFORE_END", type2(tag="T2B", iid=2, group=False))
    return d, "/INTER/TYPE2/1 and /INTER/TYPE2/2 tie the same nodes 11 12 13 14", [("RX706", "T2B.grnd_IDs")]


@fault("istf_7")
def _():
    return with_inter(base(), istf=7), "/INTER/TYPE7/1 Istf = 7 (0..5 allowed)", [("RX501", "INT.Istf")]


@fault("igap_3")
def _():
    return with_inter(base(), igap=3), "/INTER/TYPE7/1 Igap = 3 (0, 1, 2 and 1000 allowed)", [("RX501", "INT.Igap")]


@fault("istf1_stfac_zero")
def _():
    return with_inter(base(), istf=1, stfac=0.0), \
        "/INTER/TYPE7/1 Istf = 1 (stiffness given in Stfac) with Stfac = 0", [("RX502", "INT.Stfac")]


@fault("inter_tstop_before_tstart")
def _():
    return with_inter(base(), tstart=0.001, tstop=0.0005), "/INTER/TYPE7/1 Tstart = 0.001, Tstop = 0.0005", \
        [("RX507", "INT.Tstop")]


@fault("inacti_4")
def _():
    return with_inter(base(), inacti=4), "/INTER/TYPE7/1 Inacti = 4 (0, 1, 2, 3, 5, 6 allowed)", \
        [("RX501", "INT.Inacti")]


@fault("lagdt_inacti_4")
def _():
    return with_inter(base(), inacti=4, lagdt=True), \
        "/INTER/LAGDT/TYPE7/1 Inacti = 4 (0, 1, 2, 3, 5, 6 allowed)", [("RX501", "INT.Inacti")]


@fault("ifric_4")
def _():
    return with_inter(base(), ifric=4), \
        "/INTER/TYPE7/1 Ifric = 4 (0..3 allowed); no C1..C6 cards follow", [("RX501", "INT.Ifric")]


@fault("ifric3_c5_zero")
def _():
    return with_inter(base(), ifric=3, ccards=(0.2, 0.15, 0.3, 0.1, 0.0, 2.0)), \
        "/INTER/TYPE7/1 Renard friction (Ifric 3) with C5 = V_cr1 = 0", [("RX703", "INT.C5")]


def ctclaw_rows(law_lines, lid=3, inter=1):
    """A /CTCLAW/lid on interface `inter` (tag CTC); its law-string lines are CTC.law, CTC.law.2, ..."""
    return block("CTC", "/CTCLAW", lid, "Contact law", inter_ID=inter, law=law_lines)


def with_law(law_lines, extra=()):
    d = with_inter(base())
    d.insert_before("BEFORE_END", ctclaw_rows(law_lines) + list(extra))
    return d


@fault("ctclaw_unknown_parameter")
def _():
    return with_law(["n1s13{Kc1e3,Mu0.1,", "CtLin1e3,Foo3}"]), \
        "/CTCLAW/3 on /INTER/TYPE7/1: unknown parameter Foo on the second line of the law string", \
        [("RX704", "CTC.law.2")]


@fault("ctclaw_missing_parameter")
def _():
    return with_law(["n1s2{Kc1e3,Mu0.2}"]), \
        "/CTCLAW/3: friction law s2 (linear regularised Coulomb) without its slope CtLin", [("RX704", "CTC.law")]


@fault("ctclaw_lambda_and_pe")
def _():
    return with_law(["n2{pz1e5,lambda2e3,pe1e6}"]), \
        "/CTCLAW/3: exponential law n2 with both lambda and pe (exclusive)", [("RX704", "CTC.law")]


@fault("ctclaw_negative_value")
def _():
    return with_law(["n1s1{Kc1e3,Mu-0.2}"]), "/CTCLAW/3: friction coefficient Mu = -0.2", \
        [("RX704", "CTC.law")]


@fault("ctclaw_kcmax_below_initial")
def _():
    return with_law(["n2{pz1e5,lambda2e3,KcMax1e6}"]), \
        "/CTCLAW/3: KcMax = 1e6 below the initial stiffness lambda pz = 2e8", [("RX704", "CTC.law")]


@fault("ctclaw_unknown_law")
def _():
    return with_law(["n7s13{Kc1,Mu0.1,CtLin1}"]), "/CTCLAW/3: normal law n7 (n1..n4 exist)", \
        [("RX704", "CTC.law")]


@fault("ctclaw_missing_curve")
def _():
    return with_law(["n3s1{CurveID12,Mu0.1}"], funct_rows(11, [(-0.1, 100.0), (0.0, 0.0)], "Gap to pressure")), \
        "/CTCLAW/3: tabulated law n3 names /FUNCT/12; only /FUNCT/11 exists", [("RX704", "CTC.law")]


@fault("ishell_3_elastoplastic_hourglass")
def _():
    d = base()
    d.update("PSH", Ishell=3)
    return d, "/PROP/SHELL/1 Ishell = 3 (Belytschko-Tsay with elasto-plastic hourglass) on the plate's 4-node " \
        "shells: radx implements Ishell 1, 4, 12 and 24 only (--allow-substitutions would run Ishell 1 and list it)", \
        [("RX510", "PSH.Ishell")]


@fault("isolid_16_from_def_solid")
def _():
    d = base()
    d.insert_before("PSO_KW", block("DEFS", "/DEF_SOLID", Isolid=16, Ismstr=0, Icpre=0))
    d.update("PSO", Isolid=0)
    return d, "/PROP/SOLID/2 leaves Isolid 0 and /DEF_SOLID sets 16 (20-node quadratic): the block's brick " \
        "would run a formulation radx lacks", [("RX510", "PSO.Isolid")]


@fault("heph_icpre_2")
def _():
    d = base()
    d.update("PSO", Isolid=24, Icpre=2)
    return d, "/PROP/SOLID/2 Isolid 24 (HEPH) with Icpre = 2 (pressure from the plastic state): radx implements " \
        "HEPH with Icpre 0, 1 and 3 only", [("RX510", "PSO.Icpre")]


@fault("solid_numerical_viscosity")
def _():
    d = base()
    d.update("PSO", LAMBDA_V=0.01)
    return d, "/PROP/SOLID/2 numerical viscosity Lambda = 0.01: read but not implemented, and it changes " \
        "the physics", [("RX510", "PSO.LAMBDA_V")]


@fault("bcs_missing_skew")
def _():
    d = base()
    d.update("BCS", skew_ID=5)
    return d, "/BCS/1 names skew 5, and the deck has no /SKEW/FIX/5", [("RX402", "BCS.skew_ID")]


def skew_fix_rows(y_axis, title):
    """/SKEW/FIX/5 at the origin with Y' = y_axis and Z' = (0, 0, 1) (tag SKW)."""
    return block("SKW", "/SKEW/FIX", 5, title, Ox=0.0, Oy=0.0, Oz=0.0, X1=y_axis[0], Y1=y_axis[1], Z1=y_axis[2],
                 X2=0.0, Y2=0.0, Z2=1.0)


@fault("skew_parallel_axes")
def _():
    d = base()
    d.insert_before("BCS_KW", skew_fix_rows((0.0, 0.0, 2.0), "Degenerate frame"))
    d.update("BCS", skew_ID=5)
    return d, "/SKEW/FIX/5 with Y' = (0, 0, 2) parallel to Z' = (0, 0, 1): no frame", [("RX507", "SKW.X2")]


def skew_mov_rows(n1, n2, n3, direction="", sid=5, title="Frame on plate nodes"):
    """/SKEW/MOV/<sid> (2019 layout and newer: N1 N2 N3 Dir), tag SKM."""
    return block("SKM", "/SKEW/MOV", sid, title, N1=n1, N2=n2, N3=n3, Dir=direction)


def with_moving_skew(n1, n2, n3, direction=""):
    """The base model with /SKEW/MOV/5 before /BCS/1, which holds the plate in it."""
    d = base()
    d.insert_before("BCS_KW", skew_mov_rows(n1, n2, n3, direction))
    d.update("BCS", skew_ID=5)
    return d


@fault("skew_mov_missing_node")
def _():
    return with_moving_skew(1, 2, 99), "/SKEW/MOV/5 names N3 = 99, which does not exist", [("RX402", "SKM.N3")]


@fault("skew_mov_repeated_node")
def _():
    return with_moving_skew(1, 2, 1), "/SKEW/MOV/5 with N3 = N1 = 1: three distinct nodes are needed", \
        [("RX507", "SKM.N1")]


@fault("skew_mov_coincident_nodes")
def _():
    d = with_moving_skew(1, 19, 4)
    d.insert_after("NODE_18", [node_line(19, 0.0, 0.0, 0.0)])
    return d, "/SKEW/MOV/5: N2 = 19 sits on N1 = 1 at (0, 0, 0), so N1 -> N2 has no direction", \
        [("RX507", "SKM.N1")]


@fault("skew_mov_collinear_nodes")
def _():
    return with_moving_skew(1, 2, 3), "/SKEW/MOV/5 on nodes 1, 2, 3, which lie on the line y = 0: no plane", \
        [("RX507", "SKM.N1")]


@fault("skew_mov_bad_dir")
def _():
    return with_moving_skew(1, 2, 4, "W"), "/SKEW/MOV/5 Dir = W (X, Y or Z, blank = X)", [("RX501", "SKM.Dir")]


@fault("skew_duplicate_id")
def _():
    d = base()
    d.insert_before("BCS_KW", skew_fix_rows((0.0, 1.0, 0.0), "Fixed frame") + skew_mov_rows(1, 2, 4))
    d.update("BCS", skew_ID=5)
    return d, "/SKEW/FIX/5 and /SKEW/MOV/5: skews share one id space", [("RX401", "SKM_KW")]


def th_rows(path, title, variables, objects=(), records=None):
    """A /TH group with id 1 (tag TH): its variables, then the objects, one per line (records: "id" for
    /TH/BRIC, "id+skew" for /TH/SH3N, or (id, skew) pairs) or ids 10 per line; the last object line is also
    tagged TH_OBJ."""
    if records == "id":
        kw = dict(rows=[(x,) for x in objects])
    elif records == "id+skew":
        kw = dict(rows=[(x, 0) for x in objects])
    elif records is not None:
        kw = dict(rows=records)
    else:
        kw = dict(ids=objects)
    return tag_last(block("TH", path, 1, title, variables=variables, **kw), "TH_OBJ")


@fault("th_bric_missing_brick")
def _():
    d = base()
    d.insert_before("BEFORE_END", th_rows("/TH/BRIC", "Brick stresses", ["SX", "SY", "SZ"], [11, 99], "id"))
    return d, "/TH/BRIC/1 lists brick 11 and brick 99, which does not exist", [("RX402", "TH_OBJ")]


@fault("th_bric_tetra")
def _():
    d = with_tetra(base())
    d.insert_before("BEFORE_END", th_rows("/TH/BRIC", "Solid stresses", ["SX", "SY", "SZ"], [11, 21], "id"))
    return d, "/TH/BRIC/1 lists brick 11 and tetrahedron 21 (Radioss records it as a brick): radx writes no time " \
        "history of tetrahedra and goes on without it (a warning)", [("RX311 warning", "TH_OBJ")]


@fault("th_sh3n_missing_element")
def _():
    d = base()
    d.insert_before("BEFORE_END", th_rows("/TH/SH3N", "Triangles", ["DEF"], [1], "id+skew"))
    return d, "/TH/SH3N/1 lists element 1, a 4-node /SHELL: no /SH3N defines it", [("RX402", "TH_OBJ")]


@fault("th_node_missing_skew")
def _():
    d = base()
    d.insert_before("BEFORE_END", th_rows("/TH/NODE", "Plate corner in a skew", ["DEF"], records=[(1, 7)]))
    return d, "/TH/NODE/1 lists node 1 in skew 7, and the deck has no /SKEW/FIX/7 or /SKEW/MOV/7", \
        [("RX402", "TH_OBJ")]


def frame_rows(keyword, fid=7, title="Frame", **fields):
    """/FRAME/FIX or /FRAME/MOV with id fid (tag FRF or FRM): the cards of /SKEW/FIX and /SKEW/MOV."""
    return block("FRF" if keyword == "/FRAME/FIX" else "FRM", keyword, fid, title, **fields)


def frame_fix_rows(fid=7, y_axis=(0.0, 1.0, 0.0), title="Fixed frame"):
    """/FRAME/FIX/fid at (1, 2, 3) with Y' = y_axis and Z' = (0, 0, 1) (tag FRF)."""
    return frame_rows("/FRAME/FIX", fid, title, Ox=1.0, Oy=2.0, Oz=3.0, X1=y_axis[0], Y1=y_axis[1], Z1=y_axis[2],
                      X2=0.0, Y2=0.0, Z2=1.0)


@fault("th_node_moving_frame")
def _():
    # Radioss writes a node in a /FRAME/MOV relative to the moving frame (its velocity and rotation taken out).
    d = with_rows(frame_rows("/FRAME/MOV", 7, "Frame on plate nodes", N1=1, N2=2, N3=4, Dir=""),
                  th_rows("/TH/NODE", "Plate corner in a moving frame", ["DEF"], records=[(1, 7)]))
    return d, "/TH/NODE/1 lists node 1 in /FRAME/MOV/7: radx does not write motion relative to a moving frame", \
        [("RX509", "TH_OBJ")]


@fault("frame_skew_duplicate_id")
def _():
    d = base()
    d.insert_before("BCS_KW", skew_fix_rows((0.0, 1.0, 0.0), "Fixed skew") + frame_fix_rows(5))
    return d, "/SKEW/FIX/5 and /FRAME/FIX/5: skews and frames share one id space", [("RX401", "FRF_KW")]


@fault("bcs_skew_names_frame")
def _():
    d = base()
    d.insert_before("BCS_KW", frame_fix_rows(5))
    d.update("BCS", skew_ID=5)
    return d, "/BCS/1 skew_ID = 5 names /FRAME/FIX/5: Radioss reads a /BCS skew_ID as a skew only", \
        [("RX402", "BCS.skew_ID")]


@fault("impvel_in_frame")
def _():
    d = with_rows(frame_fix_rows(7), impvel_rows(7), funct_rows(7, [(0.0, 0.0), (0.002, 1.0)], "Speed"))
    d.update("IMP", frame_ID=7)
    return d, "/IMPVEL/1 frame_ID = 7: radx does not impose a velocity relative to a frame", \
        [("RX510", "IMP.frame_ID")]


@fault("frame_fix_zero_axis")
def _():
    # A skew's Y' of (0, 0, 0) is taken as (0, 1, 0); a frame's is used as given (OpenRadioss hm_read_frm.F).
    d = with_rows(frame_fix_rows(7, (0.0, 0.0, 0.0), "Frame without Y'"))
    return d, "/FRAME/FIX/7 with Y' = (0, 0, 0): no frame", [("RX507", "FRF.X2")]


@fault("frame_mov_collinear_nodes")
def _():
    d = with_rows(frame_rows("/FRAME/MOV", 7, "Frame on a line", N1=1, N2=2, N3=3, Dir=""))
    return d, "/FRAME/MOV/7 on nodes 1, 2, 3, which lie on the line y = 0: no plane", [("RX507", "FRM.N1")]


@fault("th_shel_in_skew")
def _():
    d = base()
    d.insert_before("BEFORE_END", skew_mov_rows(1, 2, 4) + th_rows("/TH/SHEL", "Shell in a skew", ["DEF"],
                                                                    records=[(1, 5)]))
    return d, "/TH/SHEL/1 lists shell 1 in skew 5: radx writes shell results in the element frame only", \
        [("RX509", "TH_OBJ")]


@fault("th_rbody_missing_rbody")
def _():
    d = base()
    d.insert_before("BEFORE_END", th_rows("/TH/RBODY", "Rigid bodies", ["DEF"], [5]))
    return d, "/TH/RBODY/1 lists rigid body 5, which does not exist (the deck has no /RBODY): left out with a " \
        "warning, as Radioss does (its 257)", [("RX402 warning", "TH_OBJ")]


@fault("th_bric_unknown_variable")
def _():
    d = base()
    d.insert_before("BEFORE_END", th_rows("/TH/BRIC", "Brick with a shell variable", ["SZ", "F1"], [11], "id"))
    return d, "/TH/BRIC/1 asks for F1, a shell variable, not a brick one (error at the keyword line)", \
        [("RX501", "TH_KW")]


@fault("th_spring_group_name")
def _():
    d = with_spring(base())
    d.insert_before("BEFORE_END", th_rows("/TH/SPRING", "Spring forces", ["DEF", "F"], [31], "id"))
    return d, "/TH/SPRING/1 asks for F: DEF is /TH/SPRING's only group name (OpenRadioss refuses F, M, L and R " \
        "there too); name FX FY FZ one by one", [("RX501", "TH_KW")]


@fault("th_rbody_no_variables")
def _():
    d = base()
    d.insert_before("BEFORE_END", [("/TH/RBODY/1", "TH_KW"), "Rigid bodies without variables"])
    return d, "/TH/RBODY/1 ends after its title: no variable line (and no object)", [("RX502", "TH_KW")]


@fault("rwall_sphere_no_diameter")
def _():
    d = base()
    d.insert_before("BEFORE_END", block("RWS", "/RWALL/SPHER", 1, "Sphere without a diameter", node_ID=0, Slide=0,
                                        grnd_ID1=1, grnd_ID2=0, Iform=0, d=0.0, Diameter=0.0, XM=0.0, YM=0.0,
                                        ZM=-50.0))
    return d, "/RWALL/SPHER/1 with Diameter = 0: a sphere wall needs a diameter", [("RX502", "RWS.Diameter")]


def rwall_paral_rows(m2):
    """A fixed /RWALL/PARAL of corner M = (0, 0, -50) and edges to M1 = (100, 0, -50) and M2, on node group 1."""
    return block("RWP", "/RWALL/PARAL", 1, "Parallelogram wall", node_ID=0, Slide=0, grnd_ID1=1, grnd_ID2=0, Iform=0,
                 d=0.0, XM=0.0, YM=0.0, ZM=-50.0, XM1=100.0, YM1=0.0, ZM1=-50.0, XM2=m2[0], YM2=m2[1], ZM2=m2[2])


@fault("rwall_paral_aligned_corners")
def _():
    d = base()
    d.insert_before("BEFORE_END", rwall_paral_rows((50.0, 0.0, -50.0)))
    return d, "/RWALL/PARAL/1: M2 on the line M M1, so the parallelogram has no area and no normal", \
        [("RX507", "RWP.XM2")]


def fgeo_rows(part=0, node=2):
    """/IMPDISP/FGEO/1 through /FUNCT/1: the plate's node `node` to (12, 0, 0) and node 3 to (20, 0, 5)."""
    return funct_rows(1, [(0.0, 0.0), (0.01, 1.0)]) + block(
        "FG", "/IMPDISP/FGEO", 1, "Final geometry", fct_ID=1, part_ID=part, sens_ID=0, Ascale=1.0, Tstart=0.0,
        Tstop=0.0, rows=[(node, 12.0, 0.0, 0.0), (3, 20.0, 0.0, 5.0)], row_tags=["FG_N1", "FG_N2"])


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
        [("RX509", "FG.part_ID")]


# Element groups and the surfaces and node groups built from them. The base model has shells 1 and 2
# (part 1), brick 11 (part 2) and no 3-node shell.


def id_list(head, tag, title, ids):
    """A keyword (head: keyword/id) with a title and a list of ids; the first id line is TAG.ids."""
    keyword, ident = head.rsplit("/", 1)
    return block(tag, keyword, int(ident), title, ids=ids)


def box_rows(bid, p1, p2, tag="BOX"):
    return block(tag, "/BOX/RECTA", bid, "Box", N1=0, N2=0, Iskew=0, Xp1=p1[0], Yp1=p1[1], Zp1=p1[2], Xp2=p2[0],
                 Yp2=p2[1], Zp2=p2[2])


def cylinder_rows(bid, p1, p2, diameter, tag="CYL"):
    return block(tag, "/BOX/CYLIN", bid, "Cylinder box", N1=0, N2=0, Diameter=diameter, Xp1=p1[0], Yp1=p1[1],
                 Zp1=p1[2], Xp2=p2[0], Yp2=p2[1], Zp2=p2[2])


def sphere_rows(bid, centre, diameter, tag="SPH"):
    return block(tag, "/BOX/SPHER", bid, "Sphere box", N1=0, Diameter=diameter, Xp1=centre[0], Yp1=centre[1],
                 Zp1=centre[2])


def with_rows(*groups):
    d = base()
    for rows in groups:
        d.insert_before("BEFORE_END", rows)
    return d


# Sections: a cut at the plate's nodes (node group 1), frame nodes 1, 2, 4.


def sect_rows(grshel, frame=0, tag="SECT"):
    """/SECT/1 summing shell group `grshel` on node group 1."""
    return block(tag, "/SECT", 1, "Cut", node_ID1=1, node_ID2=2, node_ID3=4, grnod_ID=1, Frame_ID=frame,
                 grshel_ID=grshel, fill=0)


@fault("sect_missing_shell_group")
def _():
    d = with_rows(sect_rows(5))
    return d, "/SECT/1 sums /GRSHEL group 5, which does not exist", [("RX402", "SECT.grshel_ID")]


@fault("sect_springs")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", [1, 2]),
                  block("SECT", "/SECT", 1, "Cut", node_ID1=1, node_ID2=2, node_ID3=4, grnod_ID=1, grshel_ID=1,
                        grsprg_ID=3, fill=0))
    return d, "/SECT/1 also names spring group 3: radx sums the forces of bricks, shells, trusses and beams in a " \
        "section, not those of springs", [("RX510", "SECT.grsprg_ID")]


@fault("sect_moving_frame")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", [1, 2]), sect_rows(1, frame=3))
    return d, "/SECT/1 asks for a moving frame (Frame_ID 3), which radx does not implement", \
        [("RX510", "SECT.Frame_ID")]


# Accelerometers: /ACCEL/1 on a node, in a skew, with a cut-off frequency.


def accel_rows(node, skew=0, fcut=0.0):
    """/ACCEL/1 on `node` (tag ACCEL)."""
    return block("ACCEL", "/ACCEL", 1, "Accelerometer", node_ID=node, skew_ID=skew, Fcut=fcut)


@fault("accel_missing_node")
def _():
    d = with_rows(accel_rows(99))
    return d, "/ACCEL/1 sits on node 99, which does not exist", [("RX402", "ACCEL.node_ID")]


@fault("accel_negative_fcut")
def _():
    d = with_rows(accel_rows(1, fcut=-100.0))
    return d, "/ACCEL/1 has a negative cut-off frequency", [("RX501", "ACCEL.Fcut")]


@fault("accel_missing_skew")
def _():
    d = with_rows(accel_rows(1, skew=3))
    return d, "/ACCEL/1 measures in skew 3, which does not exist", [("RX402", "ACCEL.skew_ID")]


@fault("th_accel_missing_accelerometer")
def _():
    d = with_rows(accel_rows(1), th_rows("/TH/ACCEL", "Sensors", ["DEF"], [2]))
    return d, "/TH/ACCEL/1 lists accelerometer 2; the deck has only /ACCEL/1: left out with a warning, as " \
        "Radioss does", [("RX402 warning", "TH_OBJ")]


@fault("th_sectio_missing_section")
def _():
    d = with_rows(th_rows("/TH/SECTIO", "Cuts", ["DEF"], [7]))
    return d, "/TH/SECTIO/1 lists section 7; the deck has no /SECT: left out with a warning, as Radioss does", \
        [("RX402 warning", "TH_OBJ")]


@fault("grshel_shel_missing_element")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", [1, 2, 99]))
    return d, "/GRSHEL/SHEL/1 lists shell 99, which does not exist", [("RX402", "G1.ids")]


@fault("grshel_shel_negative_id")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", [1, -2]))
    return d, "/GRSHEL/SHEL/1 lists element -2: element ids are positive (Radioss finds no element -2 either)", \
        [("RX402", "G1.ids")]


@fault("grsh3n_sh3n_missing_element")
def _():
    d = with_rows(id_list("/GRSH3N/SH3N/1", "G1", "Triangles", [7]))
    return d, "/GRSH3N/SH3N/1 lists 3-node shell 7; the deck has no /SH3N", [("RX402", "G1.ids")]


@fault("grbric_bric_missing_element")
def _():
    d = with_rows(id_list("/GRBRIC/BRIC/1", "G1", "Bricks", [11, 12]))
    return d, "/GRBRIC/BRIC/1 lists brick 12, which does not exist", [("RX402", "G1.ids")]


@fault("grshel_part_missing_part")
def _():
    d = with_rows(id_list("/GRSHEL/PART/1", "G1", "Shells of parts", [1, 9]))
    return d, "/GRSHEL/PART/1 lists part 9, which does not exist: left out (a warning), as in Radioss", [("RX402 warning", "G1.ids")]


@fault("grbric_subset_missing_subset")
def _():
    d = with_rows(id_list("/GRBRIC/SUBSET/1", "G1", "Bricks of a subset", [4]))
    return d, "/GRBRIC/SUBSET/1 lists subset 4; the deck has no /SUBSET: left out, the group is empty (two warnings, as in " \
        "Radioss)", [("RX402 warning", "G1.ids"), ("RX403 warning", "G1_KW")]


@fault("grshel_mat_missing_material")
def _():
    d = with_rows(id_list("/GRSHEL/MAT/1", "G1", "Shells of a material", [1, 7]))
    return d, "/GRSHEL/MAT/1 lists material 7, which does not exist: left out (a warning), as in Radioss", \
        [("RX402 warning", "G1.ids")]


@fault("grbric_prop_missing_property")
def _():
    d = with_rows(id_list("/GRBRIC/PROP/1", "G1", "Bricks of a property", [2, 7]))
    return d, "/GRBRIC/PROP/1 lists property 7, which does not exist: left out (a warning), as in Radioss", \
        [("RX402 warning", "G1.ids")]


@fault("grshel_box_missing_box")
def _():
    d = with_rows(id_list("/GRSHEL/BOX/1", "G1", "Shells in a box", [3]))
    return d, "/GRSHEL/BOX/1 names box 3; the deck has no /BOX: it selects nothing, the group is empty (two warnings, " \
        "as in Radioss)", [("RX402 warning", "G1.ids"), ("RX403 warning", "G1_KW")]


@fault("grtrus_box_missing_box")
def _():
    d = with_truss(base())
    d.insert_before("BEFORE_END", id_list("/GRTRUS/BOX/1", "G1", "Trusses in a box", [3]))
    return d, "/GRTRUS/BOX/1 names box 3; the deck has no /BOX: Radioss stops on it in truss and beam groups (its " \
        "error 798), where it only warns for shells and solids", [("RX402", "G1.ids")]


@fault("grbeam_box_no_box")
def _():
    d = with_beam(base())
    d.insert_before("BEFORE_END", id_list("/GRBEAM/BOX/1", "G1", "Beams in no box", [-4]))
    return d, "/GRBEAM/BOX/1 lists no positive box id: Radioss stops on it in truss and beam groups (its error " \
        "798 on box 0); the negative id is ignored (a warning)", [("RX404", "G1_KW"), ("RX310 warning", "G1.ids")]


@fault("subset_missing_child")
def _():
    d = with_rows(id_list("/SUBSET/4", "SB", "Subset with a missing child", [9]))
    return d, "/SUBSET/4 lists child subset 9, which does not exist: left out (a warning, Radioss's 182)", \
        [("RX402 warning", "SB.ids")]


@fault("part_missing_subset")
def _():
    d = base()
    d.update("PART1", subset_ID=7)
    return d, "/PART/1 names subset 7, which does not exist: the part belongs to no subset (a warning, Radioss's " \
        "183 resets it to 0)", [("RX402 warning", "PART1.subset_ID")]


@fault("box_cylinder_no_axis")
def _():
    d = with_rows(cylinder_rows(1, (5.0, 5.0, 0.0), (5.0, 5.0, 0.0), 4.0))
    return d, "/BOX/CYLIN/1 with P1 = P2: the cylinder has no axis", [("RX507", "CYL.Xp2")]


@fault("box_sphere_no_diameter")
def _():
    d = with_rows(sphere_rows(1, (10.0, 5.0, 0.0), 0.0))
    return d, "/BOX/SPHER/1 with Diameter = 0: a sphere box needs a diameter", [("RX502", "SPH.Diameter")]


@fault("grshel_box_sphere_empty")
def _():
    # The sphere of centre (10, 5, 0) and diameter 12 holds the plate's middle nodes 2 and 5, no whole shell.
    d = with_rows(sphere_rows(2, (10.0, 5.0, 0.0), 12.0),
                  id_list("/GRSHEL/BOX/1", "G1", "Shells in the sphere", [2]))
    return d, "/GRSHEL/BOX/1: box 2 (a sphere) holds no whole shell (a warning, as in Radioss)", \
        [("RX403 warning", "G1_KW")]


@fault("grbric_box_duplicate_box_id")
def _():
    # /BOX/RECTA/1 and /BOX/CYLIN/1: one id space for every box shape.
    d = with_rows(box_rows(1, (0.0, 0.0, 0.0), (20.0, 10.0, 20.0)),
                  cylinder_rows(1, (10.0, 5.0, 0.0), (10.0, 5.0, 20.0), 30.0),
                  id_list("/GRBRIC/BOX/1", "G1", "Bricks in the box", [1]))
    return d, "/BOX/RECTA/1 and /BOX/CYLIN/1: two boxes with one id", [("RX401", "CYL_KW")]


@fault("grbric_grbric_missing_group")
def _():
    d = with_rows(id_list("/GRBRIC/BRIC/1", "G1", "Bricks", [11]),
                  id_list("/GRBRIC/GRBRIC/2", "G2", "Union", [1, 5]))
    return d, "/GRBRIC/GRBRIC/2 lists brick group 5, which does not exist: left out (a warning), as in Radioss", \
        [("RX402 warning", "G2.ids")]


@fault("grshel_grshel_loop")
def _():
    d = with_rows(id_list("/GRSHEL/GRSHEL/1", "G1", "First", [2]),
                  id_list("/GRSHEL/GRSHEL/2", "G2", "Second", [1]))
    return d, "/GRSHEL/GRSHEL/1 lists group 2, which lists group 1: a loop (reported at the group met again)", \
        [("RX507", "G1_KW")]


@fault("grshel_duplicate_group_id")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", [1]),
                  id_list("/GRSHEL/PART/1", "G2", "Shells of part 1", [1]))
    return d, "/GRSHEL/SHEL/1 and /GRSHEL/PART/1: two 4-node shell groups with id 1", [("RX401", "G2_KW")]


@fault("grbric_box_partly_inside")
def _():
    d = with_rows(box_rows(1, (0.0, 0.0, 0.0), (20.0, 10.0, 6.5)),
                  id_list("/GRBRIC/BOX/1", "G1", "Bricks wholly in the box", [1]),
                  id_list("/GRBRIC/BOX2/2", "G2", "Bricks with a node in the box", [1]))
    return d, "box 1 holds the lower four nodes of brick 11 only: /GRBRIC/BOX/1 (all nodes inside) is empty, " \
        "/GRBRIC/BOX2/2 (one node inside) holds the brick", [("RX403 warning", "G1_KW")]


@fault("grsh3n_part_empty")
def _():
    d = with_rows(id_list("/GRSH3N/PART/1", "G1", "Triangles of the plate", [1]))
    return d, "/GRSH3N/PART/1 lists part 1, which has 4-node shells only: no 3-node shell (a warning)", \
        [("RX403 warning", "G1_KW")]


@fault("grshel_grshel_removes_all")
def _():
    d = with_rows(id_list("/GRSHEL/PART/1", "G1", "Plate", [1]),
                  id_list("/GRSHEL/GRSHEL/2", "G2", "Plate minus plate", [1, -1]))
    return d, "/GRSHEL/GRSHEL/2 adds group 1 and removes it again: empty (a warning)", \
        [("RX403 warning", "G2_KW")]


@fault("surf_grshel_missing_group")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", [1, 2]),
                  id_list("/SURF/GRSHEL/1", "S1", "Surface of shell groups", [1, 3]))
    return d, "/SURF/GRSHEL/1 lists shell group 3, which does not exist: left out (a warning, Radioss's 192)", \
        [("RX402 warning", "S1.ids")]


@fault("surf_grsh3n_missing_group")
def _():
    d = with_rows(id_list("/SURF/GRSH3N/1", "S1", "Surface of 3-node shell groups", [4]))
    return d, "/SURF/GRSH3N/1 lists 3-node shell group 4; the deck has none: left out, and the surface is " \
        "empty (warnings, as in Radioss)", [("RX402 warning", "S1.ids"), ("RX403 warning", "S1_KW")]


@fault("surf_grbric_ext_missing_group")
def _():
    d = with_rows(id_list("/GRBRIC/PART/1", "G1", "Block", [2]),
                  id_list("/SURF/GRBRIC/EXT/1", "S1", "Outer faces", [1, 2]))
    return d, "/SURF/GRBRIC/EXT/1 lists brick group 2, which does not exist: left out (a warning, Radioss's " \
        "192)", [("RX402 warning", "S1.ids")]


@fault("surf_grbric_without_ext")
def _():
    d = with_rows(id_list("/GRBRIC/PART/1", "G1", "Block", [2]),
                  id_list("/SURF/GRBRIC/1", "S1", "Faces of a brick group", [1]))
    return d, "/SURF/GRBRIC/1 without /EXT or /FREE: Radioss builds no surface from it either", \
        [("RX407", "S1_KW")]


@fault("surf_part_all_missing_part")
def _():
    d = with_rows(id_list("/SURF/PART/ALL/1", "S1", "All faces", [2, 5]))
    return d, "/SURF/PART/ALL/1 lists part 5, which does not exist: left out (a warning), as in Radioss", \
        [("RX402 warning", "S1.ids")]


@fault("surf_part_all_empty")
def _():
    d = base()
    d.insert_before("AFTER_PARTS", part(3, "Part without elements", 1, 1))
    d.insert_before("BEFORE_END", id_list("/SURF/PART/ALL/1", "S1", "All faces of part 3", [3]))
    return d, "/SURF/PART/ALL/1 lists part 3, which has no element: no segment (a warning, as in Radioss)", \
        [("RX403 warning", "S1_KW")]


@fault("inter_empty_main_surface")
def _():
    d = base()
    d.insert_before("BEFORE_END", id_list("/SURF/PART/ALL/5", "S5", "Faces of a part that does not exist", [99]))
    d.insert_before("BEFORE_END", type7(surf=5))
    return d, "/INTER/TYPE7/1's main surface 5 lists only part 99, which does not exist: the surface is empty " \
        "(warnings) and the interface would find no contact, which Radioss stops on (error 3160)", \
        [("RX402 warning", "S5.ids"), ("RX403 warning", "S5_KW"), ("RX403", "INT.surf_IDm")]


@fault("grnod_grshel_missing_group")
def _():
    d = with_rows(id_list("/GRSHEL/SHEL/1", "G1", "Shells", [1]),
                  id_list("/GRNOD/GRSHEL/3", "N3", "Nodes of shell groups", [1, 2]))
    return d, "/GRNOD/GRSHEL/3 lists shell group 2, which does not exist: left out (a warning), as in Radioss", \
        [("RX402 warning", "N3.ids")]


@fault("grnod_grbric_negative_only")
def _():
    d = with_rows(id_list("/GRBRIC/PART/1", "G1", "Block", [2]),
                  id_list("/GRNOD/GRBRIC/3", "N3", "Nodes of brick groups", [-1]))
    return d, "/GRNOD/GRBRIC/3 lists only -1: a negative id is ignored there (a warning), as in Radioss, so the " \
        "group holds no node (a warning)", [("RX403 warning", "N3_KW")]


@fault("grnod_part_missing_part")
def _():
    d = with_rows(id_list("/GRNOD/PART/3", "N3", "Nodes of parts", [2, 9]))
    return d, "/GRNOD/PART/3 lists part 9, which does not exist: left out (a warning), as in Radioss", \
        [("RX402 warning", "N3.ids")]


@fault("sect_grbric_tetra")
def _():
    # The cut at the brick's bottom nodes 11 12 13 14, which the tetrahedron 21 (11 14 12 15) touches.
    d = with_tetra(base())
    d.insert_before("BEFORE_END", id_list("/GRNOD/NODE/4", "N4", "Cut nodes", [11, 12, 13, 14]) +
                    id_list("/GRBRIC/PART/2", "G2", "Solids", [2, 3]) +
                    block("SECT", "/SECT", 1, "Cut", node_ID1=11, node_ID2=12, node_ID3=14, grnod_ID=4,
                          grbric_ID=2, fill=0))
    return d, "/SECT/1 sums brick group 2, which holds tetrahedron 21 on the cut: radx sums no tetrahedron " \
        "force in a section", [("RX510", "SECT.grbric_ID")]


# Added masses, initial velocities, gravity and concentrated loads: their references and values.


def admas_rows(mass, grnod, path="/ADMAS/0"):
    return block("ADM", path, 1, "Added mass", MASS=mass, grnod_ID=grnod)


@fault("admas_missing_group")
def _():
    d = with_rows(admas_rows(1e-6, 99))
    return d, "/ADMAS/0/1 adds mass to node group 99, which does not exist", [("RX402", "ADM.grnod_ID")]


@fault("admas_negative_mass")
def _():
    d = with_rows(admas_rows(-1e-6, 1, "/ADMAS/1"))
    return d, "/ADMAS/1/1 adds a negative mass", [("RX501", "ADM.MASS")]


@fault("inivel_rot_missing_group")
def _():
    d = with_rows(block("IV", "/INIVEL/ROT", 1, "Spin", Vx=0.0, Vy=0.0, Vz=100.0, grnod_ID=42, skew_ID=0,
                        Tstart=0.0, sensor_ID=0))
    return d, "/INIVEL/ROT/1 spins node group 42, which does not exist", [("RX402", "IV.grnod_ID")]


@fault("grav_missing_function")
def _():
    d = with_rows(block("GR", "/GRAV", 1, "Gravity", funct_IDT=8, DIR="Z", grnod_ID=1, Fscale_y=-9810.0, fill=0))
    return d, "/GRAV/1 follows function 8, which does not exist", [("RX402", "GR.funct_IDT")]


@fault("cload_missing_group")
def _():
    d = with_rows(block("CL", "/CLOAD", 1, "Force", funct_IDT=5, Dir="X", grnod_ID=77, Fscale_y=1.0, fill=0)
                  + funct_rows(5, [(0.0, 1.0), (1.0, 1.0)], "Constant"))
    return d, "/CLOAD/1 pushes node group 77, which does not exist", [("RX402", "CL.grnod_ID")]


@fault("mat_law_not_in_radx")
def _():
    d = with_rows([("/MAT/LAW51/9", "ML_KW"), "Multi-material ALE law",
                   rc.data_line(rc.Card(rc.r("RHO_I")).columns, [1e-9])])
    return d, "/MAT/LAW51: a Radioss material law radx does not implement (not an unknown keyword)", \
        [("RX302", "ML_KW")]


# Random perturbation of the coordinates.


def random_rows(path, xalea, tag):
    keyword, ident = (path, None) if path == "/RANDOM" else path.rsplit("/", 1)
    return block(tag, keyword, ident, XALEA=xalea, SEED=0.0)


@fault("random_negative_xalea")
def _():
    d = with_rows(random_rows("/RANDOM", -0.01, "RA"))
    return d, "/RANDOM with a negative largest perturbation XALEA", [("RX501", "RA.XALEA")]


@fault("random_grnod_missing_group")
def _():
    d = with_rows(random_rows("/RANDOM/GRNOD/9", 0.01, "RG"))
    return d, "/RANDOM/GRNOD/9 perturbs node group 9, which does not exist", [("RX402", "RG_KW")]


@fault("random_both_kinds")
def _():
    d = with_rows(random_rows("/RANDOM", 0.01, "RA") + random_rows("/RANDOM/GRNOD/1", 0.01, "RG"))
    return d, "/RANDOM (all nodes) and /RANDOM/GRNOD together: Radioss then perturbs nothing", \
        [("RX507", "RG.XALEA")]


# Model assembly: //SUBMODEL, /TRANSFORM, /MOVE_FUNCT
OFFSETS = ("off_def", "off_nod", "off_ele", "off_part", "off_mat", "off_type", "off_sub")


def submodel_head(sid=5, offsets=(0,), tag="SUB"):
    return block(tag, "//SUBMODEL", sid, "Block as a submodel", **dict(zip(OFFSETS, offsets)))


def transform_rows(kind, grnod=1, v=(0.0, 0.0, 0.0), n1=0, n2=0, sub=0, card2=None, tag="TR"):
    """/TRANSFORM/TRA/1 (v the translation) or /TRANSFORM/ROT/1 (v the axis' first point, card2 its second point
    and the angle); node ids and submodel 0 are left blank."""
    values = dict(grnod_ID=grnod, node_ID1=n1 or None, node_ID2=n2 or None, sub_ID=sub or None)
    if kind == "TRA":
        values.update(X_translation=v[0], Y_translation=v[1], Z_translation=v[2])
    else:
        values.update(X_point_1=v[0], Y_point_1=v[1], Z_point_1=v[2])
        values.update(zip(("X_point_2", "Y_point_2", "Z_point_2", "Angle"), card2))
    return block(tag, "/TRANSFORM/" + kind, 1, "Move", **values)


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
    return d, "/TRANSFORM/TRA/1 moves node group 99, which does not exist", [("RX402", "TR.grnod_ID")]


@fault("transform_missing_submodel")
def _():
    d = base()
    d.insert_before("BEFORE_END", transform_rows("TRA", grnod=0, v=(0.0, 0.0, 5.0), sub=9))
    return d, "/TRANSFORM/TRA/1 moves submodel 9, which does not exist", [("RX402", "TR.sub_ID")]


@fault("transform_group_and_submodel")
def _():
    d = with_brick_submodel(base())
    d.insert_before("BEFORE_END", transform_rows("TRA", grnod=1, v=(0.0, 0.0, 5.0), sub=5))
    return d, "/TRANSFORM/TRA/1 names both node group 1 and submodel 5: a transform moves one of them", \
        [("RX507", "TR.sub_ID")]


@fault("transform_one_node")
def _():
    d = base()
    d.insert_before("BEFORE_END", transform_rows("TRA", grnod=1, n1=1))
    return d, "/TRANSFORM/TRA/1 gives node_ID1 without node_ID2 (both or neither)", [("RX404", "TR.node_ID1")]


@fault("transform_degenerate_axis")
def _():
    d = base()
    d.insert_before("BEFORE_END", transform_rows("ROT", grnod=1, v=(5.0, 5.0, 0.0), card2=(5.0, 5.0, 0.0, 90.0)))
    return d, "/TRANSFORM/ROT/1 turns 90 degrees about an axis from (5, 5, 0) to the same point", \
        [("RX605", "TR.Angle")]


@fault("move_funct_missing_function")
def _():
    d = base()
    d.insert_before("BEFORE_END", block("MF", "/MOVE_FUNCT", 9, "Moved", Ascalex=2.0, Fscaley=1.0, Ashiftx=0.0,
                                       Fshifty=0.0))
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
    for text, names, spec in d.rows[k:d.index("BRICK_11") + 1]:
        inc.add(text, names, spec)
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
    d.insert_after("AFTER_PARTS", FOOBAR)
    d.update("EL", nu=0.6)
    d.insert_before("BEFORE_END", funct_rows(5, [(0.0, 0.0), (0.002, 1.0), (0.002, 2.0)], "Bad function"))
    return d, "four independent errors: duplicate node 3, unknown /FOOBAR, nu = 0.6 on /MAT/LAW1/2, " \
        "/FUNCT/5 X not increasing", [("RX401", "DUP"), ("RX301", "BAD_KW"), ("RX503", "EL.nu"),
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
        # "RX512 warning": a warning the deck must get (it is read, not refused)
        number, _, severity = code.partition(" ")
        head.append("# expect: %s line %d%s%s" % (number, ln, (" file " + f) if f else "",
                                                 (" " + severity) if severity else ""))
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
         "Each `.rad` file here is a small starter deck (format 2026, units Mg mm s) that must be REJECTED (those",
         "whose expectations are all marked `warning` must be read with those warnings instead). It is the same tiny valid model every time (two 4-node shells of part 1 with Johnson-Cook steel, one brick",
         "of part 2 with elastic aluminium, plate nodes clamped by `/BCS`) with one fault put in, so that it",
         "should produce only the diagnostics listed (`several_errors.rad` has four independent faults, and",
         "all four must be reported).",
         "",
         "The first lines of each deck state what the reader must report, one line per diagnostic:",
         "",
         "```",
         "# expect: RX402 line 37",
         "# expect: RX102 line 5 file inc/include_loop_b.rad",
         "# expect: RX512 line 84 warning",
         "# fault: free text describing the fault",
         "```",
         "",
         "* the code is a `Diag` of `parser/reading/diagnostics.hpp`; the line is 1-based, in the deck itself unless",
         "  `file` names another file (relative to this folder);",
         "* without `warning` the diagnostic is an error and the deck must be refused; with it, a warning, and",
         "  a deck whose expectations are all warnings must be read;",
         "* the line is the data line that holds the bad value or the bad reference; the keyword line for",
         "  keyword-level faults (unknown or unsupported keyword, empty group, a block that ends before a",
         "  required card, an id given on the keyword line); the last line of the file for a missing `/END`;",
         "  the `#include` line that closes the loop, or that names a missing file;",
         "* no other error may be reported; other warnings and notes are not part of the expectation.",
         "",
         "`radx regress decks/invalid` runs them all and checks each (docs/regress.md).",
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
        exp = "<br>".join("%s line %d%s%s" % (c.split()[0], ln, (" of " + f) if f else "",
                                               " (warning)" if " " in c else "") for c, ln, f in resolved)
        files = "`%s.rad`" % name + "".join(" + `%s`" % x for x in extras)
        L.append("| %s | %s | %s |" % (files, what.replace("|", "\\|"), exp))
    L += ["", "%d decks." % len(table), ""]
    return L


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
