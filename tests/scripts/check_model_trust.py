#!/usr/bin/python3
"""The engine trusts nothing in the model file: damaged entries, another run's model, a changed file.

usage: /usr/bin/python3 check_model_trust.py --radx-starter EXE --radx-engine EXE --deck DIR/NAME_0000.rad
                                             --other-deck DIR/OTHER_0000.rad --out DIR [--only CASE...]

Runs the starter on the deck (a model with node groups, surfaces, a TYPE7 interface, time histories, /BCS and
/INIVEL), then for each case copies its model file, changes it with h5py as a user or a damaged disk could,
and runs the engine on the copy. Every case must end with exit code 1, before the first cycle (no listing,
no results), with an error that names the model file, the diagnostic code, and the dataset and entry of the
bad value (the cases that change one integer) or what is wrong with the file as a whole:

  node_group_member      /radx/node_groups/nodes[k] = 10,000,000        RX901, the entry named
  surface_segment_node   /radx/surfaces/segments[k, j] = 10,000,000     RX901
  secondary_node         /radx/interfaces/0/secondary_nodes[k] = 1e7    RX901
  time_history_object    /radx/time_histories/objects[k] = 10,000,000   RX901
  part_material          /radx/parts/material[0] = 99                   RX901
  part_property          /radx/parts/property[0] = 99                   RX901
  all_masses_zero        /radx/node_mass = 0 everywhere                 RX902
  negative_mass          /radx/node_mass[k] = -1                        RX902
  nan_coordinate         /radx/nodes/xyz[k, 2] = NaN                    RX902
  bcs_group              /radx/bcs/group[0] = 99                        RX901, against the model file
  inivel_group           /radx/initial_velocities/group[0] = 99         RX901, against the model file
  changed_value          one coordinate moved by 1e-3 (a valid model)   RX904: changed after the starter wrote it
  other_format           radx_model_format_version = version - 1        RX903, both radx versions named
  other_model_flag       the other deck's model given with --model      RX905, both runs, decks and files
  other_model_copied     the other deck's model copied as NAME_0000.hdf RX905

Those changes are the probe's: before the checks, the first four ended in SIGSEGV (exit 139), the two part
references read freed memory and ended "NORMAL TERMINATION" with wrong energies, the zero masses ran
"normally" with zero energies, and another deck's model ran to the end on the wrong mesh.

Without a case changing the file, the unchanged model file runs (exit 0): the checks refuse no valid model.
Exit 0 when every case behaves, 1 otherwise (each failure printed as "FAIL: ...").

Needs h5py and numpy: run with /usr/bin/python3 (Debian python3-h5py, python3-numpy).
"""
import argparse
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def run(cmd):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=600)


def set_entry(path, dataset, index, value):
    with h5py.File(path, "r+") as f:
        d = f[dataset]
        a = d[()]
        a[index] = value
        d[...] = a


def set_all(path, dataset, value):
    with h5py.File(path, "r+") as f:
        d = f[dataset]
        d[...] = np.full(d.shape, value, dtype=d.dtype)


def set_root_attr(path, name, value):
    with h5py.File(path, "r+") as f:
        f.attrs.modify(name, value)


# Each case: (name, change(model_path, info), code, texts the error must contain).
def cases(info):
    k = info["last_group_member"]
    return [
        ("node_group_member", lambda p: set_entry(p, "/radx/node_groups/nodes", k, 10_000_000), "RX901",
         ["/radx/node_groups/nodes[%d]" % k, "10000000", "out of range"]),
        ("surface_segment_node", lambda p: set_entry(p, "/radx/surfaces/segments", (1, 2), 10_000_000), "RX901",
         ["/radx/surfaces/segments[1, 2]", "10000000"]),
        ("secondary_node", lambda p: set_entry(p, "/radx/interfaces/0/secondary_nodes", 3, 10_000_000), "RX901",
         ["/radx/interfaces/0/secondary_nodes[3]", "10000000"]),
        ("time_history_object", lambda p: set_entry(p, "/radx/time_histories/objects", 1, 10_000_000), "RX901",
         ["/radx/time_histories/objects[1]", "10000000"]),
        ("part_material", lambda p: set_entry(p, "/radx/parts/material", 0, 99), "RX901",
         ["/radx/parts/material[0]", "part %d" % info["part0"], "material index 99"]),
        ("part_property", lambda p: set_entry(p, "/radx/parts/property", 0, 99), "RX901",
         ["/radx/parts/property[0]", "part %d" % info["part0"], "property index 99"]),
        ("all_masses_zero", lambda p: set_all(p, "/radx/node_mass", 0.0), "RX902",
         ["/radx/node_mass", "every node has mass 0"]),
        ("negative_mass", lambda p: set_entry(p, "/radx/node_mass", 5, -1.0), "RX902",
         ["/radx/node_mass[5]", "node %d" % info["node5"], "mass -1"]),
        ("nan_coordinate", lambda p: set_entry(p, "/radx/nodes/xyz", (7, 2), np.nan), "RX902",
         ["/radx/nodes/xyz[7, 2]", "node %d" % info["node7"], "not a finite number"]),
        ("bcs_group", lambda p: set_entry(p, "/radx/bcs/group", 0, 99), "RX901",
         ["/radx/bcs/group[0]", "/BCS %d" % info["bcs0"], "node group index 99"]),
        ("inivel_group", lambda p: set_entry(p, "/radx/initial_velocities/group", 0, 99), "RX901",
         ["/radx/initial_velocities/group[0]", "node group index 99"]),
        ("changed_value", lambda p: set_entry(p, "/radx/nodes/xyz", (3, 0), info["x3"] + 1e-3), "RX904",
         ["changed after the starter wrote it"]),
        ("other_format", lambda p: set_root_attr(p, "radx_model_format_version", info["format"] - 1), "RX903",
         ["format version %d" % (info["format"] - 1), "written by radx", "this radx"]),
    ]


