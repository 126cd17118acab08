"""The regression runner itself (`radx regress`, docs/regress.md), end to end on small decks copied here.

usage: /usr/bin/python3 check_regress_runner.py --radx RADX --decks DECKS_DIR --out DIR

Decks (copies of decks/verification/free_fall, a 0.01 s free fall, and of one decks/invalid deck):
  good/     its reference written by `--update`, then a second run compares within every tolerance;
  wrong/    the same reference with energy.kinetic_translational made 10 % larger than the run's value, its
            tolerance 1 %: the deck deviates, and the line names that quantity, and only it;
  crash/    a 1000 s free fall whose `radx run` child this script kills with SIGKILL mid-run: a run-error
            (failure), never a pass;
  invalid/  a deck declaring the error it must be refused with (diagnosed), and the same deck declaring
            an error it does not get (unexpected, a failure);
  nested/ and nested/inner/, and a folder named in Latin-1: pass, whatever order they run in.
Checks: the statuses, the exit codes (0 only when every deck passes), the JUnit file parsed with
xml.etree (one testcase per deck, a <failure> or <error> for each failing deck, counts in the attributes),
the verdicts of -j 1 and -j 2 equal deck by deck (from --summary JSON), the scratch folder keeping the failing
decks' run folders only, --filter and --keep, and --update on the deviating deck: it reports the change
(value 1.1 KE back to KE: -9.09 %), keeps the line's comment, and the deck then compares.
"""
import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

FAILED = []


def check(cond, what):
    if not cond:
        FAILED.append(what)
        print("FAILED:", what, file=sys.stderr)


def copy_free_fall(src, dst, tstop=None):
    os.makedirs(dst, exist_ok=True)
    for name in ("FREE_FALL_0000.rad", "FREE_FALL_0001.rad"):
        shutil.copy(os.path.join(src, name), os.path.join(dst, name))
    if tstop is not None:
        path = os.path.join(dst, "FREE_FALL_0001.rad")
        text = open(path).read()
        assert "                0.01\n" in text, "the free-fall engine deck's Tstop line moved"
        open(path, "w").write(text.replace("                0.01\n", "%20s\n" % tstop, 1))


def regress(radx, args, log):
    with open(log, "w") as f:
        return subprocess.run([radx, "regress"] + args, stdout=f, stderr=subprocess.STDOUT).returncode


def statuses(summary_path):
    d = json.load(open(summary_path, encoding="utf-8"))
    return {x["deck"]: x["status"] for x in d["decks"]}, d


