#!/usr/bin/env python3
"""Structured mutations of valid sample decks, each run through radx, every outcome checked.

Each case takes one sample deck (BASE_DECKS: small decks that between them hold every element, material and
contact family radx runs) and changes it in one place, the way a user's typing or a converter gets a deck
wrong: a field set to 0, -1, 1e300, NaN or Inf text, an integer past 32 bits; a node or element id
duplicated, huge or colliding with another; an element made degenerate (two corners on one node, or one node
moved onto another), a node duplicated onto another's place; a group or surface emptied; a keyword id made
to collide or overflow; a card line dropped, a keyword block repeated; the engine deck's Tstop, steps and
output intervals set to 0, negative or huge. A case is deterministic: case N of seed S is the same deck on
every machine (random.Random("S:N")), whatever the number of jobs.

Each case runs as `radx run DECK --out DIR --no-plot --threads 1` with a time limit, and must end as one of

  error     exit code 1 with a located message: FILE:LINE: error: ..., or the keyword and the id it concerns
  warned    exit code 0 with a warning (in the summary JSON) and finite energies
  normal    exit code 0, finite energies and an energy balance within 5 % (the summary JSON's error_percent)

and never as

  crash     killed by a signal (a sanitizer report aborts too), or an exit code other than 0, 1
  hang      still running at the time limit
  unlocated exit code 1 without a message naming a place in the deck
  nonfinite a NaN or Inf in the final energies
  unbalanced a normal end without a warning whose energy balance is off by more than 5 %

Usage:
  scripts/mutate_decks.py --radx build/apps/radx [--seed 1] [--first 0] [--cases 100] [--jobs 2]
                          [--timeout 60] [--keep DIR] [--verbose]
  scripts/mutate_decks.py --show N [--seed 1] --write DIR    # writes case N's deck files to DIR

Exit status 1 when any case ends in a forbidden outcome (each is printed with its mutation and the command
that reproduces it), 2 on a usage error.
"""
import argparse
import concurrent.futures
import json
import math
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

# Folders under decks/: each runs in well under a second and together they hold the element families
# (BT4, QEPH and C0 shells, 3-node shells, HEPH and Isolid 1 bricks, 20-node bricks, tetrahedra, springs of
# every property, trusses, beams), the materials (elastic, Johnson-Cook, tabulated with failure, brittle,
# foam, Ogden, rigid, void, BIQUAD and JOHNSON failure) and the contacts (TYPE7 penalty, TYPE7 with /CTCLAW,
# LAGDT, TYPE2 ties, rigid walls, rigid bodies); one_file is a one-file deck.
BASE_DECKS = ("bar_rwall", "beam_cantilever", "block_impact", "block_on_plate_ctclaw", "brittle_strip",
              "fail_biquad_neck", "fail_tab_strip", "field_forms", "foam_block", "mass_scaling", "one_file",
              "old_layout_2019", "rigid_material", "rubber_block", "spring_beam", "spring_general",
              "spring_oscillator", "tetra_block", "truss_bar", "twisted_strip", "bric20_cantilever")

ROW_KEYWORDS = ("/NODE", "/SHELL", "/SH3N", "/BRICK", "/TETRA4", "/SPRING", "/TRUSS", "/BEAM", "/BRIC20")
ELEMENT_KEYWORDS = ROW_KEYWORDS[1:]
LIST_KEYWORDS = ("/GRNOD", "/GRSHEL", "/GRSH3N", "/GRBRIC", "/GRSPRI", "/GRTRUS", "/GRBEAM", "/SURF", "/SET",
                 "/LINE")
NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?$")
INTEGER = re.compile(r"[-+]?\d+$")

INT_VALUES = ("0", "-1", "2147483647", "2147483648", "9999999999", "-999999999", "1e300", "NaN")
REAL_VALUES = ("0.0", "-1.0", "1e300", "-1e300", "1e-300", "NaN", "Inf", "-Inf", "1e30", "-0.0", "")


# ---------------------------------------------------------------------------------------------------
# Reading a deck: keyword blocks and fields


def block_root(keyword):
    """'/SHELL/1' -> '/SHELL', '/GRNOD/NODE/1' -> '/GRNOD'."""
    return "/" + keyword.split("/")[1]


def has_title(keyword):
    """Whether the block's first data line is a title: keywords ending in an id, rows of bulk data aside."""
    root = block_root(keyword)
    if root in ROW_KEYWORDS or root in ("/BEGIN", "/TITLE", "/END"):
        return root in ("/BEGIN", "/TITLE")
    return bool(re.search(r"/\d+$", keyword))


