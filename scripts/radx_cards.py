"""One card writer for the Radioss block-format decks that the generators write (docs/keywords.md).

Every card layout is declared once, as data, in LAYOUTS (starter keywords, the 2026 layout of
docs/keywords.md, with the version ranges of the fields that older layouts lack or hold elsewhere) and in
ENGINE_LAYOUTS (engine keywords). A layout says whether the keyword has a title line and which card lines
follow; a card line is a list of fields, each a name (the text of the field-name comment line), a kind and
a width in columns:

    I  integer, right-justified          R  real, right-justified (shortest text that reads back exactly)
    S  text, right-justified             L  text, left-justified (/TH variable names, /BEGIN's run name)
    -  blank columns (a gap)

One writer, card(), turns `keyword + id + title + field values` into the keyword line, the title line, and
for each card its field-name comment line ('#' in column 1, each name over its field) and its data line.
Fields not given are blank; a value that does not fit its field, or a field name the layout does not have,
raises ValueError. A value given as a string is written as it is (a deliberately bad value, '1E30', a
/BCS code from bcs_code()). Field values are passed by key: the field name with every run of characters
other than letters, digits and '_' turned into '_' ('%mesh_size' -> mesh_size, 'Tra rot' -> Tra_rot).

Row-list keywords (/NODE, /SHELL, /SH3N, /BRICK, /SURF/SEG, /FUNCT, /TH/NODE ...) take `rows`, a list of
tuples in field order; id-list keywords (/GRNOD/NODE, /GRNOD/PART, /SURF/PART, /TH/PART ...) take `ids`,
written ten to a line; /TH keywords take `variables` too. Cards that only some values call for (the TYPE7
friction cards when Ifric > 0) are written when their condition holds.

marked() gives card()'s lines each with what it holds (the keyword line, the title, the field keys of a data
line, an id-list line or a row), so that a generator can name the line of a field, as make_invalid_decks.py
does for its expected diagnostics; row_line() writes one row of a row-list keyword.

Deck collects the lines of one file: its begin() writes /BEGIN with the deck version and units, ruler(),
comment(), card(), rows(), raw() add lines, write() writes the file. Deck(engine=True) takes the engine
keywords (/RUN, /TFILE, /ANIM/..., /DT, /DT/INTER/CST, /PRINT, /STOP, /END); engine data lines are free
format, they are written in columns only to be easy to read.

    import radx_cards as rc
    d = rc.Deck()
    d.begin("PLATE", units=("Mg", "mm", "s"))
    d.card("/TITLE", title="A plate")
    d.rows("/NODE", [(1, 0.0, 0.0, 0.0), (2, 10.0, 0.0, 0.0)])
    d.card("/PART", 1, "Plate", prop_ID=1, mat_ID=1)
    d.card("/GRNOD/NODE", 1, "Clamped nodes", ids=[1, 2])
    d.card("/BCS", 1, "Clamp", Tra_rot=rc.bcs_code("111", "111"), grnod_ID=1)
    d.raw("/END")
    d.write("/tmp/x/PLATE_0000.rad")
    e = rc.Deck(engine=True)
    e.card("/RUN", "PLATE/1", Tstop=0.001)
    e.raw("/ANIM/ELEM/VONM")
    e.card("/DT", Tscale=0.9, Tmin=0.0)
    e.raw("/END")

Plain python3, standard library only. The cells themselves come from radx_deck_format.py.
"""
import re

from radx_deck_format import RULER, I, R, S, bcs_code, fmt_real, ibc_code, write  # noqa: F401 (re-exported)

VERSION = 2026
ANY, LAST = 0, 9999
MAX_COLUMNS = 100


# ---------------------------------------------------------------------------------------------------
# Layout data

class Field:
    """One field of a card: name (the comment-line text), kind (I, R, S, L or -), width, first column
    (None: right after the previous field), the deck versions that have it, its value key, whether its
    name is left-justified in the comment line, and wrap: for a text field alone on its card, the characters
    after which a text longer than the field goes on to the next line (a list of texts is written one to a
    line as it is)."""
    __slots__ = ("name", "kind", "width", "col", "since", "until", "key", "name_left", "wrap")

    def __init__(self, name, kind, width, col=None, since=ANY, until=LAST, key=None, name_left=False, wrap=None):
        self.name, self.kind, self.width, self.col = name, kind, width, col
        self.since, self.until, self.name_left, self.wrap = since, until, name_left, wrap
        self.key = key if key is not None else re.sub(r"[^0-9A-Za-z_]+", "_", name).strip("_")

    def in_version(self, version):
        return self.since <= version <= self.until


def i(name, width=10, **kw):
    return Field(name, "I", width, **kw)


def r(name, width=20, **kw):
    return Field(name, "R", width, **kw)


def s(name, width=10, **kw):
    return Field(name, "S", width, **kw)


def left(name, width, **kw):
    return Field(name, "L", width, **kw)


def gap(width, **kw):
    return Field("", "-", width, **kw)


class Card:
    """One card line: its fields (placed once, here), whether it has a field-name comment line, the condition
    on the keyword's values that calls for it, and the deck versions that have it."""

    def __init__(self, *fields, names=True, when=None, since=ANY, until=LAST):
        self.fields, self.names, self.when, self.since, self.until = fields, names, when, since, until
        self.columns = []  # (first column, field)
        col = 1
        for f in fields:
            start = f.col if f.col is not None else col
            if start + f.width - 1 > MAX_COLUMNS:
                raise ValueError("field %r ends after column %d" % (f.name, MAX_COLUMNS))
            self.columns.append((start, f))
            col = start + f.width

    def in_version(self, version):
        return self.since <= version <= self.until


class IdList:
    """A list of values written per_line to a line, the comment line naming them name1, name2 ..."""

    def __init__(self, name, kind="I", width=10, per_line=10, key="ids"):
        self.name, self.kind, self.width, self.per_line, self.key = name, kind, width, per_line, key


class Layout:
    """A keyword: title line or not, its cards, then either rows (a Card repeated per row) or an id list;
    /TH keywords also carry a variable list before their objects."""

    def __init__(self, *cards, title=True, rows=None, ids=None, variables=None):
        self.title, self.cards, self.rows, self.ids, self.variables = title, cards, rows, ids, variables


def _int(v):
    try:
        return int(v)
    except (TypeError, ValueError):
        return 0


ID10 = lambda name: IdList(name)  # noqa: E731
TH_VARIABLES = IdList("var_ID", kind="L", key="variables")

