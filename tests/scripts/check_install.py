"""radx as a user gets it: installed with `cmake --install`, or packaged with `cpack -G DEB`, then run on the
default deck from a folder that has nothing to do with the source or build tree.

usage: /usr/bin/python3 check_install.py --build BUILD --source SRC --deck DECK_DIR --out DIR --version V --arch A
                                         (prefix|deb)

DECK_DIR is the folder of the deck compiled into the executables (apps/CMakeLists.txt), ROOT_0000.rad and
ROOT_0001.rad in it.

prefix: `cmake --install BUILD --prefix DIR/prefix`, then
  1. the layout: bin/radx, bin/radx-starter, bin/radx-engine; share/radx/decks/<DECK_DIR's name> with the
     default deck's two files and its regression reference; share/doc/radx/README.md and every
     docs/*.md; lib/cmake/radx/radxConfig.cmake, radxConfigVersion.cmake, radxTargets.cmake; the headers
     under include/radx; share/radx/paraview holds exactly the files of scripts/paraview (none while the
     folder is absent);
  2. the executables name neither the source nor the build folder anywhere in their bytes (nothing is read
     from those trees at run time);
  3. the run check below with DIR/prefix/bin/radx;
  4. find_package(radx 0.1) from a new CMake project built against DIR/prefix: it links radx::parser and
     radx::model, reads the installed default deck and prints its node and element counts, which must equal
     the run's NAME_summary.json (two programs, one deck: the library a consumer gets is the one the
     executables run).
deb: `cpack -G DEB` into DIR/pkg, then
  1. dpkg-deb -I: Package radx, Version V, Architecture amd64; Depends names, for each shared library the
     three executables need (objdump -p NEEDED, resolved with ldd), the Debian package that owns it
     (dpkg -S), and python3-matplotlib is recommended (the energy chart);
  2. dpkg-deb -c: the same layout as above under ./usr;
  3. dpkg-deb -x into DIR/root, and the run check with DIR/root/usr/bin/radx.
The run check: `radx run` (no deck: the embedded default deck) in a new empty working folder. It exits 0 and
writes, in that folder, the starter's and engine's listings, the model file, NAME_summary.json, the state
index NAME.hdf.series, the time history NAME_th.h5, the energy CSV and PNG. The summary's status is normal,
its energy error is within half a percentage point of the regression reference installed beside the deck
(ROOT.ref, whose own tolerance it is) and its cycle count within the reference's 1 %; its version,
commit and arch are those that `radx --version` prints, the version is V and the arch A; its units are the
work units of the installed deck's /BEGIN card (its fourth data line), and the deck files the run wrote are
the installed ones byte for byte.
"""
import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import tempfile

from results_common import check, finish

EXES = ["radx", "radx-starter", "radx-engine"]
# The default deck's folder name and file root, set by main() from --deck.
DECK = ""
ROOT = ""