def blocks(lines):
    """(keyword, index of its line, indices of its data lines, title skipped) of each keyword block."""
    out, cur = [], None
    for i, line in enumerate(lines):
        if line.startswith("/"):
            if cur:
                out.append(cur)
            cur = [line.split()[0], i, []]
        elif cur is not None and line.strip() and not line.startswith("#"):
            cur[2].append(i)
    if cur:
        out.append(cur)
    for b in out:
        if has_title(b[0]) and b[2]:
            b[2] = b[2][1:]
    return [tuple(b) for b in out]


def fixed_fields(line):
    """(start, end, text) of each number right-aligned in a 10- or 20-column field of a block-format line."""
    out = []
    for m in re.finditer(r"\S+", line):
        tok, end = m.group(0), m.end()
        if not NUMBER.match(tok) or end % 10 != 0:
            continue
        width = 10 if m.start() >= end - 10 else 20
        if m.start() >= end - width:
            out.append((end - width, end, tok))
    return out


def free_fields(line):
    """(start, end, text) of each number of a free-format (engine) line."""
    return [(m.start(), m.end(), m.group(0)) for m in re.finditer(r"\S+", line) if NUMBER.match(m.group(0))]


def put(line, field, text):
    a, b, _ = field
    if b - a >= 10 and (a % 10 == 0):  # a fixed field: right-justify in it
        return line[:a] + text.rjust(b - a)[-(b - a):] + line[b:]
    return line[:a] + text + line[b:]


class Deck:
    """The files of one sample deck: starter lines, engine lines (None for a one-file deck)."""

    def __init__(self, folder):
        self.folder = folder
        names = sorted(os.listdir(folder))
        self.starter_name = next(n for n in names if n.endswith("_0000.rad"))
        engine = self.starter_name.replace("_0000.rad", "_0001.rad")
        self.engine_name = engine if engine in names else None
        self.starter = self._read(self.starter_name)
        self.engine = self._read(self.engine_name) if self.engine_name else None

    def _read(self, name):
        with open(os.path.join(self.folder, name), encoding="latin-1") as f:
            return f.read().split("\n")

    def write(self, out):
        os.makedirs(out, exist_ok=True)
        for name in os.listdir(self.folder):  # includes and references beside the deck come along
            src = os.path.join(self.folder, name)
            if os.path.isfile(src):
                shutil.copy(src, out)
        for name, lines in ((self.starter_name, self.starter), (self.engine_name, self.engine)):
            if name:
                with open(os.path.join(out, name), "w", encoding="latin-1", newline="\n") as f:
                    f.write("\n".join(lines))
        return os.path.join(out, self.starter_name)


# ---------------------------------------------------------------------------------------------------
# Mutations: each takes (rng, deck), changes the deck and returns what it did, or None when the deck has
# nothing it applies to.


def rows(deck, roots):
    """(line index, keyword) of every data row of the given row keywords in the starter deck."""
    return [(i, kw) for kw, _, data in blocks(deck.starter) if block_root(kw) in roots for i in data]


def where(deck, i, kw):
    return "%s line %d (%s)" % (deck.starter_name, i + 1, kw)


def mutate_card_field(rng, deck):
    cards = [(kw, i) for kw, _, data in blocks(deck.starter)
             if block_root(kw) not in ROW_KEYWORDS + ("/BEGIN", "/TITLE") for i in data]
    fields = [(kw, i, f) for kw, i in cards for f in fixed_fields(deck.starter[i])]
    if not fields:
        return None
    kw, i, f = rng.choice(fields)
    text = rng.choice(INT_VALUES if INTEGER.match(f[2]) else REAL_VALUES)
    if text == f[2]:
        return None
    deck.starter[i] = put(deck.starter[i], f, text)
    return "%s: field at columns %d-%d %s -> %r" % (where(deck, i, kw), f[0] + 1, f[1], f[2], text)


def mutate_engine_field(rng, deck):
    if deck.engine is None:
        return None
    fields = [(kw, i, f) for kw, _, data in blocks(deck.engine) for i in data
              for f in free_fields(deck.engine[i])]
    if not fields:
        return None
    # /RUN's Tstop half the time: it sets how long everything else runs.
    run = [x for x in fields if block_root(x[0]) == "/RUN"]
    kw, i, f = rng.choice(run) if run and rng.random() < 0.5 else rng.choice(fields)
    text = rng.choice(("0", "-1", "-1e-3", "1e-30", "1e300", "NaN", "Inf", "2147483648", "0.0"))
    deck.engine[i] = deck.engine[i][:f[0]] + text + deck.engine[i][f[1]:]
    return "%s line %d (%s): %s -> %r" % (deck.engine_name, i + 1, kw, f[2], text)