# A /SET clause line: its word (left-justified in columns 1-10; blank carries on the clause above) and up to nine
# ids, or three (first, last, step) triples for a _G clause.
SET_CLAUSE = Card(left("clause", 10), *[i("item%d" % k) for k in range(1, 10)])

LAYOUTS = {
    # --- control
    "/BEGIN": Layout(
        Card(left("RUNNAME", 100, name_left=True)),
        Card(i("INVERS"), i("IRUN", until=2020)),
        Card(s("Input_mass", 20), s("Input_length", 20), s("Input_time", 20), since=100),
        Card(s("Work_mass", 20), s("Work_length", 20), s("Work_time", 20), since=100),
        title=False),
    "/TITLE": Layout(),  # the model title is the one line after the keyword, like a title line
    "/UNIT": Layout(Card(s("MUNIT", 20), s("LUNIT", 20), s("TUNIT", 20))),
    "/DEF_SHELL": Layout(
        Card(i("Ishell"), i("Ismstr"), i("Ithick"), i("Iplas"), i("Istrain"), i("Ioffset", since=2024), gap(10),
             i("Ish3n"), i("Idrill"), i("Ithin_dr", since=2026)),
        title=False),
    "/DEF_SOLID": Layout(
        Card(i("Isolid"), i("Ismstr"), i("Icpre", since=2021), i("Istrain", since=100, until=2020), i("Itetra4"),
             i("Itetra10"), i("Imas"), i("Iframe"), i("Icontrol", since=2025)),
        title=False),
    "/ANALY": Layout(Card(i("N2D3D"), i("ITEMP", since=2026), i("IPARITH"), i("ISUBCYC", until=2022)), title=False),
    "/IOFLAG": Layout(Card(i("IPRI"), gap(10), i("IGTYP", until=140), i("IOUTP"), i("IOUTYY"), i("IROOTYY"),
                           i("Irot")), title=False),
    "/RANDOM": Layout(Card(r("XALEA"), r("SEED")), title=False),
    "/RANDOM/GRNOD": Layout(Card(r("XALEA"), r("SEED")), title=False),
    "/ANIM/VERS": Layout(Card(i("ANIM_VERS")), title=False),
    "/MEMORY": Layout(Card(i("MEMORY"), gap(10), r("REAL")), title=False),
    "/SPMD": Layout(Card(i("Domdec"), i("Nspmd"), gap(10), i("Dkword"), gap(10), i("Nthread")), title=False),
    # --- mesh
    "/NODE": Layout(title=False, rows=Card(i("node_ID"), r("Xc"), r("Yc"), r("Zc"))),
    "/SHELL": Layout(title=False, rows=Card(i("shell_ID"), i("node_ID1"), i("node_ID2"), i("node_ID3"),
                                            i("node_ID4"), gap(10), r("PHI"), r("Thick"))),
    "/SH3N": Layout(title=False, rows=Card(i("tria_ID"), i("node_ID1"), i("node_ID2"), i("node_ID3"), gap(30),
                                           r("PHI"), r("Thick", 10))),
    "/BRICK": Layout(title=False, rows=Card(i("brick_ID"), *[i("node_ID%d" % k) for k in range(1, 9)])),
    "/TETRA4": Layout(title=False, rows=Card(i("tetra_ID"), *[i("node_ID%d" % k) for k in range(1, 5)])),
    "/SPRING": Layout(title=False, rows=Card(i("spring_ID"), i("node_ID1"), i("node_ID2"), i("node_ID3"))),
    "/ALE/BCS": Layout(Card(s("Code"), i("skew_ID"), i("grnod_ID"))),
    "/TRUSS": Layout(title=False, rows=Card(i("truss_ID"), i("node_ID1"), i("node_ID2"))),
    "/BEAM": Layout(title=False, rows=Card(i("beam_ID"), i("node_ID1"), i("node_ID2"), i("node_ID3"))),
    "/PART": Layout(Card(i("prop_ID"), i("mat_ID"), i("subset_ID"), r("Thick"))),
    "/TRANSFORM/TRA": Layout(
        Card(i("grnod_ID"), r("X_translation"), r("Y_translation"), r("Z_translation"), i("node_ID1"),
             i("node_ID2"), i("sub_ID", since=100)),
        Card(i("skew_ID"), since=2026)),
    "/TRANSFORM/ROT": Layout(
        Card(i("grnod_ID"), r("X_point_1"), r("Y_point_1"), r("Z_point_1"), i("node_ID1"), i("node_ID2"),
             i("sub_ID", since=100)),
        Card(gap(10), r("X_point_2"), r("Y_point_2"), r("Z_point_2"), r("Angle"))),
    "/TRANSFORM/SCA": Layout(
        Card(i("grnod_ID"), r("Fscale_X"), r("Fscale_Y"), r("Fscale_Z"), i("node_IDc"), gap(10),
             i("sub_ID", since=2026))),
    "/TRANSFORM/SYM": Layout(
        Card(i("grnod_ID"), r("X_point_1"), r("Y_point_1"), r("Z_point_1"), i("node_ID1"), i("node_ID2"),
             i("sub_ID", since=2026)),
        Card(gap(10), r("X_point_2"), r("Y_point_2"), r("Z_point_2"))),
    "//SUBMODEL": Layout(Card(i("off_def"), i("off_nod"), i("off_ele"), i("off_part"), i("off_mat"), i("off_type"),
                              i("off_sub"))),
    # --- properties and materials
    "/PROP/SHELL": Layout(
        Card(i("Ishell"), i("Ismstr"), i("Ish3n"), i("Idrill", since=110), i("Ipinch", since=2020), gap(10),
             r("P_Thick_Fail", since=2018)),
        Card(r("Hm"), r("Hf"), r("Hr"), r("Dm"), r("Dn")),
        Card(i("N"), i("Istrain", until=2023), r("Thick"), r("Ashear"), gap(10), i("Ithick"), i("Iplas"),
             i("Ipos", since=2024))),
    "/PROP/SOLID": Layout(
        Card(i("Isolid"), i("Ismstr"), i("Iale", since=2022), i("Icpre"), i("Itetra10", since=2019), i("Inpts"),
             i("Itetra4", since=100), i("Iframe"), r("dn")),
        Card(r("qa"), r("qb"), r("h"), r("LAMBDA_V", since=120), r("MU_V", since=120)),
        Card(r("dtmin"), i("Istrain", since=100, until=2022), i("Ihkt", since=120, until=2022),
             r("vdef_min", col=21, since=2023), r("vdef_max", since=2023), r("ASP_max", since=2023),
             r("COL_min", since=2023))),
    "/PROP/TRUSS": Layout(Card(r("Area"), r("Gap"))),
    "/PROP/BEAM": Layout(Card(gap(10), i("Ismstr")), Card(r("Dm"), r("Df")), Card(r("Area"), r("Iyy"), r("Izz"), r("Ixx")),
                         Card(s("Wdof", 10), i("Ishear"))),
    "/PROP/SPRING": Layout(
        Card(r("M"), gap(30), i("sens_ID"), i("Isflag"), i("Ileng")),
        Card(r("K"), r("C"), r("A"), r("B"), r("D")),
        Card(i("fct_ID1"), i("H"), i("fct_ID2"), i("fct_ID3"), i("fct_ID4", since=120), gap(10), r("delta_min"),
             r("delta_max")),
        Card(r("F"), r("E"), r("Ascale"), r("Hscale", since=120))),
    "/PROP/SPR_GENE": Layout(
        Card(r("M"), r("Inertia"), i("skew_ID"), i("sens_ID"), i("Isflag"), i("Ifail"), i("Ifail2", since=2018),
             i("Iequil", col=91)),
        *[c for d in "123456" for c in (
            Card(r("K" + d), r("C" + d), r("A" + d), r("B" + d), r("D" + d)),
            Card(i("fct_ID1" + d), i("H" + d), i("fct_ID2" + d), i("fct_ID3" + d), i("fct_ID4" + d), gap(10),
                 r("delta_min" + d), r("delta_max" + d)),
            Card(r("F" + d), r("E" + d), r("Ascale" + d), r("Hscale" + d)))],
        Card(i("Fsmooth"), r("Fcut"))),
    "/PROP/SPR_BEAM": Layout(
        Card(r("M"), r("Inertia"), i("skew_ID"), i("sens_ID"), i("Isflag"), i("Ifail"), i("Ileng"), i("Ifail2")),
        *[c for d in "123456" for c in (
            Card(r("K" + d), r("C" + d), r("A" + d), r("B" + d), r("D" + d)),
            Card(i("fct_ID1" + d), i("H" + d), i("fct_ID2" + d), i("fct_ID3" + d), i("fct_ID4" + d), gap(10),
                 r("delta_min" + d), r("delta_max" + d)),
            Card(r("F" + d), r("E" + d), r("Ascale" + d), r("Hscale" + d)))],
        Card(r("Vo"), r("Wo"), r("Asrate", since=2018), i("Israte", since=2018)),
        *[Card(r("c" + d), r("n" + d), r("alpha" + d), r("beta" + d)) for d in "123456"]),
    "/MAT/LAW1": Layout(Card(r("RHO_I"), r("RHO_ref")), Card(r("E"), r("nu"))),
    "/MAT/VOID": Layout(Card(r("RHO_I"), r("E"), r("nu"))),
    "/MAT/RIGID": Layout(Card(r("RHO_I"), r("RHO_ref")), Card(r("E"), r("nu"))),
    "/MAT/OGDEN": Layout(
        Card(r("RHO_I"), r("RHO_ref")),
        Card(r("nu"), r("sigma_cut"), i("Jstrain"), i("fct_IDbulk"), r("Fscale_bulk"), i("M"), i("Iform", since=140)),
        Card(r("mu_1"), r("mu_2"), r("mu_3"), r("mu_4"), r("mu_5")),
        Card(r("mu_6"), r("mu_7"), r("mu_8"), r("mu_9"), r("mu_10")),
        Card(r("alpha_1"), r("alpha_2"), r("alpha_3"), r("alpha_4"), r("alpha_5")),
        Card(r("alpha_6"), r("alpha_7"), r("alpha_8"), r("alpha_9"), r("alpha_10"))),
    "/MAT/FOAM_TAB": Layout(
        Card(r("RHO_I"), r("RHO_ref")),
        Card(r("E0"), r("nu"), r("E_max"), r("Eps_max"), i("Itens", since=120)),
        Card(r("Fcut"), i("Ismooth"), i("Nload"), i("Nunload"), i("Iflag", since=90), r("Shape", since=90),
             r("Hys", since=90)),
        *[Card(i("fct_%s%d" % (what, k)), r("rate_%s%d" % (what, k)), r("scale_%s%d" % (what, k)),
               when=lambda v, k=k, count=count: _int(v.get(count)) >= k)
          for what, count in (("L", "Nload"), ("U", "Nunload")) for k in range(1, 4)],
        Card(i("fctIDTens"), r("FscaleTens"), since=120, when=lambda v: _int(v.get("Itens")) == 1)),
    "/MAT/PLAS_JOHNS": Layout(
        Card(r("RHO_I"), r("RHO_ref")),
        Card(r("E"), r("nu"), i("Iflag", since=140), i("flagVP", since=2023), r("Pmin", since=2025)),
        Card(r("a"), r("b"), r("n"), r("EPS_p_max"), r("SIG_max0"), when=lambda v: _int(v.get("Iflag")) != 1),
        Card(r("SIG_Y"), r("UTS"), r("EUTS"), r("EPS_p_max", key="EPS_p_max"), r("SIG_max0"),
             when=lambda v: _int(v.get("Iflag")) == 1),
        Card(r("c"), r("EPS_DOT_0"), i("ICC"), i("Fsmooth"), r("F_cut"), r("Chard", since=100)),
        Card(r("m"), r("T_melt"), r("rhoC_p"), r("T_r"), r("T_max", since=2025))),
    "/MAT/PLAS_TAB": Layout(
        Card(r("RHO_I"), r("RHO_ref")),
        Card(r("E"), r("nu"), r("Eps_p_max"), r("Eps_t"), r("Eps_m")),
        Card(i("N_funct"), i("Fsmooth"), r("Chard"), r("Fcut"), r("Eps_f"), i("VP", col=91, since=2017)),
        Card(i("fct_IDp"), r("Fscale"), i("Fct_IDE", since=120), r("EInf", since=120), r("CE", since=120)),
        *[Card(*[(i if base == "fct_ID" else r)("%s%d" % (base, 5 * j + c + 1)) for c in range(5)],
               when=lambda v, j=j: _int(v.get("N_funct")) > 5 * j)
          for base in ("fct_ID", "Fscale", "Eps_dot") for j in range(4)]),
    "/MAT/PLAS_BRIT": Layout(
        Card(r("RHO_I"), r("RHO_ref")),
        Card(r("E"), r("nu")),
        Card(r("a"), r("b"), r("n"), gap(20), r("SIG_max0")),
        Card(r("c"), r("EPS_DOT_0"), i("ICC"), i("Fsmooth", since=2019), r("Fcut", since=2019)),
        Card(r("EPS_t1"), r("EPS_m1"), r("d_max1"), r("EPS_f1")),
        Card(r("EPS_t2"), r("EPS_m2"), r("d_max2"), r("EPS_f2"))),
    "/FAIL/JOHNSON": Layout(
        Card(r("D1"), r("D2"), r("D3"), r("D4"), r("D5")),
        Card(r("Epsilon_Dot_0"), i("Ifail_sh"), i("Ifail_so"), r("EPSF_MIN", since=2024), r("Dadv", col=61, since=130),
             i("Ixfem", col=91, since=120)),
        Card(i("FAILIP"), since=2025),
        title=False),
    # /FAIL/TAB: the radioss2018 layout (the keyword's last); P_thickfail at 61-80 in the 110 layout only
    "/FAIL/TAB": Layout(
        Card(i("Ifail_sh"), i("Ifail_so"), i("N_rate"), r("P_thickfail", col=41, until=100),
             r("P_thickfail", col=61, since=110, until=110), r("P_thickfail", col=41, since=120),
             i("Ixfem", col=91, since=120)),
        Card(r("Dcrit"), r("D"), r("n"), r("Dadv", since=120)),
        *[Card(i("fct_ID%d" % k), r("Fscale%d" % k), r("Epsdot%d" % k),
               when=lambda v, k=k: _int(v.get("N_rate")) >= k) for k in range(1, 11)],
        Card(i("fct_IDel"), r("Fscale_el"), r("EI_ref")),
        Card(i("fct_IDt"), r("FscaleT")),
        title=False),
    # /FAIL/BIQUAD: the radioss2017..2026 layouts (size function from 2018, Ireg 2026, the softening card 2024,
    # FAILIP 2025); the R1 R2 R4 R5 card only with M_Flag 99
    "/FAIL/BIQUAD": Layout(
        Card(r("C1"), r("C2"), r("C3"), r("C4"), r("C5")),
        Card(r("P_thickfail"), i("M_Flag"), i("S_Flag"), r("Inst_start"), i("Ireg", col=61, since=2026),
             i("fct_IDel", col=71, since=2018), r("EI_ref", col=81, since=2018)),
        Card(r("R1"), r("R2"), r("R4"), r("R5"), when=lambda v: _int(v.get("M_Flag")) == 99),
        Card(i("ICOUP", col=11), r("DCRIT"), r("EXP"), i("FAILIP", since=2025), since=2024),
        title=False),
    # --- groups and surfaces (id lists)
    # A set's clauses: a clause word in columns 1-10 (blank: the clause above goes on), then its ids.
    "/SET/GENERAL": Layout(rows=SET_CLAUSE),
    "/SET/COLLECT": Layout(rows=SET_CLAUSE),
    "/GRNOD/NODE": Layout(ids=ID10("node_ID")),
    "/GRNOD/PART": Layout(ids=ID10("part_ID")),
    "/GRNOD/GRNOD": Layout(ids=ID10("grnod_ID")),
    "/GRNOD/BOX": Layout(ids=ID10("box_ID")),
    "/GRNOD/SUBSET": Layout(ids=ID10("subs_ID")),
    "/GRNOD/MAT": Layout(ids=ID10("mat_ID")),
    "/GRNOD/PROP": Layout(ids=ID10("prop_ID")),
    "/GRNOD/SURF": Layout(ids=ID10("surf_ID")),
    "/GRNOD/GRSHEL": Layout(ids=ID10("grsh_ID")),
    "/GRNOD/GRSH3N": Layout(ids=ID10("gr3n_ID")),
    "/GRNOD/GRBRIC": Layout(ids=ID10("grbr_ID")),
    "/GRNOD/GENE": Layout(ids=ID10("node_ID")),  # (first, last) pairs of node id ranges
    "/GRNOD/GEN_INCR": Layout(rows=Card(i("first"), i("last"), i("incr"))),
    "/SUBSET": Layout(ids=ID10("subs_ID")),
    "/GRSHEL/SHEL": Layout(ids=ID10("shell_ID")),
    "/GRSHEL/PART": Layout(ids=ID10("part_ID")),
    "/GRSHEL/GRSHEL": Layout(ids=ID10("grsh_ID")),
    "/GRSHEL/SUBSET": Layout(ids=ID10("subs_ID")),
    "/GRSHEL/MAT": Layout(ids=ID10("mat_ID")),
    "/GRSHEL/PROP": Layout(ids=ID10("prop_ID")),
    "/GRSHEL/BOX": Layout(ids=ID10("box_ID")),
    "/GRSHEL/BOX2": Layout(ids=ID10("box_ID")),
    "/GRSH3N/SH3N": Layout(ids=ID10("sh3n_ID")),
    "/GRSH3N/PART": Layout(ids=ID10("part_ID")),
    "/GRSH3N/GRSH3N": Layout(ids=ID10("gr3n_ID")),
    "/GRSH3N/SUBSET": Layout(ids=ID10("subs_ID")),
    "/GRSH3N/MAT": Layout(ids=ID10("mat_ID")),
    "/GRSH3N/PROP": Layout(ids=ID10("prop_ID")),
    "/GRSH3N/BOX": Layout(ids=ID10("box_ID")),
    "/GRSH3N/BOX2": Layout(ids=ID10("box_ID")),
    "/GRBRIC/BRIC": Layout(ids=ID10("brick_ID")),
    "/GRBRIC/PART": Layout(ids=ID10("part_ID")),
    "/GRBRIC/GRBRIC": Layout(ids=ID10("grbr_ID")),
    "/GRBRIC/SUBSET": Layout(ids=ID10("subs_ID")),
    "/GRBRIC/MAT": Layout(ids=ID10("mat_ID")),
    "/GRBRIC/PROP": Layout(ids=ID10("prop_ID")),
    "/GRBRIC/BOX": Layout(ids=ID10("box_ID")),
    "/GRBRIC/BOX2": Layout(ids=ID10("box_ID")),
    "/GRTRUS/TRUS": Layout(ids=ID10("truss_ID")),
    "/GRTRUS/PART": Layout(ids=ID10("part_ID")),
    "/GRTRUS/GRTRUS": Layout(ids=ID10("grp_ID")),
    "/GRTRUS/SUBSET": Layout(ids=ID10("subs_ID")),
    "/GRTRUS/MAT": Layout(ids=ID10("mat_ID")),
    "/GRTRUS/PROP": Layout(ids=ID10("prop_ID")),
    "/GRTRUS/BOX": Layout(ids=ID10("box_ID")),
    "/GRTRUS/BOX2": Layout(ids=ID10("box_ID")),
    "/GRTRUS/GENE": Layout(ids=ID10("elem_ID")),
    "/GRBEAM/BEAM": Layout(ids=ID10("beam_ID")),
    "/GRBEAM/PART": Layout(ids=ID10("part_ID")),
    "/GRBEAM/GRBEAM": Layout(ids=ID10("grp_ID")),
    "/GRBEAM/SUBSET": Layout(ids=ID10("subs_ID")),
    "/GRBEAM/MAT": Layout(ids=ID10("mat_ID")),
    "/GRBEAM/PROP": Layout(ids=ID10("prop_ID")),
    "/GRBEAM/BOX": Layout(ids=ID10("box_ID")),
    "/GRBEAM/BOX2": Layout(ids=ID10("box_ID")),
    "/GRBEAM/GENE": Layout(ids=ID10("elem_ID")),
    "/GRNOD/GRTRUS": Layout(ids=ID10("grtr_ID")),
    "/GRNOD/GRBEAM": Layout(ids=ID10("grbm_ID")),
    "/SURF/PART": Layout(ids=ID10("part_ID")),
    "/SURF/PART/EXT": Layout(ids=ID10("part_ID")),
    "/SURF/PART/ALL": Layout(ids=ID10("part_ID")),
    "/SURF/GRSHEL": Layout(ids=ID10("grsh_ID")),
    "/SURF/GRSH3N": Layout(ids=ID10("gr3n_ID")),
    "/SURF/GRBRIC": Layout(ids=ID10("grbr_ID")),
    "/SURF/GRBRIC/EXT": Layout(ids=ID10("grbr_ID")),
    "/SURF/GRBRIC/FREE": Layout(ids=ID10("grbr_ID")),
    "/SURF/SEG": Layout(rows=Card(i("seg_ID"), i("node_ID1"), i("node_ID2"), i("node_ID3"), i("node_ID4"))),
    "/BOX/RECTA": Layout(Card(i("N1"), i("N2"), i("Iskew")), Card(r("Xp1"), r("Yp1"), r("Zp1")),
                         Card(r("Xp2"), r("Yp2"), r("Zp2"))),
    "/BOX/CYLIN": Layout(Card(i("N1"), i("N2"), gap(10), r("Diameter")), Card(r("Xp1"), r("Yp1"), r("Zp1")),
                         Card(r("Xp2"), r("Yp2"), r("Zp2"))),
    "/BOX/SPHER": Layout(Card(i("N1"), gap(20), r("Diameter")), Card(r("Xp1"), r("Yp1"), r("Zp1"))),
    # --- contact
    # The friction cards C1..C5 (Ifric 1, 2, 3) and C6 (Ifric 2, 3): an Ifric outside 0..3 has none.
    "/INTER/TYPE7": Layout(
        Card(i("grnd_IDs"), i("surf_IDm"), i("Istf"), i("Ithe"), i("Igap"), i("Multimp", until=110), i("Ibag"),
             i("Idel"), i("Icurv"), i("Iadm")),
        Card(r("Fscalegap"), r("Gap_max"), r("Fpenmax", since=120), gap(20), i("Itied", since=2020),
             i("Ists", since=2026)),
        Card(r("Stmin"), r("Stmax"), r("%mesh_size", since=110), r("dtmin", since=120), i("Irem_gap", since=120),
             i("Irem_i2", since=130)),
        Card(i("node_ID1"), i("node_ID2"), when=lambda v: _int(v.get("Icurv")) in (1, 2)),
        Card(r("Stfac"), r("Fric"), r("Gapmin"), r("Tstart"), r("Tstop")),
        Card(s("IBC"), gap(20), i("Inacti"), r("VISs"), r("VISf"), r("Bumult")),
        Card(i("Ifric"), i("Ifiltr"), r("Xfreq"), i("Iform"), i("sens_ID", since=120), i("fct_IDF", since=140),
             r("AscaleF", since=140), i("fric_ID", since=2018)),
        Card(r("C1"), r("C2"), r("C3"), r("C4"), r("C5"), when=lambda v: _int(v.get("Ifric")) in (1, 2, 3)),
        Card(r("C6"), when=lambda v: _int(v.get("Ifric")) in (2, 3))),
    # Only the standard card: the rupture (Spotflag 20..22) and penalty (25, 26) cards radx refuses.
    "/INTER/TYPE2": Layout(
        Card(i("grnd_IDs"), i("surf_IDm"), i("Ignore", since=110), i("Spotflag"), i("Level"), i("Isearch"),
             i("Idel2"), gap(10), r("Dsearch"))),
    "/INTER/LAGDT/TYPE7": Layout(
        Card(i("grnd_IDs"), i("surf_IDm"), i("Istf"), gap(10), i("Igap"), i("Multimp", until=130), i("Ibag"),
             i("Idel")),
        Card(r("Fscalegap"), r("Gapmax")),
        Card(r("Stmin"), r("Stmax")),
        Card(r("Stfac"), r("Fric"), r("Gapmin"), r("Tstart"), r("Tstop")),
        Card(s("IBC"), gap(20), i("Inacti"), r("VISs"), r("VISf"), r("Bumult")),
        Card(i("Ifric"), i("Ifiltr"), r("Xfreq"), i("Iform")),
        Card(r("C1"), r("C2"), r("C3"), r("C4"), r("C5"), when=lambda v: _int(v.get("Ifric")) in (1, 2, 3)),
        Card(r("C6"), when=lambda v: _int(v.get("Ifric")) in (2, 3))),
    # the law: a free text line after the interface id (docs/theory/contact-laws.md)
    "/CTCLAW": Layout(Card(i("inter_ID")), Card(left("law", 100, wrap=","), names=False)),
    # --- boundary conditions and loads
    "/BCS": Layout(Card(s("Tra rot"), i("skew_ID"), i("grnod_ID"))),
    "/IMPVEL": Layout(
        Card(i("funct_IDT"), s("Dir"), i("skew_ID"), i("sensor_ID"), i("grnod_ID"), i("frame_ID"),
             i("Icoor", since=120)),
        Card(r("Ascale_x"), r("Fscale_y"), r("Tstart"), r("Tstop"))),
    "/IMPDISP": Layout(
        Card(i("funct_IDT"), s("Dir"), i("skew_ID"), i("sensor_ID"), i("grnod_ID"), i("frame_ID", since=110),
             i("Icoor", since=120)),
        Card(r("Ascale_x"), r("Fscale_y"), r("Tstart"), r("Tstop"))),
    "/IMPDISP/FGEO": Layout(
        Card(i("fct_ID"), i("part_ID"), gap(10), i("sens_ID")),
        Card(r("Ascale"), gap(20), r("Tstart"), r("Tstop")),
        rows=Card(i("node_IDN"), r("Xn"), r("Yn"), r("Zn"))),
    "/INIVEL/TRA": Layout(
        Card(r("Vx"), r("Vy"), r("Vz"), i("grnod_ID"), i("skew_ID")),
        Card(r("Tstart"), i("sensor_ID"), since=2025)),
    "/INIVEL/ROT": Layout(
        Card(r("Vx"), r("Vy"), r("Vz"), i("grnod_ID"), i("skew_ID")),
        Card(r("Tstart"), i("sensor_ID"), since=2025)),
    "/ADMAS/0": Layout(Card(r("MASS"), i("grnod_ID"))),
    "/ADMAS/1": Layout(Card(r("MASS"), i("grnod_ID"))),
    "/SKEW/FIX": Layout(Card(r("Ox"), r("Oy"), r("Oz")), Card(r("X1"), r("Y1"), r("Z1")),
                        Card(r("X2"), r("Y2"), r("Z2"))),
    "/SKEW/MOV": Layout(Card(i("N1"), i("N2"), i("N3"), s("Dir", since=2019))),
    "/FRAME/FIX": Layout(Card(r("Ox"), r("Oy"), r("Oz")), Card(r("X1"), r("Y1"), r("Z1")),
                         Card(r("X2"), r("Y2"), r("Z2"))),
    "/FRAME/MOV": Layout(Card(i("N1"), i("N2"), i("N3"), s("Dir", since=2019))),
    "/ACCEL": Layout(Card(i("node_ID"), i("skew_ID"), gap(10), r("Fcut"))),
    "/CLOAD": Layout(Card(i("funct_IDT"), s("Dir"), i("skew_ID"), i("sensor_ID"), i("grnod_ID"),
                          i("Itypfun", since=2023), r("Ascale_x"), r("Fscale_y"))),
    "/PLOAD": Layout(Card(i("surf_ID"), i("funct_IDT"), i("sensor_ID"), i("Ipinch", since=2020),
                          i("Idel", since=2021), i("Itypfun", since=2023), r("Ascale_x"), r("Fscale_y"))),
    "/GRAV": Layout(Card(i("funct_IDT"), s("DIR"), i("skew_ID"), i("sensor_ID"), i("grnod_ID"), gap(10),
                         r("Ascale_x"), r("Fscale_y"))),
    "/FUNCT": Layout(rows=Card(r("X"), r("Y"))),
    "/MOVE_FUNCT": Layout(Card(r("Ascalex"), r("Fscaley"), r("Ashiftx"), r("Fshifty"))),
    "/SENSOR/TIME": Layout(Card(r("Tdelay")), Card(r("Tstop"), since=2023)),
    "/RWALL/PLANE": Layout(
        Card(i("node_ID"), i("Slide"), i("grnd_ID1"), i("grnd_ID2"), i("Iform", since=2026)),
        Card(r("d"), r("fric"), r("Diameter"), r("ffac"), i("ifq"), when=lambda v: _int(v.get("Slide")) == 2),
        Card(r("d"), when=lambda v: _int(v.get("Slide")) != 2),
        Card(r("XM"), r("YM"), r("ZM"), when=lambda v: _int(v.get("node_ID")) == 0),
        Card(r("Mass"), r("VX0"), r("VY0"), r("VZ0"), when=lambda v: _int(v.get("node_ID")) > 0),
        Card(r("XM1"), r("YM1"), r("ZM1"))),
    "/RBODY": Layout(
        Card(i("node_ID"), i("sens_ID"), i("skew_ID"), i("Ispher"), r("Mass"), i("grnd_ID"), i("Ikrem"), i("ICoG"),
             i("surf_ID")),
        Card(r("Jxx"), r("Jyy"), r("Jzz")),
        Card(r("Jxy"), r("Jyz"), r("Jxz")),
        Card(i("Ioptoff"), i("Iexpams", since=2017), i("Ifail", since=2021), since=110),
        Card(r("FN"), r("FT"), r("expN"), r("expT"), when=lambda v: _int(v.get("Ifail")) > 0, since=2021)),
    "/SECT": Layout(
        Card(i("node_ID1"), i("node_ID2"), i("node_ID3"), i("grnod_ID"), i("I_SAVE"), i("Frame_ID"), r("Dt"),
             r("alpha")),
        Card(left("file_name", 100), names=False),
        Card(i("grbric_ID"), gap(10), i("grshel_ID"), i("grtrus_ID"), i("grbeam_ID"), i("grsprg_ID"),
             i("grtria_ID"), i("Ninter"), gap(10), i("Iframe")),
        Card(*[i("inter_ID%d" % k) for k in range(1, 11)], when=lambda v: _int(v.get("Ninter")) > 0)),
    # --- time histories: variable names, then the objects
    "/TH/NODE": Layout(variables=TH_VARIABLES, rows=Card(
        i("node_ID"), i("skew_ID"), gap(1), left("node_name (columns 21-100)", 79, key="name", name_left=True))),
    "/TH/SHEL": Layout(variables=TH_VARIABLES, rows=Card(i("elem_ID"), i("skew_ID"))),
    "/TH/SH3N": Layout(variables=TH_VARIABLES, rows=Card(i("elem_ID"), i("skew_ID"))),
    "/TH/BRIC": Layout(variables=TH_VARIABLES, rows=Card(i("elem_ID"))),
    "/TH/SPRING": Layout(variables=TH_VARIABLES, rows=Card(i("elem_ID"))),
    "/TH/TRUSS": Layout(variables=TH_VARIABLES, rows=Card(i("elem_ID"))),
    "/TH/BEAM": Layout(variables=TH_VARIABLES, rows=Card(i("elem_ID"))),
    "/TH/PART": Layout(variables=TH_VARIABLES, ids=ID10("part_ID")),
    "/TH/INTER": Layout(variables=TH_VARIABLES, ids=ID10("inter_ID")),
    "/TH/RWALL": Layout(variables=TH_VARIABLES, ids=ID10("rwall_ID")),
    "/TH/SUBS": Layout(variables=TH_VARIABLES, ids=ID10("subs_ID")),
    "/TH/RBODY": Layout(variables=TH_VARIABLES, ids=ID10("rbody_ID")),
    "/TH/SECTIO": Layout(variables=TH_VARIABLES, ids=ID10("sect_ID")),
    "/TH/ACCEL": Layout(variables=TH_VARIABLES, ids=ID10("accel_ID")),
}
LAYOUTS["/TH/BRICK"] = LAYOUTS["/TH/BRIC"]
LAYOUTS["/MAT/LAW2"] = LAYOUTS["/MAT/PLAS_JOHNS"]
for _kind in ("CYL", "SPHER"):
    LAYOUTS["/RWALL/" + _kind] = Layout(
        *LAYOUTS["/RWALL/PLANE"].cards[:2],
        Card(r("d"), gap(20), r("Diameter"), when=lambda v: _int(v.get("Slide")) != 2),
        *LAYOUTS["/RWALL/PLANE"].cards[3:5],
        *([LAYOUTS["/RWALL/PLANE"].cards[5]] if _kind == "CYL" else []))