def model_info(path):
    with h5py.File(path, "r") as f:
        offsets = f["/radx/node_groups/nodes_offsets"][()]
        return {
            "last_group_member": int(offsets[1]) - 1,  # the last member of the first group
            "part0": int(f["/radx/parts/id"][0]),
            "bcs0": int(f["/radx/bcs/id"][0]),
            "node5": int(f["/radx/nodes/id"][5]),
            "node7": int(f["/radx/nodes/id"][7]),
            "x3": float(f["/radx/nodes/xyz"][3, 0]),
            "format": int(f.attrs["radx_model_format_version"]),
        }


def check_refused(name, r, code, texts, model_path, out):
    """The run refused before its first cycle, the error against the model file."""
    if r.returncode != 1:
        fail("%s: exit code %d, expected 1; stderr: %s" % (name, r.returncode, r.stderr[-1500:]))
        return
    for t in ["%s: error: %s:" % (model_path, code)] + texts:
        if t not in r.stderr:
            fail("%s: the error does not say %r; stderr: %s" % (name, t, r.stderr[-1500:]))
    if "NORMAL TERMINATION" in r.stdout + r.stderr:
        fail("%s: the run went on" % name)
    leftovers = [f for f in os.listdir(out) if f.endswith(("_0001.out", "_th.h5", ".vtkhdf", "_summary.json"))]
    if leftovers:
        fail("%s: a refused run left %s" % (name, leftovers))


def engine_deck(deck):
    return deck[: -len("_0000.rad")] + "_0001.rad"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx-starter", required=True)
    ap.add_argument("--radx-engine", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--other-deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--only", nargs="*")
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    name = os.path.basename(a.deck)[: -len("_0000.rad")]
    for deck, folder in ((a.deck, "model"), (a.other_deck, "other")):
        r = run([a.radx_starter, deck, "--out", os.path.join(a.out, folder)])
        if r.returncode != 0:
            print("the starter failed on %s: %s" % (deck, r.stderr[-2000:]))
            return 1
    model = os.path.join(a.out, "model", name + "_0000.hdf")
    other_name = os.path.basename(a.other_deck)[: -len("_0000.rad")]
    other_model = os.path.join(a.out, "other", other_name + "_0000.hdf")
    info = model_info(model)

    # The unchanged model runs: the checks refuse no valid model.
    out = os.path.join(a.out, "unchanged")
    r = run([a.radx_engine, engine_deck(a.deck), "--out", out, "--model", model, "--no-plot"])
    if r.returncode != 0:
        fail("unchanged: exit code %d; stderr: %s" % (r.returncode, r.stderr[-1500:]))

    for case, change, code, texts in cases(info):
        if a.only and case not in a.only:
            continue
        out = os.path.join(a.out, case)
        os.makedirs(out)
        copy = os.path.join(out, "changed_0000.hdf")
        shutil.copyfile(model, copy)
        change(copy)
        r = run([a.radx_engine, engine_deck(a.deck), "--out", out, "--model", copy, "--no-plot"])
        check_refused(case, r, code, texts, copy, out)
        print("%s: exit %d, %s" % (case, r.returncode, (r.stderr.splitlines() or [""])[0][:200]))

    # Another deck's model: with --model, and copied under the name the engine looks for.
    other_texts = ["model of run " + other_name, "is run " + name, engine_deck(a.deck), a.other_deck]
    if not a.only or "other_model_flag" in a.only:
        out = os.path.join(a.out, "other_model_flag")
        r = run([a.radx_engine, engine_deck(a.deck), "--out", out, "--model", other_model, "--no-plot"])
        check_refused("other_model_flag", r, "RX905", other_texts, other_model, out)
        print("other_model_flag: exit %d" % r.returncode)
    if not a.only or "other_model_copied" in a.only:
        out = os.path.join(a.out, "other_model_copied")
        os.makedirs(out)
        copied = os.path.join(out, name + "_0000.hdf")
        shutil.copyfile(other_model, copied)
        r = run([a.radx_engine, engine_deck(a.deck), "--out", out, "--no-plot"])
        check_refused("other_model_copied", r, "RX905", other_texts, copied, out)
        print("other_model_copied: exit %d" % r.returncode)

    if failures:
        print("%d failure(s)" % len(failures))
        return 1
    print("every damaged or foreign model file is refused, against the model file")
    return 0


if __name__ == "__main__":
    sys.exit(main())