def children_running(pattern):
    """Pids of processes whose command line contains `pattern`."""
    pids = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            cmd = open("/proc/%s/cmdline" % pid, "rb").read().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        if pattern in cmd and " run " in cmd:
            pids.append(int(pid))
    return pids


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--decks", required=True, help="the repository's decks/ folder")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    root = os.path.join(a.out, "decks")
    free_fall = os.path.join(a.decks, "verification", "free_fall")

    # good/: --update writes the reference, a second run compares.
    copy_free_fall(free_fall, os.path.join(root, "good"))
    rc = regress(a.radx, [os.path.join(root, "good"), "--update"], os.path.join(a.out, "update.log"))
    ref_path = os.path.join(root, "good", "FREE_FALL.ref")
    check(rc == 0 and os.path.exists(ref_path), "--update exits 0 and writes FREE_FALL.ref (rc %d)" % rc)
    rc = regress(a.radx, [os.path.join(root, "good")], os.path.join(a.out, "second.log"))
    second = open(os.path.join(a.out, "second.log")).read()
    check(rc == 0 and " compared " in second, "the run after --update compares (rc %d):\n%s" % (rc, second))

    # wrong/: one value 10 % off with a 1 % tolerance.
    copy_free_fall(free_fall, os.path.join(root, "wrong"))
    lines = []
    ke = None
    for line in open(ref_path).read().splitlines():
        f = line.split("#")[0].split()
        if f and f[0] == "energy.kinetic_translational":
            ke = float(f[1])
            line = "energy.kinetic_translational %.10g 0.01 0   # deliberately 10 %% above the run" % (1.1 * ke)
        lines.append(line)
    check(ke is not None and ke > 0, "the reference holds the kinetic energy of the fall")
    open(os.path.join(root, "wrong", "FREE_FALL.ref"), "w").write("\n".join(lines) + "\n")

    # invalid/: a deck that must be refused with its RX code, and one expecting a code it will not get.
    src = os.path.join(a.decks, "invalid", "duplicate_node_id.rad")
    text = open(src).read()
    m = re.match(r"# expect: (RX\d+) line (\d+)", text)
    check(m is not None, "duplicate_node_id.rad opens with its expectation")
    os.makedirs(os.path.join(root, "invalid"), exist_ok=True)
    open(os.path.join(root, "invalid", "refused.rad"), "w").write(text)
    open(os.path.join(root, "invalid", "wrongly_expected.rad"), "w").write(
        text.replace(m.group(0), "# expect: RX999 line %s" % m.group(2), 1))

    # nested/ and nested/inner/: a deck folder inside another's (their run folders must not hold each other),
    # and a folder whose name is not UTF-8 (the JUnit file must still parse).
    for sub in ("nested", os.path.join("nested", "inner")):
        copy_free_fall(free_fall, os.path.join(root, sub))
        shutil.copy(ref_path, os.path.join(root, sub, "FREE_FALL.ref"))
    latin1 = os.path.join(root.encode(), b"caf\xe9")
    os.makedirs(latin1)
    for name in (b"FREE_FALL_0000.rad", b"FREE_FALL_0001.rad"):
        shutil.copy(os.path.join(free_fall.encode(), name), os.path.join(latin1, name))
    shutil.copy(ref_path.encode(), os.path.join(latin1, b"FREE_FALL.ref"))

    # The batch without the crash, -j 1 and -j 2: same verdicts.
    verdicts = {}
    for jobs in ("1", "2"):
        summary = os.path.join(a.out, "summary_j%s.json" % jobs)
        junit = os.path.join(a.out, "junit_j%s.xml" % jobs)
        log = os.path.join(a.out, "batch_j%s.log" % jobs)
        rc = regress(a.radx, [root, "-j", jobs, "--summary", summary, "--junit", junit], log)
        out = open(log, errors="replace").read()
        check(rc == 1, "-j %s: a failing deck makes the exit code 1 (got %d)" % (jobs, rc))
        verdicts[jobs], _ = statuses(summary)
        wrong_line = [l for l in out.splitlines() if "] wrong " in l]
        check(len(wrong_line) == 1 and " deviates " in wrong_line[0] and
              "worst energy.kinetic_translational" in wrong_line[0] and "1 of " in wrong_line[0],
              "-j %s: wrong/ deviates on energy.kinetic_translational alone:\n%s" % (jobs, out))
        # The JUnit report, parsed.
        tree = ET.parse(junit)
        suites = tree.getroot()
        check(suites.tag == "testsuites", "JUnit root is <testsuites>")
        suite = suites.find("testsuite")
        cases = suite.findall("testcase")
        names = sorted(c.get("name") for c in cases)
        check(len(names) == len(verdicts[jobs]), "one testcase per deck: %s" % names)
        failing = {c.get("name") for c in cases if c.find("failure") is not None or c.find("error") is not None}
        check(failing == {"wrong", "invalid/wrongly_expected.rad"}, "failing testcases %s" % failing)
        check(int(suite.get("tests")) == len(cases) and
              int(suite.get("failures")) + int(suite.get("errors")) == len(failing),
              "JUnit counts %s" % suite.attrib)
        for c in cases:
            float(c.get("time"))  # a number
    check(verdicts["1"] == verdicts["2"], "-j 1 and -j 2 give the same verdicts: %s vs %s" % (verdicts["1"],
                                                                                          verdicts["2"]))
    expected = {"good": "compared", "wrong": "deviates", "invalid/refused.rad": "diagnosed",
                "invalid/wrongly_expected.rad": "unexpected", "nested": "compared", "nested/inner": "compared"}
    got = {k: v for k, v in verdicts["1"].items() if k.startswith("caf") is False}
    latin1_verdicts = [v for k, v in verdicts["1"].items() if k.startswith("caf")]
    check(got == expected and latin1_verdicts == ["compared"], "verdicts %s" % verdicts["1"])

    # Scratch folders: after the -j 2 batch, the work folder holds the failing decks' run folders only.
    out = open(os.path.join(a.out, "batch_j2.log"), errors="replace").read()
    m = re.search(r"work folder (\S+) keeps the 2 failing deck\(s\)' outputs", out)
    check(m is not None, "the batch says it keeps the 2 failing decks' outputs:\n" + out[-600:])
    if m:
        kept = sorted(x for x in os.listdir(m.group(1)) if not x.startswith("."))
        check(kept == ["invalid~wrongly_expected", "wrong"], "kept run folders %s" % kept)
        check(os.path.exists(os.path.join(m.group(1), "wrong", "run.log")), "a failing deck's run.log is kept")
        shutil.rmtree(m.group(1))

    # --filter keeps the matching decks; --keep keeps a passing deck's run folder.
    summary = os.path.join(a.out, "summary_filter.json")
    log = os.path.join(a.out, "filter.log")
    rc = regress(a.radx, [root, "--filter", "go*", "--filter", "inner", "--keep", "--summary", summary], log)
    got, d = statuses(summary)
    check(rc == 0 and got == {"good": "compared", "nested/inner": "compared"}, "--filter: %s (rc %d)" % (got, rc))
    check(d["work_dir_kept"] and os.path.exists(os.path.join(d["work_dir"], "good", "run.log")),
          "--keep keeps a passing deck's run folder")
    shutil.rmtree(d["work_dir"], ignore_errors=True)

    # --update on the deviating deck says what changed and by how much, then the deck compares.
    log = os.path.join(a.out, "update_wrong.log")
    rc = regress(a.radx, [root, "--filter", "wron[g]", "--update"], log)  # a glob: the whole name
    out = open(log, errors="replace").read()
    change = 100 * (ke - 1.1 * ke) / (1.1 * ke)  # back from 1.1 KE to KE: -9.09 %
    m = re.search(r"energy\.kinetic_translational: (\S+) -> (\S+) \(([-+.\deE]+) %\)", out)
    check(rc == 0 and m is not None, "--update reports the change (rc %d):\n%s" % (rc, out))
    if m:
        check(abs(float(m.group(1)) - 1.1 * ke) <= 1e-9 * ke and abs(float(m.group(2)) - ke) <= 1e-9 * ke,
              "old and new values %s %s" % (m.group(1), m.group(2)))
        check(abs(float(m.group(3)) - change) < 0.01, "relative change %s %% against %.3f %%" % (m.group(3), change))
    check(out.count(" -> ") == 1, "only the changed value is reported:\n" + out)
    kept = open(os.path.join(root, "wrong", "FREE_FALL.ref")).read()
    check("# deliberately 10 % above the run" in kept, "--update keeps the line's comment")
    rc = regress(a.radx, [os.path.join(root, "wrong")], os.path.join(a.out, "after_update.log"))
    check(rc == 0, "the deck compares after --update (rc %d)" % rc)

    # crash/: the engine killed by SIGKILL while it runs.
    copy_free_fall(free_fall, os.path.join(root, "crash"), tstop="1000.0")
    work = os.path.join(a.out, "work_crash")
    log = os.path.join(a.out, "crash.log")
    summary = os.path.join(a.out, "summary_crash.json")
    with open(log, "w") as f:
        p = subprocess.Popen([a.radx, "regress", os.path.join(root, "crash"), "--work", work, "--summary",
                              summary, "--timeout", "120"], stdout=f, stderr=subprocess.STDOUT)
    killed = False
    deadline = time.time() + 60
    while time.time() < deadline and p.poll() is None:
        # Killed once the engine is running: its summary says "running".
        running = os.path.join(work, "crash", "FREE_FALL_summary.json")
        pids = children_running(os.path.join(work, "crash"))
        if pids and os.path.exists(running):
            time.sleep(0.3)
            for pid in pids:
                os.kill(pid, signal.SIGKILL)
            killed = True
            break
        time.sleep(0.05)
    rc = p.wait(timeout=120)
    out = open(log, errors="replace").read()
    check(killed, "the crash deck's engine was found and killed")
    check(rc == 1, "a killed engine fails the batch (rc %d)" % rc)
    got, _ = statuses(summary)
    check(got == {"crash": "run-error"}, "a killed engine is a run-error: %s" % got)
    check("signal 9 (SIGKILL)" in out, "the line names the signal:\n%s" % out)

    if FAILED:
        print("%d check(s) failed" % len(FAILED), file=sys.stderr)
        sys.exit(1)
    print("regress runner: every check passed")


if __name__ == "__main__":
    main()