LAYOUTS["/RWALL/PARAL"] = Layout(*LAYOUTS["/RWALL/PLANE"].cards, Card(r("XM2"), r("YM2"), r("ZM2")))

# Engine keywords (free format: the columns only make the values easy to read).
ENGINE_LAYOUTS = {
    "/RUN": Layout(Card(r("Tstop")), title=False),
    "/TFILE": Layout(Card(r("dt_his")), title=False),
    "/DTIX": Layout(Card(r("DT_ini"), r("DT_max")), title=False),
    "/ANIM/DT": Layout(Card(r("Tstart"), r("dT")), title=False),
    "/DT": Layout(Card(r("Tscale"), r("Tmin")), title=False),
    "/DT/NODA/CST": Layout(Card(r("Tscale"), r("Tmin")), title=False),
    "/DT/INTER/CST": Layout(Card(r("Tscale"), r("Tmin")), title=False),
    "/DT/INTER/DEL": Layout(Card(r("Tscale"), r("Tmin")), title=False),
    "/DT/INTER/LAG": Layout(Card(r("Tscale"), r("Tmin")), title=False),
    "/STOP": Layout(Card(r("Emax"), r("Mmax"), r("Nmax"), i("NTH"), i("NANIM")), title=False),
}


# ---------------------------------------------------------------------------------------------------
# The writer

