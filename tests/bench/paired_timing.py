#!/usr/bin/env python3
"""Paired whole-process timing of two commands, A and B, with public tools only (the benchmark scripts' timer).

A and B run in turn (A B A B ...) after warm-up runs that are not counted; each run's wall time is a monotonic clock
around the child, its CPU time (user + system) and peak memory the operating system's accounting of the reaped child
(os.wait4). Printed: min, median and max of every figure, and of the ratio A/B taken pair by pair (pairing keeps the
ratio meaningful when a shared machine's speed drifts). Quote the medians.

Usage: paired_timing.py [-n RUNS] [--warmup W] --vs 'COMMAND B' -- COMMAND A ...
A command is split as a shell splits words and run without a shell (use sh -c '...' for redirections).
"""
import argparse
import os
import shlex
import statistics
import subprocess
import sys
import time


def run_once(cmd):
    """(wall s, cpu s, peak MiB, exit code) of one run of cmd, its output thrown away."""
    start = time.monotonic()
    child = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.monotonic() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0, child.returncode


def spread(values):
    return min(values), statistics.median(values), max(values)


def paired(cmd_a, cmd_b, runs, warmup=1):
    """The runs of A and B in turn (after `warmup` uncounted pairs): {"A": [...], "B": [...]}, each run_once's."""
    for _ in range(warmup):
        run_once(cmd_a)
        run_once(cmd_b)
    rows = {"A": [], "B": []}
    for _ in range(runs):
        rows["A"].append(run_once(cmd_a))
        rows["B"].append(run_once(cmd_b))
    return rows


def figures(rows):
    """(min, median, max) of every figure by name: "A cpu s", "B peak MiB", ..., and "A/B cpu", "A/B wall" pair by pair."""
    out = {}
    for side in ("A", "B"):
        for name, index in (("wall s", 0), ("cpu s", 1), ("peak MiB", 2)):
            out[f"{side} {name}"] = spread([r[index] for r in rows[side]])
    for name, index in (("cpu", 1), ("wall", 0)):
        out[f"A/B {name}"] = spread([x[index] / y[index] for x, y in zip(rows["A"], rows["B"]) if y[index] > 0])
    return out


def medians(cmd_a, cmd_b, runs, warmup=1):
    """The median of every figure of paired(cmd_a, cmd_b, runs, warmup), by figures()' names."""
    return {name: mid for name, (_, mid, _) in figures(paired(cmd_a, cmd_b, runs, warmup)).items()}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("-n", "--runs", type=int, default=5)
    ap.add_argument("--warmup", type=int, default=1)
    ap.add_argument("--vs", required=True, help="command B, one string")
    ap.add_argument("command", nargs=argparse.REMAINDER, help="-- command A")
    a = ap.parse_args()
    cmd_a = a.command[1:] if a.command[:1] == ["--"] else a.command
    cmd_b = shlex.split(a.vs)
    if not cmd_a:
        ap.error("no command A after --")
    rows = paired(cmd_a, cmd_b, a.runs, a.warmup)
    print(f"{'':18} {'min':>10} {'median':>11} {'max':>11}   n: A {a.runs}, B {a.runs}; whole process")
    for name, (lo, mid, hi) in figures(rows).items():
        digits = 4 if name.startswith("A/B") else 3
        print(f"{name:18} {lo:10.{digits}f} {mid:11.{digits}f} {hi:11.{digits}f}")
    codes = {r[3] for side in rows.values() for r in side}
    if codes != {0}:
        print(f"exit codes: {sorted(codes)}")
    return 0

if __name__ == "__main__":
    sys.exit(main())
