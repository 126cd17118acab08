#!/usr/bin/env python3
"""Independent column and consistency checker for the decks under decks/ (plain python3).

This is NOT radx's reader. It is a small second implementation, written from docs/theory/deck-format.md, used to check
the hand-made and generated decks:

  * every line is at most 100 columns and has no tab;
  * every data token lies inside one field of its card (so nothing straddles two fields or sits in unused
    columns) and parses as that field's type; integers are right-justified;
  * the field-name comment line in front of a card has each name ending at a field's last column;
  * cross references, duplicate ids, empty groups, element geometry and a few value checks; boxes select nodes
    where the starter sees them: in work units and moved by the transforms of their submodel.

Deck versions: the formats 90, 100, 110, 120, 130, 140 and 2017 to 2026. The layouts of 2017 and newer come
from docs/theory/deck-format.md; those of 90 to 140 from the FORMAT(radiossNNN) blocks OpenRadioss reads each keyword
with (the block of the highest version at or below the deck's), restated here as facts about the file format.

Problems are reported with the RX codes of parser/reading/diagnostics.hpp. For decks that carry `# expect:` lines
(decks/invalid/), the set of problems found must equal the set expected; for the other decks it must be
empty. Exit status 0 when every deck checks out.

    python3 scripts/check_decks.py                 # every deck under decks/
    python3 scripts/check_decks.py FILE.rad ...    # given decks (one-file, starter or engine)
    python3 scripts/check_decks.py -v FILE.rad     # also print what was read
"""
import math
import os
import re
import sys

SPRING_PROPS = ("/PROP/SPRING", "/PROP/TYPE4", "/PROP/SPR_GENE", "/PROP/TYPE8", "/PROP/SPR_BEAM", "/PROP/TYPE13")
SIX_LAW_PROPS = ("/PROP/SPR_GENE", "/PROP/TYPE8", "/PROP/SPR_BEAM", "/PROP/TYPE13")
# The spring hardening flags radx runs (check_formulations.cpp spring_h_runs); TYPE13 as TYPE8
SPRING_H_TYPE4 = (0, 1, 2, 4, 5, 6, 7, 8)
SPRING_H_TYPE8 = (0, 1, 2, 4, 5, 6, 7)
RULER_RE = re.compile(r"^#-+1-+\|")
REAL_RE = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([EeDd][+-]?\d+|[+-]\d+)?$")
INT_RE = re.compile(r"^[+-]?\d+$")
EXPECT_RE = re.compile(r"^#\s*expect:\s*(RX\d{3})\s+line\s+(\d+)(?:\s+file\s+(\S+))?(?:\s+warning)?\s*$")

SI_PREFIXES = {"y", "z", "a", "f", "p", "n", "u", "mu", "\u00b5", "\u03bc", "m", "c", "d", "", "da", "h", "k", "K",
               "M", "G", "T", "P", "E", "Z", "Y"}


class Units:
    """Unit names of one kind as Radioss reads them: an SI prefix before the base unit, and the names radx
    also reads (t, lb, in, ft, min, h)."""

    def __init__(self, base, extra):
        self.base, self.extra = base, extra

    def __contains__(self, name):
        return name in self.extra or (name.endswith(self.base) and name[:-1] in SI_PREFIXES)


MASS_UNITS = Units("g", {"t", "ton", "lb"})
LENGTH_UNITS = Units("m", {"in", "ft"})
TIME_UNITS = Units("s", {"min", "h"})

# Radioss keyword roots radx does not read: "not supported" (RX302) rather than unknown (RX301).
UNSUPPORTED_ROOTS = ("/MAT/", "/PROP/", "/INTER/", "/BEAM", "/TRUSS", "/RBE2", "/RBE3", "/MONVOL",
                     "/SENSOR", "/SKEW", "/FRAME", "/ADMAS", "/TETRA4", "/TETRA10", "/FAIL", "/EOS", "/TABLE",
                     "/SECT/PARAL", "/SECT/CIRCLE", "/GAUGE", "/SPHCEL", "/PARAMETER", "/INISHE", "/INIBRI", "/GRSHEL",
                     "/GRBRIC", "/LINE", "/MERGE", "/CYL_JOINT", "/IMPDISP", "/IMPACC", "/FXBODY", "/DAMP",
                     "/TH/", "/ALE/", "/EBCS", "/VISC/", "/ANIM/", "/AMS", "/CAA", "/XREF", "/REFSTA",
                     "/FUNCT_PYTHON", "/ACTIV", "/LEAK", "/DFS", "/INIGRAV", "/INIMAP1D", "/INIMAP2D", "/PERTURB",
                     "/STATE", "/SET/")
# Radioss keywords radx does not read, matched as whole words (/DT and /DT/..., not /DTX).
UNSUPPORTED_WORDS = ("/CONVEC", "/RADIATION", "/IMPFLUX", "/IMPTEMP", "/THERM_STRESS", "/HEAT", "/INITEMP",
                     "/ANIM", "/PRINT", "/PARITH", "/DT", "/RUN", "/STOP", "/RFILE", "/EIG", "/STAMPING", "/NBCS",
                     "/CLOAD", "/UPWIND", "/EXTERN", "/NONLOCAL", "/SPHGLO", "/MADYMO", "/INCLUDE",
                     "/INCLUDE_LS-DYNA", "/MONVOL", "/IMPL", "/IMPLICIT", "/H3D")


def F(name, typ, a, b):
    return (name, typ, a, b)


def reals(*specs):
    """R fields of 20 columns: reals('a', 'b') -> a 1-20, b 21-40."""
    return [F(n, "R", 1 + 20 * k, 20 + 20 * k) for k, n in enumerate(specs) if n]


def card(fields, cond=None, optional=False, gate=None):
    """gate: {field: (a, b)}: the field is read only when columns a-b of the line hold text."""
    return {"fields": fields, "cond": cond, "optional": optional, "gate": gate or {}}


# The deck formats the reader reads; 90..140 are the old numbering (140 comes before 2017).
VERSIONS = (90, 100, 110, 120, 130, 140) + tuple(range(2017, 2027))


# ---------------------------------------------------------------------------------------------------
# Starter keyword layouts (docs/keywords.md), by deck version v


def def_shell(v):
    f = [F("Ishell", "I", 1, 10), F("Ismstr", "I", 11, 20), F("Ithick", "I", 21, 30), F("Iplas", "I", 31, 40),
         F("Istrain", "I", 41, 50)]
    if v >= 2024:
        f.append(F("Ioffset", "I", 51, 60))
    f.append(F("Ish3n", "I", 71, 80))
    if v >= 110:
        f.append(F("Idrill", "I", 81, 90))
    if v >= 2026:
        f.append(F("Ithin_drape", "I", 91, 100))
    return [card(f)]


def def_solid(v):
    f = [F("Isolid", "I", 1, 10), F("Ismstr", "I", 11, 20)]
    if v >= 2021:
        f.append(F("Icpre", "I", 21, 30))
    elif v >= 100:
        f.append(F("Istrain", "I", 31, 40))
    if v >= 2019:
        f += [F("Itetra4", "I", 41, 50), F("Itetra10", "I", 51, 60)]
    if v >= 120:
        f.append(F("Imas", "I", 61, 70))
    f.append(F("Iframe", "I", 71, 80))
    if v >= 2025:
        f.append(F("Icontrol", "I", 81, 90))
    return [card(f)]


def part(v):
    return [card([F("prop_ID", "I", 1, 10), F("mat_ID", "I", 11, 20), F("subset_ID", "I", 21, 30),
                  F("Thick", "R", 31, 50)])]


def prop_shell(v):
    c1 = [F("Ishell", "I", 1, 10), F("Ismstr", "I", 11, 20), F("Ish3n", "I", 21, 30)]
    if v >= 110:
        c1.append(F("Idrill", "I", 31, 40))
    if v >= 2020:
        c1.append(F("Ipinch", "I", 41, 50))
    if v >= 2018:
        c1.append(F("P_Thick_Fail", "R", 61, 80))
    c2 = reals("Hm", "Hf", "Hr", "Dm", "Dn")
    c3 = [F("N", "I", 1, 10)]
    if v < 2024:
        c3.append(F("Istrain", "I", 11, 20))
    c3 += [F("Thick", "R", 21, 40), F("Ashear", "R", 41, 60), F("Ithick", "I", 71, 80), F("Iplas", "I", 81, 90)]
    if v >= 2024:
        c3.append(F("Ipos", "I", 91, 100))
    return [card(c1), card(c2), card(c3)]


def prop_spring(v):
    """/PROP/SPRING (TYPE4): fct_ID4 and Hscale from the 120 layout on (prop_p4_spring.cfg)."""
    c1 = [F("M", "R", 1, 20), F("sens_ID", "I", 51, 60), F("Isflag", "I", 61, 70), F("Ileng", "I", 71, 80)]
    c2 = reals("K", "C", "A", "B", "D")
    c3 = [F("fct_ID1", "I", 1, 10), F("H", "I", 11, 20), F("fct_ID2", "I", 21, 30), F("fct_ID3", "I", 31, 40)]
    if v >= 120:
        c3.append(F("fct_ID4", "I", 41, 50))
    c3 += [F("delta_min", "R", 61, 80), F("delta_max", "R", 81, 100)]
    c4 = reals("F", "E", "Ascale", "Hscale" if v >= 120 else None)
    return [card(c1), card(c2), card(c3), card(c4)]


def prop_spr_gene(v):
    """/PROP/SPR_GENE (TYPE8), the 120 layout on (prop_p8_spr_gene.cfg; Ifail2 from 2018): six blocks of three
    cards, the fields of /PROP/SPRING numbered by degree of freedom (K1, fct_ID11, delta_min1, ...)."""
    c1 = [F("M", "R", 1, 20), F("Inertia", "R", 21, 40), F("skew_ID", "I", 41, 50), F("sens_ID", "I", 51, 60),
          F("Isflag", "I", 61, 70), F("Ifail", "I", 71, 80)]
    if v >= 2018:
        c1.append(F("Ifail2", "I", 81, 90))
    c1.append(F("Iequil", "I", 91, 100))
    cards = [card(c1)]
    for d in "123456":
        cards.append(card(reals("K" + d, "C" + d, "A" + d, "B" + d, "D" + d)))
        cards.append(card([F("fct_ID1" + d, "I", 1, 10), F("H" + d, "I", 11, 20), F("fct_ID2" + d, "I", 21, 30),
                           F("fct_ID3" + d, "I", 31, 40), F("fct_ID4" + d, "I", 41, 50),
                           F("delta_min" + d, "R", 61, 80), F("delta_max" + d, "R", 81, 100)]))
        cards.append(card(reals("F" + d, "E" + d, "Ascale" + d, "Hscale" + d)))
    cards.append(card([F("Fsmooth", "I", 1, 10), F("Fcut", "R", 11, 30)]))
    return cards


def prop_spr_beam(v):
    """/PROP/SPR_BEAM (TYPE13), the 120 layout on (prop_p13_spr_beam.cfg; Asrate and Israte from 2018): the six
    blocks of /PROP/SPR_GENE after a card with Ileng and Ifail2, then the reference velocities and six cards of
    failure parameters."""
    c1 = [F("M", "R", 1, 20), F("Inertia", "R", 21, 40), F("skew_ID", "I", 41, 50), F("sens_ID", "I", 51, 60),
          F("Isflag", "I", 61, 70), F("Ifail", "I", 71, 80), F("Ileng", "I", 81, 90), F("Ifail2", "I", 91, 100)]
    cards = [card(c1)] + prop_spr_gene(v)[1:-1]
    cv = [F("Vo", "R", 1, 20), F("Wo", "R", 21, 40)]
    if v >= 2018:
        cv += [F("Asrate", "R", 41, 60), F("Israte", "I", 61, 70)]
    cards.append(card(cv))
    for d in "123456":
        cards.append(card(reals("c" + d, "n" + d, "alpha" + d, "beta" + d)))
    return cards


def prop_solid(v):
    c1 = [F("Isolid", "I", 1, 10), F("Ismstr", "I", 11, 20)]
    if v >= 2022:
        c1.append(F("Iale", "I", 21, 30))
    c1.append(F("Icpre", "I", 31, 40))
    if v >= 2019:
        c1.append(F("Itetra10", "I", 41, 50))
    c1.append(F("Inpts", "I", 51, 60))
    if v >= 100:
        c1.append(F("Itetra4", "I", 61, 70))
    c1 += [F("Iframe", "I", 71, 80), F("dn", "R", 81, 100)]
    c2 = reals("qa", "qb", "h", "Lambda" if v >= 120 else None, "Mu" if v >= 120 else None)
    if v >= 2023:
        c3 = reals("deltaT_min", "vdef_min", "vdef_max", "ASP_max", "COL_min")
    else:
        c3 = [F("deltaT_min", "R", 1, 20)]
        if v >= 100:
            c3.append(F("Istrain", "I", 21, 30))
        if v >= 120:
            c3.append(F("Ihkt", "I", 31, 40))
    if v < 140:  # no solid-to-SPH card before the 140 layout
        return [card(c1), card(c2), card(c3)]
    c4 = [F("Ndir", "I", 1, 10), F("sphpart_ID", "I", 11, 20)]
    if v >= 2025:
        c4.append(F("Icontrol", "I", 21, 30))
    return [card(c1), card(c2), card(c3), card(c4, optional=True)]


def mat_law1(v):
    return [card(reals("RHO_I", "RHO_ref")), card(reals("E", "nu"))]


def mat_void(v):
    """/MAT/VOID: one optional card, every value may be blank."""
    return [card(reals("RHO_I", "E", "nu"), optional=True)]


def mat_law42(v):
    """/MAT/OGDEN: Iform at 91-100 from 140; the mu_6..10 and alpha_6..10 cards are blank before 140 (read as 0)."""
    c2 = [F("nu", "R", 1, 20), F("sigma_cut", "R", 21, 40), F("Jstrain", "I", 41, 50), F("fct_IDbulk", "I", 51, 60),
          F("Fscale_bulk", "R", 61, 80), F("M", "I", 81, 90)]
    if v >= 140:
        c2.append(F("Iform", "I", 91, 100))
    return [card(reals("RHO_I", "RHO_ref")), card(c2),
            card(reals("mu_1", "mu_2", "mu_3", "mu_4", "mu_5")), card(reals("mu_6", "mu_7", "mu_8", "mu_9", "mu_10")),
            card(reals("alpha_1", "alpha_2", "alpha_3", "alpha_4", "alpha_5")),
            card(reals("alpha_6", "alpha_7", "alpha_8", "alpha_9", "alpha_10"))]


def mat_law2(v):
    """Up to 130: RHO_ref only when columns 11-20 hold text (the old pre-read), no Iflag, no Chard in 90."""
    c2 = [F("E", "R", 1, 20), F("nu", "R", 21, 40)]
    if v >= 140:
        c2.append(F("Iflag", "I", 41, 50))
    if v >= 2023:
        c2.append(F("flagVP", "I", 51, 60))
    if v >= 2025:
        c2.append(F("Pmin", "R", 61, 80))
    c4 = [F("c", "R", 1, 20), F("EPS_DOT_0", "R", 21, 40), F("ICC", "I", 41, 50), F("Fsmooth", "I", 51, 60),
          F("F_cut", "R", 61, 80)]
    if v >= 100:
        c4.append(F("Chard", "R", 81, 100))
    c5 = reals("m", "T_melt", "rhoC_p", "T_r", "T_max" if v >= 2025 else None)
    c1 = card(reals("RHO_I", "RHO_ref"), gate={"RHO_ref": (11, 20)} if v <= 130 else None)
    return [c1, card(c2), card(reals("a", "b", "n", "EPS_p_max", "SIG_max0")), card(c4), card(c5)]


def mat_law27(v):
    """/MAT/PLAS_BRIT: Fsmooth and Fcut from the 2019 layout; columns 61-80 of the yield card are blank."""
    c4 = [F("c", "R", 1, 20), F("EPS_DOT_0", "R", 21, 40), F("ICC", "I", 41, 50)]
    if v >= 2019:
        c4 += [F("Fsmooth", "I", 51, 60), F("Fcut", "R", 61, 80)]
    return [card(reals("RHO_I", "RHO_ref")), card(reals("E", "nu")),
            card([F("a", "R", 1, 20), F("b", "R", 21, 40), F("n", "R", 41, 60), F("SIG_max0", "R", 81, 100)]),
            card(c4), card(reals("EPS_t1", "EPS_m1", "d_max1", "EPS_f1")),
            card(reals("EPS_t2", "EPS_m2", "d_max2", "EPS_f2"))]


def mat_law36(v):
    """/MAT/PLAS_TAB: VP at 91-100 from 2017, Fct_IDE, EInf, CE from 120; then the N_funct function ids (10
    columns), scale factors and strain rates (20 columns), 5 a line, as many lines as N_funct needs."""
    c3 = [F("N_funct", "I", 1, 10), F("Fsmooth", "I", 11, 20)] + [
        F(n, "R", a, b) for n, a, b in (("Chard", 21, 40), ("Fcut", 41, 60), ("Eps_f", 61, 80))]
    if v >= 2017:
        c3.append(F("VP", "I", 91, 100))
    c4 = [F("fct_IDp", "I", 1, 10), F("Fscale", "R", 11, 30)]
    if v >= 120:
        c4 += [F("Fct_IDE", "I", 31, 40), F("EInf", "R", 41, 60), F("CE", "R", 61, 80)]
    cards = [card(reals("RHO_I", "RHO_ref")), card(reals("E", "nu", "Eps_p_max", "Eps_t", "Eps_m")), card(c3),
             card(c4)]
    for base, kind, width in (("fct_ID", "I", 10), ("Fscale", "R", 20), ("Eps_dot", "R", 20)):
        for j in range(20):
            fields = [F("%s%d" % (base, 5 * j + c + 1), kind, width * c + 1, width * (c + 1)) for c in range(5)]
            cards.append(card(fields, cond=lambda x, j=j: x.get("N_funct", 0) > 5 * j))
    return cards


def mat_law70(v):
    """/MAT/FOAM_TAB: Itens at 81-90 from 120, Iflag, Shape, Hys from 90; then Nload lines and Nunload lines
    (function 1-10, rate 11-30, scale 31-50), radx reads up to 10 each; the tension line when Itens = 1 (120+)."""
    c2 = [F("E0", "R", 1, 20), F("nu", "R", 21, 40), F("E_max", "R", 41, 60), F("Eps_max", "R", 61, 80)]
    if v >= 120:
        c2.append(F("Itens", "I", 81, 90))
    c3 = [F("Fcut", "R", 1, 20), F("Ismooth", "I", 21, 30), F("Nload", "I", 31, 40), F("Nunload", "I", 41, 50)]
    if v >= 90:
        c3 += [F("Iflag", "I", 51, 60), F("Shape", "R", 61, 80), F("Hys", "R", 81, 100)]
    cards = [card(reals("RHO_I", "RHO_ref")), card(c2), card(c3)]
    for what, count in (("L", "Nload"), ("U", "Nunload")):
        for k in range(10):
            fields = [F("fct_%s%d" % (what, k + 1), "I", 1, 10), F("rate_%s%d" % (what, k + 1), "R", 11, 30),
                      F("scale_%s%d" % (what, k + 1), "R", 31, 50)]
            cards.append(card(fields, cond=lambda x, k=k, count=count: x.get(count, 0) > k))
    if v >= 120:
        cards.append(card([F("fctIDTens", "I", 1, 10), F("FscaleTens", "R", 11, 30)],
                          cond=lambda x: x.get("Itens", 0) == 1))
    return cards


def fail_johnson(v):
    """/FAIL/JOHNSON/mat_ID (no title): EPSF_MIN from 2024, Dadv from 130, Ixfem from 120, FAILIP from 2025, then
    the optional fail_ID card."""
    c2 = [F("Epsilon_Dot_0", "R", 1, 20), F("Ifail_sh", "I", 21, 30), F("Ifail_so", "I", 31, 40)]
    if v >= 2024:
        c2.append(F("EPSF_MIN", "R", 41, 60))
    if v >= 130:
        c2.append(F("Dadv", "R", 61, 80))
    if v >= 120:
        c2.append(F("Ixfem", "I", 91, 100))
    cards = [card(reals("D1", "D2", "D3", "D4", "D5")), card(c2)]
    if v >= 2025:
        cards.append(card([F("FAILIP", "I", 1, 10)], optional=True))
    cards.append(card([F("fail_ID", "I", 1, 10)], optional=True))
    return cards


def fail_biquad(v):
    """/FAIL/BIQUAD/mat_ID (no title), the radioss2017..2026 layouts: C1..C5; P_thickfail, M_Flag, S_Flag,
    Inst_start, with Ireg at 61-70 from 2026, fct_IDel 71-80 and EI_ref 81-100 from 2018; R1 R2 R4 R5 when
    M_Flag = 99; ICOUP 11-20, DCRIT, EXP from 2024 and FAILIP 61-70 from 2025; the optional fail_ID card."""
    c2 = [F("P_thickfail", "R", 1, 20), F("M_Flag", "I", 21, 30), F("S_Flag", "I", 31, 40),
          F("Inst_start", "R", 41, 60)]
    if v >= 2026:
        c2.append(F("Ireg", "I", 61, 70))
    if v >= 2018:
        c2 += [F("fct_IDel", "I", 71, 80), F("EI_ref", "R", 81, 100)]
    cards = [card(reals("C1", "C2", "C3", "C4", "C5")), card(c2),
             card(reals("R1", "R2", "R4", "R5"), cond=lambda x: x.get("M_Flag", 0) == 99)]
    if v >= 2024:
        c4 = [F("ICOUP", "I", 11, 20), F("DCRIT", "R", 21, 40), F("EXP", "R", 41, 60)]
        if v >= 2025:
            c4.append(F("FAILIP", "I", 61, 70))
        cards.append(card(c4))
    cards.append(card([F("fail_ID", "I", 1, 10)], optional=True))
    return cards


def fail_tab(v):
    """/FAIL/TAB/mat_ID (no title), the radioss110..2018 layouts: P_thickfail at 61-80 in 110, at 41-60 before
    (the 100 QA decks) and from 120 (with Ixfem at 91-100); Dadv from 120; N_rate lines of fct_ID, Fscale,
    Epsdot; the element-size and temperature cards; the optional fail_ID card from 130."""
    c1 = [F("Ifail_sh", "I", 1, 10), F("Ifail_so", "I", 11, 20), F("N_rate", "I", 21, 30)]
    c1.append(F("P_thickfail", "R", 61, 80) if v == 110 else F("P_thickfail", "R", 41, 60))
    if v >= 120:
        c1.append(F("Ixfem", "I", 91, 100))
    c2 = [F("Dcrit", "R", 1, 20), F("D", "R", 21, 40), F("n", "R", 41, 60)]
    if v >= 120:
        c2.append(F("Dadv", "R", 61, 80))
    cards = [card(c1), card(c2)]
    for i in range(100):
        cards.append(card([F("fct_ID%d" % (i + 1), "I", 1, 10), F("Fscale%d" % (i + 1), "R", 11, 30),
                           F("Epsdot%d" % (i + 1), "R", 31, 50)], cond=lambda x, i=i: x.get("N_rate", 0) > i))
    cards.append(card([F("fct_IDel", "I", 1, 10), F("Fscale_el", "R", 11, 30), F("EI_ref", "R", 31, 50)]))
    cards.append(card([F("fct_IDt", "I", 1, 10), F("FscaleT", "R", 11, 30)]))
    if v >= 130:
        cards.append(card([F("fail_ID", "I", 1, 10)], optional=True))
    return cards


def ibc_fields():
    return [F("IBCX", "I", 8, 8), F("IBCY", "I", 9, 9), F("IBCZ", "I", 10, 10)]


def inter_type2(v):
    """TYPE2 (deck-format of hm_read_inter_type02.F): Ignore 21-30 from 110; the rupture cards for Spotflag 20..22,
    the penalty card for 25, 26."""
    c1 = [F("grnd_IDs", "I", 1, 10), F("surf_IDm", "I", 11, 20)]
    if v >= 110:
        c1.append(F("Ignore", "I", 21, 30))
    c1 += [F("Spotflag", "I", 31, 40), F("Level", "I", 41, 50), F("Isearch", "I", 51, 60), F("Idel2", "I", 61, 70),
           F("Dsearch", "R", 81, 100)]
    rupt = lambda x: x.get("Spotflag", 0) in (20, 21, 22)
    return [card(c1),
            card([F("Rupt", "I", 1, 10), F("Ifiltr", "I", 11, 20), F("fct_IDsr", "I", 21, 30),
                  F("fct_IDsn", "I", 31, 40), F("fct_IDst", "I", 41, 50), F("Isym", "I", 51, 60),
                  F("Max_N_Dist", "R", 61, 80), F("Max_T_Dist", "R", 81, 100)], cond=rupt),
            card(reals("Fscalestress", "Fscalestr_rate", "Fscaledist", "Alpha"), cond=rupt),
            card(reals("Stfac", "Visc"), cond=lambda x: x.get("Spotflag", 0) in (25, 26))]


def inter_type7(v):
    """TYPE7 by version: Multimp 51-60 up to 110; Fpenmax, dtmin, Irem_gap, sens_ID from 120; %mesh_size from
    110; Irem_i2 from 130; fct_IDF, AscaleF and the second thermal card from 140; up to 100 the Iadm card
    follows the thermal card (which the 90 layout reads for Ithe > 1, without Ithe_form)."""
    c1 = [F("grnd_IDs", "I", 1, 10), F("surf_IDm", "I", 11, 20), F("Istf", "I", 21, 30), F("Ithe", "I", 31, 40),
          F("Igap", "I", 41, 50)]
    if v <= 110:
        c1.append(F("Multimp", "I", 51, 60))
    c1 += [F("Ibag", "I", 61, 70), F("Idel", "I", 71, 80), F("Icurv", "I", 81, 90), F("Iadm", "I", 91, 100)]
    c2 = reals("Fscalegap", "Gap_max", "Fpenmax" if v >= 120 else None)
    if v >= 2020:
        c2.append(F("Itied", "I", 81, 90))
    if v >= 2026:
        c2.append(F("Ists", "I", 91, 100))
    c3 = reals("Stmin", "Stmax", "%mesh_size" if v >= 110 else None, "dtmin" if v >= 120 else None)
    if v >= 120:
        c3.append(F("Irem_gap", "I", 81, 90))
    if v >= 130:
        c3.append(F("Irem_i2", "I", 91, 100))
    c4 = [F("node_ID1", "I", 1, 10), F("node_ID2", "I", 11, 20)]
    c5 = reals("Stfac", "Fric", "Gapmin", "Tstart", "Tstop")
    c6 = ibc_fields() + [F("Inacti", "I", 31, 40), F("VISs", "R", 41, 60), F("VISf", "R", 61, 80),
                         F("Bumult", "R", 81, 100)]
    c7 = [F("Ifric", "I", 1, 10), F("Ifiltr", "I", 11, 20), F("Xfreq", "R", 21, 40), F("Iform", "I", 41, 50)]
    if v >= 120:
        c7.append(F("sens_ID", "I", 51, 60))
    if v >= 140:
        c7 += [F("fct_IDF", "I", 61, 70), F("AscaleF", "R", 71, 90)]
    if v >= 2018:
        c7.append(F("fric_ID", "I", 91, 100))
    adm = card([F("NRadm", "I", 1, 10), F("Padm", "R", 11, 30), F("Angladm", "R", 31, 50)],
               cond=lambda x: x.get("Iadm", 0) == 2)
    if v >= 140:
        thermal = [card([F("Kthe", "R", 1, 20), F("fct_IDK", "I", 21, 30), F("Tint", "R", 41, 60),
                         F("Ithe_form", "I", 61, 70), F("AscaleK", "R", 71, 90)], cond=lambda x: x.get("Ithe", 0) == 1),
                   card(reals("Frad", "Drad", "Fheats", "Fheatm"), cond=lambda x: x.get("Ithe", 0) == 1)]
    elif v >= 100:
        thermal = [card([F("Kthe", "R", 1, 20), F("Tint", "R", 41, 60), F("Ithe_form", "I", 61, 70)],
                        cond=lambda x: x.get("Ithe", 0) == 1)]
    else:
        thermal = [card([F("Kthe", "R", 1, 20), F("Tint", "R", 41, 60)], cond=lambda x: (x.get("Ithe") or 0) > 1)]
    tail = [adm] + thermal if v >= 110 else thermal + [adm]
    return [card(c1), card(c2), card(c3), card(c4, cond=lambda x: x.get("Icurv", 0) in (1, 2)), card(c5), card(c6),
            card(c7), card(reals("C1", "C2", "C3", "C4", "C5"), cond=lambda x: x.get("Ifric", 0) > 0),
            card(reals("C6"), cond=lambda x: x.get("Ifric", 0) > 1)] + tail


