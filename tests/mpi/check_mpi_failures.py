"""MPI failures end the whole job, with a message naming what failed, instead of leaving ranks waiting.

usage: /usr/bin/python3 check_mpi_failures.py --mpirun MPIRUN --program TEST_COMM_MPI

  * A rank lost mid-run: three ranks loop votes (all-reduces) and rank 1 kills itself with SIGKILL at its 5th
    iteration, as a crashed or out-of-memory-killed rank would. Open MPI's mpirun handles it by default, with no
    option: it sees a process end on a signal, kills the other ranks (blocked in an all-reduce that will never
    complete) and prints "mpirun noticed that process rank 1 ... exited on signal 9 (Killed)".
  * A failed MPI call: every rank gathers to a root that does not exist. The communicator (errors returned,
    not fatal) prints the call and MPI's reason ("MPI_Gather (message sizes) failed: MPI_ERR_ROOT") and
    ends every rank with MPI_Abort.

Each runs under `timeout 60` and must end with an exit code that is neither 0 nor the timeout's 124, within
15 s, with its message.
"""
import argparse
import re
import subprocess
import sys
import time

LIMIT_S = 15.0
MPI_FLAGS = ["--allow-run-as-root", "--oversubscribe", "--mca", "mpi_yield_when_idle", "1"]


def scenario(a, name, args, message_pattern):
    cmd = ["timeout", "60", a.mpirun, *MPI_FLAGS, "-np", "3", a.program, *args]
    t0 = time.monotonic()
    r = subprocess.run(cmd, capture_output=True, text=True)
    elapsed = time.monotonic() - t0
    text = r.stdout + r.stderr
    fails = []
    if r.returncode in (0, 124):
        fails.append("exit code %d (0: nothing failed; 124: the job hung until the timeout)" % r.returncode)
    if elapsed > LIMIT_S:
        fails.append("the job took %.1f s to end, beyond %.0f s" % (elapsed, LIMIT_S))
    if not re.search(message_pattern, text):
        fails.append("no message matching %r" % message_pattern)
    print("%s: mpirun exit %d after %.1f s; its message:\n%s\n" % (name, r.returncode, elapsed, text.strip()[-1200:]))
    return [name + ": " + f for f in fails]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--mpirun", required=True)
    ap.add_argument("--program", required=True)
    a = ap.parse_args()
    fails = scenario(a, "rank lost", ["--lose-rank", "1", "5"], r"process rank 1\b.*signal 9")
    fails += scenario(a, "failed call", ["--bad-root"], r"MPI rank \d: MPI_Gather \(message sizes\) failed: MPI_ERR_ROOT")
    for f in fails:
        print("FAIL: " + f)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