def sh(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    check(r.returncode == 0, "%s: exit %d\n%s%s" % (" ".join(cmd), r.returncode, r.stdout[-3000:], r.stderr[-3000:]))
    return r


def check_layout(files, prefix, source):
    """files: the installed paths relative to the prefix (as a set of strings)."""
    for exe in EXES:
        check("bin/" + exe in files, "bin/%s not installed" % exe)
    for name in ["%s_0000.rad" % ROOT, "%s_0001.rad" % ROOT, "%s.ref" % ROOT]:
        check("share/radx/decks/%s/%s" % (DECK, name) in files, "default deck file %s not installed" % name)
    check("share/doc/radx/README.md" in files, "README.md not installed")
    for doc in glob.glob(os.path.join(source, "docs", "*.md")):
        check("share/doc/radx/" + os.path.basename(doc) in files, "docs/%s not installed" % os.path.basename(doc))
    for f in ["radxConfig.cmake", "radxConfigVersion.cmake", "radxTargets.cmake", "FindCHOLMOD.cmake"]:
        check("lib/cmake/radx/" + f in files, "lib/cmake/radx/%s not installed" % f)
    check("include/radx/solver/model/model.hpp" in files, "headers not installed")
    pv = sorted(os.path.basename(p) for p in glob.glob(os.path.join(source, "scripts", "paraview", "*"))
                if os.path.isfile(p))
    installed_pv = sorted(f.rsplit("/", 1)[1] for f in files if f.startswith("share/radx/paraview/"))
    check(installed_pv == pv, "share/radx/paraview has %s, scripts/paraview has %s" % (installed_pv, pv))


def version_parts(radx):
    out = sh([radx, "--version"]).stdout.strip()
    m = re.fullmatch(r"radx (\S+) \(commit (\S+), (\S+)\)", out)
    check(m is not None, "radx --version printed %r" % out)
    return m.groups() if m else ("?", "?", "?")


def reference(deck_dir):
    """quantity -> (value, rel_tol, abs_floor) from the installed NAME.ref."""
    ref = {}
    for line in open(os.path.join(deck_dir, ROOT + ".ref")):
        f = line.split()
        if f and not f[0].startswith("#") and len(f) >= 4:
            ref[f[0]] = tuple(float(x) for x in f[1:4])
    return ref


def work_units(starter_deck):
    """The /BEGIN card's work units: its data lines are the run name, the deck version, the input units and
    the work units (comment lines, starting with #, are not data)."""
    lines = open(starter_deck).read().splitlines()
    k = next(i for i, l in enumerate(lines) if l.rstrip() == "/BEGIN")
    data = [l for l in lines[k + 1:] if not l.startswith("#")]
    return data[3].split()


def check_run(radx, share, want_version, want_arch):
    deck_dir = os.path.join(share, "radx", "decks", DECK)
    work = tempfile.mkdtemp(prefix="radx_installed_run_")
    try:
        r = subprocess.run([radx, "run"], cwd=work, capture_output=True, text=True)
        check(r.returncode == 0, "radx run of the default deck: exit %d\n%s" % (r.returncode, r.stderr[-3000:]))
        for f in ["%s_0000.rad" % ROOT, "%s_0001.rad" % ROOT, "%s_0000.out" % ROOT, "%s_0000.hdf" % ROOT,
                  "%s_0001.out" % ROOT, "%s_summary.json" % ROOT, "%s.hdf.series" % ROOT, "%s_th.h5" % ROOT,
                  "%s_energy.csv" % ROOT, "%s_energy.png" % ROOT]:
            p = os.path.join(work, f)
            check(os.path.isfile(p) and os.path.getsize(p) > 0, "the run wrote no %s in %s" % (f, work))
        # The embedded deck is the installed deck's text.
        for f in ["%s_0000.rad" % ROOT, "%s_0001.rad" % ROOT]:
            p = os.path.join(work, f)
            if os.path.isfile(p):
                check(open(p, "rb").read() == open(os.path.join(deck_dir, f), "rb").read(),
                      "the deck the run wrote differs from the installed %s" % f)
        try:
            s = json.load(open(os.path.join(work, ROOT + "_summary.json")))
        except (OSError, ValueError) as e:
            check(False, "cannot read the summary: %s" % e)
            return None
        check(s["status"] == "normal", "status %s: %s" % (s["status"], s.get("message")))
        ref = reference(deck_dir)
        check("energy.error_percent" in ref and "cycles" in ref, "%s.ref lacks the energy error or the cycles" % ROOT)
        if "energy.error_percent" not in ref or "cycles" not in ref:
            return s
        value, _, floor = ref["energy.error_percent"]
        err = s["energy"]["error_percent"]
        check(abs(err - value) <= floor, "energy error %.4g %% is not within %g points of the reference %.4g %%" %
              (err, floor, value))
        cycles, rel, floor = ref["cycles"]
        check(abs(s["cycles"] - cycles) <= max(rel * cycles, floor), "cycles %d, reference %d" % (s["cycles"], cycles))
        version, commit, arch = version_parts(radx)
        check(s.get("version") == version == want_version, "summary version %r, --version %r, project %r" %
              (s.get("version"), version, want_version))
        check(s.get("commit") == commit, "summary commit %r, --version %r" % (s.get("commit"), commit))
        check(re.fullmatch(r"[0-9a-f]{7,40}(-dirty)?|unknown", commit or "") is not None, "commit %r" % commit)
        check(s.get("arch") == arch == want_arch, "summary arch %r, --version %r, build %r" %
              (s.get("arch"), arch, want_arch))
        mass, length, time = work_units(os.path.join(deck_dir, ROOT + "_0000.rad"))
        check(s.get("units") == {"mass": mass, "length": length, "time": time},
              "summary units %r, /BEGIN work units %s %s %s" % (s.get("units"), mass, length, time))
        return s
    finally:
        shutil.rmtree(work, ignore_errors=True)


def check_no_tree_paths(exe, build, source):
    data = open(exe, "rb").read()
    for tree in {os.path.realpath(build), os.path.realpath(source), build, source}:
        check(tree.encode() not in data, "%s holds the path %s" % (exe, tree))


CONSUMER_CMAKE = """cmake_minimum_required(VERSION 3.25)
project(radx_consumer LANGUAGES C CXX)
set(CMAKE_CXX_STANDARD 20)
find_package(radx 0.1 REQUIRED)
add_executable(count_deck count_deck.cpp)
target_link_libraries(count_deck PRIVATE radx::parser radx::model)
"""


def consumer_source(source):
    """The consumer's main: reads a deck with the library's reader and model builder."""
    return open(os.path.join(source, "tests", "scripts", "install_consumer.cpp")).read()


def check_find_package(prefix, out, source, summary):
    proj = os.path.join(out, "consumer")
    os.makedirs(proj)
    open(os.path.join(proj, "CMakeLists.txt"), "w").write(CONSUMER_CMAKE)
    open(os.path.join(proj, "count_deck.cpp"), "w").write(consumer_source(source))
    b = os.path.join(proj, "build")
    r = sh(["cmake", "-S", proj, "-B", b, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_PREFIX_PATH=" + prefix])
    if r.returncode:
        return
    if sh(["cmake", "--build", b]).returncode:
        return
    deck = os.path.join(prefix, "share", "radx", "decks", DECK, ROOT + "_0000.rad")
    r = sh([os.path.join(b, "count_deck"), deck])
    m = re.fullmatch(r"nodes (\d+) elements (\d+)", r.stdout.strip())
    check(m is not None, "the consumer printed %r" % r.stdout)
    if m and summary:
        check((int(m.group(1)), int(m.group(2))) == (summary["nodes"], summary["elements"]),
              "the consumer read %s nodes %s elements, the run had %d and %d" %
              (m.group(1), m.group(2), summary["nodes"], summary["elements"]))


def installed_files(prefix):
    files = set()
    for d, _, names in os.walk(prefix):
        for n in names:
            files.add(os.path.relpath(os.path.join(d, n), prefix))
    return files


def run_prefix(a):
    prefix = os.path.join(a.out, "prefix")
    if sh(["cmake", "--install", a.build, "--prefix", prefix]).returncode:
        return
    check_layout(installed_files(prefix), prefix, a.source)
    for exe in EXES:
        check_no_tree_paths(os.path.join(prefix, "bin", exe), a.build, a.source)
    summary = check_run(os.path.join(prefix, "bin", "radx"), os.path.join(prefix, "share"), a.version, a.arch)
    check_find_package(prefix, a.out, a.source, summary)


def owning_package(path):
    """The Debian package that installed `path` (also tried with and without the /usr of a merged /usr)."""
    candidates = [path, os.path.realpath(path)]
    for p in list(candidates):
        candidates.append(p[4:] if p.startswith("/usr/") else "/usr" + p)
    for p in candidates:
        r = subprocess.run(["dpkg", "-S", p], capture_output=True, text=True)
        if r.returncode == 0:
            return r.stdout.split(":")[0].strip()
    return None


def needed_packages(exe):
    """{soname: owning package} for each NEEDED entry of exe, resolved by ldd."""
    needed = re.findall(r"NEEDED\s+(\S+)", sh(["objdump", "-p", exe]).stdout)
    resolved = dict(re.findall(r"^\s*(\S+) => (\S+)", sh(["ldd", exe]).stdout, re.M))
    out = {}
    for so in needed:
        check(so in resolved, "%s: ldd does not resolve %s" % (exe, so))
        if so in resolved:
            out[so] = owning_package(resolved[so])
            check(out[so] is not None, "no Debian package owns %s" % resolved[so])
    return out


def run_deb(a):
    pkgdir = os.path.join(a.out, "pkg")
    if sh(["cpack", "-G", "DEB", "-B", pkgdir, "--config", os.path.join(a.build, "CPackConfig.cmake")],
          cwd=a.build).returncode:
        return
    debs = glob.glob(os.path.join(pkgdir, "radx_*.deb"))
    check(len(debs) == 1, "cpack made %s" % debs)
    if len(debs) != 1:
        return
    deb = debs[0]
    check(os.path.basename(deb) == "radx_%s_amd64.deb" % a.version, "package file %s" % deb)
    info = sh(["dpkg-deb", "-I", deb]).stdout
    field = dict(re.findall(r"^ (\S+): (.*)$", info, re.M))
    check(field.get("Package") == "radx", "Package: %r" % field.get("Package"))
    check(field.get("Version") == a.version, "Version: %r" % field.get("Version"))
    check(field.get("Architecture") == "amd64", "Architecture: %r" % field.get("Architecture"))
    depends = {d.strip().split()[0] for d in field.get("Depends", "").split(",") if d.strip()}
    for exe in EXES:
        for so, pkg in needed_packages(os.path.join(a.build, "apps", exe)).items():
            check(pkg in depends, "%s needs %s from %s, not in Depends: %s" % (exe, so, pkg, sorted(depends)))
    check("python3-matplotlib" in field.get("Recommends", ""), "Recommends: %r" % field.get("Recommends"))
    listing = sh(["dpkg-deb", "-c", deb]).stdout
    files = {re.sub(r"^\./usr/", "", l.split()[-1]) for l in listing.splitlines() if not l.startswith("d")}
    check_layout(files, "/usr", a.source)
    root = os.path.join(a.out, "root")
    if sh(["dpkg-deb", "-x", deb, root]).returncode:
        return
    check_run(os.path.join(root, "usr", "bin", "radx"), os.path.join(root, "usr", "share"), a.version, a.arch)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--version", required=True)
    ap.add_argument("--arch", required=True)
    ap.add_argument("mode", choices=["prefix", "deb"])
    a = ap.parse_args()
    global DECK, ROOT
    DECK = os.path.basename(os.path.normpath(a.deck))
    starters = glob.glob(os.path.join(a.deck, "*_0000.rad"))
    check(len(starters) == 1, "%s has %d starter decks" % (a.deck, len(starters)))
    if len(starters) != 1:
        finish("")
    ROOT = os.path.basename(starters[0])[:-len("_0000.rad")]
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    if a.mode == "prefix":
        run_prefix(a)
    else:
        run_deb(a)
    finish("radx installed (%s) runs the default deck from a new folder" % a.mode)


if __name__ == "__main__":
    main()