def inter_lagdt(v):
    c1 = [F("grnd_IDs", "I", 1, 10), F("surf_IDm", "I", 11, 20), F("Istf", "I", 21, 30), F("Igap", "I", 41, 50)]
    if v <= 130:  # the 90 block, used up to 130, has Multimp
        c1.append(F("Multimp", "I", 51, 60))
    c1 += [F("Ibag", "I", 61, 70), F("Idel", "I", 71, 80)]
    c5 = ibc_fields() + [F("Inacti", "I", 31, 40), F("VISs", "R", 41, 60), F("VISf", "R", 61, 80),
                         F("Bumult", "R", 81, 100)]
    c6 = [F("Ifric", "I", 1, 10), F("Ifiltr", "I", 11, 20), F("Xfreq", "R", 21, 40), F("Iform", "I", 41, 50)]
    return [card(c1), card(reals("Fscalegap", "Gapmax")), card(reals("Stmin", "Stmax")),
            card(reals("Stfac", "Fric", "Gapmin", "Tstart", "Tstop")), card(c5), card(c6),
            card(reals("C1", "C2", "C3", "C4", "C5"), cond=lambda x: x.get("Ifric", 0) > 0),
            card(reals("C6"), cond=lambda x: x.get("Ifric", 0) > 1)]


def bcs(v):
    return [card([F("Tx", "I", 4, 4), F("Ty", "I", 5, 5), F("Tz", "I", 6, 6), F("Rx", "I", 8, 8),
                  F("Ry", "I", 9, 9), F("Rz", "I", 10, 10), F("skew_ID", "I", 11, 20), F("grnod_ID", "I", 21, 30)])]


def impvel(v, frame_from=90):
    """/IMPVEL: Icoor from 120. /IMPDISP (frame_from 110): frame_ID from 110, Icoor from 120."""
    c1 = [F("funct_IDT", "I", 1, 10), F("Dir", "S", 11, 20), F("skew_ID", "I", 21, 30), F("sensor_ID", "I", 31, 40),
          F("grnod_ID", "I", 41, 50)]
    if v >= frame_from:
        c1.append(F("frame_ID", "I", 51, 60))
    if v >= 120:
        c1.append(F("Icoor", "I", 61, 70))
    return [card(c1), card(reals("Ascale_x", "Fscale_y", "Tstart", "Tstop"))]


def impdisp(v):
    return impvel(v, frame_from=110)


def skew_fix(v):
    return [card(reals("Ox", "Oy", "Oz")), card(reals("X1", "Y1", "Z1")), card(reals("X2", "Y2", "Z2"))]


def skew_mov(v):
    """/SKEW/MOV: N1 N2 N3; Dir (the axis N1 -> N2 gives, blank = X) from the 2019 layout."""
    f = [F("N1", "I", 1, 10), F("N2", "I", 11, 20), F("N3", "I", 21, 30)]
    if v >= 2019:
        f.append(F("Dir", "S", 31, 40))
    return [card(f)]


def accel(v):
    return [card([F("node_ID", "I", 1, 10), F("skew_ID", "I", 11, 20), F("Fcut", "R", 31, 50)])]


def random_card(v):
    return [card([F("XALEA", "R", 1, 20), F("SEED", "R", 21, 40)])]


def admas(v):
    return [card([F("MASS", "R", 1, 20), F("grnod_ID", "I", 21, 30)])]


def inivel(v):
    cards = [card(reals("Vx", "Vy", "Vz") + [F("grnod_ID", "I", 61, 70), F("skew_ID", "I", 71, 80)])]
    if v >= 2025:
        cards.append(card([F("Tstart", "R", 1, 20), F("sensor_ID", "I", 21, 30)], optional=True))
    return cards


def grav(v):
    return [card([F("funct_IDT", "I", 1, 10), F("DIR", "S", 11, 20), F("skew_ID", "I", 21, 30),
                  F("sensor_ID", "I", 31, 40), F("grnod_ID", "I", 41, 50), F("Ascale_x", "R", 61, 80),
                  F("Fscale_y", "R", 81, 100)])]


def rwall_plane(v):
    """/RWALL/PLANE (docs/keywords.md): card 2 depends on Slide, card 3 on node_ID; Iform only from 2026."""
    c1 = [F("node_ID", "I", 1, 10), F("Slide", "I", 11, 20), F("grnd_ID1", "I", 21, 30), F("grnd_ID2", "I", 31, 40)]
    if v >= 2026:
        c1.append(F("Iform", "I", 41, 50))
    return [card(c1),
            card(reals("d", "fric", "Diameter", "ffac") + [F("ifq", "I", 81, 90)],
                 cond=lambda x: x.get("Slide", 0) == 2),
            card(reals("d"), cond=lambda x: x.get("Slide", 0) != 2),
            card(reals("XM", "YM", "ZM"), cond=lambda x: x.get("node_ID", 0) == 0),
            card(reals("Mass", "VX0", "VY0", "VZ0"), cond=lambda x: x.get("node_ID", 0) > 0),
            card(reals("XM1", "YM1", "ZM1"))]


def rwall_curved(v, with_m1):
    """/RWALL/CYL (with M1, the axis) and /RWALL/SPHER (without): as /RWALL/PLANE, the diameter on card 2
    whatever Slide is."""
    cards = rwall_plane(v)
    cards[2] = card([F("d", "R", 1, 20), F("Diameter", "R", 41, 60)], cond=lambda x: x.get("Slide", 0) != 2)
    return cards if with_m1 else cards[:-1]


def rwall_paral(v):
    """/RWALL/PARAL: the cards of /RWALL/PLANE and a fifth, the corner M2."""
    return rwall_plane(v) + [card(reals("XM2", "YM2", "ZM2"))]


def impdisp_fgeo(v):
    """/IMPDISP/FGEO (the 140 layout, for every version): function, spring part, sensor; the time cards; then one
    line per node with its final position."""
    return [card([F("fct_ID", "I", 1, 10), F("part_ID", "I", 11, 20), F("sens_ID", "I", 31, 40)]),
            card([F("Ascale", "R", 1, 20), F("Tstart", "R", 41, 60), F("Tstop", "R", 61, 80)])]


FGEO_REC = [F("node_IDN", "I", 1, 10), F("Xn", "R", 11, 30), F("Yn", "R", 31, 50), F("Zn", "R", 51, 70)]


def cload(v):
    f = [F("funct_IDT", "I", 1, 10), F("Dir", "S", 11, 20), F("skew_ID", "I", 21, 30), F("sensor_ID", "I", 31, 40),
         F("grnod_ID", "I", 41, 50)]
    if v >= 2023:
        f.append(F("Itypfun", "I", 51, 60))
    return [card(f + [F("Ascale_x", "R", 61, 80), F("Fscale_y", "R", 81, 100)])]


def pload(v):
    """/PLOAD (OpenRadioss pload.cfg): surface, function, sensor; Ipinch from 2020, Idel from 2021, Itypfun from
    2023; then the two scales."""
    f = [F("surf_ID", "I", 1, 10), F("funct_IDT", "I", 11, 20), F("sensor_ID", "I", 21, 30)]
    if v >= 2020:
        f.append(F("Ipinch", "I", 31, 40))
    if v >= 2021:
        f.append(F("Idel", "I", 41, 50))
    if v >= 2023:
        f.append(F("Itypfun", "I", 51, 60))
    return [card(f + [F("Ascale_x", "R", 61, 80), F("Fscale_y", "R", 81, 100)])]


def sensor_time(v):
    """/SENSOR/TIME (OpenRadioss sensor_time.cfg): Tdelay; from 2023 a second card with Tstop (0 = never), which
    may be left out."""
    cards = [card([F("Tdelay", "R", 1, 20)])]
    if v >= 2023:
        cards.append(card([F("Tstop", "R", 1, 20)], optional=True))
    return cards


def rbody(v):
    """/RBODY (docs/keywords.md): cards 1-4; Ifail on card 4 from 2021, and card 5 when it is set. Card 4 starts in
    the 110 layout with Ioptoff alone; Iexpams from 2017."""
    cards = [card([F("node_ID", "I", 1, 10), F("sens_ID", "I", 11, 20), F("skew_ID", "I", 21, 30),
                   F("Ispher", "I", 31, 40), F("Mass", "R", 41, 60), F("grnd_ID", "I", 61, 70),
                   F("Ikrem", "I", 71, 80), F("ICoG", "I", 81, 90), F("surf_ID", "I", 91, 100)]),
             card(reals("Jxx", "Jyy", "Jzz")),
             card(reals("Jxy", "Jyz", "Jxz"))]
    if v >= 110:
        c4 = [F("Ioptoff", "I", 1, 10)]
        if v >= 2017:
            c4.append(F("Iexpams", "I", 11, 20))
        if v >= 2021:
            c4.append(F("Ifail", "I", 21, 30))
        cards.append(card(c4))
    return cards + [card(reals("FN", "FT", "expN", "expT"), cond=lambda x: x.get("Ifail", 0) != 0)]


def sect(v):
    """/SECT (OpenRadioss card layout): frame nodes and cut, the cut-file name, the element groups, and the
    interface ids when Ninter > 0."""
    return [card([F("node_ID1", "I", 1, 10), F("node_ID2", "I", 11, 20), F("node_ID3", "I", 21, 30),
                  F("grnod_ID", "I", 31, 40), F("I_SAVE", "I", 41, 50), F("Frame_ID", "I", 51, 60),
                  F("Dt", "R", 61, 80), F("alpha", "R", 81, 100)]),
            card([F("file_name", "S", 1, 100)]),
            card([F("grbric_ID", "I", 1, 10), F("grshel_ID", "I", 21, 30), F("grtrus_ID", "I", 31, 40),
                  F("grbeam_ID", "I", 41, 50), F("grsprg_ID", "I", 51, 60), F("grtria_ID", "I", 61, 70),
                  F("Ninter", "I", 71, 80), F("Iframe", "I", 91, 100)]),
            card([F("inter%d" % (k + 1), "I", 1 + 10 * k, 10 + 10 * k) for k in range(10)],
                 cond=lambda x: x.get("Ninter", 0) > 0)]


NODE_REC = [F("node_ID", "I", 1, 10), F("X", "R", 11, 30), F("Y", "R", 31, 50), F("Z", "R", 51, 70)]
SHELL_REC = [F("shell_ID", "I", 1, 10)] + [F("n%d" % (k + 1), "I", 11 + 10 * k, 20 + 10 * k) for k in range(4)] + \
    [F("PHI", "R", 61, 80), F("Thick", "R", 81, 100)]
BRICK_REC = [F("brick_ID", "I", 1, 10)] + [F("n%d" % (k + 1), "I", 11 + 10 * k, 20 + 10 * k) for k in range(8)]
SPRING_REC = [F("spring_ID", "I", 1, 10), F("n1", "I", 11, 20), F("n2", "I", 21, 30), F("n3", "I", 31, 40)]
TRUSS_REC = [F("truss_ID", "I", 1, 10), F("n1", "I", 11, 20), F("n2", "I", 21, 30)]
TRUSS_PROPS = ("/PROP/TRUSS", "/PROP/TYPE2")
BEAM_REC = [F("beam_ID", "I", 1, 10), F("n1", "I", 11, 20), F("n2", "I", 21, 30), F("n3", "I", 31, 40)]
BEAM_PROPS = ("/PROP/BEAM", "/PROP/TYPE3")
TETRA_REC = [F("tetra_ID", "I", 1, 10)] + [F("n%d" % (k + 1), "I", 11 + 10 * k, 20 + 10 * k) for k in range(4)]
# /BRIC20: three lines an element (hm_cfg_files radioss41/ELEM/bric20.cfg): id and n1..n8; n9..n16; n17..n20
BRIC20_LINES = [[F("brick20_ID", "I", 1, 10)] + [F("n%d" % (k + 1), "I", 11 + 10 * k, 20 + 10 * k) for k in range(8)],
                [F("n%d" % (k + 9), "I", 1 + 10 * k, 10 + 10 * k) for k in range(8)],
                [F("n%d" % (k + 17), "I", 1 + 10 * k, 10 + 10 * k) for k in range(4)]]
# /SH3N as OpenRadioss cuts the card (docs/keywords.md): PHI 71-90, Thick 91-100.
SH3N_REC = [F("tria_ID", "I", 1, 10)] + [F("n%d" % (k + 1), "I", 11 + 10 * k, 20 + 10 * k) for k in range(3)] + \
    [F("PHI", "R", 71, 90), F("Thick", "R", 91, 100)]
FUNCT_REC = reals("X", "Y")
THNODE_REC = [F("node_ID", "I", 1, 10), F("skew_ID", "I", 11, 20), F("name", "S", 21, 100)]
THELEM_REC = [F("elem_ID", "I", 1, 10), F("name", "S", 21, 100)]  # /TH/BRIC: no skew column


def thshel_rec(v):
    """/TH/SHEL element lines: no skew_ID (columns 11-20 blank) before the 140 layout."""
    return [F("elem_ID", "I", 1, 10)] + ([F("skew_ID", "I", 11, 20)] if v >= 140 else []) + [F("name", "S", 21, 100)]


def ioflag(v):
    """/IOFLAG: Igtyp 21-30 up to 140; Outyy, Irootyy, Irot from 100."""
    f = [F("Ipri", "I", 1, 10)]
    if v <= 140:
        f.append(F("Igtyp", "I", 21, 30))
    f.append(F("Ioutp", "I", 31, 40))
    if v >= 100:
        f += [F("Outyy", "I", 41, 50), F("Irootyy", "I", 51, 60), F("Irot", "I", 61, 70)]
    return [card(f)]


def spmd(v):
    """/SPMD: Nthread 51-60 from 110."""
    f = [F("Domdec", "I", 1, 10), F("Nspmd", "I", 11, 20), F("Dkword", "I", 31, 40)]
    if v >= 110:
        f.append(F("Nthread", "I", 51, 60))
    return [card(f)]


def analy(v):
    """/ANALY: ISUBCYC 31-40 up to 2022; ITEMP 11-20 from 2026."""
    f = [F("N2D3D", "I", 1, 10)]
    if v >= 2026:
        f.append(F("ITEMP", "I", 11, 20))
    f.append(F("IPARITH", "I", 21, 30))
    if v <= 2022:
        f.append(F("ISUBCYC", "I", 31, 40))
    return [card(f)]


def unit_card(v):
    """/UNIT/unit_ID (same layout in every version): the mass, length and time units, names or factors to SI."""
    return [card([F("MUNIT", "S", 1, 20), F("LUNIT", "S", 21, 40), F("TUNIT", "S", 41, 60)])]


ID_REC = [F("id%d" % (k + 1), "I", 1 + 10 * k, 10 + 10 * k) for k in range(10)]
# /GRNOD/GEN_INCR: one arithmetic range a line (read from the 2017 layout on)
GEN_INCR_REC = [F("first", "I", 1, 10), F("last", "I", 11, 20), F("incr", "I", 21, 30)]
# /SET/GENERAL, /SET/COLLECT: a clause word in columns 1-10 (blank: the clause above goes on), then nine ids
SET_REC = [F("clause", "S", 1, 10)] + [F("item%d" % k, "I", 1 + 10 * k, 10 + 10 * k) for k in range(1, 10)]
# /SURF/SEG: one segment a line; n4 = 0 makes a triangle
SEG_REC = [F("seg_ID", "I", 1, 10), F("n1", "I", 11, 20), F("n2", "I", 21, 30), F("n3", "I", 31, 40),
           F("n4", "I", 41, 50)]

# path -> (header, has_title, cards(v), tail, record: a field list, or a function of the version)
STARTER = {
    "/UNIT/MASS": ("word", False, lambda v: [], None, None),
    "/UNIT/LENGTH": ("word", False, lambda v: [], None, None),
    "/UNIT/TIME": ("word", False, lambda v: [], None, None),
    "/UNIT": ("id", True, unit_card, None, None),
    # control cards radx accepts and ignores (layouts of docs/keywords.md; /SHFRA/V4 has no data)
    "/ANALY": ("none", False, analy, None, None),
    "/MEMORY": ("none", False, lambda v: [card([F("MEMORY", "I", 1, 10), F("REAL", "R", 21, 40)])], None, None),
    "/ANIM/VERS": ("none", False, lambda v: [card([F("ANIM_VERS", "I", 1, 10)])], None, None),
    "/SHFRA/V4": ("none", False, lambda v: [], None, None),
    "/SHFRA": ("none", False, lambda v: [], None, None),
    "/IOFLAG": ("none", False, ioflag, None, None),
    "/SPMD": ("none", False, spmd, None, None),
    "/TH/SHEL": ("id", True, lambda v: [], "threcords", thshel_rec),
    "/TITLE": ("none", False, lambda v: [card([F("title", "S", 1, 100)])], None, None),
    "/DEF_SHELL": ("none", False, def_shell, None, None),
    "/DEF_SOLID": ("none", False, def_solid, None, None),
    "/NODE": ("unit", False, lambda v: [], "records", NODE_REC),
    "/SHELL": ("part", False, lambda v: [], "records", SHELL_REC),
    "/BRICK": ("part", False, lambda v: [], "records", BRICK_REC),
    "/TETRA4": ("part", False, lambda v: [], "records", TETRA_REC),
    "/BRIC20": ("part", False, lambda v: [], "records3", BRIC20_LINES),
    "/SPRING": ("part", False, lambda v: [], "records", SPRING_REC),
    "/TRUSS": ("part", False, lambda v: [], "records", TRUSS_REC),
    "/PROP/TRUSS": ("id", True, lambda v: [card([F("Area", "R", 1, 20), F("Gap", "R", 21, 40)])], None, None),
    "/BEAM": ("part", False, lambda v: [], "records", BEAM_REC),
    "/PROP/BEAM": ("id", True, lambda v: [card([F("Ismstr", "I", 11, 20)]), card(reals("Dm", "Df")),
                                          card(reals("Area", "Iyy", "Izz", "Ixx")),
                                          card([F("Wx1", "I", 4, 4), F("Wy1", "I", 5, 5), F("Wz1", "I", 6, 6),
                                                F("Wx2", "I", 8, 8), F("Wy2", "I", 9, 9), F("Wz2", "I", 10, 10),
                                                F("Ishear", "I", 11, 20)])], None, None),
    "/PROP/SPRING": ("id", True, prop_spring, None, None),
    "/PROP/TYPE4": ("id", True, prop_spring, None, None),
    "/PROP/SPR_GENE": ("id", True, prop_spr_gene, None, None),
    "/PROP/TYPE8": ("id", True, prop_spr_gene, None, None),
    "/PROP/SPR_BEAM": ("id", True, prop_spr_beam, None, None),
    "/PROP/TYPE13": ("id", True, prop_spr_beam, None, None),
    "/SH3N": ("part", False, lambda v: [], "records", SH3N_REC),
    "/PART": ("id", True, part, None, None),
    "/PROP/SHELL": ("id", True, prop_shell, None, None),
    "/PROP/TYPE1": ("id", True, prop_shell, None, None),
    "/PROP/SOLID": ("id", True, prop_solid, None, None),
    "/PROP/TYPE14": ("id", True, prop_solid, None, None),
    "/MAT/LAW1": ("id", True, mat_law1, None, None),
    "/MAT/ELAST": ("id", True, mat_law1, None, None),
    "/MAT/LAW01": ("id", True, mat_law1, None, None),
    "/MAT/LAW2": ("id", True, mat_law2, None, None),
    "/MAT/PLAS_JOHNS": ("id", True, mat_law2, None, None),
    "/MAT/LAW02": ("id", True, mat_law2, None, None),
    "/MAT/LAW36": ("id", True, mat_law36, None, None),
    "/MAT/PLAS_TAB": ("id", True, mat_law36, None, None),
    "/MAT/LAW27": ("id", True, mat_law27, None, None),
    "/MAT/PLAS_BRIT": ("id", True, mat_law27, None, None),
    "/MAT/LAW0": ("id", True, mat_void, None, None),
    "/MAT/VOID": ("id", True, mat_void, None, None),
    "/MAT/LAW00": ("id", True, mat_void, None, None),
    "/MAT/LAW13": ("id", True, mat_law1, None, None),
    "/MAT/LAW42": ("id", True, mat_law42, None, None),
    "/MAT/LAW70": ("id", True, mat_law70, None, None),
    "/MAT/FOAM_TAB": ("id", True, mat_law70, None, None),
    "/MAT/OGDEN": ("id", True, mat_law42, None, None),
    "/MAT/RIGID": ("id", True, mat_law1, None, None),
    "/FAIL/JOHNSON": ("id", False, fail_johnson, None, None),
    "/FAIL/TAB": ("id", False, fail_tab, None, None),
    "/FAIL/BIQUAD": ("id", False, fail_biquad, None, None),
    "/GRNOD/NODE": ("id", True, lambda v: [], "ids", ID_REC),
    "/GRNOD/PART": ("id", True, lambda v: [], "ids", ID_REC),
    "/GRNOD/GRNOD": ("id", True, lambda v: [], "ids", ID_REC),
    "/GRNOD/BOX": ("id", True, lambda v: [], "ids", ID_REC),
    "/GRNOD/SUBSET": ("id", True, lambda v: [], "ids", ID_REC),
    "/GRNOD/MAT": ("id", True, lambda v: [], "ids", ID_REC),
    "/GRNOD/PROP": ("id", True, lambda v: [], "ids", ID_REC),
    "/GRNOD/SURF": ("id", True, lambda v: [], "ids", ID_REC),
    "/GRNOD/GENE": ("id", True, lambda v: [], "ids", ID_REC),
    "/GRNOD/GEN_INCR": ("id", True, lambda v: [], "records", GEN_INCR_REC),
    "/SURF/SEG": ("id", True, lambda v: [], "records", SEG_REC),
    "/SET/GENERAL": ("id", True, lambda v: [], "clauses", SET_REC),
    "/SET/COLLECT": ("id", True, lambda v: [], "clauses", SET_REC),
    "/SURF/PART/EXT": ("id", True, lambda v: [], "ids", ID_REC),
    "/SURF/PART": ("id", True, lambda v: [], "ids", ID_REC),
    "/INTER/LAGDT/TYPE7": ("id", True, inter_lagdt, None, None),
    "/INTER/TYPE7": ("id", True, inter_type7, None, None),
    "/INTER/TYPE2": ("id", True, inter_type2, None, None),
    "/BCS": ("id", True, bcs, None, None),
    "/ALE/BCS": ("id", True, bcs, None, None),
    "/IMPVEL": ("id", True, impvel, None, None),
    "/IMPDISP": ("id", True, impdisp, None, None),
    "/INIVEL/TRA": ("id", True, inivel, None, None),
    "/INIVEL/T+G": ("id", True, inivel, None, None),
    "/INIVEL/ROT": ("id", True, inivel, None, None),
    "/ADMAS/0": ("id", True, admas, None, None),
    "/ADMAS/1": ("id", True, admas, None, None),
    "/GRAV": ("id", True, grav, None, None),
    "/SKEW/FIX": ("id", True, skew_fix, None, None),
    "/SKEW/MOV": ("id", True, skew_mov, None, None),
    "/FRAME/FIX": ("id", True, skew_fix, None, None),
    "/FRAME/MOV": ("id", True, skew_mov, None, None),
    "/CLOAD": ("id", True, cload, None, None),
    "/PLOAD": ("id", True, pload, None, None),
    "/RWALL/PLANE": ("id", True, rwall_plane, None, None),
    "/RWALL/CYL": ("id", True, lambda v: rwall_curved(v, True), None, None),
    "/RWALL/SPHER": ("id", True, lambda v: rwall_curved(v, False), None, None),
    "/RWALL/PARAL": ("id", True, rwall_paral, None, None),
    "/IMPDISP/FGEO": ("id", True, impdisp_fgeo, "records", FGEO_REC),
    "/RBODY": ("id", True, rbody, None, None),
    "/SENSOR/TIME": ("id", True, sensor_time, None, None),
    "/SENSOR/TYPE0": ("id", True, sensor_time, None, None),
    "/FUNCT": ("id", True, lambda v: [], "records", FUNCT_REC),
    "/TH/NODE": ("id", True, lambda v: [], "threcords", THNODE_REC),
    "/TH/PART": ("id", True, lambda v: [], "thids", ID_REC),
    "/TH/INTER": ("id", True, lambda v: [], "thids", ID_REC),
    "/TH/RWALL": ("id", True, lambda v: [], "thids", ID_REC),
    "/TH/BRIC": ("id", True, lambda v: [], "threcords", THELEM_REC),
    "/TH/BRICK": ("id", True, lambda v: [], "threcords", THELEM_REC),
    "/TH/SH3N": ("id", True, lambda v: [], "threcords", THNODE_REC),
    "/TH/SPRING": ("id", True, lambda v: [], "threcords", THELEM_REC),
    "/TH/TRUSS": ("id", True, lambda v: [], "threcords", THELEM_REC),
    "/TH/BEAM": ("id", True, lambda v: [], "threcords", THELEM_REC),
    "/TH/RBODY": ("id", True, lambda v: [], "thids", ID_REC),
    "/TH/SUBS": ("id", True, lambda v: [], "thids", ID_REC),
    "/SECT": ("id", True, sect, None, None),
    "/TH/SECTIO": ("id", True, lambda v: [], "thids", ID_REC),
    "/ACCEL": ("id", True, accel, None, None),
    "/RANDOM": ("none", False, random_card, None, None),
    "/RANDOM/GRNOD": ("id", False, random_card, None, None),
    "/TH/ACCEL": ("id", True, lambda v: [], "thids", ID_REC),
    # docs/theory/contact-laws.md section 5: the interface, then the law string on the lines up to the next keyword
    "/CTCLAW": ("id", True, lambda v: [card([F("inter_ID", "I", 1, 10)])], "text", None),
}