def _cell(kind, value, width, sig):
    """The text of one field, its width wide."""
    if kind == "-":
        if value is not None:
            raise ValueError("a value for a blank gap")
        return " " * width
    if value is None:
        return " " * width
    if kind == "I":
        return I(value, width)
    if kind == "R":
        return R(value, width, sig)
    text = str(value)
    if len(text) > width:
        raise ValueError("text %r does not fit in %d columns" % (text, width))
    return text.ljust(width) if kind == "L" else text.rjust(width)


def _place(cells):
    """One line from (first column, text) cells, trailing blanks dropped."""
    end = 1
    for col, text in cells:
        if col != end:
            break
        end += len(text)
    else:  # side by side from column 1 (most lines): no need to place them
        return "".join(text for _, text in cells).rstrip()
    out = [" "] * MAX_COLUMNS
    for col, text in cells:
        out[col - 1:col - 1 + len(text)] = list(text)
    return "".join(out).rstrip()


def name_line(fields_at):
    """The field-name comment line of (first column, field) pairs: each name right-justified over its field
    (left-justified when the field says so), '#' in column 1."""
    cells = []
    for col, f in fields_at:
        if f.kind == "-" or not f.name:
            continue
        cells.append((col, f.name.ljust(f.width) if f.name_left else f.name.rjust(f.width)))
    text = _place(cells)
    if text.startswith(" "):
        return "#" + text[1:]
    if cells and cells[0][0] == 1 and fields_at[0][1].name_left:
        return "#" + text  # a left-justified name in column 1 follows the '#'
    raise ValueError("first field name fills column 1: %r" % text)