def mutate_node_coordinate(rng, deck):
    nodes = rows(deck, ("/NODE",))
    if not nodes:
        return None
    i, kw = rng.choice(nodes)
    f = rng.choice(fixed_fields(deck.starter[i])[1:4])
    text = rng.choice(("NaN", "Inf", "1e300", "-1e300", "1e-300", "1e30"))
    deck.starter[i] = put(deck.starter[i], f, text)
    return "%s: coordinate %s -> %r" % (where(deck, i, kw), f[2], text)


def mutate_node_onto_node(rng, deck):
    """A node moved onto another: duplicate nodes, and a degenerate element when they share one."""
    elements = rows(deck, ELEMENT_KEYWORDS)
    nodes = {fixed_fields(deck.starter[i])[0][2]: i for i, _ in rows(deck, ("/NODE",))}
    if not elements:
        return None
    i, kw = rng.choice(elements)
    ids = [f[2] for f in fixed_fields(deck.starter[i])[1:] if f[2] in nodes]
    if len(ids) < 2:
        return None
    a, b = rng.sample(ids, 2)
    la, lb = nodes[a], nodes[b]
    fa, fb = fixed_fields(deck.starter[la]), fixed_fields(deck.starter[lb])
    line = deck.starter[la]
    for k in (1, 2, 3):
        line = put(line, fa[k], fb[k][2])
    deck.starter[la] = line
    return "%s: node %s moved onto node %s (both corners of the element on line %d)" % (
        where(deck, la, "/NODE"), a, b, i + 1)


def mutate_node_id(rng, deck):
    nodes = rows(deck, ("/NODE",))
    if len(nodes) < 2:
        return None
    (i, kw), (j, _) = rng.sample(nodes, 2)
    f = fixed_fields(deck.starter[i])[0]
    text = rng.choice((fixed_fields(deck.starter[j])[0][2], "0", "-5", "2147483647", "2147483648", "9999999999"))
    deck.starter[i] = put(deck.starter[i], f, text)
    return "%s: node id %s -> %s" % (where(deck, i, kw), f[2], text)


def mutate_element_node(rng, deck):
    elements = rows(deck, ELEMENT_KEYWORDS)
    if not elements:
        return None
    i, kw = rng.choice(elements)
    fields = fixed_fields(deck.starter[i])
    if len(fields) < 3:
        return None
    k = rng.randrange(1, len(fields))
    other = fields[rng.choice([m for m in range(1, len(fields)) if m != k])][2]
    text = rng.choice((other, other, "0", "-1", "999999", "2147483648", "9999999999"))
    deck.starter[i] = put(deck.starter[i], fields[k], text)
    return "%s: node %d of the element %s -> %s" % (where(deck, i, kw), k, fields[k][2], text)


def mutate_element_id(rng, deck):
    elements = rows(deck, ELEMENT_KEYWORDS)
    if len(elements) < 2:
        return None
    (i, kw), (j, _) = rng.sample(elements, 2)
    f = fixed_fields(deck.starter[i])[0]
    text = rng.choice((fixed_fields(deck.starter[j])[0][2], "0", "-3", "2147483648", "9999999999"))
    deck.starter[i] = put(deck.starter[i], f, text)
    return "%s: element id %s -> %s" % (where(deck, i, kw), f[2], text)


def mutate_empty_list(rng, deck):
    lists = [(kw, k, data) for kw, k, data in blocks(deck.starter) if block_root(kw) in LIST_KEYWORDS and data]
    if not lists:
        return None
    kw, k, data = rng.choice(lists)
    for i in reversed(data):
        del deck.starter[i]
    return "%s line %d (%s): its %d data line(s) removed, the list is empty" % (
        deck.starter_name, k + 1, kw, len(data))