# /TH variable names per keyword, as OpenRadioss names them: (groups, single names). A name outside both is an
# error (RX501), as is a block without variable names (RX502); both at the keyword line.
TH_SHELL = ["F1", "F2", "F12", "M1", "M2", "M12", "IEM", "IEB", "OFF", "EMIN", "EMAX", "EPSD", "THIC"]
TH_BRICK = ["OFF", "SX", "SY", "SZ", "SXY", "SYZ", "SXZ", "IE", "DENS", "BULK", "VOL", "PLAS", "TEMP", "PLSR",
            "VX", "VY", "VZ"]
TH_VARIABLES = {
    "/TH/NODE": (["DEF", "D", "V", "A", "VR", "AR", "XYZ"],
                 [a + x for a in ("D", "V", "A", "VR", "AR", "DR", "REAC") for x in "XYZ"] + ["X", "Y", "Z", "REACXX",
                                                                                              "REACYY", "REACZZ"]),
    "/TH/PART": (["DEF"], ["IE", "KE", "XMOM", "YMOM", "ZMOM", "MASS", "HE", "ERODED", "HEAT"]),
    "/TH/SUBS": (["DEF"], ["IE", "KE", "XMOM", "YMOM", "ZMOM", "MASS", "HE", "ERODED", "HEAT"]),
    "/TH/INTER": (["DEF", "FN", "FT"], ["FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ", "CE_ELAST", "CE_FRIC", "CE_DAMP"]),
    "/TH/RWALL": (["DEF", "FN", "FT"], ["FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ"]),
    "/TH/SH3N": (["DEF"], TH_SHELL),
    "/TH/BRIC": (["DEF", "STRESS"], TH_BRICK),
    "/TH/BRICK": (["DEF", "STRESS"], TH_BRICK),
    "/TH/SECTIO": (["DEF", "FN", "FT", "M", "CENTER", "GLOBAL", "LOCAL"],
                   [a + x for a in ("FN", "FT", "M", "C") for x in "XYZ"] + [a + k for a in "FM" for k in "123"]),
    "/TH/ACCEL": (["DEF", "W"], ["AX", "AY", "AZ", "WX", "WY", "WZ"]),
    "/TH/SPRING": (["DEF"], ["OFF"] + [a + x for a in "FMLR" for x in "XYZ"] + ["IE"]),
    "/TH/RBODY": (["DEF", "F", "M", "R", "FI", "MI", "D", "V", "A", "XYZ"],
                  [a + x for a in ("F", "M", "R") for x in "XYZ"] + [a + x + "I" for a in "FM" for x in "XYZ"] +
                  ["X", "Y", "Z"] + [a + x for a in ("D", "V", "A", "VR", "AR") for x in "XYZ"] +
                  ["MASS", "IXX", "IYY", "IZZ", "IXY", "IYZ", "IZX", "STATUS"]),
}


def box_recta(v):
    return [card([F("N1", "I", 1, 10), F("N2", "I", 11, 20), F("Iskew", "I", 21, 30)]),
            card(reals("Xp1", "Yp1", "Zp1")), card(reals("Xp2", "Yp2", "Zp2"))]


def box_cylin(v):
    return [card([F("N1", "I", 1, 10), F("N2", "I", 11, 20), F("Diameter", "R", 31, 50)]),
            card(reals("Xp1", "Yp1", "Zp1")), card(reals("Xp2", "Yp2", "Zp2"))]


def box_spher(v):
    return [card([F("N1", "I", 1, 10), F("Diameter", "R", 31, 50)]), card(reals("Xp1", "Yp1", "Zp1"))]


# Element groups: root -> (element keyword, subtype listing element ids, element name). Every subtype reads a
# title and a list of ids; a unit id may follow the group id on the keyword line.
GROUP_FAMILIES = {"/GRSHEL": ("/SHELL", "SHEL", "4-node shell"), "/GRSH3N": ("/SH3N", "SH3N", "3-node shell"),
                  "/GRBRIC": ("/BRICK", "BRIC", "brick"), "/GRTRUS": ("/TRUSS", "TRUS", "truss"),
                  "/GRBEAM": ("/BEAM", "BEAM", "beam")}
GROUP_SUBTYPES = ("PART", "SUBSET", "MAT", "PROP", "BOX", "BOX2", "GENE")
for _root, (_ekw, _list, _name) in GROUP_FAMILIES.items():
    for _sub in (_list, _root[1:]) + GROUP_SUBTYPES:
        STARTER[_root + "/" + _sub] = ("id", True, lambda v: [], "ids", ID_REC)
NODES_OF_GROUPS = ("/GRNOD/GRSHEL", "/GRNOD/GRSH3N", "/GRNOD/GRBRIC", "/GRNOD/GRTRUS", "/GRNOD/GRBEAM")
SURFS_OF_GROUPS = ("/SURF/GRSHEL", "/SURF/GRSH3N", "/SURF/GRBRIC/EXT", "/SURF/GRBRIC/FREE", "/SURF/GRBRIC")
for _path in NODES_OF_GROUPS + SURFS_OF_GROUPS + ("/SURF/PART/ALL", "/SUBSET"):
    STARTER[_path] = ("id", True, lambda v: [], "ids", ID_REC)
STARTER["/SH3N"] = ("part", False, lambda v: [], "records", SH3N_REC)
STARTER["/BOX/RECTA"] = ("id", True, box_recta, None, None)
STARTER["/BOX/CYLIN"] = ("id", True, box_cylin, None, None)
STARTER["/BOX/SPHER"] = ("id", True, box_spher, None, None)


# Model assembly (Radioss reference: //SUBMODEL, /TRANSFORM/TRA, /ROT, /SCA, /SYM and /MOVE_FUNCT). sub_ID is in
# column 91-100 of TRA and ROT from the 100 layout on, of SCA and SYM only from 2026.
def submodel_card(v):
    return [card([F(n, "I", 1 + 10 * k, 10 + 10 * k) for k, n in
                  enumerate(("off_def", "off_nod", "off_ele", "off_part", "off_mat", "off_type", "off_sub"))])]


def transform_cards(kind):
    def cards(v):
        sub = [F("sub_ID", "I", 91, 100)] if v >= (2026 if kind in ("SCA", "SYM") else 100) else []
        if kind == "SCA":
            return [card([F("grnod_ID", "I", 1, 10)] + [F("s" + x, "R", 11 + 20 * k, 30 + 20 * k)
                                                         for k, x in enumerate("XYZ")] +
                         [F("node_IDc", "I", 71, 80)] + sub)]
        c1 = card([F("grnod_ID", "I", 1, 10)] + [F(x + "1", "R", 11 + 20 * k, 30 + 20 * k) for k, x in enumerate("XYZ")] +
                  [F("node_ID1", "I", 71, 80), F("node_ID2", "I", 81, 90)] + sub)
        if kind == "TRA":
            return [c1] + ([card([F("skew_ID", "I", 1, 10)])] if v >= 2026 else [])
        c2 = [F(x + "2", "R", 11 + 20 * k, 30 + 20 * k) for k, x in enumerate("XYZ")]
        if kind == "ROT":
            c2.append(F("Angle", "R", 71, 90))
        return [c1, card(c2)]
    return cards


STARTER["//SUBMODEL"] = ("id", True, submodel_card, None, None)
STARTER["//ENDSUB"] = ("none", False, lambda v: [], None, None)
for _kind in ("TRA", "ROT", "SCA", "SYM"):
    STARTER["/TRANSFORM/" + _kind] = ("id", True, transform_cards(_kind), None, None)
STARTER["/MOVE_FUNCT"] = ("id", True, lambda v: [card(reals("Ascalex", "Fscaley", "Ashiftx", "Fshifty"))], None,
                          None)

# Inside a //SUBMODEL every id is shifted by the submodel's offset for the kind of object it names (nodes
# off_nod, elements off_ele, parts off_part, materials off_mat, properties off_type, submodels off_sub, all else
# off_def; a specific offset of 0 takes off_def), summed over the enclosing submodels. Ids of 0 or less stay.
NODE_FIELDS = {"node_ID", "node_ID1", "node_ID2", "node_ID3", "node_IDc", "node_IDN", "N1", "N2", "N3", "n1", "n2",
               "n3", "n4", "n5", "n6", "n7", "n8"}
ELEM_FIELDS = {"elem_ID"}
OTHER_FIELDS = {"grnod_ID", "grnd_ID1", "grnd_ID2", "grnd_IDs", "grnd_ID", "surf_IDm", "surf_ID", "skew_ID",
                "funct_IDT", "sensor_ID", "sens_ID", "subset_ID", "inter_ID", "Iskew", "frame_ID", "Frame_ID",
                "grbric_ID", "grshel_ID", "grtria_ID", "fct_ID", "fct_IDF", "fric_ID"}


def id_kind_of_keyword(path):
    if path.startswith("/MAT/"):
        return "mat"
    if path.startswith("/PROP/"):
        return "prop"
    if path in ("/PART", "/SHELL", "/SH3N", "/BRICK", "/TETRA4"):
        return "part"
    if path == "//SUBMODEL":
        return "sub"
    return "def"


def id_kind_of_list(path):
    last = path.split("/")[2] if path.count("/") >= 2 else ""
    if path.startswith("/TH/"):
        return {"NODE": "nod", "PART": "part", "BRIC": "ele", "BRICK": "ele", "SH3N": "ele", "SHEL": "ele"}.get(
            last, "def")
    return {"NODE": "nod", "GENE": "nod", "SHEL": "ele", "SH3N": "ele", "BRIC": "ele", "PART": "part",
            "MAT": "mat", "PROP": "prop"}.get(last, "def")


def field_kind(name):
    if name in NODE_FIELDS:
        return "nod"
    if name in ELEM_FIELDS or name in ("shell_ID", "tria_ID", "brick_ID", "tetra_ID"):
        return "ele"
    if name == "prop_ID":
        return "prop"
    if name == "mat_ID":
        return "mat"
    if name == "part_ID":
        return "part"
    if name == "sub_ID":
        return "sub"
    if name in OTHER_FIELDS or name.startswith("inter_ID"):
        return "def"
    return None


def shift_ids(obj, offsets):
    def sh(x, kind):
        return x + offsets[kind] if isinstance(x, int) and x > 0 and kind else x
    if obj["path"] not in ("/NODE",):
        obj["id"] = sh(obj["id"], id_kind_of_keyword(obj["path"]))
    obj["unit_id"] = sh(obj["unit_id"], "def")  # a unit system is one of the "everything else" ids
    for k, (x, p) in list(obj["vals"].items()):
        obj["vals"][k] = (sh(x, field_kind(k)), p)
    elem = obj["path"] in ("/SHELL", "/SH3N", "/BRICK", "/TETRA4")
    for r, _ in obj["recs"]:
        for k in list(r):
            kind = "ele" if elem and k == "id" else ("nod" if obj["path"] == "/NODE" and k == "node_ID" else
                                                     field_kind(k))
            if obj["path"].startswith("/TH/") and k in ("node_ID", "elem_ID"):
                kind = id_kind_of_list(obj["path"])
            if obj["path"] == "/GRNOD/GEN_INCR" and k in ("first", "last"):
                kind = "nod"
            r[k] = sh(r[k], kind)
    obj["ids"] = [(sh(x, id_kind_of_list(obj["path"])), p) for x, p in obj["ids"]]


def match_keyword(parts):
    """parts: keyword fields without blanks, upper case. Returns (path, rest) or (None, None)."""
    for n in range(min(len(parts), 4), 0, -1):
        path = "/" + "/".join(parts[:n])
        if path in STARTER:
            return path, parts[n:]
    return None, None


# ---------------------------------------------------------------------------------------------------
# Reading


class Issue:
    def __init__(self, code, file, line, msg, warning=False):
        self.code, self.file, self.line, self.msg, self.warning = code, file, line, msg, warning

    def key(self):
        return (self.code, self.file, self.line)

    def __str__(self):
        return "%s:%d: %s %s" % (self.file, self.line, self.code, self.msg)


class Checker:
    def __init__(self, verbose=False):
        self.issues = []
        self.style = []  # column/style problems that are not input errors (ruler mismatch, etc.)
        self.verbose = verbose

    def issue(self, code, file, line, msg, warning=False):
        """A problem radx reports; warning=True when it reads the deck anyway (the checks that depend on whether
        an error was found count the errors only)."""
        self.issues.append(Issue(code, file, line, msg, warning))

    def errors(self):
        return sum(1 for x in self.issues if not x.warning)

    def warn(self, file, line, msg):
        self.style.append(Issue("STYLE", file, line, msg))

    # ---- files and includes
    def load(self, path, display, stack, out, top=True):
        try:
            with open(path, "rb") as f:
                raw = f.read()
        except OSError:
            return False
        text = raw.decode("utf-8", errors="replace")
        lines = text.split("\n")
        if lines and lines[-1] == "":
            lines.pop()
        for k, ln in enumerate(lines, 1):
            ln = ln.rstrip("\r")
            # an included file ends at its /END or #enddata (Radioss reads the /END as #enddata); a warning
            # when lines that are not comments follow
            if not top and (ln.rstrip().replace(" ", "").upper() == "/END" or ln.lower().startswith("#enddata")):
                if ln.startswith("/"):
                    self.ended_in_include = True
                if any(x.strip() and not is_comment(x.strip()) for x in lines[k:]):
                    self.issue("RX108", display, k, "%s ends the included file; lines after it are not read" %
                               ln.strip())
                break
            if ln.lower().startswith("#include"):
                name = ln[8:].strip().replace("'", "")
                if len(name) >= 2 and name[0] == name[-1] == '"':
                    name = name[1:-1]
                    self.issue("RX109", display, k, "double-quoted include name (OpenRadioss does not read it)")
                target = os.path.normpath(os.path.join(os.path.dirname(path), name))
                tdisp = os.path.normpath(os.path.join(os.path.dirname(display), name))
                if os.path.abspath(target) in stack:
                    self.issue("RX102", display, k, "include loop: %s is already being read" % name)
                    continue
                if not os.path.exists(target):
                    self.issue("RX103", display, k, "include file not found: %s" % name)
                    continue
                self.load(target, tdisp, stack + [os.path.abspath(target)], out, top=False)
                continue
            out.append((display, k, ln))
        return True

    # ---- field parsing
    def parse_fields(self, fields, rec, kw, strict=True, card=False):
        """Parse one data line against fields. Returns dict name -> value (blank -> None)."""
        file, lineno, text = rec
        vals = {}
        if len(text) > 100:
            self.warn(file, lineno, "line longer than 100 columns")
        if "," in text:
            return vals
        body = text[:100].replace("\t", " ")
        # token placement
        for m in re.finditer(r"\S+", body):
            s, e = m.start() + 1, m.end()
            host = [f for f in fields if f[2] <= s and e <= f[3]]
            digits = all(any(f[2] == f[3] == c for f in fields) for c in range(s, e + 1))
            if not host and not digits:
                self.warn(file, lineno, "%s: token %r at columns %d-%d is not inside one field" % (kw, m.group(), s, e))
        for name, typ, a, b in fields:
            cell = body[a - 1:b]
            tok = cell.strip()
            if not tok:
                vals[name] = None
                continue
            # A card field holding only numbers apart (shifted columns): Radioss reads the leading one (RX207).
            if card and typ in ("I", "R") and len(tok.split()) > 1 and all(REAL_RE.match(x) for x in tok.split()):
                self.warn(file, lineno, "%s: %s = %r holds two values; the leading one is read" % (kw, name, tok))
                tok = tok.split()[0]
                cell = tok
            if typ == "I":
                if not INT_RE.match(tok):
                    self.issue("RX201", file, lineno, "%s: %s = %r is not an integer" % (kw, name, tok))
                    vals[name] = None
                    continue
                if strict and cell.rstrip() != cell:
                    self.warn(file, lineno, "%s: integer %s not right-justified in columns %d-%d" % (kw, name, a, b))
                vals[name] = int(tok)
            elif typ == "R":
                if not REAL_RE.match(tok):
                    self.issue("RX202", file, lineno, "%s: %s = %r is not a real" % (kw, name, tok))
                    vals[name] = None
                    continue
                t = tok.replace("D", "E").replace("d", "e")
                t = re.sub(r"(\d)([+-]\d+)$", r"\1E\2", t)
                x = float(t)
                if math.isinf(x):
                    self.issue("RX203", file, lineno, "%s: %s = %r overflows a double" % (kw, name, tok))
                    vals[name] = None
                    continue
                vals[name] = x
            else:
                vals[name] = tok
        return vals

    def check_names_line(self, comment, fields, kw):
        """The comment line in front of a card: every name must end at a field's last column (or, for a
        string field, start inside it)."""
        if comment is None:
            return
        file, lineno, text = comment
        if RULER_RE.match(text) or text.startswith("# expect") or text.startswith("# fault"):
            return
        body = " " + text[1:]
        for m in re.finditer(r"\S+", body):
            s, e = m.start() + 1, m.end()
            ok = any(f[3] == e for f in fields) or any(f[1] == "S" and f[2] <= s <= f[3] for f in fields)
            if not ok:
                self.warn(file, lineno, "%s: field name %r ends at column %d, not at a field end" % (kw, m.group(), e))

    # ---- starter
    def starter(self, recs, mainfile, last_line, version_hint=None, fragment=False):
        """recs: (file, line, text) of the whole file set, includes expanded."""
        i = 0
        n = len(recs)
        version = version_hint or 2026
        if not fragment:
            while i < n and not is_begin_line(recs[i][2]):
                i += 1
            if i == n:
                first_kw = next((r for r in recs if r[2].startswith("/")), recs[0] if recs else (mainfile, 1, ""))
                self.issue("RX105", first_kw[0], first_kw[1], "no /BEGIN")
                return None
            i += 1
            cards = []

            def take(count):
                nonlocal i
                while i < n and len(cards) < count:
                    r = recs[i]
                    if r[2].startswith("/"):
                        break
                    if not is_comment(r[2]):
                        cards.append(r)
                    i += 1

            take(2)
            begin_units = {}
            if len(cards) < 2:
                self.issue("RX502", mainfile, recs[i - 1][1], "/BEGIN has no version card")
                return None
            vv = self.parse_fields([F("INVERS", "I", 1, 10), F("IRUN", "I", 11, 20)], cards[1], "/BEGIN")
            version = vv.get("INVERS") or 0
            if version not in VERSIONS:
                self.issue("RX307", cards[1][0], cards[1][1], "unsupported version %r" % version)
            # Version 90 has no unit cards (/UNIT/MASS, /LENGTH, /TIME name the units); 100 and newer have two.
            if version >= 100:
                take(4)
                if len(cards) < 4:
                    self.issue("RX502", mainfile, recs[i - 1][1], "/BEGIN has fewer than 4 cards")
                    return None
                for c, kinds in ((cards[2], "input"), (cards[3], "work")):
                    uv = self.parse_fields([F("M", "S", 1, 20), F("L", "S", 21, 40), F("T", "S", 41, 60)], c,
                                           "/BEGIN")
                    begin_units[kinds] = tuple(uv.get(x) for x in ("M", "L", "T"))
                    bad = [x for x, ok in ((uv.get("M"), MASS_UNITS), (uv.get("L"), LENGTH_UNITS),
                                           (uv.get("T"), TIME_UNITS)) if x is not None and x not in ok and not
                           REAL_RE.match(x)]
                    if bad:
                        self.issue("RX506", c[0], c[1], "unknown %s unit(s) %s" % (kinds, ", ".join(bad)))
        model = Model(version)
        if not fragment:
            model.units = begin_units
        self.open_subs = []  # the open //SUBMODEL objects, innermost last
        end_seen = False
        prev_comment = None
        while i < n:
            file, lineno, text = recs[i]
            if is_comment(text):
                prev_comment = recs[i]
                i += 1
                continue
            if not text.startswith("/"):
                self.warn(file, lineno, "data line outside any keyword")
                i += 1
                continue
            parts = [p.replace(" ", "").upper() for p in text.rstrip().split("/")[1:]]
            if parts and parts[0] == "END" and len(parts) == 1:
                end_seen = True
                break
            path, rest = match_keyword(parts)
            # block lines up to the next keyword
            j = i + 1
            block = []
            while j < n and not recs[j][2].startswith("/"):
                block.append(recs[j])
                j += 1
            if path is None:
                written = "/" + "/".join(parts)
                if any(written.startswith(u) for u in UNSUPPORTED_ROOTS) or \
                        any(written == u or written.startswith(u + "/") for u in UNSUPPORTED_WORDS) or \
                        (written.startswith("/INCLUDE") and not written.startswith("/INCLUDE_")):
                    self.issue("RX302", file, lineno, "keyword %s is not supported" % written)
                else:
                    self.issue("RX301", file, lineno, "unknown keyword %s" % written)
                i = j
                continue
            self.keyword(model, path, rest, recs[i], block, version)
            i = j
        if not end_seen and not fragment and not getattr(self, "ended_in_include", False):
            self.issue("RX106", mainfile, last_line, "no /END")
        for o in self.open_subs:
            self.issue("RX312", o["pos"][0], o["pos"][1], "//SUBMODEL %d has no //ENDSUB" % o["id"])
        return model

    def keyword(self, model, path, rest, kwrec, block, v):
        header, has_title, cards_fn, tail, recfields = STARTER[path]
        if callable(recfields):
            recfields = recfields(v)
        file, lineno, text = kwrec
        oid = 0
        word = None
        if header == "word":
            # /UNIT/LENGTH/mm: the unit as written (case matters: Mg is not mg)
            word = text.rstrip().split("/")[-1].replace(" ", "")
            kinds = {"/UNIT/MASS": MASS_UNITS, "/UNIT/LENGTH": LENGTH_UNITS, "/UNIT/TIME": TIME_UNITS}[path]
            if len(rest) != 1:
                self.issue("RX306", file, lineno, "%s takes one unit name" % path)
            elif word not in kinds and not REAL_RE.match(word):
                self.issue("RX506", file, lineno, "unknown unit %r" % word)
            if v > 90:
                self.warn(file, lineno, "%s is ignored in a deck of version %d (units are /BEGIN cards)" % (path, v))
        if header in ("id", "part"):
            if not rest and path.startswith("/INTER/"):
                # an interface with no id is interface 1, as OpenRadioss reads it (RX508 warning)
                self.issue("RX508", file, lineno, "%s has no id: read as interface 1" % path)
                rest = ["1"]
                oid = 1
            elif not rest or not INT_RE.match(rest[0]):
                self.issue("RX306", file, lineno, "%s needs an id" % path)
            else:
                oid = int(rest[0])
        # split into (comment before, data line) pairs
        data = []
        comment = None
        for r in block:
            if is_comment(r[2]):
                comment = r
                continue
            data.append((comment, r))
            comment = None
        k = 0
        title = ""
        if has_title:
            if k < len(data):
                title = data[k][1][2]
                k += 1
        # the unit id of the keyword line: after the object id (/NODE and element blocks: /NODE/unit_ID)
        ucell = rest[0] if header == "unit" and rest else (rest[1] if header in ("id", "part") and len(rest) > 1
                                                           else "")
        obj = {"path": path, "id": oid, "pos": (file, lineno), "title": title, "cards": [], "vals": {},
               "recs": [], "ids": [], "word": word,
               "own_units": len(rest) > 1 and rest[1] not in ("", "0"), "in_sub": bool(self.open_subs),
               "unit_id": int(ucell) if INT_RE.match(ucell) else 0}
        vals = {}
        card_list = cards_fn(v)
        for c in card_list:
            if c["cond"] is not None and not c["cond"](vals):
                continue
            if k >= len(data):
                obj["cards"].append(None)
                if not c["optional"]:
                    obj.setdefault("missing", []).append(c)
                continue
            cm, r = data[k]
            k += 1
            self.check_names_line(cm, c["fields"], path)
            cv = self.parse_fields(c["fields"], r, path, card=True)
            for key, (ga, gb) in c["gate"].items():
                # the old pre-read: the field is not read when the gate columns are blank
                if "," not in r[2] and not r[2][ga - 1:gb].strip():
                    if cv.get(key) is not None:
                        self.warn(r[0], r[1], "%s: %s is not read in this layout (columns %d-%d blank)" %
                                  (path, key, ga, gb))
                    cv[key] = None
            for key, val in cv.items():
                vals[key] = val
                obj["vals"][key] = (val, (r[0], r[1]))
            obj["cards"].append((r[0], r[1]))
        if tail in ("thids", "threcords"):
            # variable lines: first line always, then while col 1-10 non-blank and not starting with a digit
            first = True
            while k < len(data):
                t = data[k][1][2]
                head = t[:10].strip()
                if first or (head and not head[0].isdigit() and head[0] not in "+-"):
                    obj.setdefault("vars", []).append(t.split())
                    k += 1
                    first = False
                    continue
                break
        if tail == "text":
            # every character but blanks, each with the line it was written on
            obj["text"] = [(ch, (r[0], r[1])) for _, r in data[k:] for ch in r[2] if ch not in " \t"]
            k = len(data)
        if tail == "records3":
            # three lines a record; a block that ends inside one is RX304 (deck_reader.cpp)
            rows = [(cm, r) for cm, r in data[k:]]
            for j in range(0, len(rows) - len(rows) % 3, 3):
                vals3, first = {}, rows[j][1]
                if any("," in rows[j + q][1][2] for q in range(3)):
                    # fixed 10-column fields only (deck_reader.cpp read_multi_line_records)
                    self.issue("RX201", first[0], first[1], "%s: an element's lines hold commas" % path)
                    continue
                for q in range(3):
                    vals3.update(self.parse_fields(recfields[q], rows[j + q][1], path))
                obj["recs"].append((vals3, (first[0], first[1])))
            if len(rows) % 3:
                r0 = rows[len(rows) - len(rows) % 3][1]
                self.issue("RX304", r0[0], r0[1], "%s: the block ends inside an element's three lines" % path)
            k = len(data)
        if tail in ("records", "threcords", "ids", "thids"):
            # a list line that starts with a letter is no record: OpenRadioss skips it, radx warns once
            rest = [(cm, r) for cm, r in data[k:] if not r[2].strip()[:1].isalpha()]
            skipped = len(data) - k - len(rest)
            if skipped:
                first = next(r for _, r in data[k:] if r[2].strip()[:1].isalpha())
                self.warn(first[0], first[1], "%s: %d line(s) start with text and are skipped" % (path, skipped))
            data = data[:k] + rest
        if tail == "clauses":
            # a clause line starts with its word: no line is skipped for starting with text
            for cm, r in data[k:]:
                obj["recs"].append((self.parse_fields(recfields, r, path), (r[0], r[1])))
            k = len(data)
        if tail in ("records", "threcords"):
            for cm, r in data[k:]:
                self.check_names_line(cm, recfields, path)
                obj["recs"].append((self.parse_fields(recfields, r, path), (r[0], r[1])))
            k = len(data)
        elif tail in ("ids", "thids"):
            for cm, r in data[k:]:
                self.check_names_line(cm, ID_REC, path)
                cv = self.parse_fields(ID_REC, r, path)
                for f in ID_REC:
                    if cv.get(f[0]) is not None:
                        obj["ids"].append((cv[f[0]], (r[0], r[1])))
            k = len(data)
        if k < len(data):
            self.warn(data[k][1][0], data[k][1][1], "%s: extra data line" % path)
        if self.verbose:
            print("  %s/%s %r cards=%d recs=%d ids=%d" % (path, oid, title, len(obj["cards"]), len(obj["recs"]),
                                                          len(obj["ids"])))
        if path == "//ENDSUB":
            if not self.open_subs:
                self.issue("RX312", file, lineno, "//ENDSUB with no open //SUBMODEL")
            else:
                self.open_subs.pop()
            return
        if path in SIX_LAW_PROPS and v < 120:
            self.issue("RX307", file, lineno, "%s is read from the 120 layout on, not in %d" % (path, v))
            return
        if path == "/GRNOD/GEN_INCR" and v < 2017:
            self.issue("RX307", file, lineno, "/GRNOD/GEN_INCR is read from the 2017 layout on, not in %d" % v)
            return
        parent = self.open_subs[-1] if self.open_subs else None
        if parent is not None:
            shift_ids(obj, parent["offsets"])
        # the submodels around the object (shifted ids, innermost last) and the unit system its values are in:
        # its own, else the one of the submodel around it (0: the /BEGIN input units)
        obj["subs"] = [o["id"] for o in self.open_subs]
        obj["unit"] = obj["unit_id"] or (parent["unit"] if parent else 0)
        if path == "//SUBMODEL":
            def given(name):
                return (obj["vals"].get(name) or (None,))[0] or 0
            off = {k: given("off_" + k) or given("off_def") for k in ("nod", "ele", "part", "mat", "type", "sub")}
            off["prop"] = off.pop("type")
            off["def"] = given("off_def")
            obj["offsets"] = {k: x + (parent["offsets"][k] if parent else 0) for k, x in off.items()}
            self.open_subs.append(obj)
        model.add(obj)

    # ---- engine
    def engine(self, recs):
        for file, lineno, text in recs:
            if len(text) > 100:
                self.warn(file, lineno, "line longer than 100 columns")
            if "\t" in text:
                self.warn(file, lineno, "tab in engine line")
            if is_comment(text) or text.startswith("/"):
                if text.upper().startswith("/END"):
                    return
                continue
            for tok in text.replace(",", " ").split():
                if not REAL_RE.match(tok):
                    self.warn(file, lineno, "engine data %r is not a number" % tok)


