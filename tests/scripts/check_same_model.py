#!/usr/bin/python3
"""The same model written in several deck formats gives the same model file.

usage: /usr/bin/python3 check_same_model.py --radx-starter EXE --reference DECK --decks DECK... --out DIR

Runs the starter on the reference deck and on each other deck (each into its own folder under DIR), then
compares every model file with the reference's, independently of the C++ reader and writer: the same HDF5
groups and datasets, the same shapes, dtypes and values (exact: the decks write the same decimal text, so
any difference is a field read from the wrong columns, a card read in the wrong order or a default applied
differently), and the same attributes. Only /radx@deck_version, the format the deck was written in, may
differ (it must be the deck's /BEGIN version), and with it the fingerprint of the deck (the root attributes
radx_run, radx_deck_hash, radx_deck_files, radx_content_hash). Exit 0 when every model file matches, 1
otherwise (each difference printed as "FAIL: ...").

Needs h5py and numpy: run with /usr/bin/python3 (Debian python3-h5py, python3-numpy).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

import h5py
import numpy as np

failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def run_starter(exe, deck, out):
    shutil.rmtree(out, ignore_errors=True)
    r = subprocess.run([exe, deck, "--out", out], capture_output=True, text=True)
    if r.returncode != 0:
        fail("%s: the starter failed (%d): %s" % (deck, r.returncode, r.stderr[-2000:]))
        return None
    name = os.path.splitext(os.path.basename(deck))[0]
    return os.path.join(out, name + ".hdf")


def deck_version(deck):
    lines = [ln for ln in open(deck) if not ln.startswith(("#", "$"))]
    i = next(k for k, ln in enumerate(lines) if ln.upper().startswith("/BEGIN"))
    return int(lines[i + 2][:10])


def same_value(a, b):
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        a, b = np.asarray(a), np.asarray(b)
        return a.shape == b.shape and a.dtype == b.dtype and bool(np.all(a == b))
    return a == b


def objects(f):
    out = {}

    def visit(name, obj):
        out[name] = obj  # returning None lets visititems go on

    f.visititems(visit)
    return out


def compare(ref_path, path, version):
    with h5py.File(ref_path, "r") as ref, h5py.File(path, "r") as got:
        ro, go = objects(ref), objects(got)
        for name in sorted(set(ro) ^ set(go)):
            fail("%s: /%s is only in %s" % (path, name, "the reference" if name in ro else "this file"))
        checked = 0
        for name in ["/"] + sorted(set(ro) & set(go)):
            r, g = (ref, got) if name == "/" else (ro[name], go[name])
            if isinstance(r, h5py.Dataset) != isinstance(g, h5py.Dataset):
                fail("%s: /%s is a dataset in one file only" % (path, name))
                continue
            if isinstance(r, h5py.Dataset):
                if r.shape != g.shape or r.dtype != g.dtype:
                    fail("%s: /%s shape/dtype %s %s, reference %s %s" % (path, name, g.shape, g.dtype, r.shape,
                                                                         r.dtype))
                elif not same_value(r[()], g[()]):
                    fail("%s: /%s differs from the reference" % (path, name))
                checked += 1
            for key in sorted(set(r.attrs) | set(g.attrs)):
                where = "%s@%s" % (name, key)
                if key not in r.attrs or key not in g.attrs:
                    fail("%s: attribute %s is only in one file" % (path, where))
                elif name == "/" and key in ("radx_run", "radx_deck_hash", "radx_deck_files", "radx_content_hash"):
                    continue  # the fingerprint of another deck (its run, its text; deck_version below)
                elif name == "radx" and key == "deck_version":
                    if int(g.attrs[key]) != version:
                        fail("%s: deck_version %s, the deck says %d" % (path, g.attrs[key], version))
                elif not same_value(r.attrs[key], g.attrs[key]):
                    fail("%s: attribute %s = %r, reference %r" % (path, where, g.attrs[key], r.attrs[key]))
        return checked


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx-starter", required=True)
    ap.add_argument("--reference", required=True)
    ap.add_argument("--decks", nargs="+", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    ref = run_starter(a.radx_starter, a.reference, os.path.join(a.out, "reference"))
    if ref is None:
        return 1
    for deck in a.decks:
        name = re.sub(r"_0000$", "", os.path.splitext(os.path.basename(deck))[0])
        got = run_starter(a.radx_starter, deck, os.path.join(a.out, name))
        if got is None:
            continue
        n = compare(ref, got, deck_version(deck))
        print("%s (version %d): %d datasets compared with %s" % (os.path.basename(deck), deck_version(deck), n,
                                                                 os.path.basename(a.reference)))
    if failures:
        print("%d difference(s)" % len(failures))
        return 1
    print("every model file matches the reference")
    return 0


if __name__ == "__main__":
    sys.exit(main())