def mutate_keyword_id(rng, deck):
    owned = [(kw, k) for kw, k, _ in blocks(deck.starter) if re.search(r"/\d+$", kw)
             and block_root(kw) not in ELEMENT_KEYWORDS]
    if not owned:
        return None
    kw, k = rng.choice(owned)
    base = kw.rsplit("/", 1)[0]
    same_kind = [x for x, _ in owned if x.startswith(block_root(kw)) and x != kw]
    other = rng.choice(same_kind).rsplit("/", 1)[1] if same_kind else "0"
    ident = rng.choice((other, other, "0", "2147483648", "99999999999999999999"))
    deck.starter[k] = deck.starter[k].replace(kw, base + "/" + ident, 1)
    return "%s line %d: %s -> %s/%s" % (deck.starter_name, k + 1, kw, base, ident)


def mutate_drop_line(rng, deck):
    cards = [(kw, i) for kw, _, data in blocks(deck.starter)
             if block_root(kw) not in ("/BEGIN", "/END") for i in data]
    if not cards:
        return None
    kw, i = rng.choice(cards)
    text = deck.starter[i]
    del deck.starter[i]
    return "%s line %d (%s) removed: %r" % (deck.starter_name, i + 1, kw, text.strip()[:60])


def mutate_repeat_block(rng, deck):
    bl = [b for b in blocks(deck.starter) if block_root(b[0]) not in ("/BEGIN", "/END", "/TITLE")]
    if not bl:
        return None
    n = rng.randrange(len(bl))
    kw, k, data = bl[n]
    end = (data[-1] + 1) if data else k + 2
    copy = deck.starter[k:end]
    deck.starter[end:end] = copy
    return "%s line %d (%s): the block repeated after itself" % (deck.starter_name, k + 1, kw)


MUTATIONS = (
    ("card_field", mutate_card_field, 6),
    ("engine_field", mutate_engine_field, 3),
    ("node_coordinate", mutate_node_coordinate, 1),
    ("node_onto_node", mutate_node_onto_node, 1),
    ("node_id", mutate_node_id, 1),
    ("element_node", mutate_element_node, 2),
    ("element_id", mutate_element_id, 1),
    ("empty_list", mutate_empty_list, 1),
    ("keyword_id", mutate_keyword_id, 1),
    ("drop_line", mutate_drop_line, 1),
    ("repeat_block", mutate_repeat_block, 1),
)


def make_case(seed, n):
    """(base deck folder name, mutation name, what it did, the mutated Deck) of case n of the seed."""
    rng = random.Random("%s:%d" % (seed, n))
    names = [m[0] for m in MUTATIONS]
    weights = [m[2] for m in MUTATIONS]
    for _ in range(100):
        base = rng.choice(BASE_DECKS)
        name = rng.choices(names, weights)[0]
        deck = Deck(os.path.join(ROOT, "decks", base))
        what = dict((m[0], m[1]) for m in MUTATIONS)[name](rng, deck)
        if what:
            return base, name, what, deck
    raise RuntimeError("no mutation applies")


# ---------------------------------------------------------------------------------------------------
# Running a case and judging its outcome

# A located error: the reader's FILE:LINE: error: ..., or an engine error termination naming the keyword or the
# entity (node, element, part, interface ...) and its id.
LOCATED_ERROR = re.compile(r"\.rad:\d+(:\d+)?: error: |error( termination)?: .*((?<![\w/.~-])\[?/[A-Z][A-Z0-9_]+|\b(node|element|"
                           r"shell|brick|tetrahedron|part|interface|spring|truss|beam|group|rigid body|wall|"
                           r"function|surface)\s+-?\d)")
ERROR_LINE = re.compile(r"[Ee]rror( termination)?: ")


def finite(v):
    """A number and finite: the summary JSON writes a NaN or Inf energy as null."""
    return isinstance(v, (int, float)) and math.isfinite(v)


def judge(rc, output, out_dir):
    """(outcome, detail) of a finished run."""
    if rc < 0 or rc > 2 and rc not in (130, 143):
        sig = -rc if rc < 0 else rc - 128
        return "crash", "exit %d (%s)" % (rc, signal.Signals(sig).name if 0 < sig < 65 else "code")
    if rc == 2:
        return "crash", "usage error from radx run"
    lines = output.splitlines()
    if rc == 1:
        errors = [l for l in lines if ERROR_LINE.search(l)]
        located = [l for l in errors if LOCATED_ERROR.search(l)]
        if located:
            return "error", located[0][:200]
        return "unlocated", (errors[0] if errors else (lines[-1] if lines else "no output"))[:200]
    summaries = [f for f in os.listdir(out_dir) if f.endswith("_summary.json")] if os.path.isdir(out_dir) else []
    if not summaries:
        return "unlocated", "exit 0 without a summary JSON"
    with open(os.path.join(out_dir, summaries[0])) as f:
        summary = json.load(f, parse_constant=lambda c: float(c))
    energy = summary.get("energy", {})
    if not all(finite(v) for v in energy.values()):
        return "nonfinite", "%s, energies not finite: %s" % (summary.get("message", ""), ", ".join(
            "%s %s" % (k, v) for k, v in energy.items() if not finite(v)))
    warnings = summary.get("warnings", []) + summary.get("substitutions", [])
    error = abs(energy.get("error_percent", 0.0))
    if warnings:
        return "warned", str(warnings[0])[:200]
    if error > 5.0:
        return "unbalanced", "energy error %.3g %% (%s)" % (error, summary.get("message", ""))
    return "normal", "energy error %.3g %%" % error