def is_begin_line(text):
    """/BEGIN, /BEGIN/ or /BEGIN/<digits>: Radioss finds /BEGIN by its prefix, older generators add a field."""
    parts = text.strip().upper().split("/")
    return len(parts) >= 2 and parts[0] == "" and parts[1] == "BEGIN" and (
        len(parts) == 2 or (len(parts) == 3 and (parts[2] == "" or parts[2].isdigit())))


def is_comment(text):
    return text.startswith("#") or text.startswith("$")


# ---------------------------------------------------------------------------------------------------
# Semantic checks


class Model:
    def __init__(self, version):
        self.version = version
        self.objs = []
        self.units = {}  # "input" and "work": (mass, length, time) names as written in /BEGIN, None if blank

    def add(self, obj):
        self.objs.append(obj)

    def of(self, *paths):
        return [o for o in self.objs if o["path"] in paths]


def val(o, name, default=0):
    v = o["vals"].get(name)
    if v is None or v[0] is None:
        return default
    return v[0]


def pos(o, name):
    v = o["vals"].get(name)
    return v[1] if v else o["pos"]


def semantic(ck, m):
    """The checks across keywords, one function per keyword family as parser/building/ builds them. They run in
    this order, the order the problems are reported in: a table of objects by id reports its duplicate ids where
    it is built, and a family reads the tables and the results of the families before it."""
    tables = Tables(ck, m)
    model_objects(tables)
    unit_systems(tables)
    submodel_placement(tables)
    tables.functs = tables.by_id(("/FUNCT",), "function")
    tables.inters = tables.by_id(("/INTER/TYPE7", "/INTER/LAGDT/TYPE7"), "interface")
    elements(tables)
    spring_elements(tables)
    truss_elements(tables)
    beam_elements(tables)
    parts_and_properties(tables)
    spring_properties(tables)
    formulations(tables)
    laws_on_elements(tables)
    materials(tables)
    groups(tables)
    sets(tables)
    material_curves(tables)
    failure_models(tables)
    loads(tables)
    skews(tables)
    random_perturbation(tables)
    sensors_bodies_walls(tables)
    interfaces(tables)
    tied_interfaces(tables)
    contact_laws(tables)
    sections(tables)
    transforms(tables)
    time_history(tables)
    empty_sets_in_use(tables)
    return tables.nodes, tables.parts


class Tables:
    """What the keyword families share: the checker (issue reports a problem), the model, the tables of its
    objects by id and what the families before found (nodes, elements, groups, ...), as attributes."""

    def __init__(self, ck, m):
        self.ck, self.m, self.issue = ck, m, ck.issue
        # the /DEF_SHELL and /DEF_SOLID whose values a property's 0 flags take (resolved)
        self.defs = {k: (m.of(k) or [None])[0] for k in ("/DEF_SHELL", "/DEF_SOLID")}

    def by_id(self, paths, what):
        """The objects of the keywords `paths` by id; an id given twice is RX401 (the first one is kept)."""
        table = {}
        for o in self.m.of(*paths):
            if o["id"] in table:
                self.issue("RX401", o["pos"][0], o["pos"][1], "%s %d defined twice" % (what, o["id"]))
                continue
            table[o["id"]] = o
        return table

    def length_factor(self, o):
        """Work length units per length unit the object is written in (1 when a name is not understood)."""
        m, units = self.m, self.units
        begin = m.units.get("input", (None,) * 3)[1], m.units.get("work", (None,) * 3)[1]
        work = begin[1] or begin[0] or next((x["word"] for x in m.of("/UNIT/LENGTH")), None)
        written = val(units[o["unit"]], "LUNIT", None) if o.get("unit") in units else (begin[0] or work)
        a, b = unit_si(written or work, LENGTH_SI), unit_si(work, LENGTH_SI)
        return a / b if a and b else 1.0

    def place(self, o, point):
        """A point written in object o (a box corner) where the boxes see it: in work units, moved with the
        submodels o is written in."""
        f = self.length_factor(o)
        q = tuple(x * f for x in point)
        for sid, fn in self.moves:
            if sid in o["subs"]:
                q = fn(q)
        return q

    def resolved(self, o, name, def_key, hard):
        """A formulation flag of property o: its own value, else the /DEF_SHELL or /DEF_SOLID one (-2 there read as
        -1), else `hard`."""
        if val(o, name, 0) != 0:
            return val(o, name)
        d = self.defs[def_key]
        if d is not None and val(d, name, 0) != 0:
            return -1 if val(d, name) == -2 else val(d, name)
        return hard

    def need(self, o, field, table, what, zero_ok=True):
        """The id in o's field names an object of `table` (RX402); 0 is RX502 unless zero_ok."""
        I = self.issue
        x = val(o, field, 0)
        p = pos(o, field)
        if x == 0:
            if not zero_ok:
                I("RX502", p[0], p[1], "%s %d: %s is required" % (o["path"], o["id"], field))
            return
        if x in table:
            return
        # a set of the id stands for a node group or a surface no group has (docs/sets.md)
        if what in ("node group", "surface") and x in getattr(self, "set_members", {}):
            self.set_uses.add((x, what, o["path"], o["id"]))
            return
        I("RX402", p[0], p[1], "%s %d: %s %d does not exist" % (o["path"], o["id"], what, x))


# ---------------------------------------------------------------------------------------------------
# The keyword families, in semantic's order


def model_objects(tables):
    """Nodes, then the tables of parts, properties, materials, node groups and surfaces by id (model_builder.cpp);
    a node or object id given twice is RX401."""
    I, by_id, m = tables.issue, tables.by_id, tables.m
    nodes = {}  # as written (the element geometry is checked on these)
    node_block = {}  # node id -> its /NODE object (unit system, submodels)
    for o in m.of("/NODE"):
        for r, p in o["recs"]:
            nid = r.get("node_ID")
            if nid is None:
                continue
            if nid in nodes:
                I("RX401", p[0], p[1], "node %d defined twice" % nid)
                continue
            nodes[nid] = (r.get("X") or 0.0, r.get("Y") or 0.0, r.get("Z") or 0.0)
            node_block[nid] = o

    parts = by_id(("/PART",), "part")
    props = by_id(("/PROP/SHELL", "/PROP/TYPE1", "/PROP/SOLID", "/PROP/TYPE14", "/PROP/SPRING", "/PROP/TYPE4",
                   "/PROP/SPR_GENE", "/PROP/TYPE8", "/PROP/SPR_BEAM", "/PROP/TYPE13", "/PROP/TRUSS", "/PROP/TYPE2",
                   "/PROP/BEAM", "/PROP/TYPE3"),
                  "property")
    mats = by_id(("/MAT/LAW1", "/MAT/ELAST", "/MAT/LAW01", "/MAT/LAW2", "/MAT/PLAS_JOHNS", "/MAT/LAW02",
                  "/MAT/LAW36", "/MAT/PLAS_TAB", "/MAT/LAW27", "/MAT/PLAS_BRIT", "/MAT/LAW0", "/MAT/VOID",
                  "/MAT/LAW00", "/MAT/LAW13", "/MAT/RIGID", "/MAT/LAW42", "/MAT/OGDEN", "/MAT/LAW70",
                  "/MAT/FOAM_TAB"), "material")
    grnods = by_id(tuple(k for k in STARTER if k.startswith("/GRNOD/")), "node group")
    surfs = by_id(tuple(k for k in STARTER if k.startswith("/SURF/")), "surface")
    tables.grnods, tables.mats, tables.node_block, tables.nodes = grnods, mats, node_block, nodes
    tables.parts, tables.props, tables.surfs = parts, props, surfs


def unit_systems(tables):
    """Unit systems (/UNIT): names as in /BEGIN; a unit id on a keyword line (or a //SUBMODEL's) must name one,
    and one with an unknown unit name is no unit system."""
    I, by_id, m = tables.issue, tables.by_id, tables.m
    units = by_id(("/UNIT",), "unit system")
    for o in list(units.values()):
        for name, table in (("MUNIT", MASS_UNITS), ("LUNIT", LENGTH_UNITS), ("TUNIT", TIME_UNITS)):
            x = val(o, name, None)
            if x is not None and x not in table and not REAL_RE.match(x):
                p = pos(o, name)
                I("RX506", p[0], p[1], "/UNIT %d: unknown unit %r" % (o["id"], x))
                units.pop(o["id"], None)
    for o in m.objs:
        if o.get("unit_id", 0) > 0 and o["unit_id"] not in units:
            I("RX402", o["pos"][0], o["pos"][1], "%s %d: unit system %d does not exist" % (o["path"], o["id"],
                                                                                          o["unit_id"]))
    tables.units = units


def submodel_placement(tables):
    """Node positions the boxes see (keywords.md, Submodels and transforms; build_transforms.cpp): the nodes in
    work units, then moved by the transforms of the submodels they are written in (sub_ID), the innermost
    submodel's first, each submodel's in deck order. Node-group transforms come after the groups are built, so
    boxes never see them."""
    length_factor, m, node_block, nodes = tables.length_factor, tables.m, tables.node_block, tables.nodes
    placed = {}
    for nid, c in nodes.items():
        f = length_factor(node_block[nid])
        placed[nid] = tuple(x * f for x in c)
    depth = {o["id"]: len(o["subs"]) for o in m.of("//SUBMODEL")}
    moving = [o for o in m.of("/TRANSFORM/TRA", "/TRANSFORM/ROT", "/TRANSFORM/SCA", "/TRANSFORM/SYM")
              if val(o, "sub_ID", 0) in depth and not val(o, "grnod_ID", 0)]
    moves = []  # (submodel id, point -> point), in the order they apply
    for o in sorted(moving, key=lambda o: -depth[val(o, "sub_ID")]):
        fn = transform_function(o, placed, length_factor(o))
        if fn is None:
            continue  # degenerate: reported by transforms (RX605)
        sid = val(o, "sub_ID")
        moves.append((sid, fn))
        for nid in placed:
            if sid in node_block[nid]["subs"]:
                placed[nid] = fn(placed[nid])
    tables.moves, tables.placed = moves, placed


# Natural coordinates of the 20-node brick's nodes (corners, then the mid-side nodes of edges 1-2, 2-3, 3-4, 4-1,
# 1-5, 2-6, 3-7, 4-8, 5-6, 6-7, 7-8, 8-5).
HEX20_NAT = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1),
             (0, -1, -1), (1, 0, -1), (0, 1, -1), (-1, 0, -1), (-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0),
             (0, -1, 1), (1, 0, 1), (0, 1, 1), (-1, 0, 1)]


def hex20_min_det(pts):
    """The smallest det J of the serendipity brick at the 3 x 3 x 3 Gauss points (the starter's check)."""
    g = (-math.sqrt(0.6), 0.0, math.sqrt(0.6))
    dmin = None
    for x in g:
        for y in g:
            for z in g:
                p = (x, y, z)
                J = [[0.0] * 3 for _ in range(3)]
                for a, s in enumerate(HEX20_NAT):
                    if a < 8:
                        f = [1 + p[c] * s[c] for c in range(3)]
                        gg = sum(p[c] * s[c] for c in range(3)) - 2
                        d = [0.125 * s[c] * f[(c + 1) % 3] * f[(c + 2) % 3] * (gg + f[c]) for c in range(3)]
                    else:
                        c0 = [c for c in range(3) if s[c] == 0][0]
                        d1, d2 = (c0 + 1) % 3, (c0 + 2) % 3
                        q, f1, f2 = 1 - p[c0] ** 2, 1 + p[d1] * s[d1], 1 + p[d2] * s[d2]
                        d = [0.0] * 3
                        d[c0], d[d1], d[d2] = -0.5 * p[c0] * f1 * f2, 0.25 * q * s[d1] * f2, 0.25 * q * f1 * s[d2]
                    for i in range(3):
                        for c in range(3):
                            J[i][c] += pts[a][i] * d[c]
                det = dot(J[0], cross(J[1], J[2]))
                dmin = det if dmin is None else min(dmin, det)
    return dmin


def elements(tables):
    """Shells, triangles, bricks and tetrahedra (model_builder.cpp): the part and its property kind, unique ids,
    existing nodes, the geometry (area, volume, orientation) and the shell thickness."""
    I, m, nodes, parts, props = tables.issue, tables.m, tables.nodes, tables.parts, tables.props
    elem_ids = {"/SHELL": set(), "/SH3N": set(), "/BRICK": set(), "/TETRA4": set(), "/BRIC20": set(),
                "/TRUSS": set(), "/BEAM": set()}
    # element id -> (part id, node ids); trusses and beams (their two nodes) are added by their own checks
    elements = {"/SHELL": {}, "/SH3N": {}, "/BRICK": {}, "/TETRA4": {}, "/BRIC20": {}, "/TRUSS": {}, "/BEAM": {}}
    part_kind = {}
    for o in m.of("/SHELL", "/SH3N", "/BRICK", "/TETRA4", "/BRIC20"):
        kind = o["path"]
        if o["id"] not in parts:
            I("RX402", o["pos"][0], o["pos"][1], "%s: part %d does not exist" % (kind, o["id"]))
        part_kind.setdefault(o["id"], set()).add(kind)
        # an element keyword in a part whose property is of the other kind (model_builder.cpp)
        po = parts.get(o["id"])
        if po is not None and val(po, "prop_ID") in props:
            solid_prop = props[val(po, "prop_ID")]["path"] in ("/PROP/SOLID", "/PROP/TYPE14")
            spring_prop = props[val(po, "prop_ID")]["path"] in SPRING_PROPS
            if spring_prop or solid_prop != (kind in ("/BRICK", "/TETRA4", "/BRIC20")):
                I("RX407", o["pos"][0], o["pos"][1], "%s/%d: part of the wrong property kind" % (kind, o["id"]))
        nn = {"/SHELL": 4, "/SH3N": 3, "/BRICK": 8, "/TETRA4": 4, "/BRIC20": 20}[kind]
        for r, p in o["recs"]:
            eid = r.get({"/SHELL": "shell_ID", "/SH3N": "tria_ID", "/BRICK": "brick_ID", "/TETRA4": "tetra_ID",
                         "/BRIC20": "brick20_ID"}[kind])
            # tetrahedra and 20-node bricks share the bricks' id space (solid elements)
            if eid in elem_ids[kind] or (kind == "/TETRA4" and eid in elem_ids["/BRICK"]) or \
                    (kind == "/BRIC20" and (eid in elem_ids["/BRICK"] or eid in elem_ids["/TETRA4"])):
                I("RX401", p[0], p[1], "element %d defined twice" % eid)
                continue
            elem_ids[kind].add(eid)
            ns = [r.get("n%d" % (k + 1)) for k in range(nn)]
            if any(x is None or x not in nodes for x in ns):
                I("RX406", p[0], p[1], "element %s uses a node that does not exist" % eid)
                continue
            elements[kind][eid] = (o["id"], ns)
            pts = [nodes[x] for x in ns]
            if kind in ("/SHELL", "/SH3N"):
                if kind == "/SH3N":
                    a = cross(sub(pts[1], pts[0]), sub(pts[2], pts[0]))
                else:
                    a = cross(sub(pts[2], pts[0]), sub(pts[3], pts[1]))
                if 0.5 * norm(a) <= 1e-12:
                    I("RX602", p[0], p[1], "%s %d has zero area" % (kind[1:].lower(), eid))
                # thickness
                t_el = r.get("Thick") or 0.0
                po = parts.get(o["id"])
                if po is None:
                    continue
                t_pr = 0.0
                if po is not None and val(po, "prop_ID") in props:
                    t_pr = val(props[val(po, "prop_ID")], "Thick", 0.0)
                t = t_el if t_el != 0.0 else t_pr
                if t == 0.0:
                    I("RX504", p[0], p[1], "shell %d has no thickness (element and property are 0)" % eid)
            elif kind == "/BRIC20":
                if len(set(ns)) < 20:
                    I("RX604", p[0], p[1], "20-node brick %d repeats a node" % eid)
                    continue
                if hex20_min_det(pts) <= 0:
                    I("RX601", p[0], p[1], "20-node brick %d has a non-positive Jacobian at a Gauss point" % eid)
            elif kind == "/TETRA4":
                if len(set(ns)) < 4:
                    I("RX604", p[0], p[1], "tetrahedron %d repeats a node" % eid)
                    continue
                # Radioss's sign: (x1 - x4) . ((x2 - x4) x (x3 - x4)) / 6
                vol = dot(sub(pts[0], pts[3]), cross(sub(pts[1], pts[3]), sub(pts[2], pts[3]))) / 6.0
                lmax = max(norm(sub(pts[a], pts[b])) for a in range(4) for b in range(a))
                if abs(vol) <= 1e-10 * lmax ** 3:
                    I("RX601", p[0], p[1], "tetrahedron %d has zero volume" % eid)
                elif vol < 0:
                    I("RX608", p[0], p[1], "tetrahedron %d has negative volume (renumbered)" % eid)
            else:
                vol = hex_volume(pts)
                if vol <= 1e-12:
                    I("RX601", p[0], p[1], "brick %d has volume %g" % (eid, vol))
                elif hex_tangled(pts):
                    I("RX607", p[0], p[1], "brick %d has a corner turned inside out" % eid)
    tables.elem_ids, tables.elements, tables.part_kind = elem_ids, elements, part_kind


def spring_elements(tables):
    """Springs (build_springs.cpp): the part has a spring property, n1 and n2 exist and differ, n3 exists when
    given, ids unique."""
    I, m, nodes, part_kind, parts = tables.issue, tables.m, tables.nodes, tables.part_kind, tables.parts
    props = tables.props
    spring_ids = set()
    for o in m.of("/SPRING"):
        if o["id"] not in parts:
            I("RX402", o["pos"][0], o["pos"][1], "/SPRING: part %d does not exist" % o["id"])
        part_kind.setdefault(o["id"], set()).add("/SPRING")
        po = parts.get(o["id"])
        if po is not None and val(po, "prop_ID") in props and \
                props[val(po, "prop_ID")]["path"] not in SPRING_PROPS:
            I("RX407", o["pos"][0], o["pos"][1], "/SPRING/%d: part of the wrong property kind" % o["id"])
        for r, p in o["recs"]:
            eid = r.get("spring_ID")
            if eid in spring_ids:
                I("RX401", p[0], p[1], "spring %d defined twice" % eid)
                continue
            spring_ids.add(eid)
            ns = [r.get("n1"), r.get("n2")]
            bad = [x for x in ns if x is None or x not in nodes]
            if r.get("n3") not in (None, 0) and r.get("n3") not in nodes:
                bad.append(r.get("n3"))
            for _ in bad:
                I("RX406", p[0], p[1], "spring %s uses a node that does not exist" % eid)
            if not bad and ns[0] == ns[1]:
                I("RX604", p[0], p[1], "spring %s joins a node to itself" % eid)


LINE_ELEMENT_LAWS = ("/MAT/LAW1", "/MAT/ELAST", "/MAT/LAW01", "/MAT/LAW2", "/MAT/PLAS_JOHNS", "/MAT/LAW02")


def line_elements(tables, keyword, id_field, prop_paths, what, orientation=None):
    """Trusses or beams (model_builder.cpp check_line_shape, check_formulations.cpp check_line_element_laws): the
    part exists and has a property of `prop_paths`, ids unique, n1 and n2 (and the optional `orientation` node)
    exist, n1 and n2 differ and lie apart, the orientation node lies off the axis; the part's material is law 1
    or 2. Registers the elements with their two nodes (an orientation node is not one of them in groups)."""
    I, m, nodes, part_kind, parts = tables.issue, tables.m, tables.nodes, tables.part_kind, tables.parts
    props, mats = tables.props, tables.mats
    ids = set()
    for o in m.of(keyword):
        if o["id"] not in parts:
            I("RX402", o["pos"][0], o["pos"][1], "%s: part %d does not exist" % (keyword, o["id"]))
        part_kind.setdefault(o["id"], set()).add(keyword)
        po = parts.get(o["id"])
        if po is not None and val(po, "prop_ID") in props and props[val(po, "prop_ID")]["path"] not in prop_paths:
            I("RX407", o["pos"][0], o["pos"][1], "%s/%d: part of the wrong property kind" % (keyword, o["id"]))
        for r, p in o["recs"]:
            eid = r.get(id_field)
            if eid in ids:
                I("RX401", p[0], p[1], "%s %d defined twice" % (what, eid))
                continue
            ids.add(eid)
            ns = [r.get("n1"), r.get("n2")]
            tables.elements[keyword][eid] = (o["id"], ns)
            tables.elem_ids[keyword].add(eid)
            bad = [x for x in ns if x is None or x not in nodes]
            n3 = r.get(orientation) if orientation else None
            if n3 not in (None, 0) and n3 not in nodes:
                bad.append(n3)
            for _ in bad:
                I("RX406", p[0], p[1], "%s %s uses a node that does not exist" % (what, eid))
            if bad:
                continue
            if ns[0] == ns[1] or nodes[ns[0]] == nodes[ns[1]]:
                I("RX604", p[0], p[1], "%s %s has no length" % (what, eid))
            elif n3 not in (None, 0):
                a, b, c = nodes[ns[0]], nodes[ns[1]], nodes[n3]
                axis, y = sub(b, a), sub(c, a)
                if not norm(cross(axis, y)) > 1e-12 * norm(axis) * norm(y):
                    I("RX603", p[0], p[1], "%s %s: n3 on its axis" % (what, eid))
    for pid, kinds in part_kind.items():
        if keyword not in kinds or pid not in parts:
            continue
        mat = mats.get(val(parts[pid], "mat_ID"))
        if mat is not None and mat["path"] not in LINE_ELEMENT_LAWS:
            p = pos(parts[pid], "mat_ID")
            I("RX510", p[0], p[1], "part %d: %ss run laws 1 and 2 only" % (pid, what))


def truss_elements(tables):
    """Trusses: the elements (line_elements); the property's area > 0, Gap 0 (a gap truss changes the physics)."""
    I = tables.issue
    line_elements(tables, "/TRUSS", "truss_ID", TRUSS_PROPS, "truss")
    for o in tables.props.values():
        if o["path"] not in TRUSS_PROPS:
            continue
        if val(o, "Area", None) is None:
            p = pos(o, "Area")
            I("RX502", p[0], p[1], "truss property %d: Area is blank" % o["id"])
        elif not val(o, "Area") > 0:
            p = pos(o, "Area")
            I("RX501", p[0], p[1], "truss property %d: Area %g is not positive" % (o["id"], val(o, "Area")))
        if val(o, "Gap", 0.0) != 0:
            p = pos(o, "Gap")
            I("RX510", p[0], p[1], "truss property %d: Gap changes the physics" % o["id"])


def beam_elements(tables):
    """Type-3 beams: the elements (line_elements, with the orientation node n3); the section's values > 0,
    Ismstr 1 and 3 refused."""
    I = tables.issue
    line_elements(tables, "/BEAM", "beam_ID", BEAM_PROPS, "beam", orientation="n3")
    for o in tables.props.values():
        if o["path"] not in BEAM_PROPS:
            continue
        for name in ("Area", "Iyy", "Izz", "Ixx"):
            if val(o, name, None) is None:
                p = pos(o, name)
                I("RX502", p[0], p[1], "beam property %d: %s is blank" % (o["id"], name))
            elif not val(o, name) > 0:
                p = pos(o, name)
                I("RX501", p[0], p[1], "beam property %d: %s is not positive" % (o["id"], name))
        if val(o, "Ismstr", 0) in (1, 3):
            p = pos(o, "Ismstr")
            I("RX510", p[0], p[1], "beam property %d: small strain" % o["id"])


def parts_and_properties(tables):
    """Parts and shell properties (model_builder.cpp): the property and the material exist, the thickness and
    the number of integration points."""
    I, mats, parts, props = tables.issue, tables.mats, tables.parts, tables.props
    for pid, o in parts.items():
        if val(o, "prop_ID") not in props:
            p = pos(o, "prop_ID")
            I("RX402", p[0], p[1], "part %d: property %d does not exist" % (pid, val(o, "prop_ID")))
        # a spring part has no material; a part whose property is missing is reported for that alone
        spring_part = val(o, "prop_ID") not in props or \
            props[val(o, "prop_ID")]["path"] in SPRING_PROPS
        if val(o, "mat_ID", 0) == 0 and not spring_part:
            p = pos(o, "mat_ID")
            I("RX404", p[0], p[1], "part %d: mat_ID is blank or 0" % pid)
        elif val(o, "mat_ID", 0) != 0 and val(o, "mat_ID") not in mats:
            p = pos(o, "mat_ID")
            I("RX402", p[0], p[1], "part %d: material %d does not exist" % (pid, val(o, "mat_ID")))
        subset_ids = {x["id"] for x in tables.m.of("/SUBSET")}
        if val(o, "subset_ID", 0) != 0 and val(o, "subset_ID") not in subset_ids:
            # Radioss resets it to none with its warning 183
            p = pos(o, "subset_ID")
            I("RX402", p[0], p[1], "part %d: subset %d does not exist" % (pid, val(o, "subset_ID")), warning=True)

    # properties
    for o in props.values():
        if o["path"] in ("/PROP/SHELL", "/PROP/TYPE1"):
            if val(o, "Thick", 0.0) < 0:
                p = pos(o, "Thick")
                I("RX504", p[0], p[1], "negative shell thickness")
            nn = val(o, "N", 0)
            if nn < 0 or nn > 10:
                p = pos(o, "N")
                I("RX501", p[0], p[1], "N = %d outside 0..10" % nn)