def data_line(fields_at, values, sig=None):
    """The data line of (first column, field) pairs and their values (None: blank)."""
    cells = [(col, _cell(f.kind, v, f.width, sig)) for (col, f), v in zip(fields_at, values)]
    return _place(cells)


def _fields(card, version):
    return [(col, f) for col, f in card.columns if f.in_version(version)]


def _list_lines(spec, values, sig=None):
    """An id list (or /TH variable list): the comment line names as many as the first line holds, then the
    values spec.per_line to a line. (text, mark) pairs, as marked() gives them."""
    if not values:
        raise ValueError("empty %s list" % spec.name)
    n = min(spec.per_line, len(values))
    fields = [(1 + k * spec.width, Field("%s%d" % (spec.name, k + 1), spec.kind, spec.width)) for k in range(n)]
    out = [(name_line(fields), None)]
    for k in range(0, len(values), spec.per_line):
        chunk = values[k:k + spec.per_line]
        out.append((data_line(fields[:len(chunk)], chunk, sig), (spec.key,)))
    return out


def _wrapped(f, value):
    """The lines of a text field that may go on over several lines (Field.wrap)."""
    if isinstance(value, (list, tuple)):
        parts = list(value)
    else:
        parts, rest = [], str(value)
        while len(rest) > f.width:
            k = max(rest.rfind(c, 0, f.width) for c in f.wrap) + 1
            if k == 0:
                raise ValueError("text %r has no %r to break it at within %d columns" % (rest, f.wrap, f.width))
            parts.append(rest[:k])
            rest = rest[k:]
        parts.append(rest)
    return parts


