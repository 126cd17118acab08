#!/usr/bin/env python3
"""Weak-scaling estimate of radx-engine-mpi past this machine: a latency-bandwidth model of the network fed
with what the engine measurably sends per cycle.

Measured here (the contact-free impact model of bench/mpi_scaling.sh, bench/gen_shell_plate.py --impact
--contact none, N x N shells and (N/10)^2 x 4 bricks):
  * per cycle and per collective kind, on the busiest rank, the calls, messages and bytes sent and received,
    from radx-engine-mpi --comm-stats at np 2 and np 3; two runs of CYCLES1 and CYCLES2 cycles each, and
    the difference taken, so the set-up (partition broadcast, first outputs) drops out;
  * the compute time per element and cycle of radx-engine --threads 1 on the same model (its listing's cost);
  * the domain exchange at P ranks (bench/domain_traffic.cpp, the METIS split): the busiest rank's bytes
    (shared-node sums and ghost update, sent plus received) and messages per cycle, on the impact model of
    about E elements per rank (N_P = sqrt(P E / 1.04)), for each P of --ranks.

Model of one cycle on P ranks with E elements each (alpha latency, beta bandwidth; L = ceil(log2 P)):
  compute          t_c = (us per element-cycle) x E, times the element imbalance (--imbalance, METIS's
                   tolerance 1.03 by default)
  all-reduce       (vote, max, sum_exact, bit_or: n bytes)  L (alpha + n / beta)  (recursive doubling)
  all-gather       (c bytes a rank, with its 8-byte size)    2 L alpha + (P - 1) c / beta
                   (recursive doubling / Bruck: L steps for the sizes and L for the data; every rank
                   receives every other rank's contribution, so the bytes grow with P)
  broadcast        (n bytes)                                 2 L (alpha + n / beta)  (binomial tree)
  gather           as all-gather; barrier L alpha
  exchange         the sizes' all-to-all (Bruck: L steps of 4 P bytes) + m alpha + b / beta, m and b the
                   busiest rank's messages and bytes sent plus received (domain traffic at P: the shared-node
                   sums and the ghost update of the design, also in the "as measured" rows, which today send
                   the sums alone; without it, the measured exchange bytes at np 3 scaled with the rank's
                   perimeter, sqrt(E / E_measured))
A contribution measured at np 2 and np 3 is fitted as a + b x (elements per rank) through the two points and
taken at E (an all-gather of every owned node's sums or every group's vote grows with the rank's share; a
reduction does not). Parallel efficiency = t_c / (imbalance x t_c + t_comm). Communication is not overlapped
with compute (the engine waits in each collective), so this is the estimate's upper bound on its cost.

The engine on main replicates the node passes (every rank integrates every node) and all-gathers every
node's sums each cycle; the "as measured" rows model what it sends today (with the compute split as
designed: today's replicated node passes would add their O(all nodes) time on every rank). The "design"
rows replace that all-gather by the domain exchange (owned nodes only, ghosts updated;
docs/parallel-domain.md), keeping the all-gather of the group votes (--vote-bytes a group, default 72: the
engine's GroupVote).

Usage: bench/mpi_weak_scaling.py [--n 300] [--cycles 20 40] [--ranks 16 64] [--elements-per-rank 100000]
                                 [--alpha 1.5e-6] [--gbits 100] [--no-domain-traffic] [--keep DIR]
(builds radx-starter, radx-engine, radx-engine-mpi and radx_bench_domain in build/ when needed)
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
BIN = os.path.join(ROOT, "build", "apps")
MPI_FLAGS = ["--allow-run-as-root", "--oversubscribe", "--mca", "mpi_yield_when_idle", "1"]
REDUCTIONS = ("vote", "max", "sum_exact", "bit_or")


def run(cmd, **kw):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)
    if r.returncode != 0:
        sys.exit("mpi_weak_scaling: %s failed (exit %d):\n%s" % (" ".join(cmd), r.returncode, r.stdout[-1500:]))
    return r.stdout


def model_elements(n):
    return n * n + 4 * (n // 10) ** 2


def write_model(n, tstop, out):
    """The contact-free impact model, without animation states or time history after t = 0: the per-cycle
    figures are those of the cycles between outputs."""
    run([sys.executable, os.path.join(ROOT, "bench", "gen_shell_plate.py"), "--n", str(n), "--impact", "--block",
         str(n // 10), "--brick-size", "%g" % (2000.0 / n), "--contact", "none", "--tstop", "%.6g" % tstop,
         "--th-records", "0", "--anim-states", "0", "--out", out])
    return os.path.join(out, "PLATE%dI_NOCONTACT" % n)


def summary(out, root):
    with open(os.path.join(out, os.path.basename(root) + "_summary.json")) as f:
        return json.load(f)


def parse_comm_stats(text):
    """{rank: {kind: [calls, messages, sent, received, seconds]}} from a --comm-stats table."""
    stats = {}
    for line in text.splitlines():
        m = re.match(r"^\|\s*(\d+)\s*\|\s*(\w+)\s*\|\s*(\d+)\s*\|\s*(\d+)\s*\|\s*(\d+)\s*\|\s*(\d+)\s*\|\s*([\d.]+)\s*\|$",
                     line)
        if m:
            stats.setdefault(int(m.group(1)), {})[m.group(2)] = [int(m.group(i)) for i in range(3, 7)] + [
                float(m.group(7))]
    if not stats:
        sys.exit("mpi_weak_scaling: no --comm-stats table in radx-engine-mpi's output:\n" + text[-1500:])
    return stats


def per_cycle_stats(a, work, root, model, dt, np_):
    """Per cycle, per kind: the busiest rank's calls, messages, sent, received (bytes), from two runs."""
    runs = []
    for cycles in a.cycles:
        out = os.path.join(work, "np%d_c%d" % (np_, cycles))
        os.makedirs(out)
        deck_dir = os.path.join(out, "deck")
        deck = write_model(a.n, cycles * dt, deck_dir) + "_0001.rad"
        text = run(["mpirun", *MPI_FLAGS, "-np", str(np_), os.path.join(BIN, "radx-engine-mpi"), deck, "--model",
                    model, "--out", out, "--threads", "1", "--no-plot", "--comm-stats"])
        runs.append((summary(out, root)["cycles"], parse_comm_stats(text)))
        if a.keep:
            with open(os.path.join(a.keep, "np%d_c%d.out" % (np_, cycles)), "w") as f:
                f.write(text)
    (c1, s1), (c2, s2) = runs
    if c2 <= c1:
        sys.exit("mpi_weak_scaling: the runs made %d and %d cycles: give --cycles with a larger second count" %
                 (c1, c2))
    kinds = sorted({k for r in s2.values() for k in r if k != "total"})
    result = {}
    for k in kinds:
        best = None
        for rank in s2:
            d = [(s2[rank].get(k, [0] * 5)[i] - s1[rank].get(k, [0] * 5)[i]) / (c2 - c1) for i in range(4)]
            if best is None or d[2] + d[3] > best[2] + best[3]:
                best = d
        result[k] = best
    return result