def spring_properties(tables):
    """Spring properties TYPE4, TYPE8 and TYPE13 (build_springs.cpp)."""
    I, functs, m, props = tables.issue, tables.functs, tables.m, tables.props

    # H 4, 5, 6 need fct_ID1 and fct_ID3, H 8 fct_ID1 (build_springs.cpp read_spring_law)
    def spring_h_curves(o, d):
        h = val(o, "H" + d, 0)
        if h in (4, 5, 6, 8) and val(o, "fct_ID1" + d, 0) == 0:
            p = pos(o, "fct_ID1" + d)
            I("RX502", p[0], p[1], "spring property %d: H%s = %d needs fct_ID1%s" % (o["id"], d, h, d))
        if h in (4, 5, 6) and val(o, "fct_ID3" + d, 0) == 0:
            p = pos(o, "fct_ID3" + d)
            I("RX502", p[0], p[1], "spring property %d: H%s = %d needs fct_ID3%s" % (o["id"], d, h, d))

    def flat(fid):
        """The function fid has no slope (a missing one is reported elsewhere: not flat here)."""
        if fid not in functs:
            return False
        pts = [(r.get("X"), r.get("Y") or 0.0) for r, _ in functs[fid]["recs"] if r.get("X") is not None]
        return not any(b[0] > a[0] and b[1] != a[1] for a, b in zip(pts, pts[1:]))

    def bad_zero_k(o, d):
        """K = 0 with a force curve: accepted for H = 0 (the curve is the law, its slope gives the step) unless
        the curve is flat; refused for the other H, which unload or yield with the slope K."""
        f = val(o, "fct_ID1" + d, 0)
        return f != 0 and (val(o, "H" + d, 0) != 0 or flat(f))

    # springs (build_springs.cpp): mass > 0, K >= 0 (> 0 without damping and curve), K = 0 with a curve only for
    # H = 0 and a curve with a slope, C >= 0, the curves exist, failure elongations of the right sign
    for o in props.values():
        if o["path"] not in ("/PROP/SPRING", "/PROP/TYPE4"):
            continue
        if not val(o, "M", 0.0) > 1e-15:
            p = pos(o, "M")
            I("RX501", p[0], p[1], "spring mass %g is not positive" % val(o, "M", 0.0))
        k, c = val(o, "K", 0.0), val(o, "C", 0.0)
        if k < 0 or (k == 0 and bad_zero_k(o, "")):
            p = pos(o, "K")
            I("RX501", p[0], p[1], "spring stiffness %g" % k)
        elif k == 0 and c <= 0 and val(o, "fct_ID4", 0) == 0 and val(o, "fct_ID1", 0) == 0:
            # a spring of mass only: read, with a warning (OpenRadioss runs it)
            p = pos(o, "K")
            I("RX501", p[0], p[1], "spring stiffness 0 without damping: mass only", warning=True)
        if c < 0:
            p = pos(o, "C")
            I("RX501", p[0], p[1], "negative spring damping")
        if val(o, "delta_min", 0.0) > 0:
            p = pos(o, "delta_min")
            I("RX501", p[0], p[1], "positive delta_min")
        if val(o, "delta_max", 0.0) < 0:
            p = pos(o, "delta_max")
            I("RX501", p[0], p[1], "negative delta_max")
        for name in ("fct_ID1", "fct_ID2", "fct_ID3", "fct_ID4"):
            f = val(o, name, 0)
            if f != 0 and f not in functs:
                p = pos(o, name)
                I("RX402", p[0], p[1], "spring property %d: function %d does not exist" % (o["id"], f))
        spring_h_curves(o, "")

    # TYPE8 and TYPE13 springs (build_springs.cpp): mass > 0, inertia > 0 when a rotation (for TYPE13 also a
    # shear) has stiffness or damping, per degree of freedom K >= 0 (> 0 with a curve), C >= 0, the curves exist,
    # failure limits of the right sign; the skew exists (TYPE8: and is fixed, a moving one is RX510); TYPE8's
    # Ifail2, Iequil, Fsmooth, TYPE13's Ileng, Ifail2, Israte, and sens_ID are not implemented
    for o in props.values():
        if o["path"] not in SIX_LAW_PROPS:
            continue
        type13 = o["path"] in ("/PROP/SPR_BEAM", "/PROP/TYPE13")
        if not val(o, "M", 0.0) > 1e-15:
            p = pos(o, "M")
            I("RX501", p[0], p[1], "spring mass %g is not positive" % val(o, "M", 0.0))
        rot = any(val(o, "K" + d, 0.0) > 0 or val(o, "C" + d, 0.0) > 0 for d in ("23456" if type13 else "456"))
        if val(o, "Inertia", 0.0) < 0 or (rot and not val(o, "Inertia", 0.0) > 1e-15):
            p = pos(o, "Inertia")
            I("RX501", p[0], p[1], "spring inertia %g is not positive" % val(o, "Inertia", 0.0))
        for d in "123456":
            k = val(o, "K" + d, 0.0)
            if k < 0 or (k == 0 and bad_zero_k(o, d)):
                p = pos(o, "K" + d)
                I("RX501", p[0], p[1], "spring stiffness K%s %g" % (d, k))
            if val(o, "C" + d, 0.0) < 0:
                p = pos(o, "C" + d)
                I("RX501", p[0], p[1], "negative spring damping C%s" % d)
            if val(o, "delta_min" + d, 0.0) > 0:
                p = pos(o, "delta_min" + d)
                I("RX501", p[0], p[1], "positive delta_min%s" % d)
            if val(o, "delta_max" + d, 0.0) < 0:
                p = pos(o, "delta_max" + d)
                I("RX501", p[0], p[1], "negative delta_max%s" % d)
            for name in ("fct_ID1", "fct_ID2", "fct_ID3", "fct_ID4"):
                f = val(o, name + d, 0)
                if f != 0 and f not in functs:
                    p = pos(o, name + d)
                    I("RX402", p[0], p[1], "spring property %d: function %d does not exist" % (o["id"], f))
            spring_h_curves(o, d)
        for name in (("Ileng", "Ifail2", "Israte", "sens_ID") if type13 else ("Ifail2", "Iequil", "Fsmooth", "sens_ID")):
            if val(o, name, 0) != 0:
                p = pos(o, name)
                I("RX510", p[0], p[1], "%s %d: %s changes the physics" % (o["path"], o["id"], name))
        sk = val(o, "skew_ID", 0)
        if sk != 0:
            skew = next((x for x in m.of("/SKEW/FIX", "/SKEW/MOV") if x["id"] == sk), None)
            p = pos(o, "skew_ID")
            if skew is None:
                I("RX402", p[0], p[1], "spring property %d: skew %d does not exist" % (o["id"], sk))


def formulations(tables):
    """Formulations (check_formulations.cpp): a flag of a property used by elements must be one radx implements,
    resolved as property value, else the /DEF_SHELL or /DEF_SOLID value, else the hard default."""
    I, part_kind, parts, props = tables.issue, tables.part_kind, tables.parts, tables.props
    resolved = tables.resolved
    used = {}
    for pid, kinds in part_kind.items():
        if pid in parts and val(parts[pid], "prop_ID") in props:
            used.setdefault(val(parts[pid], "prop_ID"), set()).update(kinds)
    for prop_id, kinds in used.items():
        o = props[prop_id]
        bad = []
        if o["path"] in ("/PROP/SPRING", "/PROP/TYPE4"):
            # H 0 1 2 4 5 6 7 8 run (H 7 without fct_ID3 is H 2); without fct_ID1 H 1 2 7 do not act (linear)
            h = val(o, "H", 0)
            if val(o, "fct_ID1", 0) != 0 and h not in SPRING_H_TYPE4:
                bad.append("H")
        elif o["path"] in SIX_LAW_PROPS:
            # as TYPE4 but H 8, refused with or without a curve (the starter keeps it)
            for d in "123456":
                h = val(o, "H" + d, 0)
                if (val(o, "fct_ID1" + d, 0) != 0 and h not in SPRING_H_TYPE8) or h == 8:
                    bad.append("H" + d)
        elif o["path"] in ("/PROP/SHELL", "/PROP/TYPE1"):
            # Ishell 1, 4 (warp correction), 12 (QBAT) and 24 (QEPH; 22 and 23 run as 24, docs/theory/elements.md 1.1)
            if "/SHELL" in kinds and resolved(o, "Ishell", "/DEF_SHELL", 1) not in (1, 4, 12, 22, 23, 24):
                bad.append("Ishell")
            if "/SH3N" in kinds and resolved(o, "Ish3n", "/DEF_SHELL", 2) not in (1, 2):
                bad.append("Ish3n")
            if resolved(o, "Ismstr", "/DEF_SHELL", 2) not in (1, 2, 4, -1):
                bad.append("Ismstr")
        elif "/TETRA4" in kinds and "/BRICK" not in kinds:
            if resolved(o, "Itetra4", "/DEF_SOLID", 1000) in (1, 3, 10):
                bad.append("Itetra4")
            if resolved(o, "Ismstr", "/DEF_SOLID", 4) not in (2, 4):
                bad.append("Ismstr")
            if resolved(o, "Iframe", "/DEF_SOLID", 1) != 1:
                bad.append("Iframe")
        elif "/BRICK" in kinds:
            if "/TETRA4" in kinds and resolved(o, "Itetra4", "/DEF_SOLID", 1000) in (1, 3, 10):
                bad.append("Itetra4")
            # tetrahedra sharing the property run the Jaumann rate only (OpenRadioss: co-rotational with 2)
            if "/TETRA4" in kinds and resolved(o, "Iframe", "/DEF_SOLID", 1) != 1:
                bad.append("Iframe")
            isolid = resolved(o, "Isolid", "/DEF_SOLID", 1)
            # one point (1, 2), HEPH (24) and the fully integrated 12, 14, 17, 18 (2 x 2 x 2 points)
            if isolid not in (1, 2, 24, 12, 14, 17, 18):
                bad.append("Isolid")
            if isolid == 14 and val(o, "Inpts", 0) not in (0, 222):
                bad.append("Inpts")
            if isolid == 24 and resolved(o, "Icpre", "/DEF_SOLID", 0) not in (0, 1, 3):
                bad.append("Icpre")
            if isolid == 24 and val(o, "Ihkt", 0) > 1:
                bad.append("Ihkt")
            if resolved(o, "Ismstr", "/DEF_SOLID", 4) not in (2, 4):
                bad.append("Ismstr")
            # Isolid 24 forces the co-rotational frame; 1 and 2 take Iframe 1 (Jaumann) or 2 (co-rotational)
            if isolid != 24 and resolved(o, "Iframe", "/DEF_SOLID", 1) not in (1, 2) and "Iframe" not in bad:
                bad.append("Iframe")
            if val(o, "Icontrol", 0) == 1:
                bad.append("Icontrol")
        if "/BRIC20" in kinds and o["path"] in ("/PROP/SOLID", "/PROP/TYPE14"):
            # 20-node bricks: Isolid 16, 14, 17 (14 and 17 also run the 20-node brick in OpenRadioss); Inpts of 2 or
            # 3 points per direction (check_formulations.cpp check_brick20_flags)
            isolid = resolved(o, "Isolid", "/DEF_SOLID", 1)
            if isolid not in (16, 14, 17) and "Isolid" not in bad:
                bad.append("Isolid")
            inpts = val(o, "Inpts", 0) or 0
            digits_ok = inpts == 0 or (100 <= inpts <= 999 and all(c in "23" for c in str(inpts)))
            if isolid != 17 and not digits_ok and "Inpts" not in bad:
                bad.append("Inpts")
            if "/BRICK" not in kinds and "/TETRA4" not in kinds and resolved(o, "Ismstr", "/DEF_SOLID", 4) not in (2, 4):
                bad.append("Ismstr")
        for name in bad:
            p = pos(o, name)
            I("RX510", p[0], p[1], "%s %d: %s not implemented by radx" % (o["path"], o["id"], name))


def laws_on_elements(tables):
    """The laws radx runs on some elements only (check_formulations.cpp, build_hyperelastic.cpp), and the solid
    property fields that change the physics."""
    I, mats, part_kind, parts, props = tables.issue, tables.mats, tables.part_kind, tables.parts, tables.props
    resolved = tables.resolved
    # law 27 is a shell law with integration points (check_formulations.cpp check_shell_only_laws): refused on
    # bricks and tetrahedra (at the material's keyword line) and with a shell property of N = 0
    for pid, kinds in part_kind.items():
        if pid not in parts:
            continue
        mat = mats.get(val(parts[pid], "mat_ID"))
        prop = props.get(val(parts[pid], "prop_ID"))
        if mat is None or prop is None or mat["path"] not in ("/MAT/LAW27", "/MAT/PLAS_BRIT"):
            continue
        if kinds & {"/BRICK", "/TETRA4", "/BRIC20"}:
            I("RX510", mat["pos"][0], mat["pos"][1], "law 27 on solids (part %d)" % pid)
        if ("/SHELL" in kinds or "/SH3N" in kinds) and prop["path"] in ("/PROP/SHELL", "/PROP/TYPE1") \
                and val(prop, "N", 0) == 0:
            p = pos(prop, "N")
            I("RX510", p[0], p[1], "law 27 with N = 0 (part %d)" % pid)
    # law 42 on one-point bricks only (build_hyperelastic.cpp check_ogden_parts): shells or tetrahedra at the
    # material's keyword line, Isolid other than 1 and 2, Ismstr other than 4 at the property's field
    for pid, kinds in part_kind.items():
        if pid not in parts:
            continue
        mat = mats.get(val(parts[pid], "mat_ID"))
        prop = props.get(val(parts[pid], "prop_ID"))
        if mat is None or prop is None or mat["path"] not in ("/MAT/LAW42", "/MAT/OGDEN"):
            continue
        if kinds & {"/SHELL", "/SH3N", "/TETRA4", "/BRIC20"}:
            I("RX510", mat["pos"][0], mat["pos"][1], "law 42 on shells, tetrahedra or 20-node bricks (part %d)" % pid)
        if "/BRICK" in kinds and prop["path"] in ("/PROP/SOLID", "/PROP/TYPE14"):
            if resolved(prop, "Isolid", "/DEF_SOLID", 1) not in (1, 2):
                p = pos(prop, "Isolid")
                I("RX510", p[0], p[1], "law 42 with Isolid %d (part %d)" % (resolved(prop, "Isolid", "/DEF_SOLID", 1), pid))
            if resolved(prop, "Ismstr", "/DEF_SOLID", 4) != 4:
                p = pos(prop, "Ismstr")
                I("RX510", p[0], p[1], "law 42 with Ismstr %d (part %d)" % (resolved(prop, "Ismstr", "/DEF_SOLID", 4), pid))
    # law 70 on one-point bricks only (build_hyperelastic.cpp check_ogden_parts)
    for pid, kinds in part_kind.items():
        if pid not in parts:
            continue
        mat = mats.get(val(parts[pid], "mat_ID"))
        prop = props.get(val(parts[pid], "prop_ID"))
        if mat is None or prop is None or mat["path"] not in ("/MAT/LAW70", "/MAT/FOAM_TAB"):
            continue
        if kinds & {"/SHELL", "/SH3N", "/TETRA4", "/BRIC20"}:
            I("RX510", mat["pos"][0], mat["pos"][1], "law 70 on shells, tetrahedra or 20-node bricks (part %d)" % pid)
        if "/BRICK" in kinds and prop["path"] in ("/PROP/SOLID", "/PROP/TYPE14"):
            if resolved(prop, "Isolid", "/DEF_SOLID", 1) not in (1, 2):
                p = pos(prop, "Isolid")
                I("RX510", p[0], p[1], "law 70 with Isolid %d (part %d)" % (resolved(prop, "Isolid", "/DEF_SOLID", 1), pid))
    # fields read but not implemented whose non-zero value changes the physics (keywords_starter.cpp)
    for o in props.values():
        if o["path"] in ("/PROP/SOLID", "/PROP/TYPE14"):
            for name in ("Iale", "Lambda", "Mu", "deltaT_min", "Ndir", "sphpart_ID"):
                if val(o, name, 0) not in (0, 0.0):
                    p = pos(o, name)
                    I("RX510", p[0], p[1], "%s %d: %s = %g changes the physics" % (o["path"], o["id"], name,
                                                                                val(o, name)))


def materials(tables):
    """Materials (model_builder.cpp, build_hyperelastic.cpp, build_foam_tab.cpp, build_rigid_materials.cpp): the
    required cards, a plausible wave speed, Poisson's ratio and each law's own values."""
    I, m, mats = tables.issue, tables.m, tables.mats
    velocity_si = work_velocity_si(m)
    for o in mats.values():
        if o.get("missing"):
            I("RX502", o["pos"][0], o["pos"][1], "%s %d ends before its required cards" % (o["path"], o["id"]))
            continue
        rho, young = val(o, "RHO_I", 0.0) or 0.0, val(o, "E", 0.0) or 0.0
        if velocity_si is not None and rho > 0 and young > 0 and not o["own_units"] and not o["in_sub"]:
            # sqrt(E/rho) in m/s must lie between 1 m/s and the speed of light, in every usual system
            # (1e-3 to 1e4 m/s per unit of velocity) when the deck names no units
            fastest, slowest = velocity_si
            c = math.sqrt(young / rho)
            if c * fastest < 1.0 or c * slowest > 299792458.0:
                p = pos(o, "E")
                I("RX512", p[0], p[1], "%s %d: wave speed %g units is implausible" % (o["path"], o["id"], c))
        nu = val(o, "nu", 0.0)
        if nu >= 0.5 or nu <= -1.0 or (nu < 0 and o["path"] in ("/MAT/LAW42", "/MAT/OGDEN")):
            p = pos(o, "nu")
            I("RX503", p[0], p[1], "Poisson's ratio %g" % nu)
        if o["path"] in ("/MAT/LAW70", "/MAT/FOAM_TAB"):
            # the fields' rules (keywords_starter.cpp add_foam_tab), then build_foam_tab.cpp read_foam_tab
            if nu >= 0.5 or nu < 0:
                p = pos(o, "nu")
                I("RX503", p[0], p[1], "Poisson's ratio %g" % nu)
            for name, lo, hi in (("Nload", 1, 10), ("Nunload", 0, 10), ("Iflag", 0, 4), ("Itens", 0, 1),
                                 ("Ismooth", 0, 1)):
                x = val(o, name, 0) or 0
                if not lo <= x <= hi:
                    p = pos(o, name)
                    I("RX501", p[0], p[1], "%s %d: %s = %d" % (o["path"], o["id"], name, x))
            if not (val(o, "E0", 0.0) or 0.0) > 0:
                p = pos(o, "E0")
                I("RX501" if val(o, "E0", None) is not None else "RX502", p[0], p[1], "E0 must be > 0")
            continue  # no E
        if o["path"] in ("/MAT/LAW42", "/MAT/OGDEN"):
            # the fields' rules (keywords_starter.cpp add_ogden), then build_hyperelastic.cpp read_ogden
            for name in ("fct_IDbulk", "M"):
                if val(o, name, 0) != 0:
                    p = pos(o, name)
                    I("RX510", p[0], p[1], "%s %d: %s not implemented by radx" % (o["path"], o["id"], name))
            if val(o, "Iform", 0) not in (0, 1, 2):
                p = pos(o, "Iform")
                I("RX501", p[0], p[1], "%s %d: Iform = %d" % (o["path"], o["id"], val(o, "Iform")))
            g = 0.0
            for k in range(1, 11):
                mu, alpha = val(o, "mu_%d" % k, 0.0) or 0.0, val(o, "alpha_%d" % k, 0.0) or 0.0
                if mu != 0 and alpha == 0:
                    p = pos(o, "alpha_%d" % k)
                    I("RX507", p[0], p[1], "%s %d: mu_%d with alpha_%d = 0" % (o["path"], o["id"], k, k))
                if mu != 0:
                    g += mu * alpha
            if not g > 0:
                p = pos(o, "mu_1")
                I("RX507", p[0], p[1], "%s %d: sum mu_p alpha_p = %g" % (o["path"], o["id"], g))
            continue  # no E
        if o["path"] in ("/MAT/LAW0", "/MAT/VOID", "/MAT/LAW00"):
            continue  # a void's values may all be blank
        if o["path"] in ("/MAT/LAW13", "/MAT/RIGID") and rho <= 0:
            p = pos(o, "RHO_I")
            I("RX502", p[0], p[1], "a rigid material needs RHO_I > 0")
        if val(o, "E", 0.0) <= 0:
            p = pos(o, "E")
            I("RX502", p[0], p[1], "E must be > 0")
        if o["path"] in ("/MAT/LAW2", "/MAT/PLAS_JOHNS", "/MAT/LAW02"):
            if val(o, "c", 0.0) > 0 and val(o, "EPS_DOT_0", 0.0) == 0:
                p = pos(o, "EPS_DOT_0")
                I("RX502", p[0], p[1], "c > 0 needs EPS_DOT_0")
            if val(o, "n", 0.0) > 1:
                p = pos(o, "n")
                I("RX501", p[0], p[1], "JC exponent n > 1")
            if val(o, "a", 0.0) <= 0:
                p = pos(o, "a")
                I("RX502", p[0], p[1], "JC a must be > 0")
        if o["path"] in ("/MAT/LAW27", "/MAT/PLAS_BRIT"):
            # the fields' rules (0 takes the default first), then model_builder.cpp read_plas_brit
            for name, lo, hi, hi_open in (("n", 0.0, 1.0, False), ("d_max1", 0.0, 1.0, True)):
                x = val(o, name, 0.0)
                if x != 0 and (x < lo or x > hi or (hi_open and x == hi) or (name == "n" and x <= 0)):
                    p = pos(o, name)
                    I("RX501", p[0], p[1], "%s %d: %s = %g out of range" % (o["path"], o["id"], name, x))
            for name in ("a", "EPS_t1", "EPS_m1", "EPS_f1"):
                if val(o, name, 0.0) < 0:
                    p = pos(o, name)
                    I("RX501", p[0], p[1], "%s %d: %s must be > 0" % (o["path"], o["id"], name))
            if val(o, "c", 0.0) != 0 and val(o, "EPS_DOT_0", 0.0) <= 0:
                p = pos(o, "EPS_DOT_0")
                I("RX502", p[0], p[1], "c needs EPS_DOT_0")
            eps_t = val(o, "EPS_t1", 0.0) or 1e20
            eps_m = val(o, "EPS_m1", 0.0) or 1.1e20
            if not eps_m > eps_t:
                p = pos(o, "EPS_m1")
                I("RX507", p[0], p[1], "%s %d: EPS_m1 <= EPS_t1" % (o["path"], o["id"]))


def groups(tables):
    """Subsets, element groups, node groups, surfaces and functions (build_groups.cpp)."""
    I, by_id, ck, elements, functs = tables.issue, tables.by_id, tables.ck, tables.elements, tables.functs
    grnods, m, mats, nodes, part_kind = tables.grnods, tables.m, tables.mats, tables.nodes, tables.part_kind
    parts, place, placed, props, surfs = tables.parts, tables.place, tables.placed, tables.props, tables.surfs
    subsets = by_id(("/SUBSET",), "subset")
    for o in subsets.values():
        for x, p in o["ids"]:
            if x != 0 and x not in subsets:  # left out, as Radioss's warning 182 (0: no child)
                I("RX402", p[0], p[1], "/SUBSET %d: child subset %d does not exist" % (o["id"], x), warning=True)
    egroups, emembers, surf_nodes, boxes = element_group_checks(ck, m, nodes, placed, place, parts, props, mats,
                                                                subsets, elements, surfs)
    tables.grnod_members = node_group_checks(ck, m, nodes, placed, boxes, parts, props, mats, subsets, elements,
                                             egroups, emembers, surfs, surf_nodes, grnods)
    tables.emembers = emembers
    tables.boxes = boxes
    tables.surf_nodes = surf_nodes
    for sid, o in surfs.items():
        if o["path"] not in ("/SURF/PART", "/SURF/PART/EXT"):
            continue  # element_group_checks
        before = ck.errors()
        for x, p in o["ids"]:
            if abs(x) not in parts:
                I("RX402", p[0], p[1], "surface %d: part %d does not exist" % (sid, x), warning=True)
            else:
                # surfaces of 20-node bricks are not built (OpenRadioss's ssurftag.F skips them): refused
                if "/BRIC20" in part_kind.get(abs(x), set()):
                    I("RX510", p[0], p[1], "surface %d: part %d has 20-node bricks" % (sid, x))
                if o["path"] == "/SURF/PART" and part_kind.get(abs(x), set()) & {"/BRICK", "/TETRA4", "/BRIC20"}:
                    I("RX407", p[0], p[1], "surface %d: /SURF/PART on solid part %d" % (sid, x))
        # empty: a warning, as in Radioss, when nothing else stopped the surface
        if not surf_nodes.get(sid) and ck.errors() == before:
            I("RX403", o["pos"][0], o["pos"][1], "surface %d is empty" % sid, warning=True)

    # functions
    for fid, o in functs.items():
        xs = [(r.get("X"), p) for r, p in o["recs"]]
        for k in range(1, len(xs)):
            if xs[k][0] is not None and xs[k - 1][0] is not None and xs[k][0] <= xs[k - 1][0]:
                I("RX505", xs[k][1][0], xs[k][1][1], "function %d: X not increasing" % fid)
                break
    tables.egroups, tables.subsets = egroups, subsets


def material_curves(tables):
    """The curves of /MAT/PLAS_TAB and /MAT/FOAM_TAB (model_builder.cpp read_plas_tab, build_foam_tab.cpp)."""
    I, functs, mats, need = tables.issue, tables.functs, tables.mats, tables.need
    # /MAT/PLAS_TAB: each curve names a function, rates strictly increase, scales >= 0; the options radx does not
    # implement are refused (keywords_starter.cpp, model_builder.cpp read_plas_tab)
    for o in mats.values():
        if o["path"] not in ("/MAT/LAW36", "/MAT/PLAS_TAB"):
            continue
        n = val(o, "N_funct", 0)
        for k in range(1, min(n, 100) + 1):
            need(o, "fct_ID%d" % k, functs, "function", zero_ok=False)
            if val(o, "Fscale%d" % k, 0.0) < 0:
                p = pos(o, "Fscale%d" % k)
                I("RX501", p[0], p[1], "%s %d: Fscale%d < 0" % (o["path"], o["id"], k))
            if k > 1 and not val(o, "Eps_dot%d" % k, 0.0) > val(o, "Eps_dot%d" % (k - 1), 0.0):
                p = pos(o, "Eps_dot%d" % k)
                I("RX507", p[0], p[1], "%s %d: strain rates not increasing" % (o["path"], o["id"]))
        for name in ("Eps_t", "Eps_m", "Chard", "Eps_f", "VP", "fct_IDp", "Fct_IDE", "CE"):
            if val(o, name, 0) not in (0, 0.0):
                p = pos(o, name)
                I("RX510", p[0], p[1], "%s %d: %s not implemented by radx" % (o["path"], o["id"], name))
    # /MAT/FOAM_TAB: each curve names a function, rates distinct within the loading and the unloading curves,
    # the tension function with Itens 1 (build_foam_tab.cpp)
    for o in mats.values():
        if o["path"] not in ("/MAT/LAW70", "/MAT/FOAM_TAB"):
            continue
        for what, count in (("L", "Nload"), ("U", "Nunload")):
            n = max(0, min(val(o, count, 0) or 0, 10))
            rates = []
            for k in range(1, n + 1):
                need(o, "fct_%s%d" % (what, k), functs, "function", zero_ok=False)
                r = val(o, "rate_%s%d" % (what, k), 0.0) or 0.0
                if r in rates:
                    p = pos(o, "rate_%s%d" % (what, k))
                    I("RX507", p[0], p[1], "%s %d: two %sing curves at rate %g" % (o["path"], o["id"], what, r))
                rates.append(r)
        if val(o, "Itens", 0) == 1:
            need(o, "fctIDTens", functs, "function", zero_ok=False)