def keyword_line(keyword, ident=None):
    return keyword if ident is None else "%s/%s" % (keyword, ident)


def card(keyword, ident=None, title=None, **kw):
    """The lines of one keyword: keyword line (with /ident), title line, then for each card of the layout that
    the version has and the values call for, its field-name comment line (unless names=False) and its data
    line; then the variable list, the id list or the rows. sig: reals too long for their field are written
    with sig significant digits. fill=0: the card fields not given are written as 0 (integers) and 0.0
    (reals), text fields stay blank; a value given as None is blank either way. The keyword arguments are
    marked()'s."""
    return [text for text, _ in marked(keyword, ident, title, **kw)]


def marked(keyword, ident=None, title=None, *, rows=None, ids=None, variables=None, sig=None, names=True,
           fill=None, version=VERSION, engine=False, **values):
    """card()'s lines, each as (text, mark), the mark saying what the line holds, so that a generator can
    find the line of a given field (an expected diagnostic's line): 'keyword', 'title', None for a
    field-name comment line, the tuple of the field keys of a card's data line (every line of a wrapped text
    field), ('ids',) or ('variables',) for each line of an id or variable list, ('rows',) for each row."""
    layout = (ENGINE_LAYOUTS if engine else LAYOUTS).get(keyword)
    if layout is None:
        raise ValueError("no card layout for %s" % keyword)
    out = [(keyword_line(keyword, ident), "keyword")]
    if layout.title:
        if title is None:
            raise ValueError("%s needs a title" % keyword)
        out.append((title, "title"))
    elif title is not None:
        raise ValueError("%s has no title line" % keyword)
    used = set()
    for c in layout.cards:
        if not c.in_version(version) or (c.when is not None and not c.when(values)):
            continue
        fields = _fields(c, version)
        row = []
        for _, f in fields:
            if f.kind == "-":
                row.append(None)
                continue
            if f.key in values:
                row.append(values[f.key])
            elif fill is None or f.kind in "SL":
                row.append(None)
            else:
                row.append(int(fill) if f.kind == "I" else float(fill))
            used.add(f.key)
        if names and c.names:
            out.append((name_line(fields), None))
        keys = tuple(f.key for _, f in fields if f.kind != "-")
        if len(fields) == 1 and fields[0][1].wrap and row[0] is not None:
            out += [(data_line(fields, [part], sig), keys) for part in _wrapped(fields[0][1], row[0])]
        else:
            out.append((data_line(fields, row, sig), keys))
    unknown = set(values) - used
    if unknown:
        raise ValueError("%s (version %d) has no field %s" % (keyword, version, ", ".join(sorted(unknown))))
    if layout.variables is not None:
        if variables is None:
            raise ValueError("%s needs its variables" % keyword)
        out += _list_lines(layout.variables, list(variables))
    elif variables is not None:
        raise ValueError("%s takes no variables" % keyword)
    if layout.ids is not None:
        if ids is None:
            raise ValueError("%s needs its ids" % keyword)
        out += _list_lines(layout.ids, list(ids), sig)
    elif ids is not None:
        raise ValueError("%s takes no id list" % keyword)
    if layout.rows is not None:
        if rows is None:
            raise ValueError("%s needs its rows" % keyword)
        if names:
            out.append((name_line(_fields(layout.rows, version)), None))
        out += [(row_line(keyword, row, version, sig), ("rows",)) for row in rows]
    elif rows is not None:
        raise ValueError("%s takes no rows" % keyword)
    return out


