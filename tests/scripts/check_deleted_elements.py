#!/usr/bin/env python3
"""The deleted-element counts of the summary and the listing against the results: a deck whose elements fail
(decks/perforation_tab: a plate whose shells are deleted by /FAIL/JOHNSON) is run, and the summary's
deleted_elements (total, per part, the first ones) must equal what the last state's element_status says (0 =
deleted), counted per part_id independently of the engine's own count; the listing's DELETED ELEMENTS block
must give the same numbers, and the first deleted elements must be ones the last state shows deleted, in the
order of their deletion times.

Usage: check_deleted_elements.py --radx RADX --deck NAME_0000.rad --out DIR
"""
import argparse
import os
import re
from collections import Counter

import h5py

from results_common import check, finish, listed_states, read_summary, run_radx


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--radx", required=True)
    p.add_argument("--deck", required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args()
    name = run_radx(a.radx, a.deck, a.out)
    s = read_summary(a.out, name)
    d = s["deleted_elements"]
    last = listed_states(a.out, name)[-1][0]
    with h5py.File(os.path.join(a.out, last), "r") as f:
        cells = f["VTKHDF/CellData"]
        status = cells["element_status"][()]
        part = cells["part_id"][()]
        element = cells["element_id"][()]
    deleted = Counter(int(part[i]) for i in range(len(status)) if status[i] == 0)
    deleted_ids = {(int(part[i]), int(element[i])) for i in range(len(status)) if status[i] == 0}
    check(sum(deleted.values()) > 0, "the deck deletes no element: it does not test the counts")
    check(d["total"] == sum(deleted.values()),
          "summary total %d, last state %d deleted" % (d["total"], sum(deleted.values())))
    by_part = {e["part"]: e["count"] for e in d["by_part"]}
    check(by_part == dict(deleted), "summary per part %s, last state %s" % (by_part, dict(deleted)))
    first = d["first"]
    check(len(first) == min(10, d["total"]), "%d first deleted listed for %d" % (len(first), d["total"]))
    for e in first:
        check((e["part"], e["id"]) in deleted_ids, "first deleted %s is not deleted in the last state" % e)
    check([e["time"] for e in first] == sorted(e["time"] for e in first), "first deleted not in time order")
    listing = open(os.path.join(a.out, name + "_0001.out")).read()
    block = listing[listing.find("DELETED ELEMENTS"):]
    m = re.search(r"total\s+(\d+)", block)
    check(m is not None and int(m.group(1)) == d["total"], "listing DELETED ELEMENTS total differs from the summary")
    for pid, n in deleted.items():
        check(re.search(r"part %d\b[^\n]*\s%d\n" % (pid, n), block) is not None,
              "listing has no line 'part %d ... %d'" % (pid, n))
    finish("%d deleted elements in %d part(s), as the last state shows" % (d["total"], len(deleted)))


if __name__ == "__main__":
    main()