def failure_models(tables):
    """Failure models /FAIL/JOHNSON, /FAIL/TAB and /FAIL/BIQUAD (model_builder.cpp, build_fail_biquad.cpp,
    check_formulations.cpp)."""
    I, functs, m, mats, need = tables.issue, tables.functs, tables.m, tables.mats, tables.need
    part_kind, parts = tables.part_kind, tables.parts
    # /FAIL/JOHNSON/mat_ID: on an existing LAW2 or LAW36 material, one per material
    failed_mats = set()
    for o in m.of("/FAIL/JOHNSON"):
        mat = mats.get(o["id"])
        if mat is None:
            I("RX402", o["pos"][0], o["pos"][1], "/FAIL/JOHNSON: material %d does not exist" % o["id"])
        elif mat["path"] not in ("/MAT/LAW2", "/MAT/PLAS_JOHNS", "/MAT/LAW02", "/MAT/LAW36", "/MAT/PLAS_TAB"):
            I("RX510", o["pos"][0], o["pos"][1], "/FAIL/JOHNSON on %s %d" % (mat["path"], o["id"]))
        elif o["id"] in failed_mats:
            I("RX401", o["pos"][0], o["pos"][1], "/FAIL/JOHNSON: material %d has one already" % o["id"])
        failed_mats.add(o["id"])
        if val(o, "Ixfem", 0) != 0:
            p = pos(o, "Ixfem")
            I("RX510", p[0], p[1], "/FAIL/JOHNSON %d: Ixfem not implemented by radx" % o["id"])
    # /FAIL/TAB/mat_ID (model_builder.cpp build_fail_tab, resolve_fail_tab_functions; check_formulations.cpp):
    # on an existing LAW2 or LAW36 material, one failure model per material, functions that exist, a constant
    # temperature function, increasing rates; on solids n = 1 and no size function
    for o in m.of("/FAIL/TAB"):
        n_rate = val(o, "N_rate", 0)
        if n_rate <= 0:
            p = pos(o, "N_rate")
            I("RX502", p[0], p[1], "/FAIL/TAB %d: N_rate is required" % o["id"])
        elif n_rate > 100:
            p = pos(o, "N_rate")
            I("RX501", p[0], p[1], "/FAIL/TAB %d: N_rate > 100" % o["id"])
        for name in ("Dcrit", "n"):
            if val(o, name, 0.0) < 0:
                p = pos(o, name)
                I("RX501", p[0], p[1], "/FAIL/TAB %d: %s must be > 0" % (o["id"], name))
        if val(o, "Ixfem", 0) != 0:
            p = pos(o, "Ixfem")
            I("RX510", p[0], p[1], "/FAIL/TAB %d: Ixfem not implemented by radx" % o["id"])
        mat = mats.get(o["id"])
        if mat is None:
            I("RX402", o["pos"][0], o["pos"][1], "/FAIL/TAB: material %d does not exist" % o["id"])
            continue
        if mat["path"] not in ("/MAT/LAW2", "/MAT/PLAS_JOHNS", "/MAT/LAW02", "/MAT/LAW36", "/MAT/PLAS_TAB"):
            I("RX510", o["pos"][0], o["pos"][1], "/FAIL/TAB on %s %d" % (mat["path"], o["id"]))
            continue
        if o["id"] in failed_mats:
            I("RX401", o["pos"][0], o["pos"][1], "/FAIL/TAB: material %d has one already" % o["id"])
            continue
        failed_mats.add(o["id"])
        if val(o, "P_thickfail", 0.0) < 0:
            p = pos(o, "P_thickfail")
            I("RX510", p[0], p[1], "/FAIL/TAB %d: P_thickfail < 0 not implemented by radx" % o["id"])
        for k in range(1, min(max(n_rate, 0), 100) + 1):
            need(o, "fct_ID%d" % k, functs, "function", zero_ok=False)
            if k > 1 and not val(o, "Epsdot%d" % k, 0.0) > val(o, "Epsdot%d" % (k - 1), 0.0):
                p = pos(o, "Epsdot%d" % k)
                I("RX507", p[0], p[1], "/FAIL/TAB %d: strain rates not increasing" % o["id"])
        need(o, "fct_IDel", functs, "function")
        need(o, "fct_IDt", functs, "function")
        ft = functs.get(val(o, "fct_IDt", 0))
        if ft is not None:
            ys = [r.get("Y") or 0.0 for r, _ in ft["recs"]]
            if not ys or any(y != ys[0] for y in ys):
                p = pos(o, "fct_IDt")
                I("RX510", p[0], p[1], "/FAIL/TAB %d: temperature function not constant" % o["id"])
        solid = any(kinds & {"/BRICK", "/TETRA4", "/BRIC20"} and pid in parts
                    and val(parts[pid], "mat_ID") == o["id"] for pid, kinds in part_kind.items())
        if solid:
            nv = val(o, "n", 0.0)
            if nv not in (0, 0.0, 1, 1.0):
                p = pos(o, "n")
                I("RX510", p[0], p[1], "/FAIL/TAB %d: n != 1 on solids" % o["id"])
            if val(o, "fct_IDel", 0) != 0:
                p = pos(o, "fct_IDel")
                I("RX510", p[0], p[1], "/FAIL/TAB %d: size function on solids" % o["id"])

    # /FAIL/BIQUAD/mat_ID (build_fail_biquad.cpp, check_formulations.cpp): on an existing LAW2 or LAW36
    # material, one failure model per material; refused: the softening (ICOUP 1, or 2 with S_Flag 3 and
    # 0 < Inst_start < C4 after M_Flag, or DCRIT > 0), Ireg > 1 with a size function, P_thickfail < 0, a size
    # function on solids; S_Flag outside 0..3 is out of range
    ratios = {2: (4.3, 1.4, 0.6, 1.6), 3: (5.2, 3.1, 0.8, 3.5), 4: (5.0, 1.0, 0.4, 0.8), 5: (7.8, 3.5, 0.6, 2.8),
              6: (3.6, 0.6, 0.5, 0.6), 7: (10.0, 2.7, 0.6, 0.7)}
    tension = {2: 0.5, 3: 0.12, 4: 0.3, 5: 0.17, 6: 0.1, 7: 0.11}
    for o in m.of("/FAIL/BIQUAD"):
        mat = mats.get(o["id"])
        if mat is None:
            I("RX402", o["pos"][0], o["pos"][1], "/FAIL/BIQUAD: material %d does not exist" % o["id"])
            continue
        if mat["path"] not in ("/MAT/LAW2", "/MAT/PLAS_JOHNS", "/MAT/LAW02", "/MAT/LAW36", "/MAT/PLAS_TAB"):
            I("RX510", o["pos"][0], o["pos"][1], "/FAIL/BIQUAD on %s %d" % (mat["path"], o["id"]))
            continue
        if o["id"] in failed_mats:
            I("RX401", o["pos"][0], o["pos"][1], "/FAIL/BIQUAD: material %d has one already" % o["id"])
            continue
        failed_mats.add(o["id"])
        m_flag = val(o, "M_Flag", 0)
        c3 = val(o, "C3", 0.0) or tension.get(m_flag, 0.6)
        c4 = val(o, "C4", 0.0)
        blank = all(val(o, k, 0.0) == 0 for k in ("C1", "C2", "C4", "C5"))
        if m_flag == 99:
            c4 = val(o, "R4", 0.0) * c3
        elif m_flag != 0 or blank:
            c4 = ratios.get(m_flag, (3.5, 1.6, 0.6, 1.5))[2] * c3
        s_flag = val(o, "S_Flag", 0)
        if s_flag not in (0, 1, 2, 3):
            p = pos(o, "S_Flag")
            I("RX501", p[0], p[1], "/FAIL/BIQUAD %d: S_Flag not 0..3" % o["id"])
        inst = val(o, "Inst_start", 0.0)
        s3 = s_flag == 3 and 0 < inst < c4
        icoup, dcrit = val(o, "ICOUP", 0), min(max(val(o, "DCRIT", 0.0), 0.0), 1.0)
        if icoup == 2 and not s3:
            icoup = 0
        if icoup != 0:
            p = pos(o, "ICOUP")
            I("RX510", p[0], p[1], "/FAIL/BIQUAD %d: ICOUP (softening)" % o["id"])
        elif dcrit > 0 and val(o, "ICOUP", 0) == 0:
            p = pos(o, "DCRIT")
            I("RX510", p[0], p[1], "/FAIL/BIQUAD %d: DCRIT > 0 (softening)" % o["id"])
        if val(o, "fct_IDel", 0) != 0 and val(o, "Ireg", 0) > 1:
            p = pos(o, "Ireg")
            I("RX510", p[0], p[1], "/FAIL/BIQUAD %d: Ireg > 1" % o["id"])
        if val(o, "P_thickfail", 0.0) < 0:
            p = pos(o, "P_thickfail")
            I("RX510", p[0], p[1], "/FAIL/BIQUAD %d: P_thickfail < 0 not implemented by radx" % o["id"])
        need(o, "fct_IDel", functs, "function")
        solid = any(kinds & {"/BRICK", "/TETRA4", "/BRIC20"} and pid in parts
                    and val(parts[pid], "mat_ID") == o["id"] for pid, kinds in part_kind.items())
        if solid and val(o, "fct_IDel", 0) != 0:
            p = pos(o, "fct_IDel")
            I("RX510", p[0], p[1], "/FAIL/BIQUAD %d: size function on solids" % o["id"])



def loads(tables):
    """Kinematic conditions and loads (build_loads.cpp): /BCS, /ADMAS, /INIVEL, /IMPVEL, /IMPDISP, /GRAV."""
    I, functs, grnods, m, need = tables.issue, tables.functs, tables.grnods, tables.m, tables.need
    for o in m.of("/BCS"):
        need(o, "grnod_ID", grnods, "node group", zero_ok=False)
    # /ALE/BCS: only ALE nodes' grid and material velocities; radx's nodes are Lagrangian (build_loads.cpp)
    for o in m.of("/ALE/BCS"):
        need(o, "grnod_ID", grnods, "node group", zero_ok=False)
        if val(o, "grnod_ID", 0) in grnods:
            p = pos(o, "grnod_ID")
            I("RX509", p[0], p[1], "/ALE/BCS %d changes nothing on Lagrangian nodes" % o["id"], warning=True)
    for o in m.of("/ADMAS/0", "/ADMAS/1"):
        need(o, "grnod_ID", grnods, "node group", zero_ok=False)
        if val(o, "MASS", 0.0) < 0:
            p = pos(o, "MASS")
            I("RX501", p[0], p[1], "%s %d: MASS must be >= 0" % (o["path"], o["id"]))
    for o in m.of("/INIVEL/TRA", "/INIVEL/T+G", "/INIVEL/ROT"):
        need(o, "grnod_ID", grnods, "node group", zero_ok=False)
    for o in m.of("/IMPVEL", "/IMPDISP"):
        need(o, "funct_IDT", functs, "function", zero_ok=False)
        need(o, "grnod_ID", grnods, "node group", zero_ok=False)
    for o in m.of("/IMPDISP"):
        if str(val(o, "Dir", "")).strip().upper() in ("XX", "YY", "ZZ"):
            p = pos(o, "Dir")
            I("RX510", p[0], p[1], "/IMPDISP %d: an imposed rotation angle is not implemented" % o["id"])
    for o in m.of("/GRAV"):
        need(o, "funct_IDT", functs, "function")
        need(o, "grnod_ID", grnods, "node group")


def skews(tables):
    """Skews and frames (build_skews.cpp; one id space for /SKEW/FIX, /SKEW/MOV, /FRAME/FIX and /FRAME/MOV): a
    fixed one needs two independent directions (a skew's direction with only a Y (Z) component is its sign, a
    frame's is used as given), a moving one three distinct existing nodes, N2 off N1 and N3 off the line N1 N2
    (sine of the angle > 1e-5), Dir X, Y, Z or blank; the loads and conditions may name a skew only, /IMPVEL and
    /IMPDISP frame_ID a frame (refused: RX510)."""
    I, by_id, m, nodes = tables.issue, tables.by_id, tables.m, tables.nodes
    both = by_id(("/SKEW/FIX", "/SKEW/MOV", "/FRAME/FIX", "/FRAME/MOV"), "skew or frame")
    skews = {k: o for k, o in both.items() if o["path"].startswith("/SKEW/")}
    frames = {k: o for k, o in both.items() if o["path"].startswith("/FRAME/")}
    for o in both.values():
        if o["path"] not in ("/SKEW/MOV", "/FRAME/MOV"):
            continue
        ids = [val(o, k, 0) for k in ("N1", "N2", "N3")]
        d = str(val(o, "Dir", "")).strip().upper()
        if d not in ("", "X", "Y", "Z"):
            p = pos(o, "Dir")
            I("RX501", p[0], p[1], "%s %d: Dir = %r is not X, Y or Z" % (o["path"], o["id"], d))
        bad = False
        for k, x in zip(("N1", "N2", "N3"), ids):
            p = pos(o, k)
            if x == 0:
                I("RX502", p[0], p[1], "%s %d: %s is required" % (o["path"], o["id"], k))
                bad = True
            elif x not in nodes:
                I("RX402", p[0], p[1], "%s %d: node %d does not exist" % (o["path"], o["id"], x))
                bad = True
        if bad:
            continue
        p = pos(o, "N1")
        if len(set(ids)) < 3:
            I("RX507", p[0], p[1], "%s %d: the nodes %s are not distinct" % (o["path"], o["id"], ids))
            continue
        e = sub(nodes[ids[1]], nodes[ids[0]])
        t = sub(nodes[ids[2]], nodes[ids[0]])
        if norm(e) == 0:
            I("RX507", p[0], p[1], "%s %d: N2 sits on N1" % (o["path"], o["id"]))
        elif norm(cross(e, t)) <= 1e-5 * norm(e) * norm(t):
            I("RX507", p[0], p[1], "%s %d: N3 lies on the line N1 N2" % (o["path"], o["id"]))
    for o in both.values():
        if o["path"] not in ("/SKEW/FIX", "/FRAME/FIX"):
            continue
        y = [val(o, k, 0.0) for k in ("X1", "Y1", "Z1")]
        z = [val(o, k, 0.0) for k in ("X2", "Y2", "Z2")]
        if o["path"] == "/SKEW/FIX":
            if y[0] == 0 and y[2] == 0:
                y[1] = -1.0 if y[1] < 0 else 1.0
            if z[0] == 0 and z[1] == 0:
                z[2] = -1.0 if z[2] < 0 else 1.0
        if norm(z) == 0 or norm(cross(y, z)) <= 1e-12 * norm(y) * norm(z):
            p = pos(o, "X2")
            I("RX507", p[0], p[1], "%s %d: Y' and Z' are parallel or zero" % (o["path"], o["id"]))
    for o in m.of("/BCS", "/IMPVEL", "/IMPDISP", "/INIVEL/TRA", "/INIVEL/T+G", "/INIVEL/ROT", "/CLOAD", "/GRAV"):
        sk = val(o, "skew_ID", 0)
        if sk and sk not in skews:
            p = pos(o, "skew_ID")
            I("RX402", p[0], p[1], "%s %d: skew %d does not exist" % (o["path"], o["id"], sk))
    for o in m.of("/IMPVEL", "/IMPDISP"):
        fr = val(o, "frame_ID", 0)
        if fr:
            p = pos(o, "frame_ID")
            if fr not in frames:
                I("RX402", p[0], p[1], "%s %d: frame %d does not exist" % (o["path"], o["id"], fr))
            else:
                I("RX510", p[0], p[1], "%s %d: imposed relative to frame %d" % (o["path"], o["id"], fr))
    tables.skews = skews
    tables.frames = frames


def random_perturbation(tables):
    """Random perturbation (build_random.cpp): XALEA >= 0; a group that exists; all nodes or groups, not both
    (Radioss: neither)."""
    I, grnods, m = tables.issue, tables.grnods, tables.m
    for o in m.of("/RANDOM", "/RANDOM/GRNOD"):
        if val(o, "XALEA", 0.0) < 0:
            p = pos(o, "XALEA")
            I("RX501", p[0], p[1], "%s: XALEA must be >= 0" % o["path"])
    for o in m.of("/RANDOM/GRNOD"):
        if val(o, "XALEA", 0.0) > 0 and o["id"] not in grnods:
            I("RX402", o["pos"][0], o["pos"][1], "/RANDOM/GRNOD/%d: node group does not exist" % o["id"])
    rall = [o for o in m.of("/RANDOM") if val(o, "XALEA", 0.0) > 0]
    rgrp = [o for o in m.of("/RANDOM/GRNOD") if val(o, "XALEA", 0.0) > 0]
    if rall and rgrp:
        p = pos(rgrp[0], "XALEA")
        I("RX507", p[0], p[1], "/RANDOM and /RANDOM/GRNOD both given")


def sensors_bodies_walls(tables):
    """Accelerometers, /CLOAD, sensors, rigid bodies, rigid walls and /IMPDISP/FGEO (build_loads.cpp)."""
    I, by_id, functs, grnods, m = tables.issue, tables.by_id, tables.functs, tables.grnods, tables.m
    need, nodes, skews = tables.need, tables.nodes, tables.skews
    # accelerometers: on an existing node, in an existing skew, with a cut-off frequency >= 0
    accels = by_id(("/ACCEL",), "accelerometer")
    for o in accels.values():
        need(o, "node_ID", nodes, "node", zero_ok=False)
        need(o, "skew_ID", skews, "skew")
        if val(o, "Fcut", 0.0) < 0:
            p = pos(o, "Fcut")
            I("RX501", p[0], p[1], "/ACCEL %d: Fcut must be >= 0" % o["id"])
    for o in m.of("/TH/ACCEL"):
        for x, p in o["ids"]:
            if x not in accels:
                I("RX402", p[0], p[1], "TH accelerometer %d does not exist" % x, warning=True)
    for o in m.of("/CLOAD"):
        need(o, "funct_IDT", functs, "function", zero_ok=False)
        need(o, "grnod_ID", grnods, "node group", zero_ok=False)
    # sensors: Tstop (0 = never) after Tdelay; every sensor_ID / sens_ID names one; a rigid body's sensor must not
    # switch off again (radx does not form a released body again: RX510)
    sensors = by_id(("/SENSOR/TIME", "/SENSOR/TYPE0"), "sensor")
    for o in sensors.values():
        t_stop = val(o, "Tstop", 0.0)
        if t_stop != 0 and t_stop <= val(o, "Tdelay", 0.0):
            p = pos(o, "Tstop")
            I("RX507", p[0], p[1], "/SENSOR/TIME %d: Tstop <= Tdelay" % o["id"])
    for o in m.of("/IMPVEL", "/IMPDISP", "/INIVEL/TRA", "/INIVEL/T+G", "/INIVEL/ROT", "/CLOAD", "/GRAV"):
        need(o, "sensor_ID", sensors, "sensor")
    for o in m.of("/INTER/TYPE7", "/RBODY"):
        need(o, "sens_ID", sensors, "sensor")
    for o in m.of("/RBODY"):
        sensor = sensors.get(val(o, "sens_ID", 0))
        if sensor is not None and val(sensor, "Tstop", 0.0) != 0:
            p = pos(o, "sens_ID")
            I("RX510", p[0], p[1], "/RBODY %d: its sensor switches off again (Tstop)" % o["id"])
        # Ioptoff = 1 (elements inside the body not computed) changes the step and the energies: refused
        if val(o, "Ioptoff", 0) == 1:
            p = pos(o, "Ioptoff")
            I("RX510", p[0], p[1], "/RBODY %d: Ioptoff = 1 is not implemented" % o["id"])
        # a group holding only the main node: a warning; then, without added inertia and with a main node of no
        # shell, beam or spring, the body has no rotational inertia (Radioss's error 274)
        main, gid = val(o, "node_ID", 0), val(o, "grnd_ID", 0)
        if gid in grnods and main in nodes:
            members = tables.grnod_members.get(gid, set())
            if members and not (members - {main}):
                p = pos(o, "grnd_ID")
                I("RX403", p[0], p[1], "/RBODY %d: its group holds only the main node" % o["id"], warning=True)
            rotational = any(main in ns for kind in ("/SHELL", "/SH3N", "/BEAM")
                             for _, ns in tables.elements[kind].values()) or \
                any(main in [r.get("n1"), r.get("n2"), r.get("n3")] for so in m.of("/SPRING") for r, _ in so["recs"])
            if not (members - {main}) and val(o, "sens_ID", 0) == 0 and not rotational and \
                    all(val(o, k, 0.0) <= 0 for k in ("Jxx", "Jyy", "Jzz")):
                p = pos(o, "grnd_ID")
                I("RX502", p[0], p[1], "/RBODY %d: no secondary node and no inertia" % o["id"])
    for o in m.of("/RWALL/CYL", "/RWALL/SPHER"):
        if val(o, "Diameter", 0.0) <= 0:
            p = pos(o, "Diameter")
            I("RX502" if val(o, "Diameter", 0.0) == 0 else "RX501", p[0], p[1],
              "%s %d: Diameter must be > 0" % (o["path"], o["id"]))
    for o in m.of("/RWALL/PLANE", "/RWALL/CYL", "/RWALL/SPHER", "/RWALL/PARAL"):
        need(o, "grnd_ID1", grnods, "node group")
        need(o, "grnd_ID2", grnods, "node group")
    for o in m.of("/RWALL/PARAL"):
        corner = [val(o, k, 0.0) for k in ("XM", "YM", "ZM")]
        if val(o, "node_ID", 0) in nodes:
            corner = list(nodes[val(o, "node_ID")])
        e1 = sub([val(o, k, 0.0) for k in ("XM1", "YM1", "ZM1")], corner)
        e2 = sub([val(o, k, 0.0) for k in ("XM2", "YM2", "ZM2")], corner)
        if norm(cross(e1, e2)) == 0:
            p = pos(o, "XM2")
            I("RX507", p[0], p[1], "/RWALL/PARAL %d: M, M1 and M2 are aligned" % o["id"])
    for o in m.of("/IMPDISP/FGEO"):
        need(o, "fct_ID", functs, "function", zero_ok=False)
        if val(o, "part_ID", 0) != 0:
            p = pos(o, "part_ID")
            I("RX509", p[0], p[1], "/IMPDISP/FGEO %d: the spring-part form is not supported" % o["id"])
        for r, p in o["recs"]:
            if r.get("node_IDN") not in nodes:
                I("RX402", p[0], p[1], "/IMPDISP/FGEO %d: node %s does not exist" % (o["id"], r.get("node_IDN")))
        if not o["recs"] and val(o, "part_ID", 0) == 0:
            I("RX305", o["pos"][0], o["pos"][1], "/IMPDISP/FGEO %d lists no node" % o["id"])


def interfaces(tables):
    """Contact interfaces /INTER/TYPE7 and /INTER/LAGDT/TYPE7 (build_interfaces.cpp)."""
    I, grnods, inters, need, surfs = tables.issue, tables.grnods, tables.inters, tables.need, tables.surfs
    for iid, o in inters.items():
        # 0: the main surface's nodes are the secondary nodes (a self-contact), as Radioss takes them
        need(o, "grnd_IDs", grnods, "node group", zero_ok=True)
        need(o, "surf_IDm", surfs, "surface", zero_ok=False)
        # a main surface that holds no segment: Radioss stops (its error 3160), radx too
        sid = val(o, "surf_IDm", 0)
        if sid in surfs and sid in tables.surf_nodes and not tables.surf_nodes[sid]:
            p = pos(o, "surf_IDm")
            I("RX403", p[0], p[1], "interface %d: the main surface %d holds no segment" % (iid, sid))
        rng = {"Istf": (0, 1, 2, 3, 4, 5), "Igap": (0, 1, 2, 1000), "Inacti": (0, 1, 2, 3, 5, 6), "Ifric": (0, 1, 2, 3),
               "Idel": (-2, -1, 0, 1, 2), "Iform": (0, 1, 2), "Ifiltr": (0, 1, 2, 3)}
        for f, allowed in rng.items():
            if val(o, f, 0) not in allowed:
                p = pos(o, f)
                I("RX501", p[0], p[1], "interface %d: %s = %d" % (iid, f, val(o, f, 0)))
        if val(o, "Istf", 0) == 1 and val(o, "Stfac", 0.0) == 0:
            p = pos(o, "Stfac")
            I("RX502", p[0], p[1], "interface %d: Istf = 1 needs a stiffness in Stfac" % iid)
        ts, te = val(o, "Tstart", 0.0), val(o, "Tstop", 0.0)
        if te != 0 and te <= ts:
            p = pos(o, "Tstop")
            I("RX507", p[0], p[1], "interface %d: Tstop <= Tstart" % iid)
        if val(o, "Ifric", 0) == 3:
            c = [val(o, "C%d" % k, 0.0) for k in range(1, 7)]
            if c[4] == 0 or not (c[4] < c[5]) or not (c[3] <= c[0] <= c[2]) or not (c[3] <= c[1] <= c[2]):
                p = pos(o, "C5")
                I("RX703", p[0], p[1], "interface %d: Renard coefficients inconsistent" % iid)


