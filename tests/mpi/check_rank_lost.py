"""A rank lost mid-run ends the whole job, with a message naming it, instead of leaving the others waiting.

usage: /usr/bin/python3 check_rank_lost.py --mpirun MPIRUN --program TEST_COMM_MPI

Three ranks loop votes (all-reduces); rank 1 kills itself with SIGKILL at its 5th iteration, as a crashed or
out-of-memory-killed rank would. Open MPI's mpirun does this by default, with no option: it sees a process end
on a signal, kills the other ranks (blocked in the all-reduce that will never complete) and prints
"mpirun noticed that process rank 1 ... exited on signal 9 (Killed)". The check runs it under `timeout 60`
and wants: an exit code that is neither 0 nor the timeout's 124, within 15 s, and the lost rank named.
"""
import argparse
import re
import subprocess
import sys
import time

LIMIT_S = 15.0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--mpirun", required=True)
    ap.add_argument("--program", required=True)
    a = ap.parse_args()
    cmd = ["timeout", "60", a.mpirun, "--allow-run-as-root", "--oversubscribe", "--mca", "mpi_yield_when_idle",
           "1", "-np", "3", a.program, "--lose-rank", "1", "5"]
    t0 = time.monotonic()
    r = subprocess.run(cmd, capture_output=True, text=True)
    elapsed = time.monotonic() - t0
    text = r.stdout + r.stderr
    fails = []
    if r.returncode in (0, 124):
        fails.append("exit code %d (0: no rank was lost; 124: the job hung until the timeout)" % r.returncode)
    if elapsed > LIMIT_S:
        fails.append("the job took %.1f s to end, beyond %.0f s" % (elapsed, LIMIT_S))
    if not re.search(r"process rank 1\b.*signal 9", text):
        fails.append("no message naming the lost rank 1 and its signal")
    print("mpirun exit %d after %.1f s; its message:\n%s" % (r.returncode, elapsed, text.strip()[-1500:]))
    for f in fails:
        print("FAIL: " + f)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