def run_case(radx, seed, n, timeout, work, keep):
    base, name, what, deck = make_case(seed, n)
    case_dir = os.path.join(work, "case%06d" % n)
    deck_path = deck.write(os.path.join(case_dir, "deck"))
    out_dir = os.path.join(case_dir, "out")
    cmd = [radx, "run", deck_path, "--out", out_dir, "--no-plot", "--threads", "1"]
    env = dict(os.environ, OMP_WAIT_POLICY="passive")
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env, start_new_session=True)
    try:
        output = p.communicate(timeout=timeout)[0].decode("latin-1")
        try:
            outcome, detail = judge(p.returncode, output, out_dir)
        except (OSError, ValueError, KeyError, TypeError) as e:  # an unreadable summary is a finding too
            outcome, detail = "unlocated", "the run's outputs could not be judged: %r" % e
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        output = p.communicate()[0].decode("latin-1")
        outcome, detail = "hang", "still running after %g s" % timeout
    bad = outcome not in ("error", "warned", "normal")
    if bad and keep:
        dest = os.path.join(keep, "seed%s_case%06d" % (seed, n))
        shutil.rmtree(dest, ignore_errors=True)
        shutil.copytree(os.path.join(case_dir, "deck"), dest)
        with open(os.path.join(dest, "run.log"), "w") as f:
            f.write(output)
    shutil.rmtree(case_dir, ignore_errors=True)
    return n, base, name, what, outcome, detail, bad


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--radx", default=os.path.join(ROOT, "build", "apps", "radx"))
    ap.add_argument("--seed", default="1")
    ap.add_argument("--first", type=int, default=0)
    ap.add_argument("--cases", type=int, default=100)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("--keep", default="", help="copy each failing case's deck and log under this folder")
    ap.add_argument("--show", type=int, default=None, help="write case N's deck (with --write DIR) and stop")
    ap.add_argument("--write", default="")
    ap.add_argument("--verbose", action="store_true", help="print every case, not only the failing ones")
    a = ap.parse_args(argv)
    if a.show is not None:
        base, name, what, deck = make_case(a.seed, a.show)
        print("case %d of seed %s: %s, %s: %s" % (a.show, a.seed, base, name, what))
        if a.write:
            print(deck.write(a.write))
        return 0
    radx = os.path.abspath(a.radx)
    if not os.access(radx, os.X_OK):
        print("error: %s is not an executable (--radx)" % radx, file=sys.stderr)
        return 2
    work = tempfile.mkdtemp(prefix="radx-mutate-")
    counts, failures = {}, []
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
            futures = [pool.submit(run_case, radx, a.seed, n, a.timeout, work, a.keep)
                       for n in range(a.first, a.first + a.cases)]
            for fut in futures:
                n, base, name, what, outcome, detail, bad = fut.result()
                counts[outcome] = counts.get(outcome, 0) + 1
                if bad or a.verbose:
                    print("%-10s case %d (%s, %s): %s\n           %s" % (outcome, n, base, name, what, detail),
                          flush=True)
                if bad:
                    failures.append(n)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    order = ("error", "warned", "normal", "crash", "hang", "unlocated", "nonfinite", "unbalanced")
    print("seed %s, cases %d to %d: %s" % (a.seed, a.first, a.first + a.cases - 1,
                                           ", ".join("%s %d" % (k, counts.get(k, 0)) for k in order)))
    for n in failures:
        print("reproduce: python3 scripts/mutate_decks.py --seed %s --show %d --write /tmp/case%d && "
              "%s run /tmp/case%d/<NAME>_0000.rad --out /tmp/case%d/out" % (a.seed, n, n, a.radx, n, n))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