def tied_interfaces(tables):
    """Tied interfaces (build_tied.cpp): references, Spotflag values (0, 1, 5 run), the ones radx refuses (RX510),
    a node tied by two TYPE2 (RX706, on the second; the nodes of the groups, which all find a segment here)."""
    I, grnods, m, need, surfs = tables.issue, tables.grnods, tables.m, tables.need, tables.surfs
    tied_nodes = {}
    for o in m.of("/INTER/TYPE2"):
        need(o, "grnd_IDs", grnods, "node group", zero_ok=False)
        need(o, "surf_IDm", surfs, "surface", zero_ok=False)
        flag = val(o, "Spotflag", 0)
        p = pos(o, "Spotflag")
        if flag not in (0, 1, 2, 3, 4, 5, 10, 11, 12, 20, 21, 22, 25, 26, 27, 28, 30):
            I("RX501", p[0], p[1], "/INTER/TYPE2 %d: Spotflag = %d" % (o["id"], flag))
        elif flag not in (0, 1, 5):
            I("RX510", p[0], p[1], "/INTER/TYPE2 %d: Spotflag %d not implemented" % (o["id"], flag))
        if val(o, "Idel2", 0) not in (0, 1000):
            p = pos(o, "Idel2")
            I("RX510", p[0], p[1], "/INTER/TYPE2 %d: Idel2 not implemented" % o["id"])
        sid = val(o, "surf_IDm", 0)
        got = tables.set_members.get(sid) if sid not in surfs else None
        if got is not None and not (got["/SHELL"] or got["/SH3N"] or got["solids"]):
            p = pos(o, "surf_IDm")
            I("RX403", p[0], p[1], "/INTER/TYPE2 %d: the main surface (set %d) has no segment" % (o["id"], sid))
        g = grnods.get(val(o, "grnd_IDs", 0))
        if g is not None and flag in (0, 1, 5) and g["path"] == "/GRNOD/NODE":
            ids = [x for x, _ in g.get("ids", []) if isinstance(x, int) and x > 0]
            twice = [x for x in ids if x in tied_nodes]
            if twice:
                p = pos(o, "grnd_IDs")
                I("RX706", p[0], p[1], "/INTER/TYPE2 %d: nodes tied twice" % o["id"])
            for x in ids:
                tied_nodes.setdefault(x, o["id"])


def contact_laws(tables):
    """Contact laws (/CTCLAW, docs/theory/contact-laws.md sections 4 and 5; build_interfaces.cpp): the interface exists,
    the law string reads."""
    I, functs, inters, m, need = tables.issue, tables.functs, tables.inters, tables.m, tables.need
    for o in m.of("/CTCLAW"):
        need(o, "inter_ID", inters, "interface", zero_ok=False)
        for at, msg in law_string_problems(o.get("text", []), functs):
            I("RX704", at[0], at[1], "/CTCLAW %d: %s" % (o["id"], msg))


def sections(tables):
    """Sections (build_sections.cpp): frame nodes, the cut's node group and the element groups must exist; radx
    refuses a moving frame, interface forces, reading cut files and truss, beam or spring groups (RX510,
    RX402)."""
    I, by_id, egroups, grnods, need = tables.issue, tables.by_id, tables.egroups, tables.grnods, tables.need
    nodes = tables.nodes
    sects = by_id(("/SECT",), "section")
    for o in sects.values():
        for f in ("node_ID1", "node_ID2", "node_ID3"):
            if val(o, f, 0) != 0 and val(o, f) not in nodes:
                p = pos(o, f)
                I("RX402", p[0], p[1], "/SECT %d: node %d does not exist" % (o["id"], val(o, f)))
        need(o, "grnod_ID", grnods, "node group", zero_ok=False)
        for f in ("Frame_ID", "Ninter"):
            if val(o, f, 0) != 0:
                p = pos(o, f)
                I("RX510", p[0], p[1], "/SECT %d: %s is not implemented" % (o["id"], f))
        if val(o, "I_SAVE", 0) >= 100:
            p = pos(o, "I_SAVE")
            I("RX510", p[0], p[1], "/SECT %d: reading cut files is not implemented" % o["id"])
        if val(o, "grsprg_ID", 0) != 0:
            p = pos(o, "grsprg_ID")
            I("RX510", p[0], p[1], "/SECT %d: grsprg_ID: a section sums no spring force" % o["id"])
        listed = [(f, root) for f, root in (("grbric_ID", "/GRBRIC"), ("grshel_ID", "/GRSHEL"),
                                            ("grtria_ID", "/GRSH3N"), ("grtrus_ID", "/GRTRUS"),
                                            ("grbeam_ID", "/GRBEAM")) if val(o, f, 0) != 0]
        if not listed:
            p = pos(o, "grshel_ID")
            I("RX404", p[0], p[1], "/SECT %d: no element group" % o["id"])
        for f, root in listed:
            if (root, val(o, f)) not in egroups:
                p = pos(o, f)
                I("RX402", p[0], p[1], "/SECT %d: %s group %d does not exist" % (o["id"], root, val(o, f)))
            elif root == "/GRBRIC":
                # a brick group's tetrahedra on the cut: radx sums no tetrahedron force in a section
                cut = tables.grnod_members.get(val(o, "grnod_ID"), set())
                tetras = tables.elements["/TETRA4"]
                if any(e in tetras and e not in tables.elements["/BRICK"] and set(tetras[e][1]) & cut
                       for e in tables.emembers[(root, val(o, f))]):
                    p = pos(o, f)
                    I("RX510", p[0], p[1], "/SECT %d: tetrahedra of brick group %d on the cut" % (o["id"], val(o, f)))
    tables.sects = sects


def transforms(tables):
    """Model assembly (build_transforms.cpp): a transform moves a node group or a submodel (one of them), its node
    pairs are complete, its rotation axis or mirror normal is not of zero length; /MOVE_FUNCT names an existing
    function."""
    I, by_id, functs, grnods, m = tables.issue, tables.by_id, tables.functs, tables.grnods, tables.m
    need, nodes = tables.need, tables.nodes
    subs = by_id(("//SUBMODEL",), "submodel")
    for o in m.of("/TRANSFORM/TRA", "/TRANSFORM/ROT", "/TRANSFORM/SCA", "/TRANSFORM/SYM"):
        kind = o["path"].split("/")[2]
        g, sb = val(o, "grnod_ID", 0), val(o, "sub_ID", 0)
        if g and sb:
            p = pos(o, "sub_ID")
            I("RX507", p[0], p[1], "%s %d: grnod_ID and sub_ID both given" % (o["path"], o["id"]))
            continue
        if not g and not sb:
            p = pos(o, "grnod_ID")
            I("RX404", p[0], p[1], "%s %d: neither grnod_ID nor sub_ID" % (o["path"], o["id"]))
            continue
        if g:
            need(o, "grnod_ID", grnods, "node group")
        else:
            need(o, "sub_ID", subs, "submodel")
        if kind == "SCA":
            need(o, "node_IDc", nodes, "node")
            continue
        a, b = val(o, "node_ID1", 0), val(o, "node_ID2", 0)
        if bool(a) != bool(b):
            p = pos(o, "node_ID1" if not a else "node_ID2")
            I("RX404", p[0], p[1], "%s %d: one node of the pair is missing" % (o["path"], o["id"]))
            continue
        need(o, "node_ID1", nodes, "node")
        need(o, "node_ID2", nodes, "node")
        if kind == "TRA" or (kind == "ROT" and val(o, "Angle", 0.0) == 0.0):
            continue
        if a:
            if a in nodes and b in nodes and nodes[a] == nodes[b]:
                p = pos(o, "node_ID2")
                I("RX605", p[0], p[1], "%s %d: both nodes at one place" % (o["path"], o["id"]))
        elif all(val(o, x + "1", 0.0) == val(o, x + "2", 0.0) for x in "XYZ"):
            p = pos(o, "X2")
            I("RX605", p[0], p[1], "%s %d: point 1 = point 2" % (o["path"], o["id"]))
    for o in m.of("/MOVE_FUNCT"):
        if o["id"] not in functs:
            I("RX402", o["pos"][0], o["pos"][1], "/MOVE_FUNCT %d: no such function" % o["id"])


def time_history(tables):
    """Time-history requests (build_loads.cpp): the objects they name exist (a missing node or element is an
    error, a missing part, subset, interface, wall, body, section or accelerometer a warning: left out, as
    Radioss does), and their variable names."""
    I, by_id, elem_ids, inters, m = tables.issue, tables.by_id, tables.elem_ids, tables.inters, tables.m
    nodes, parts, sects, skews, subsets = tables.nodes, tables.parts, tables.sects, tables.skews, tables.subsets
    for o in m.of("/TH/SECTIO"):
        for x, p in o["ids"]:
            if x not in sects:
                I("RX402", p[0], p[1], "TH section %d does not exist" % x, warning=True)

    # time history; node values may be written in a skew, shell results only in the element frame
    for o in m.of("/TH/NODE"):
        for r, p in o["recs"]:
            if r.get("node_ID") not in nodes:
                I("RX402", p[0], p[1], "TH node %s does not exist" % r.get("node_ID"))
    for o in m.of("/TH/NODE", "/TH/SHEL", "/TH/SH3N"):
        for r, p in o["recs"]:
            sk = r.get("skew_ID") or 0
            # a /TH/NODE skew_ID may name a frame: a /FRAME/FIX is written, a /FRAME/MOV refused (RX509)
            if sk and o["path"] == "/TH/NODE" and sk in tables.frames:
                if tables.frames[sk]["path"] == "/FRAME/MOV":
                    I("RX509", p[0], p[1], "%s %d: node in moving frame %d" % (o["path"], o["id"], sk))
            elif sk and sk not in skews and sk not in tables.frames:
                I("RX402", p[0], p[1], "%s %d: skew %d does not exist" % (o["path"], o["id"], sk))
            elif sk and o["path"] != "/TH/NODE":
                I("RX509", p[0], p[1], "%s %d: shell results in skew %d" % (o["path"], o["id"], sk))
    for o in m.of("/TH/PART"):
        for x, p in o["ids"]:
            if x not in parts:
                I("RX402", p[0], p[1], "TH part %d does not exist" % x, warning=True)
    for o in m.of("/TH/SUBS"):
        for x, p in o["ids"]:
            if x not in subsets:
                I("RX402", p[0], p[1], "TH subset %d does not exist" % x, warning=True)
    type2_ids = {o["id"] for o in m.of("/INTER/TYPE2")}
    for o in m.of("/TH/INTER"):
        for x, p in o["ids"]:
            if x not in inters and x not in type2_ids:  # a TYPE2 id: a warning, not written
                I("RX402", p[0], p[1], "TH interface %d does not exist" % x, warning=True)
    rbodies = by_id(("/RBODY",), "rigid body")
    for o in m.of("/TH/BRIC", "/TH/BRICK", "/TH/SH3N"):
        kind = "/BRICK" if o["path"] != "/TH/SH3N" else "/SH3N"
        for r, p in o["recs"]:
            eid = r.get("elem_ID", r.get("node_ID"))
            if kind == "/BRICK" and eid not in elem_ids[kind] and eid in elem_ids["/TETRA4"]:
                # Radioss records a tetrahedron as a brick; radx writes none (a warning, the run goes on)
                I("RX311", p[0], p[1], "TH tetrahedron %s is not written" % eid, warning=True)
            elif eid not in elem_ids[kind] and not (kind == "/BRICK" and eid in elem_ids["/BRIC20"]):
                # a 20-node brick is recorded under /TH/BRIC (build_loads.cpp)
                I("RX402", p[0], p[1], "TH %s element %s does not exist" % (kind, eid))
    for o in m.of("/TH/RBODY"):
        for x, p in o["ids"]:
            if x not in rbodies:
                I("RX402", p[0], p[1], "TH rigid body %d does not exist" % x, warning=True)
    for o in m.objs:
        if o["path"] not in TH_VARIABLES:
            continue
        groups, single = TH_VARIABLES[o["path"]]
        words = [w.upper() for line_ in o.get("vars", []) for w in line_]
        if not words:
            I("RX502", o["pos"][0], o["pos"][1], "%s %d: no variable names" % (o["path"], o["id"]))
        for w in words:
            if w not in groups and w not in single:
                I("RX501", o["pos"][0], o["pos"][1], "%s %d: unknown variable %s" % (o["path"], o["id"], w))


# ---------------------------------------------------------------------------------------------------
# Element groups (/GRSHEL, /GRSH3N, /GRBRIC) and the node groups and surfaces built from them, as Radioss
# defines them:
#   * SHEL/SH3N/BRIC list element ids (a negative or unknown id is an error);
#   * PART, SUBSET (with its child subsets), MAT, PROP, and the family's own group subtype: a negative id
#     removes, whatever its place in the list;
#   * BOX: elements with all their nodes in the box (faces included), BOX2: with one node in it; only the
#     first positive box id is read;
#   * /GRNOD/GR...: nodes of the groups' elements, negative ids ignored;
#   * /SURF/GRSHEL, /SURF/GRSH3N: one segment per element; /SURF/GRBRIC/EXT: brick faces no other brick of the
#     groups has; /FREE: no other brick at all; bare /SURF/GRBRIC is refused; /SURF/PART/ALL: every brick face
#     of the parts (a shell of the listed parts on a face replaces it) plus their shells.
# Errors: RX402 at the id's line (a warning unless it is an element id: the part, group or box is left out, as in
# Radioss), RX507 for a group that reaches itself (at the keyword line of the group found again), RX403 (a
# warning) at the keyword line when the result is empty and no error was found while building it (node groups:
# whenever empty), RX407 for a bare /SURF/GRBRIC. /GRBRIC takes the tetrahedra as bricks; GENE the existing ids
# of each pair `first last`.

