"""What the executables say of their build, and the script that finds the commit.

usage: /usr/bin/python3 check_version.py --source SRC --script RadxGitCommit.cmake --version V --arch A
                                         --out DIR EXE...

1. Each EXE (radx, radx-starter, radx-engine) prints, for --version, exactly "NAME V (commit C, A)" with NAME
   its file name, V the project version and A the instruction set of the build (both from CMake); C is the
   commit of SRC found here with git itself: the short hash of HEAD, "-dirty" after it when `git status`
   lists a changed tracked file, "unknown" when SRC is not the top of a git work tree. radx-starter and
   radx-engine print the same for Radioss's -version.
2. The commit script (cmake -P) on repositories made here: a new repository with one commit gives that
   commit's short hash; a changed tracked file adds "-dirty"; an untracked file does not; a new commit gives
   the new hash (HEAD followed without a configure); a folder without git (a source tarball) gives
   "unknown", and so does one unpacked inside another repository. The generated file is not rewritten (its
   modification time is kept) when the commit is unchanged, so a build at the same commit recompiles nothing.
"""
import argparse
import os
import re
import shutil
import subprocess
import time

from results_common import check, finish


def git(repo, *args):
    return subprocess.run(["git", "-C", repo] + list(args), capture_output=True, text=True)


def expected_commit(src):
    top = git(src, "rev-parse", "--show-toplevel")
    if top.returncode or os.path.realpath(top.stdout.strip()) != os.path.realpath(src):
        return "unknown"
    h = git(src, "rev-parse", "--short", "HEAD").stdout.strip()
    dirty = git(src, "status", "--porcelain", "--untracked-files=no").stdout.strip()
    return h + ("-dirty" if dirty else "")


def commit_of(script, src, output):
    r = subprocess.run(["cmake", "-DSOURCE_DIR=" + src, "-DOUTPUT=" + output, "-P", script], capture_output=True,
                       text=True)
    check(r.returncode == 0, "the commit script failed on %s: %s" % (src, r.stderr))
    m = re.search(r'build_commit\(\) \{ return "([^"]*)"; \}', open(output).read()) if os.path.exists(output) else None
    check(m is not None, "no build_commit() in %s" % output)
    return m.group(1) if m else None


def check_script(script, out):
    env_git = ["-c", "user.name=radx test", "-c", "user.email=test@radx", "-c", "commit.gpgsign=false"]
    repo = os.path.join(out, "repo")
    os.makedirs(repo)
    gen = os.path.join(out, "build_commit.cpp")
    subprocess.run(["git", "init", "-q", repo], check=True)
    open(os.path.join(repo, "a.txt"), "w").write("one\n")
    subprocess.run(["git", "-C", repo, "add", "a.txt"], check=True)
    subprocess.run(["git"] + env_git + ["-C", repo, "commit", "-q", "-m", "one"], check=True)
    first = git(repo, "rev-parse", "--short", "HEAD").stdout.strip()
    check(commit_of(script, repo, gen) == first, "clean repository: expected %s" % first)
    # The same commit again: the file keeps its modification time (nothing to recompile).
    stamp = os.stat(gen).st_mtime_ns
    time.sleep(0.05)
    commit_of(script, repo, gen)
    check(os.stat(gen).st_mtime_ns == stamp, "the generated file was rewritten at an unchanged commit")
    open(os.path.join(repo, "untracked.txt"), "w").write("x\n")
    check(commit_of(script, repo, gen) == first, "an untracked file made the tree dirty")
    open(os.path.join(repo, "a.txt"), "w").write("two\n")
    check(commit_of(script, repo, gen) == first + "-dirty", "a changed tracked file: expected %s-dirty" % first)
    subprocess.run(["git"] + env_git + ["-C", repo, "commit", "-q", "-am", "two"], check=True)
    second = git(repo, "rev-parse", "--short", "HEAD").stdout.strip()
    check(second != first, "two commits with one hash")
    check(commit_of(script, repo, gen) == second, "a new commit: expected %s" % second)
    # A source tarball: no .git at all, then the same unpacked inside the repository above.
    tarball = os.path.join(out, "tarball")
    os.makedirs(tarball)
    open(os.path.join(tarball, "CMakeLists.txt"), "w").write("\n")
    check(commit_of(script, tarball, gen) == "unknown", "a folder without git")
    nested = os.path.join(repo, "radx-0.1.0")
    shutil.copytree(tarball, nested)
    check(commit_of(script, nested, gen) == "unknown", "a tarball unpacked inside another repository")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--source", required=True)
    ap.add_argument("--script", required=True)
    ap.add_argument("--version", required=True)
    ap.add_argument("--arch", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("exes", nargs="+")
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)

    commit = expected_commit(a.source)
    for exe in a.exes:
        name = os.path.basename(exe)
        want = "%s %s (commit %s, %s)" % (name, a.version, commit, a.arch)
        flags = ["--version"] + (["-version"] if name != "radx" else [])
        for flag in flags:
            r = subprocess.run([exe, flag], capture_output=True, text=True)
            check(r.returncode == 0, "%s %s: exit %d" % (name, flag, r.returncode))
            check(r.stdout == want + "\n", "%s %s printed %r, expected %r" % (name, flag, r.stdout, want))
    check_script(a.script, a.out)
    finish("--version names the version, the commit %s and the instruction set" % commit)


if __name__ == "__main__":
    main()