def domain_traffic(a, work, P):
    """The busiest rank's bytes (sent + received) and messages per cycle of the METIS split at P ranks."""
    n = int(round(math.sqrt(P * a.elements_per_rank / 1.04)))
    out = os.path.join(work, "domain%d" % P)
    os.makedirs(out)
    root = write_model(n, 1e-5, out)
    run([os.path.join(BIN, "radx-starter"), root + "_0000.rad", "--out", out])
    text = run([os.path.join(ROOT, "build", "bench", "radx_bench_domain"), root + "_0000.hdf", str(P)])
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 8 and cells[1] == "metis" and int(cells[0]) == P:
            shutil.rmtree(out)
            return n, model_elements(n), float(cells[6]) * 1e3, int(cells[7])
    sys.exit("mpi_weak_scaling: no METIS row for P = %d in radx_bench_domain's output:\n%s" % (P, text))


def fit(points, e):
    """a + b x through the two (elements per rank, value) points, at e (the value itself when flat)."""
    (x1, y1), (x2, y2) = points
    if x1 == x2:
        return y2
    b = (y2 - y1) / (x2 - x1)
    return max(0.0, y1 + b * (e - x1))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=300,
                    help="model measured at np 2 and 3 (default 300: 93,600 elements, about 100 k)")
    ap.add_argument("--cycles", type=int, nargs=2, default=[20, 40], metavar=("CYCLES1", "CYCLES2"))
    ap.add_argument("--ranks", type=int, nargs="+", default=[16, 64])
    ap.add_argument("--elements-per-rank", type=int, default=100000)
    ap.add_argument("--alpha", type=float, default=1.5e-6, help="latency, s (default 1.5e-6)")
    ap.add_argument("--gbits", type=float, default=100.0, help="bandwidth, Gb/s (default 100)")
    ap.add_argument("--imbalance", type=float, default=1.03, help="heaviest rank's compute over the mean")
    ap.add_argument("--vote-bytes", type=int, default=72, help="bytes of one group's vote record (design rows)")
    ap.add_argument("--no-domain-traffic", action="store_true",
                    help="do not build the P-rank models: scale the measured exchange with the perimeter instead")
    ap.add_argument("--keep", help="keep the runs' outputs in this folder")
    a = ap.parse_args()
    if a.n < 20 or a.cycles[0] < 1 or a.cycles[1] <= a.cycles[0] or min(a.ranks) < 2:
        ap.error("--n >= 20, 0 < CYCLES1 < CYCLES2, --ranks >= 2")
    targets = ["radx-starter", "radx-engine", "radx-engine-mpi"] + ([] if a.no_domain_traffic else ["radx_bench_domain"])
    subprocess.run(["cmake", "--build", os.path.join(ROOT, "build"), "--target", *targets], check=True,
                   stdout=subprocess.DEVNULL)
    if a.keep:
        os.makedirs(a.keep, exist_ok=True)
    alpha, beta = a.alpha, a.gbits * 1e9 / 8
    work = tempfile.mkdtemp()
    try:
        root = write_model(a.n, 20 * 1.7e-4 / a.n, work)  # about 20 steps of the plate's shells
        model = root + "_0000.hdf"
        run([os.path.join(BIN, "radx-starter"), root + "_0000.rad", "--out", work])
        probe = os.path.join(work, "probe")
        os.makedirs(probe)
        run([os.path.join(BIN, "radx-engine"), root + "_0001.rad", "--model", model, "--out", probe, "--threads", "1",
             "--no-plot"])
        s = summary(probe, root)  # its last step is cut to end on Tstop
        dt = s["time"] / (s["cycles"] - 0.5)
        serial = os.path.join(work, "serial")
        os.makedirs(serial)
        deck = write_model(a.n, a.cycles[1] * dt, os.path.join(serial, "deck")) + "_0001.rad"
        run([os.path.join(BIN, "radx-engine"), deck, "--model", model, "--out", serial, "--threads", "1", "--no-plot"])
        us = summary(serial, root)["us_per_element_cycle"]
        elements = model_elements(a.n)
        measured = {np_: per_cycle_stats(a, work, root, model, dt, np_) for np_ in (2, 3)}
        traffic = {} if a.no_domain_traffic else {P: domain_traffic(a, work, P) for P in a.ranks}
    finally:
        shutil.rmtree(work)

    E = a.elements_per_rank
    print("measured on PLATE%dI_NOCONTACT (%d elements): %.4f us per element-cycle (radx-engine --threads 1)"
          % (a.n, elements, us))
    print("network: alpha %.3g us, beta %g Gb/s; %d elements per rank; imbalance %.3f" %
          (alpha * 1e6, a.gbits, E, a.imbalance))
    print()
    print("per cycle, busiest rank (difference of %d- and %d-cycle runs):" % tuple(a.cycles))
    print("| np | collective | calls | messages | bytes sent | bytes received |")
    print("|---:|------------|------:|---------:|-----------:|---------------:|")
    for np_, kinds in measured.items():
        for k, (calls, msgs, sent, recv) in kinds.items():
            if calls == 0:
                continue
            print("| %d | %s | %.2f | %.2f | %.0f | %.0f |" % (np_, k, calls, msgs, sent, recv))
    if traffic:
        print()
        print("domain exchange at P (bench/domain_traffic.cpp, METIS split, busiest rank):")
        for P, (n, el, b, m) in traffic.items():
            print("  P = %d: N = %d, %d elements (%d a rank), %.0f bytes sent + received and %d messages per cycle"
                  % (P, n, el, el // P, b, m))

    # Each kind's per-call contribution (bytes sent a call) as a function of the elements per rank.
    kinds = sorted({k for s in measured.values() for k, v in s.items() if v[0] > 0})

    def contribution(k):
        pts = []
        for np_ in (2, 3):
            calls, _, sent, _ = measured[np_].get(k, [0, 0, 0, 0])
            pts.append((elements / np_, sent / calls if calls else 0.0))
        return pts

    rows = []
    for P in a.ranks:
        L = math.ceil(math.log2(P))
        t_c = us * 1e-6 * E
        times = {}
        for k in kinds:
            calls = max(measured[np_].get(k, [0])[0] for np_ in (2, 3))
            if calls == 0:
                continue
            c = fit(contribution(k), E)
            if k in REDUCTIONS:
                t = L * (alpha + c / beta)
            elif k in ("all_gather", "gather"):
                t = 2 * L * alpha + (P - 1) * c / beta
            elif k == "broadcast":
                t = 2 * L * (alpha + c / beta)
            elif k == "barrier":
                t = L * alpha
            elif k == "exchange":
                sizes = L * (alpha + 4 * P / beta)
                if P in traffic:
                    _, _, b, m = traffic[P]
                    per_call_b, per_call_m = b / calls, m / calls
                else:
                    np_ = 3
                    _, msgs, sent, recv = measured[np_][k]
                    scale = math.sqrt(E / (elements / np_))
                    per_call_b = (sent + recv) / calls * scale
                    per_call_m = msgs / calls
                t = sizes + per_call_m * alpha + per_call_b / beta
            else:
                continue
            times[k] = (calls, c, calls * t)
        t_comm = sum(v[2] for v in times.values())
        rows.append((P, "as measured", t_c, times, t_comm))
        # Design: the node sums' all-gather replaced by the domain exchange (already modelled), votes gathered.
        design = dict(times)
        if "all_gather" in design:
            groups = E / 128.0
            c = groups * a.vote_bytes + 8
            design["all_gather"] = (1, c, 2 * L * alpha + (P - 1) * c / beta)
        rows.append((P, "design", t_c, design, sum(v[2] for v in design.values())))

    print()
    print("model per cycle (times in microseconds; c: bytes a rank contributes per call, at %d elements a rank):" % E)
    print("| P | case | compute | " + " | ".join(kinds) + " | communication | efficiency |")
    print("|--:|------|--------:|" + "|".join("------:" for _ in kinds) + "|--------:|-------:|")
    for P, case, t_c, times, t_comm in rows:
        cells = ["%.1f" % (times[k][2] * 1e6) if k in times else "-" for k in kinds]
        eff = t_c / (a.imbalance * t_c + t_comm)
        print("| %d | %s | %.0f | %s | %.1f | %.3f |" % (P, case, t_c * 1e6, " | ".join(cells), t_comm * 1e6, eff))
    print()
    print("grows with P: all_gather (every rank receives every other rank's contribution: (P - 1) c bytes, today")
    print("every node's sums, 48 B a node), the log2 P steps of every reduction, and the exchange's size all-to-all.")
    print("The domain exchange's bytes a rank stay about constant (its neighbours' boundaries).")


if __name__ == "__main__":
    main()