def row_line(keyword, row, version=VERSION, sig=None):
    """The data line of one row of a row-list keyword (a tuple in field order; a shorter one leaves the last
    fields blank)."""
    layout = LAYOUTS.get(keyword)
    if layout is None or layout.rows is None:
        raise ValueError("%s is not a row-list keyword" % keyword)
    fields = [(col, f) for col, f in _fields(layout.rows, version) if f.kind != "-"]
    if len(row) > len(fields):
        raise ValueError("%s row %r has more than %d fields" % (keyword, row, len(fields)))
    return data_line(fields[:len(row)], row, sig)


def _layout_card(keyword, card_index, engine, version):
    layout = (ENGINE_LAYOUTS if engine else LAYOUTS).get(keyword)
    if layout is None:
        raise ValueError("no card layout for %s" % keyword)
    return _fields(layout.cards[card_index], version)


def data(keyword, card_index=0, engine=False, version=VERSION, sig=None, **values):
    """The data line alone of one card of a keyword (to replace a card's values in a deck read back)."""
    fields = _layout_card(keyword, card_index, engine, version)
    unknown = set(values) - {f.key for _, f in fields}
    if unknown:
        raise ValueError("%s card %d has no field %s" % (keyword, card_index + 1, ", ".join(sorted(unknown))))
    return data_line(fields, [values.get(f.key) for _, f in fields], sig)


