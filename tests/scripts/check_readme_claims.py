#!/usr/bin/env python3
"""The README's claims against the keyword declarations, where a claim can be checked mechanically:

* every keyword the README names in backticks (`/MAT/PLAS_JOHNS`, `/INTER/LAGDT/TYPE7`) is one radx declares in
  docs/keywords.md (generated from the declarations and kept current by the keywords.doc test): one it runs,
  unless the README's sentence says it is refused, ignored or not written; a family root (`/GRNOD`) must have
  keywords radx runs under it;
* a keyword named in a sentence that says something is refused, ignored or not written must still be one radx
  declares (such a sentence may name keywords that run beside the one refused, so it is not required to be in
  the refused column);
* the count of sample folders the README states ("thirty-five folders under `decks/`") is the number of deck
  folders directly under decks/.

Usage: check_readme_claims.py ROOT
"""
import os
import re
import sys

NUMBERS = {w: i for i, w in enumerate(
    "zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen sixteen "
    "seventeen eighteen nineteen twenty".split())}
for tens, word in ((20, "twenty"), (30, "thirty"), (40, "forty"), (50, "fifty"), (60, "sixty")):
    NUMBERS[word] = tens
    for unit in range(1, 10):
        NUMBERS["%s-%s" % (word, list(NUMBERS)[unit])] = tens + unit


def support_table(keywords_md):
    """{column: set of keyword paths} from the 'What radx supports' table."""
    runs, other, refused = set(), set(), set()
    in_table = False
    for line in keywords_md.splitlines():
        if line.startswith("## What radx supports"):
            in_table = True
            continue
        if in_table and line.startswith("## "):
            break
        if in_table and line.startswith("| ") and not line.startswith("| family"):
            cells = [c.strip() for c in line.strip("|").split("|")]
            if len(cells) != 4:
                continue
            for cell, bucket in zip(cells[1:], (runs, other, refused)):
                bucket.update(re.sub(r" \(engine\)$", "", k) for k in re.findall(r"`([^`]+)`", cell))
    return runs, other, refused


def main(root):
    readme = open(os.path.join(root, "README.md")).read()
    keywords_md = open(os.path.join(root, "docs", "keywords.md")).read()
    runs, other, refused = support_table(keywords_md)
    failures = []
    if not runs or not refused:
        failures.append("docs/keywords.md has no 'What radx supports' table to check against")
    # Each sentence (up to a full stop followed by a blank or a line end) with the keywords it names.
    for sentence in re.split(r"\.\s", readme):
        named = set(re.findall(r"`(/[A-Z][A-Z0-9_]*(?:/[A-Z0-9_]+)*)`", sentence))
        if not named:
            continue
        says_not_run = re.search(r"refuse|not supported|does not run|ignore|not written|warned", sentence)
        for k in sorted(named):
            # a keyword with an id written after it (/INTER/TYPE7/1) is its path without the number
            path = re.sub(r"/\d+$", "", k)
            every = runs | other | refused
            # a family named by its root (`/GRNOD`, `/ANIM`) is a claim about keywords radx runs under it
            family = any(r.startswith(path + "/") for r in runs)
            known = path in every or family or any(path.startswith(r + "/") for r in every)
            if not known:
                failures.append("README names %s, which radx does not declare (docs/keywords.md)" % k)
            elif not says_not_run and not family and path not in runs and not any(
                    path.startswith(r + "/") for r in runs):
                failures.append("README names %s as if it ran, but radx %s it" %
                                (k, "refuses" if path in refused else "ignores or does not write"))
    # The sample folders: the README's count in words against decks/.
    m = re.search(r"([a-z]+(?:-[a-z]+)?) folders under `decks/`", readme)
    if not m:
        failures.append("README states no count of sample folders under decks/")
    else:
        folders = [d for d in os.listdir(os.path.join(root, "decks"))
                   if os.path.isdir(os.path.join(root, "decks", d)) and d not in ("invalid", "verification", "versions")
                   and any(f.endswith(".rad") for f in os.listdir(os.path.join(root, "decks", d)))]
        said = NUMBERS.get(m.group(1))
        if said != len(folders):
            failures.append("README says %s folders under decks/, there are %d" % (m.group(1), len(folders)))
        else:
            print("ok   %s folders under decks/" % m.group(1))
    for f in failures:
        print("FAIL " + f)
    print("%d keyword claims checked" % len(set(re.findall(r"`(/[A-Z][A-Z0-9_]*(?:/[A-Z0-9_]+)*)`", readme))))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
