#!/usr/bin/env python3
"""Check that the sample decks use every keyword radx reads.

The keyword list comes from `radx keywords --markdown`: every starter keyword (each `### /KEY` of the
"Starter keywords" section, with its "Also written" spellings) and every engine keyword whose radx column says
"read". The sample decks are the decks directly in a folder decks/<name>/ (NAME_0000.rad starter,
NAME_0001.rad engine, or a one-file deck: its starter from /BEGIN to /END, its engine part the rest), not those of
decks/invalid, decks/verification and decks/versions; #include lines are followed.

A keyword line counts for the longest declared keyword it starts with (followed by '/' or the end of the
line): /SURF/PART/EXT/2 counts for /SURF/PART/EXT, /ANIM/ELEM/VONM for /ANIM/ELEM, /PRINT/-100 for /PRINT.
The few keywords no sample deck can use sensibly are exempt, each with its reason (EXEMPT below).

    python3 tests/scripts/check_sample_keywords.py --radx build/apps/radx [--decks decks] [-v]

Exit status 0 when every keyword is used; 1 listing each keyword no sample deck uses.
Plain python3, standard library only.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

SKIPPED_FOLDERS = {"invalid", "verification", "versions"}

EXEMPT = {
    "/UNIT/MASS": "names the work mass unit only in version-90 decks (newer decks ignore it with a warning); "
                  "decks/versions covers the 90 layout",
    "/UNIT/LENGTH": "as /UNIT/MASS: version-90 decks only",
    "/UNIT/TIME": "as /UNIT/MASS: version-90 decks only",
    "/ALE/BCS": "read only to say it acts on nothing on radx's Lagrangian nodes (a warning): no sample deck has an "
                "ALE node; decks/invalid/ale_bcs_on_lagrangian_nodes.rad reads it",
    "/SURF/GRBRIC": "declared only to be refused (RX302) as Radioss refuses it; /SURF/GRBRIC/EXT and /FREE are "
                    "the readable forms",
}


def declared_keywords(radx):
    """(starter, engine): dicts of each spelling to its keyword, from radx keywords --markdown."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "keywords.md")
        subprocess.run([radx, "keywords", "--markdown", "--output", path], check=True,
                       stdout=subprocess.DEVNULL)
        with open(path) as f:
            lines = f.read().splitlines()
    starter, engine = {}, {}
    section = None
    current = None
    for text in lines:
        if text.startswith("## "):
            section = text[3:].strip()
            continue
        if section == "Starter keywords":
            if text.startswith("### /"):
                current = text[4:].strip()
                starter[current] = current
            elif text.startswith("Also written:") and current:
                for alias in re.findall(r"`(/[^`]+)`", text):
                    starter[alias] = current
        elif section == "Engine keywords" and text.startswith("| /"):
            cells = [c.strip() for c in text.strip().strip("|").split("|")]
            if len(cells) >= 4 and cells[3] == "read":
                spellings = re.findall(r"/[^\s()]+", cells[0])
                for s in spellings:
                    engine[s] = spellings[0]
    if not starter or not engine:
        raise SystemExit("could not read the keyword lists from radx keywords --markdown")
    return starter, engine


def deck_lines(path, seen=None):
    """The lines of a deck with its #include files spliced in (each file once)."""
    seen = set() if seen is None else seen
    real = os.path.realpath(path)
    if real in seen:
        return []
    seen.add(real)
    out = []
    with open(path, errors="replace") as f:
        for text in f.read().splitlines():
            if text.lower().startswith("#include"):
                name = text.split(None, 1)[1].strip() if len(text.split(None, 1)) > 1 else ""
                out += deck_lines(os.path.join(os.path.dirname(path), name), seen)
            else:
                out.append(text)
    return out


def keyword_lines(lines):
    return [t.strip() for t in lines if t.startswith("/")]


def sample_decks(root):
    """(starter keyword lines, engine keyword lines, files) of every sample deck under root."""
    starter, engine, files = [], [], []
    for name in sorted(os.listdir(root)):
        folder = os.path.join(root, name)
        if name in SKIPPED_FOLDERS or not os.path.isdir(folder):
            continue
        for fname in sorted(os.listdir(folder)):
            if not fname.endswith(".rad"):
                continue
            path = os.path.join(folder, fname)
            words = keyword_lines(deck_lines(path))
            files.append(path)
            if fname.endswith("_0001.rad"):
                engine += words
            elif any(w.startswith("/RUN") or w == "/END/ENGINE" for w in words):
                # one-file deck: the starter runs from /BEGIN to the /END after it, the engine part is the rest
                first = next((k for k, w in enumerate(words) if w.startswith("/BEGIN")), 0)
                last = next((k for k in range(first, len(words)) if words[k] == "/END"), len(words) - 1)
                starter += words[first:last + 1]
                engine += words[:first] + words[last + 1:]
            else:
                starter += words
    return starter, engine, files


def used(lines, spellings):
    """The keywords the lines use: each line counts for the longest spelling it starts with."""
    found = set()
    by_length = sorted(spellings, key=len, reverse=True)
    for text in lines:
        head = text.split()[0]
        for s in by_length:
            if head == s or head.startswith(s + "/"):
                found.add(spellings[s])
                break
    return found


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--radx", required=True, help="the radx executable")
    ap.add_argument("--decks", default=os.path.join(here, "..", "..", "decks"), help="the decks folder")
    ap.add_argument("-v", "--verbose", action="store_true", help="also list the decks read and the keywords used")
    args = ap.parse_args(argv)
    starter, engine = declared_keywords(args.radx)
    starter_lines, engine_lines, files = sample_decks(args.decks)
    if args.verbose:
        print("sample decks:\n  " + "\n  ".join(files))
    missing = []
    for kind, spellings, lines in (("starter", starter, starter_lines), ("engine", engine, engine_lines)):
        have = used(lines, spellings)
        for key in sorted(set(spellings.values())):
            if key in have:
                if args.verbose:
                    print("used     %s keyword %s" % (kind, key))
            elif kind == "starter" and key in EXEMPT:
                print("exempt   %s keyword %s: %s" % (kind, key, EXEMPT[key]))
            else:
                missing.append((kind, key))
    for kind, key in missing:
        print("MISSING  %s keyword %s: no sample deck uses it" % (kind, key))
    total = len(set(starter.values())) + len(set(engine.values()))
    print("%d keywords, %d sample deck files, %d missing" % (total, len(files), len(missing)))
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