def read(keyword, text, card_index=0, engine=False, version=VERSION):
    """The fields of one data line of a keyword's card, by key: stripped text, '' for a blank field."""
    return {f.key: text[col - 1:col - 1 + f.width].strip()
            for col, f in _layout_card(keyword, card_index, engine, version) if f.kind != "-"}


def rows(keyword, rows_, ident=None, title=None, **kw):
    """card() of a row-list keyword: rows_ is a list of tuples in field order (shorter tuples leave the last
    fields blank)."""
    return card(keyword, ident, title, rows=rows_, **kw)


def bric20_rows(part, rows_):
    """/BRIC20/part: each row (id, n1 .. n20) on three lines, 10-column fields: the id and the 8 corners;
    the mid-side nodes n9-n16 from column 1; n17-n20."""
    head = "".join("%10s" % h for h in ["brick_ID"] + ["node_ID%d" % k for k in range(1, 9)])
    out = ["/BRIC20/%d" % part, "#" + head[1:],
           "#" + "".join("%10s" % ("node_ID%d" % k) for k in range(9, 17))[1:],
           "#" + "".join("%10s" % ("node_ID%d" % k) for k in range(17, 21))[1:]]
    for r in rows_:
        assert len(r) == 21, "a /BRIC20 row is the id and 20 nodes"
        out.append("".join("%10d" % v for v in r[:9]))
        out.append("".join("%10d" % v for v in r[9:17]))
        out.append("".join("%10d" % v for v in r[17:21]))
    return out


def begin(run, units, work_units=None, version=VERSION):
    """/BEGIN: run name, deck version, input units and work units (the input units when not given)."""
    work_units = work_units or units
    return card("/BEGIN", RUNNAME=run, INVERS=version, Input_mass=units[0], Input_length=units[1],
                Input_time=units[2], Work_mass=work_units[0], Work_length=work_units[1], Work_time=work_units[2],
                version=version)


class Deck:
    """The lines of one deck file. Starter decks take LAYOUTS in their version; Deck(engine=True) takes
    ENGINE_LAYOUTS; fill is card()'s default fill. Every method returns the deck, so calls can chain."""

    def __init__(self, version=VERSION, engine=False, fill=None):
        self.version, self.engine, self.fill, self.lines = version, engine, fill, []

    def raw(self, *lines):
        """Lines as they are (a keyword without cards, a deliberately odd line)."""
        self.lines.extend(lines)
        return self

    def comment(self, *texts):
        """'# text' lines."""
        self.lines.extend("# " + t if t else "#" for t in texts)
        return self

    def ruler(self):
        self.lines.append(RULER)
        return self

    def begin(self, run, units, work_units=None):
        self.lines += begin(run, units, work_units, self.version)
        return self

    def card(self, keyword, ident=None, title=None, **kw):
        kw.setdefault("version", self.version)
        kw.setdefault("fill", self.fill)
        self.lines += card(keyword, ident, title, engine=self.engine, **kw)
        return self

    def rows(self, keyword, rows_, ident=None, title=None, **kw):
        return self.card(keyword, ident, title, rows=rows_, **kw)

    def __iadd__(self, lines):
        self.lines += lines
        return self

    def write(self, path, report=False):
        write(path, self.lines, report)
        return self