HEX_FACES = ((1, 4, 3, 2), (5, 6, 7, 8), (1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (4, 1, 5, 8))  # 1-based, outward
TET_FACES = ((1, 2, 3), (1, 2, 4), (2, 3, 4), (1, 3, 4))  # 1-based, as node sets


def group_elements(elements, root):
    """The elements a group of `root` can hold, by id: a brick group takes the tetrahedra too (Radioss stores a
    tetrahedron as a brick)."""
    els = dict(elements[GROUP_FAMILIES[root][0]])
    if root == "/GRBRIC":
        for e, v in list(elements["/TETRA4"].items()) + list(elements["/BRIC20"].items()):
            els.setdefault(e, v)
    return els


# The law string of /CTCLAW, read from docs/theory/contact-laws.md section 4 as a table of laws and their parameters:
# "req" required, "opt" optional, "multi" the power terms kp<m>=<value>. Values: a rule on the number.
LAW_NORMAL = {1: {"kc": "req"}, 2: {"pz": "req", "lambda": "opt", "pe": "opt", "kcmax": "opt"},
              3: {"curveid": "req", "cubic": "opt"}, 4: {"kp": "multi"}}
LAW_FRICTION = {f: ({"mu": "req", "kappa": "opt"} if f in (1, 11) else {"mu": "req", "ctlin": "req", "kappa": "opt"})
                for f in (1, 2, 3, 4, 11, 12, 13, 14)}
LAW_RULES = {"kc": lambda x: x > 0 or x == -1, "pz": lambda x: x > 0, "lambda": lambda x: x > 0,
             "pe": lambda x: x > 0, "kcmax": lambda x: x > 0, "curveid": lambda x: x >= 1 and x == int(x),
             "cubic": lambda x: x in (0, 1), "mu": lambda x: x >= 0, "ctlin": lambda x: x > 0,
             "kappa": lambda x: x > 0}
LAW_HEAD_RE = re.compile(r"^(?:([nN])(\d*))?(?:([sS])(\d*))?")
LAW_PARAM_RE = re.compile(r"^([A-Za-z_]+)(.*)$")


def law_number(text):
    """A real in any Fortran form (1.D5, .5, 1.5-3), or None."""
    if not REAL_RE.match(text):
        return None
    x = float(re.sub(r"(\d)([+-]\d+)$", r"\1E\2", text.replace("D", "E").replace("d", "e")))
    return None if math.isinf(x) else x


def law_string_problems(chars, functs):
    """chars: [(character, (file, line))] of the law string without blanks. Returns [((file, line), msg)]."""
    if not chars:
        return []
    text = "".join(c for c, _ in chars)
    where = [p for _, p in chars]
    out = []

    def bad(i, msg):
        out.append((where[min(i, len(where) - 1)], msg))

    head = LAW_HEAD_RE.match(text)
    laws = {}
    for letter, digits, table, kind in ((head.group(1), head.group(2), LAW_NORMAL, "n"),
                                        (head.group(3), head.group(4), LAW_FRICTION, "s")):
        if letter is None:
            laws[kind] = 0
        elif digits and int(digits) in table:
            laws[kind] = int(digits)
        else:
            laws[kind] = -1
            bad(head.start(1 if kind == "n" else 3), "unknown %s law %s%s" % (kind, letter, digits))
    if not head.group(1) and not head.group(3):
        bad(0, "neither an n nor an s part")
        laws = {"n": -1, "s": -1}
    rest = head.end()
    body, body_at = "", rest
    if rest < len(text):
        if text[rest] != "{":
            brace = text.find("{", rest)
            bad(rest, "unexpected text")
            rest = len(text) if brace < 0 else brace
        if rest < len(text):
            close = text.find("}", rest)
            if close < 0:
                bad(rest, "unclosed brace")
                close = len(text)
            elif close + 1 < len(text):
                bad(close + 1, "text after the closing brace")
            body, body_at = text[rest + 1:close], rest + 1
    takes = {}
    for kind, table in (("n", LAW_NORMAL), ("s", LAW_FRICTION)):
        if laws[kind] > 0:
            takes.update(table[laws[kind]])
        elif laws[kind] < 0:  # an unknown law: its parameters are not judged
            for t in table.values():
                for name in t:
                    takes.setdefault(name, "any")
    given, powers = {}, []
    offset = body_at
    for item in (body.split(",") if body else []):
        at, offset = offset, offset + len(item) + 1
        m = LAW_PARAM_RE.match(item)
        if not item or "{" in item or m is None:
            bad(at, "malformed parameter %r" % item)
            continue
        name, value = m.group(1).lower(), m.group(2)
        if name not in LAW_RULES and name != "kp":
            bad(at, "unknown parameter %s" % m.group(1))
            continue
        if name not in takes:
            bad(at, "%s is not a parameter of this law" % m.group(1))
            continue
        # the syntax of a value is always judged, its range only under a known law
        judged = takes[name] != "any"
        if name == "kp":
            mx, eq, kx = value.partition("=")
            expo, coef = law_number(mx), law_number(kx)
            if not eq:
                bad(at, "power term not kp<m>=<value>")
            elif expo is None or coef is None:
                # located at the number at fault
                if expo is None:
                    bad(at + 2, "power exponent %r is not a number" % mx)
                if coef is None:
                    bad(at + 3 + len(mx), "power coefficient %r is not a number" % kx)
            elif judged and (expo < 1 or coef < 0 or any(e == expo for e, _, _ in powers)):
                bad(at, "power term exponent or value out of range, or repeated")
            powers.append((expo, coef, at))
            continue
        if name in given:
            bad(at, "%s given twice" % name)
            continue
        x = law_number(value[1:] if value.startswith("=") else value)
        given[name] = (x, at)
        if x is None:
            bad(at + len(m.group(1)), "%s is not a number" % name)  # where the value starts
        elif judged and not LAW_RULES[name](x):
            bad(at, "%s = %g out of range" % (name, x))
    for name, need_it in takes.items():
        if need_it == "req" and name not in given:
            bad(0, "%s missing" % name)
    if laws["n"] == 2:
        if "lambda" in given and "pe" in given:
            bad(max(given["lambda"][1], given["pe"][1]), "lambda and pe together")
        elif "lambda" not in given and "pe" not in given:
            bad(0, "lambda or pe missing")
        x = {k: v[0] for k, v in given.items()}
        if "pe" not in x and all(isinstance(x.get(k), float) and LAW_RULES[k](x[k]) for k in ("pz", "lambda", "kcmax")):
            if x["kcmax"] < x["lambda"] * x["pz"]:
                bad(given["kcmax"][1], "KcMax below lambda pz")
    if laws["n"] == 4:
        if not powers:
            bad(0, "no power term")
        elif all(e is not None and c is not None and e >= 1 and c >= 0 for e, c, _ in powers) and \
                len({e for e, _, _ in powers}) == len(powers) and all(c == 0 for _, c, _ in powers):
            bad(powers[0][2], "every kp is 0")
    if laws["n"] == 3 and "curveid" in given:
        cid, at = given["curveid"]
        if cid is not None and LAW_RULES["curveid"](cid):
            f = functs.get(int(cid))
            if f is None:
                bad(at, "CurveID %d names no /FUNCT" % cid)
            else:
                ys = [r.get("Y") or 0.0 for r, _ in f["recs"]]
                if len(ys) < 2 or any(y < 0 for y in ys) or any(b > a for a, b in zip(ys, ys[1:])):
                    bad(at, "the curve of CurveID %d is not a pressure that falls with the gap" % cid)
    return out


def distinct(ns):
    out = []
    for n in ns:
        if n not in out:
            out.append(n)
    return out


def parts_of_subset(parts, subsets, sid):
    """The parts of a subset and of its child subsets."""
    out, seen, todo = set(), set(), [sid]
    while todo:
        x = todo.pop()
        if x in seen or x not in subsets:
            continue
        seen.add(x)
        out |= {pid for pid, po in parts.items() if val(po, "subset_ID", 0) == x}
        todo += [c for c, _ in subsets[x]["ids"]]
    return out


def check_boxes(ck, m, nodes, placed, place):
    """Boxes, one id space: a test "is this point inside (boundary included)" per box id."""
    I = ck.issue

    # Boxes, one id space: a test "is this point inside (boundary included)" per box. The points come from the
    # nodes N1 and N2 when both are given (the sphere: N1), else from the coordinates, which move with the
    # submodel they are written in.
    boxes = {}
    for o in m.of("/BOX/RECTA", "/BOX/CYLIN", "/BOX/SPHER"):
        if o["id"] in boxes:
            I("RX401", o["pos"][0], o["pos"][1], "box %d defined twice" % o["id"])
            continue
        a = list(place(o, [val(o, k, 0.0) for k in ("Xp1", "Yp1", "Zp1")]))
        b = list(place(o, [val(o, k, 0.0) for k in ("Xp2", "Yp2", "Zp2")]))
        sphere = o["path"] == "/BOX/SPHER"
        n1, n2 = val(o, "N1", 0), val(o, "N2", 0)
        if (n1 and sphere) or (n1 and n2):
            for k in (("N1",) if sphere else ("N1", "N2")):
                if val(o, k, 0) not in nodes:
                    p = pos(o, k)
                    I("RX402", p[0], p[1], "box %d: node %d does not exist" % (o["id"], val(o, k, 0)))
            a = list(placed.get(n1, a))
            b = list(placed.get(n2, b))
        if o["path"] == "/BOX/RECTA":
            lo, hi = [min(a[i], b[i]) for i in range(3)], [max(a[i], b[i]) for i in range(3)]
            boxes[o["id"]] = lambda x, lo=lo, hi=hi: all(lo[i] <= x[i] <= hi[i] for i in range(3))
            continue
        dia = val(o, "Diameter", 0.0)
        if dia <= 0:
            p = pos(o, "Diameter")
            I("RX502" if dia == 0 else "RX501", p[0], p[1], "box %d: Diameter must be > 0" % o["id"])
        if sphere:
            boxes[o["id"]] = lambda x, c=a, r=0.5 * dia: norm(sub(x, c)) <= r
            continue
        length = norm(sub(b, a))
        if length == 0:
            p = pos(o, "N2" if n1 and n2 else "Xp2")
            I("RX507", p[0], p[1], "box %d: the cylinder's end centres coincide" % o["id"])
            boxes[o["id"]] = lambda x: False
            continue
        axis = [c / length for c in sub(b, a)]

        def in_cylinder(x, p1=a, u=axis, h=length, r=0.5 * dia):
            d = sub(x, p1)
            t = sum(d[i] * u[i] for i in range(3))
            return 0 <= t <= h and norm([d[i] - t * u[i] for i in range(3)]) <= r
        boxes[o["id"]] = in_cylinder
    return boxes


def resolve_element_groups(ck, m, placed, parts, props, mats, subsets, elements, boxes):
    """Every element group of every family resolved to its element ids. Returns (groups, members)."""
    I = ck.issue

    groups = {}
    for root in GROUP_FAMILIES:
        for o in m.of(*[p for p in STARTER if p.startswith(root + "/")]):
            key = (root, o["id"])
            if key in groups:
                I("RX401", o["pos"][0], o["pos"][1], "%s group %d defined twice" % key)
                continue
            groups[key] = o
    state, members = {}, {}

    def resolve(key):
        o = groups[key]
        if state.get(key) == 2:
            return members[key]
        if state.get(key) == 1:
            I("RX507", o["pos"][0], o["pos"][1], "%s group %d reaches itself" % key)
            return None
        state[key] = 1
        before = ck.errors()
        root = key[0]
        ekw, list_kind, name = GROUP_FAMILIES[root]
        els = group_elements(elements, root)
        kind = o["path"][len(root) + 1:]
        add, rem = set(), set()

        def missing(p, what, warning=True):
            # an element id that does not exist stops radx as Radioss; anything else is left out with a warning
            I("RX402", p[0], p[1], "%s %d: %s does not exist" % (o["path"], o["id"], what), warning=warning)

        if kind == list_kind:
            for x, p in o["ids"]:
                if x <= 0 or x not in els:
                    missing(p, "%s %d" % (name, x), warning=False)
                else:
                    add.add(x)
        elif kind == "GENE":
            ids = [x for x, _ in o["ids"]]
            if len(ids) % 2:
                p = o["ids"][-1][1]
                I("RX507", p[0], p[1], "%s %d: the last pair 'first last' is incomplete" % (o["path"], o["id"]))
            for k in range(0, len(ids) - 1, 2):
                add.update(e for e in els if ids[k] <= e <= ids[k + 1])
        elif kind in ("PART", "SUBSET", "MAT", "PROP"):
            plus, minus = set(), set()
            for x, p in o["ids"]:
                a = abs(x)
                if kind == "PART":
                    sel = {a} if a in parts else None
                elif kind == "SUBSET":
                    sel = parts_of_subset(parts, subsets, a) if a in subsets else None
                else:
                    table, field = (mats, "mat_ID") if kind == "MAT" else (props, "prop_ID")
                    sel = {pid for pid, po in parts.items() if val(po, field) == a} if a in table else None
                if sel is None:
                    missing(p, "%s %d" % (kind.lower(), a))
                    continue
                (minus if x < 0 else plus).update(sel)
            add = {e for e, (pid, _) in els.items() if pid in plus - minus}
        elif kind == root[1:]:
            for x, p in o["ids"]:
                k2 = (root, abs(x))
                if k2 not in groups:
                    missing(p, "group %d" % abs(x))
                    continue
                got = resolve(k2)
                if got is not None:
                    (rem if x < 0 else add).update(got)
        elif kind in ("BOX", "BOX2"):
            first = next(((x, p) for x, p in o["ids"] if x > 0), None)
            for x, p in o["ids"]:  # only the first positive id is read
                if first is None or (x, p) != first:
                    I("RX310", p[0], p[1], "%s %d: box id %d ignored" % (o["path"], o["id"], x), warning=True)
            if first is None and root in ("/GRTRUS", "/GRBEAM"):
                I("RX404", o["pos"][0], o["pos"][1], "%s %d names no box" % (o["path"], o["id"]))
            if first is not None and first[0] not in boxes:
                # Radioss stops on a missing box in truss and beam groups (its error 798), not in the others
                missing(first[1], "box %d" % first[0], warning=root not in ("/GRTRUS", "/GRBEAM"))
            elif first is not None:
                inside = boxes[first[0]]
                for e, (pid, ns) in els.items():
                    ins = [inside(placed[n]) for n in ns]
                    if all(ins) if kind == "BOX" else any(ins):
                        add.add(e)
        res = add - rem
        if not res and ck.errors() == before:
            I("RX403", o["pos"][0], o["pos"][1], "%s group %d holds no element" % key, warning=True)
        state[key], members[key] = 2, res
        return res

    for key in groups:
        resolve(key)
    return groups, members


def surface_nodes(ck, nodes, parts, elements, surfs, groups, members):
    """The nodes of each surface's segments, by surface id (for /GRNOD/SURF), with the surfaces' own checks."""
    I = ck.issue

    def faces_of(ns):
        """Faces of a brick or a tetrahedron (node ids) with 3 or 4 distinct nodes, as sets."""
        out = []
        for f in (HEX_FACES if len(ns) == 8 else TET_FACES):
            d = distinct([ns[k - 1] for k in f])
            if len(d) >= 3:
                out.append(frozenset(d))
        return out

    def shell_nodes(listed):
        return {n for kw in ("/SHELL", "/SH3N") for pid, ns in elements[kw].values() if pid in listed for n in ns}

    # the nodes of each surface's segments (for /GRNOD/SURF); /SURF/PART and /SURF/PART/EXT are checked in
    # semantic()
    surf_nodes = {}
    for o in surfs.values():
        path = o["path"]
        if path in ("/SURF/PART", "/SURF/PART/EXT"):
            listed = {abs(x) for x, _ in o["ids"]}
            got = shell_nodes(listed)
            if path.endswith("/EXT"):
                # solid faces no other solid of the listed parts shares
                seen = {}
                for pid, ns in list(elements["/BRICK"].values()) + list(elements["/TETRA4"].values()):
                    if pid in listed:
                        for f in set(faces_of(ns)):
                            seen[f] = seen.get(f, 0) + 1
                got |= {n for f, k in seen.items() if k == 1 for n in f}
            surf_nodes[o["id"]] = got
            continue
        before = ck.errors()
        if path == "/SURF/SEG":
            # n4 = 0 makes a triangle (n4 := n3); each of n1 n2 n3 (and a non-zero n4) must exist
            got, count = set(), 0
            for r, p in o["recs"]:
                ns = [r.get(k) or 0 for k in ("n1", "n2", "n3")] + [r.get("n4") or r.get("n3") or 0]
                bad = [x for x in ns if x not in nodes]
                for x in distinct(bad):
                    I("RX402", p[0], p[1], "/SURF/SEG %d: segment node %d does not exist" % (o["id"], x))
                if not bad:
                    got.update(ns)
                    count += 1
            surf_nodes[o["id"]] = got
            if count == 0 and ck.errors() == before:
                I("RX403", o["pos"][0], o["pos"][1], "/SURF/SEG %d holds no segment" % o["id"], warning=True)
            continue
        if path not in SURFS_OF_GROUPS + ("/SURF/PART/ALL",):
            continue
        if path == "/SURF/GRBRIC":
            I("RX407", o["pos"][0], o["pos"][1], "/SURF/GRBRIC %d needs /EXT or /FREE" % o["id"])
            continue
        count = 0
        got = set()
        if path == "/SURF/PART/ALL":
            listed = set()
            for x, p in o["ids"]:
                if abs(x) not in parts:
                    I("RX402", p[0], p[1], "/SURF/PART/ALL %d: part %d does not exist" % (o["id"], abs(x)),
                      warning=True)
                else:
                    listed.add(abs(x))
            count = sum(1 for kw in ("/SHELL", "/SH3N") for pid, _ in elements[kw].values() if pid in listed)
            got = shell_nodes(listed)
            # a brick face that a shell of the listed parts covers (4-node shell on a quad face, 3-node shell on
            # a triangle face) is that shell's segment, not a second one
            covers = [set(ns) for kw, n in (("/SHELL", 4), ("/SH3N", 3)) for pid, ns in elements[kw].values()
                      if pid in listed and len(set(ns)) == n]
            for pid, ns in elements["/BRICK"].values():
                if pid in listed:
                    faces = [f for f in faces_of(ns) if set(f) not in covers]
                    count += len(faces)
                    got.update(n for f in faces for n in f)
        else:
            root = "/GR" + path.split("/")[2][2:]
            solids = group_elements(elements, "/GRBRIC")
            chosen = set()
            for x, p in o["ids"]:
                if (root, abs(x)) not in groups:
                    # left out with a warning, as Radioss's warning 192 does
                    I("RX402", p[0], p[1], "%s %d: group %d does not exist" % (path, o["id"], abs(x)), warning=True)
                    continue
                chosen |= members[(root, abs(x))]
                if root == "/GRBRIC" and members[(root, abs(x))] & set(elements["/BRIC20"]):
                    # no faces of 20-node bricks (build_groups.cpp surface_from_brick_groups): refused
                    I("RX510", p[0], p[1], "%s %d: group %d holds 20-node bricks" % (path, o["id"], abs(x)))
            if root == "/GRBRIC":
                solids = {e: v for e, v in solids.items() if e not in elements["/BRIC20"]}
                chosen = {e for e in chosen if e in solids}
            if root != "/GRBRIC":
                count = len(chosen)
                got = {n for e in chosen for n in elements[GROUP_FAMILIES[root][0]][e][1]}
            else:
                around = chosen if path.endswith("/EXT") else set(solids)
                seen = {}
                for e in around:
                    for f in set(faces_of(solids[e][1])):
                        seen[f] = seen.get(f, 0) + 1
                faces = [f for e in chosen for f in faces_of(solids[e][1]) if seen[f] == 1]
                count = len(faces)
                got = {n for f in faces for n in f}
        surf_nodes[o["id"]] = got
        if count == 0 and ck.errors() == before:
            I("RX403", o["pos"][0], o["pos"][1], "%s %d holds no segment" % (path, o["id"]), warning=True)
    return surf_nodes


def element_group_checks(ck, m, nodes, placed, place, parts, props, mats, subsets, elements, surfs):
    """Boxes, element groups and surfaces. nodes: as written (ids); placed: where the boxes see them; place(o, p):
    a point written in o where the boxes see it. Returns (groups, members, surface nodes, boxes)."""
    boxes = check_boxes(ck, m, nodes, placed, place)
    groups, members = resolve_element_groups(ck, m, placed, parts, props, mats, subsets, elements, boxes)
    surf_nodes = surface_nodes(ck, nodes, parts, elements, surfs, groups, members)
    return groups, members, surf_nodes, boxes


# Node groups (/GRNOD/..., docs/theory/deck-format.md section 2 and keywords.md), resolved to node ids:
#   * NODE: the listed nodes; PART: the nodes of the parts' elements, a negative id removes;
#   * GRNOD: union of node groups, a negative id removes (RX507 for a group that reaches itself, at the keyword
#     line of the group found again);
#   * BOX: the nodes (any node, used or not) inside each listed box, where the boxes see them (after the submodel
#     transforms, before the node-group ones);
#   * GENE: every existing node id in each pair `first last` (an odd count is RX507 at the last id's line);
#     GEN_INCR: first, first + incr, ... up to last (incr 0 or less: 1), however wide the range;
#   * SUBSET (with child subsets), MAT, PROP: the nodes of the parts' elements; SURF: the surfaces' segment nodes;
#   * GRSHEL, GRSH3N, GRBRIC: the nodes of the groups' elements, negative ids ignored.
# An id that names nothing is RX402 at its line (an error for a node id, else a warning: it is left out, as in
# Radioss); a group left empty is RX403 (a warning) at the keyword line, whatever else went wrong.
def node_group_checks(ck, m, nodes, placed, boxes, parts, props, mats, subsets, elements, egroups, emembers,
                      surfs, surf_nodes, grnods):
    I = ck.issue

    def part_nodes(pids):
        return {n for kw in elements for pid, ns in elements[kw].values() if pid in pids for n in ns}

    state, members = {}, {}

    def resolve(gid):
        o = grnods[gid]
        if state.get(gid) == 2:
            return members[gid]
        if state.get(gid) == 1:
            I("RX507", o["pos"][0], o["pos"][1], "node group %d reaches itself" % gid)
            return None
        state[gid] = 1
        kind = o["path"][len("/GRNOD/"):]
        add, rem = set(), set()

        def missing(p, what):
            # a node id that does not exist stops radx as Radioss; anything else is left out with a warning
            I("RX402", p[0], p[1], "%s %d: %s does not exist" % (o["path"], gid, what),
              warning=not what.startswith("node "))

        for x, p in o["ids"]:
            a = abs(x)
            if kind == "NODE":
                if x in nodes:
                    add.add(x)
                else:
                    missing(p, "node %d" % x)
            elif kind == "PART":
                if a in parts:
                    (rem if x < 0 else add).update(part_nodes({a}))
                else:
                    missing(p, "part %d" % a)
            elif kind == "GRNOD":
                if a not in grnods:
                    missing(p, "node group %d" % a)
                    continue
                got = resolve(a)
                if got is not None:
                    (rem if x < 0 else add).update(got)
            elif kind == "BOX":
                if x in boxes:
                    add.update(n for n, c in placed.items() if boxes[x](c))
                else:
                    missing(p, "box %d" % x)
            elif kind in ("MAT", "PROP"):
                table, field = (mats, "mat_ID") if kind == "MAT" else (props, "prop_ID")
                if x in table:
                    add.update(part_nodes({pid for pid, po in parts.items() if val(po, field) == x}))
                else:
                    missing(p, "%s %d" % ("material" if kind == "MAT" else "property", x))
            elif kind == "SUBSET":
                if x in subsets:
                    add.update(part_nodes(parts_of_subset(parts, subsets, x)))
                else:
                    missing(p, "subset %d" % x)
            elif kind == "SURF":
                if x in surfs:
                    add.update(surf_nodes.get(x, ()))
                else:
                    missing(p, "surface %d" % x)
            elif kind in ("GRSHEL", "GRSH3N", "GRBRIC", "GRTRUS", "GRBEAM"):
                root = "/" + kind
                if x < 0:
                    continue  # ignored (a warning)
                if (root, x) not in egroups:
                    missing(p, "%s group %d" % (root, x))
                    continue
                els = group_elements(elements, root)
                for e in emembers[(root, x)]:
                    add.update(els[e][1])
        ranges = []
        if kind == "GENE":
            ids = [x for x, _ in o["ids"]]
            if len(ids) % 2:
                p = o["ids"][-1][1]
                I("RX507", p[0], p[1], "/GRNOD/GENE %d: the last pair 'first last' is incomplete" % gid)
            ranges = [(ids[k], ids[k + 1], 1) for k in range(0, len(ids) - 1, 2)]
        elif kind == "GEN_INCR":
            ranges = [(r.get("first") or 0, r.get("last") or 0, max(r.get("incr") or 1, 1)) for r, _ in o["recs"]]
        for lo, hi, step in ranges:
            add.update(n for n in nodes if lo <= n <= hi and (n - lo) % step == 0)
        res = add - rem
        if not res:
            I("RX403", o["pos"][0], o["pos"][1], "%s %d holds no node" % (o["path"], gid), warning=True)
        state[gid], members[gid] = 2, res
        return res

    for gid in grnods:
        resolve(gid)
    return members


# Sets (build_sets.cpp, docs/sets.md): /SET/GENERAL and /SET/COLLECT (every /SET/COLLECT of one id is one set).
# A set holds nodes, parts and elements; its clauses join it kind by kind: a plain clause adds, _D removes, _I
# keeps what both hold. PART: the parts, their elements and the elements' nodes; NODE; SHELL, SH3N, SOLID (bricks
# and tetrahedra): the elements and their nodes; BOX, BOX2: the nodes in the boxes and the elements with every
# (BOX) or one (BOX2) node in them; ALL: everything; SET, SETCOL: the union of the sets listed; _G: triples
# first, last, step. An id that names nothing is RX402, a warning; a word that is no clause or ids before any
# word RX507; a Radioss clause or option radx does not build, or a set in a //SUBMODEL, RX510; a loop RX507.
SET_CLAUSES = ("PART", "NODE", "SHELL", "SH3N", "SOLID", "SET", "SETCOL", "BOX", "BOX2", "ALL")
SET_REFUSED = ("SEG", "SUBS", "SUBM", "RBODY", "ELLIPS", "PLANE", "NODENS", "BEAM", "TRUSS", "SPRING", "QUAD", "TRIA")
SET_KINDS = ("nodes", "parts", "/SHELL", "/SH3N", "solids")


def set_clauses(I, o):
    """The clauses of one set object: (key, options, cells with 0 for blanks, (file, line) of each cell)."""
    out = []
    for r, p in o["recs"]:
        word = (r.get("clause") or "").strip().upper()
        cells = [r.get("item%d" % k) or 0 for k in range(1, 10)]
        if word:
            key, _, opts = word.partition("_")
            out.append([key, opts, [], [], p])
        elif not out:
            I("RX507", p[0], p[1], "%s %d: ids before any clause word" % (o["path"], o["id"]))
            continue
        out[-1][2] += cells
        out[-1][3] += [p] * len(cells)
    return out


def sets(tables):
    I, m, elements, nodes, parts = tables.issue, tables.m, tables.elements, tables.nodes, tables.parts
    placed, boxes = tables.placed, tables.boxes
    general, collect = {}, {}
    for o in m.of("/SET/GENERAL", "/SET/COLLECT"):
        if o["in_sub"]:
            I("RX510", o["pos"][0], o["pos"][1], "%s %d inside a //SUBMODEL" % (o["path"], o["id"]))
            continue
        own, other = (collect, general) if o["path"] == "/SET/COLLECT" else (general, collect)
        if o["id"] in other:
            I("RX401", o["pos"][0], o["pos"][1], "set %d is both a /SET/GENERAL and a /SET/COLLECT" % o["id"])
        elif o["path"] == "/SET/COLLECT":
            own.setdefault(o["id"], []).append(o)
        elif o["id"] in own:
            I("RX401", o["pos"][0], o["pos"][1], "set %d defined twice" % o["id"])
        else:
            own[o["id"]] = [o]
    solids = {**elements["/BRICK"], **elements["/TETRA4"]}
    by_kind = {"/SHELL": elements["/SHELL"], "/SH3N": elements["/SH3N"], "solids": solids}
    state, members = {}, {}

    def element_nodes(res):
        for kind in ("/SHELL", "/SH3N", "solids"):
            for e in res[kind]:
                res["nodes"].update(by_kind[kind][e][1])

    def clause(o, key, opts, cells, cpos):
        res = {k: set() for k in SET_KINDS}

        def named(universe, what):
            if "G" in opts:
                got = set()
                for k in range(0, len(cells), 3):
                    lo, hi, step = cells[k], cells[k + 1], max(cells[k + 2], 1)
                    if lo or hi:
                        got.update(x for x in universe if lo <= x <= hi and (x - lo) % step == 0)
                return got
            got = set()
            for x, p in zip(cells, cpos):
                if x == 0:
                    continue
                if x in universe:
                    got.add(x)
                else:
                    I("RX402", p[0], p[1], "%s %d: %s %d does not exist" % (o["path"], o["id"], what, x), warning=True)
            return got

        if key == "PART":
            res["parts"] = named(parts, "part")
            for kind in ("/SHELL", "/SH3N", "solids"):
                res[kind] = {e for e, (pid, _) in by_kind[kind].items() if pid in res["parts"]}
            element_nodes(res)
        elif key == "NODE":
            res["nodes"] = named(nodes, "node")
        elif key in ("SHELL", "SH3N", "SOLID"):
            kind = {"SHELL": "/SHELL", "SH3N": "/SH3N", "SOLID": "solids"}[key]
            res[kind] = named(by_kind[kind], {"SHELL": "4-node shell", "SH3N": "3-node shell", "SOLID": "solid"}[key])
            element_nodes(res)
        elif key in ("BOX", "BOX2"):
            inside = set()
            for b in named(boxes, "box"):
                inside.update(n for n, c in placed.items() if boxes[b](c))
            res["nodes"] = inside
            for kind in ("/SHELL", "/SH3N", "solids"):
                res[kind] = {e for e, (_, ns) in by_kind[kind].items()
                             if (all if key == "BOX" else any)(n in inside for n in ns)}
        elif key == "ALL":
            res["nodes"], res["parts"] = set(nodes), set(parts)
            for kind in ("/SHELL", "/SH3N", "solids"):
                res[kind] = set(by_kind[kind])
        else:
            table = collect if key == "SETCOL" else general
            for x in named(table, "/SET/COLLECT set" if key == "SETCOL" else "/SET/GENERAL set"):
                got = resolve(table, x)
                if got is not None:
                    for k in SET_KINDS:
                        res[k] |= got[k]
        return res

    def resolve(table, sid):
        if state.get(sid) == 2:
            return members[sid]
        objs = table[sid]
        if state.get(sid) == 1:
            I("RX507", objs[0]["pos"][0], objs[0]["pos"][1], "set %d includes itself" % sid)
            return None
        state[sid] = 1
        before = tables.ck.errors()
        res = {k: set() for k in SET_KINDS}
        for o in objs:
            for key, opts, cells, cpos, p in set_clauses(I, o):
                if key in SET_REFUSED or any(c in "BCE" for c in opts):
                    I("RX510", p[0], p[1], "%s %d: clause %s is not built" % (o["path"], sid, key + "_" + opts))
                    continue
                if key not in SET_CLAUSES or any(c not in "DGIOA" for c in opts):
                    I("RX507", p[0], p[1], "%s %d: %r is not a clause" % (o["path"], sid, key))
                    continue
                got = clause(o, key, opts, cells, cpos)
                for k in SET_KINDS:
                    res[k] = res[k] - got[k] if "D" in opts else res[k] & got[k] if "I" in opts else res[k] | got[k]
        res["errors"] = tables.ck.errors() > before
        state[sid], members[sid] = 2, res
        return res

    for table in (general, collect):
        for sid in table:
            resolve(table, sid)
    tables.set_members, tables.set_objects, tables.set_uses = members, {**collect, **general}, set()


def empty_sets_in_use(tables):
    """A set named as a node group that holds no node, or as a surface that holds no element: RX403, a warning
    (once per set and use), as Radioss warns of the empty group it builds."""
    warned = set()
    for sid, what, _, _ in sorted(tables.set_uses):
        got = tables.set_members[sid]
        empty = not got["nodes"] if what == "node group" else not (got["/SHELL"] or got["/SH3N"] or got["solids"])
        if empty and not got["errors"] and (sid, what) not in warned:
            warned.add((sid, what))
            o = tables.set_objects[sid][0]
            tables.issue("RX403", o["pos"][0], o["pos"][1], "set %d is used as an empty %s" % (sid, what),
                         warning=True)


def transform_function(o, at, f):
    """The move of a /TRANSFORM as a function point -> point (None when its axis or normal has no length). at:
    node id -> where the transform sees that node (node_ID1, node_ID2, node_IDc); f: work lengths per length
    unit the transform is written in. TRA: x + t; ROT: right-handed turn by Angle degrees about the axis
    point 1 -> point 2; SCA: c + s (x - c) per axis about node_IDc (else the origin), a factor 0 means 1; SYM:
    mirror in the plane through point 1 normal to point 1 -> point 2. Two nodes replace the two points."""
    kind = o["path"].split("/")[2]
    n1, n2 = val(o, "node_ID1", 0), val(o, "node_ID2", 0)
    pair = n1 in at and n2 in at
    p1 = [val(o, x + "1", 0.0) * f for x in "XYZ"]
    if kind == "TRA":
        t = sub(at[n2], at[n1]) if pair else p1
        return lambda x: (x[0] + t[0], x[1] + t[1], x[2] + t[2])
    if kind == "SCA":
        c = at.get(val(o, "node_IDc", 0), (0.0, 0.0, 0.0))
        s = [val(o, "s" + x, 0.0) or 1.0 for x in "XYZ"]
        return lambda x: tuple(c[i] + s[i] * (x[i] - c[i]) for i in range(3))
    a, b = (at[n1], at[n2]) if pair else (p1, [val(o, x + "2", 0.0) * f for x in "XYZ"])
    d = sub(b, a)
    length = norm(d)
    if length == 0:
        return None
    u = [c / length for c in d]
    if kind == "SYM":
        def mirror(x):
            h = dot(sub(x, a), u)
            return tuple(x[i] - 2 * h * u[i] for i in range(3))
        return mirror
    ang = math.radians(val(o, "Angle", 0.0))
    cs, sn = math.cos(ang), math.sin(ang)

    def turn(x):  # Rodrigues
        v = sub(x, a)
        w = cross(u, v)
        k = dot(u, v) * (1 - cs)
        return tuple(a[i] + v[i] * cs + w[i] * sn + u[i] * k for i in range(3))
    return turn


def unit_si(name, table):
    """SI value of a unit name or of a factor written as a number; None when neither."""
    if name is None:
        return None
    if name in table:
        return table[name]
    if REAL_RE.match(name):
        x = float(re.sub(r"(\d)([+-]\d+)$", r"\1E\2", name.replace("D", "E").replace("d", "e")))
        return x if x > 0 and not math.isinf(x) else None
    return None


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a):
    return math.sqrt(dot(a, a))


LENGTH_SI = {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "um": 1e-6, "mum": 1e-6, "km": 1e3, "in": 0.0254, "ft": 0.3048}
TIME_SI = {"s": 1.0, "ms": 1e-3, "us": 1e-6, "mus": 1e-6, "ns": 1e-9, "min": 60.0, "h": 3600.0}


def work_velocity_si(m):
    """(fastest, slowest) m/s worth of one work velocity unit: equal when /BEGIN names units, 1e4 and 1e-3
    (cm/us and mm/s) when it names none; None when units are converted (input != work, old /UNIT/ cards)."""
    if m.of("/UNIT/MASS", "/UNIT/LENGTH", "/UNIT/TIME"):
        return None
    given = m.units.get("input", (None,) * 3) + m.units.get("work", (None,) * 3)
    if all(x is None for x in given):
        return 1e4, 1e-3
    if m.units.get("input") != m.units.get("work"):
        return None

    def si(name, table):
        if name is None:
            return 1.0
        if name in table:
            return table[name]
        return float(name.replace("D", "E").replace("d", "e")) if REAL_RE.match(name) else None

    length, time = si(m.units["work"][1], LENGTH_SI), si(m.units["work"][2], TIME_SI)
    if length is None or time is None:
        return None
    return length / time, length / time


def hex_tangled(p):
    """A corner whose three edges (in the order of n1: n2, n4, n5) turn the wrong way: det / lengths < -1e-6."""
    neighbours = ((1, 3, 4), (2, 0, 5), (3, 1, 6), (0, 2, 7), (7, 5, 0), (4, 6, 1), (5, 7, 2), (6, 4, 3))
    for k, nb in enumerate(neighbours):
        e = [sub(p[j], p[k]) for j in nb]
        lengths = norm(e[0]) * norm(e[1]) * norm(e[2])
        if lengths > 0 and dot(e[0], cross(e[1], e[2])) / lengths < -1e-6:
            return True
    return False


def hex_volume(p):
    """Volume of an 8-node hexahedron by 2x2x2 Gauss integration of the trilinear Jacobian."""
    sgn = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
    g = 1 / math.sqrt(3)
    vol = 0.0
    for xi in (-g, g):
        for eta in (-g, g):
            for ze in (-g, g):
                J = [[0.0] * 3 for _ in range(3)]
                for (a, b, c), x in zip(sgn, p):
                    dn = (a * (1 + b * eta) * (1 + c * ze) / 8, b * (1 + a * xi) * (1 + c * ze) / 8,
                          c * (1 + a * xi) * (1 + b * eta) / 8)
                    for r in range(3):
                        for s in range(3):
                            J[r][s] += dn[r] * x[s]
                vol += dot(cross(J[0], J[1]), J[2])
    return vol


# ---------------------------------------------------------------------------------------------------
# Driver


def check_file(path, root, verbose=False):
    ck = Checker(verbose)
    display = os.path.relpath(path, root)
    recs = []
    ck.load(path, display, [os.path.abspath(path)], recs)
    # raw line checks on the files actually read
    seen = set()
    keyword = ""
    for f, k, t in recs:
        if t.startswith("/"):
            keyword = t.upper().replace(" ", "")
        if len(t) > 100:
            ck.warn(f, k, "line longer than 100 columns")
        # a tab before a value moves the columns; tabs among the trailing blanks move nothing
        if "\t" in t and not is_comment(t) and "," not in t and t[:t.index("\t")].strip() != t.strip():
            ck.issue("RX104", f, k, "tab in a fixed-column line")
        if "," in t and not is_comment(t) and not keyword.startswith("/CTCLAW/"):
            ck.warn(f, k, "comma in a non-comment line (would switch the line to free format)")
        seen.add(f)
    with open(path, encoding="utf-8", errors="replace") as fh:
        nlines = sum(1 for _ in fh)
    own = [r for r in recs]
    split = next((n for n, r in enumerate(own) if r[2].upper().startswith("/END/ENGINE")), None)
    has_begin = any(is_begin_line(r[2]) for r in own)
    if split is not None:
        ck.engine(own[:split + 1])
        model = ck.starter(own[split + 1:], display, nlines)
    elif not has_begin and any(r[2].upper().startswith("/RUN") for r in own):
        ck.engine(own)
        model = None
    else:
        frag = os.path.basename(os.path.dirname(path)) == "inc"
        model = ck.starter(own, display, nlines, fragment=frag)
    if model is not None:
        semantic(ck, model)
    return ck


def expectations(path, root):
    exp = set()
    display = os.path.relpath(path, root)
    with open(path, encoding="utf-8", errors="replace") as fh:
        for ln in fh:
            m = EXPECT_RE.match(ln.rstrip("\n"))
            if m:
                f = display if not m.group(3) else os.path.normpath(os.path.join(os.path.dirname(display),
                                                                                  m.group(3)))
                exp.add((m.group(1), f, int(m.group(2))))
    return exp


def main(argv):
    verbose = "-v" in argv
    files = [a for a in argv if a != "-v"]
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.normpath(os.path.join(here, ".."))
    if not files:
        for d, _, fs in sorted(os.walk(os.path.join(root, "decks"))):
            for f in sorted(fs):
                if f.endswith(".rad"):
                    files.append(os.path.join(d, f))
    bad = 0
    for path in files:
        path = os.path.abspath(path)
        if os.path.basename(os.path.dirname(path)) == "inc":
            ck = check_file(path, root, verbose)
            probs = [str(x) for x in ck.style]
            # fragments are checked for columns only; their errors belong to the deck that includes them
            if probs:
                bad += 1
                print("FAIL %s" % os.path.relpath(path, root))
                for p in probs:
                    print("   ", p)
            else:
                print("ok   %s (fragment, columns only)" % os.path.relpath(path, root))
            continue
        ck = check_file(path, root, verbose)
        exp = expectations(path, root)
        got = {x.key() for x in ck.issues}
        style = [x for x in ck.style if (x.file, x.line) not in {(e[1], e[2]) for e in exp}]
        ok = got == exp and not style
        rel = os.path.relpath(path, root)
        if ok:
            print("ok   %s%s" % (rel, ("  expects " + " ".join("%s@%d" % (e[0], e[2]) for e in sorted(exp,
                  key=lambda e: (e[2], e[0])))) if exp else ""))
        else:
            bad += 1
            print("FAIL %s" % rel)
            for x in sorted(ck.issues, key=lambda x: (x.file, x.line)):
                tag = "  " if x.key() in exp else "+ "
                print("   %s%s" % (tag, x))
            for e in sorted(exp - got):
                print("   - expected but not found: %s %s line %d" % e)
            for x in style:
                print("   ! %s" % x)
    print("%d file(s) checked, %d failed" % (len(files), bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
