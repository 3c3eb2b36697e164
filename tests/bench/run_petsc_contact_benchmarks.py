#!/usr/bin/env python3
"""Benchmarks of issue 37 (the rolling pass through PETSc: `--petsc-method mumps`) -> docs/petsc-contact-bench-output.md.

Usage: tests/bench/run_petsc_contact_benchmarks.py [--build DIR] [--out FILE] [--ranks LIST] [--repeats N] [--with-3d]
  --build     build directory holding app/rollsim built with -DROLLSIM_WITH_PETSC=ON (default: build)
  --out       the tables (default docs/petsc-contact-bench-output.md; docs/BENCHMARKS-PETSC.md §6 reads them)
  --ranks     MPI ranks of the mumps runs (default 1,2,4,8; above 2 oversubscribed on this 2-core machine)
  --repeats   runs of each 2D case whose median wall time is quoted (default 3)
  --with-3d   also the 3D pass 16 x 8 x 4 (samples/rolling-3d-16x8x4.json: about 10 min per run), on 2 ranks
  --sections  cases,subdomains,weak,weak3d,weaklong,weak3dlong (default: the first three): the three 2D passes, the
              72 x 12 slab in 1-8 subdomains, a slab refined with its subdomains (18 x 12 elements each; weak3d: the
              3D slab, 8 x 8 x 4 each), or made longer with them (weaklong, weak3dlong: the sample's elements)

Each case runs under `direct` in one process (the reference), under the sample's own mode in one process, and under
`mpirun -n N --oversubscribe rollsim run --solver petsc --petsc-method mumps | mixed` for every N (mixed: up to the
number of groups, the most it takes); the tables hold what
summary.json and rolling.csv say: status, Newton iterations, interface CG iterations per Newton iteration, the
factorizations of the busiest and idlest rank (mixed), roll force and torque, the largest relative difference of any
rolling.csv entry from direct's, whether the same output files were written, the median wall time and the largest
peak RSS of any rank (/usr/bin/time -v). A last table tears the 72 x 12 slab into 1-8 subdomains on as many ranks
plus one (the mixed method without and with FETI's Dirichlet preconditioner, and mumps).
Nothing is typed in; timing is not a test: this script fails only if a run fails with an error (a run that diverges is
a row with its status, and the check that failed below the table).
"""
import argparse
import csv
import json
import os
import platform
import re
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")

CASES_2D = [
    ("2D pass, sticking (the main job), 36 x 6", "rolling-2d-36x6.json", [], "mixed"),
    ("2D pass, Coulomb mu 0.35, 0.5 mm steps", "rolling-2d-36x6.json",
     ["--set", "process.friction=coulomb", "--set", "process.friction_coefficient=0.35",
      "--set", "process.travel_increment=0.5"], "mixed"),
    ("2D pass, slab 72 x 12 in 4 subdomains (glue + contact), 10 mm", "rolling-2d-72x12-dd.json", [], "feti"),
]
CASE_3D = ("3D pass 16 x 8 x 4, half width, sticking", "rolling-3d-16x8x4.json", [], "mixed")


def log(*a):
    print("run_petsc_contact_benchmarks:", *a, file=sys.stderr, flush=True)


class Runner:
    def __init__(self, rollsim, work):
        self.rollsim, self.work, self.count = rollsim, work, 0

    def run(self, sample, extra, mode, ranks):
        """`mode` in one process (ranks 0) or `petsc` with petsc_method `mode` under mpirun -n ranks. Returns
        (summary, out dir, wall s, largest peak RSS of a process in MiB)."""
        self.count += 1
        out = os.path.join(self.work, "run%d" % self.count)
        solver = ["--solver", mode] if ranks == 0 else ["--solver", "petsc", "--petsc-method", mode]
        solver += ["--interface-solver", "krylov"]  # the main job's sample forms its interface; over MPI: CG only
        cmd = ["/usr/bin/time", "-v", self.rollsim, "run", os.path.join(ROOT, "samples", sample), *solver, *extra,
               "--out", out, "--quiet"]
        if ranks:
            cmd = ["mpirun", "-n", str(ranks), "--oversubscribe", *cmd]
        t0 = time.time()
        p = subprocess.run(cmd, capture_output=True, text=True)
        wall = time.time() - t0
        if p.returncode not in (0, 4):  # 4: diverged, a result the tables show (with the check that failed)
            log("FAILED:", " ".join(cmd), "\n", p.stderr[-3000:])
            raise SystemExit(1)
        rss = [int(m) / 1024 for m in re.findall(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr)]
        with open(os.path.join(out, "summary.json")) as f:
            return json.load(f), out, wall, max(rss) if rss else float("nan")


def rolling_rows(out):
    with open(os.path.join(out, "rolling.csv")) as f:
        return [[float(v) for v in row] for row in list(csv.reader(f))[1:] if row]


def largest_difference(a, b):
    """max |a - b| over every entry of every column, relative to that column's largest |a| (1 when shapes differ)."""
    if len(a) != len(b) or any(len(x) != len(y) for x, y in zip(a, b)):
        return 1.0
    worst = 0.0
    for c in range(len(a[0]) if a else 0):
        scale = max(abs(row[c]) for row in a)
        if scale > 0:
            worst = max(worst, max(abs(x[c] - y[c]) for x, y in zip(a, b)) / scale)
    return worst


def per_newton(s):
    return s["solver"]["cg_iterations_total"] / max(1, s["solver"]["newton_iterations"])


def rank_factorizations(s):
    """The largest and smallest factorization count of a rank (mixed over MPI), or '' for other runs."""
    per = [r["factorizations"] for r in s["solver"].get("ranks", {}).get("per_rank", [])]
    return "%d / %d" % (max(per), min(per)) if per else ""


def case(runner, lines, title, sample, extra, own_mode, ranks, repeats):
    log(title)
    lines += ["", "### " + title, "",
              "| run | status | Newton iterations | interface CG per Newton iteration | factorizations: rank max / min "
              "| roll force | roll torque | max rel. diff. of rolling.csv | same files | wall s (median of %d) "
              "| peak RSS per rank MiB |" % repeats,
              "|---|---|---|---|---|---|---|---|---|---|---|"]
    ref, groups = None, None
    runs_asked = [("direct", 0), (own_mode, 0)] + [("mumps", n) for n in ranks] + [("mixed", n) for n in ranks]
    for mode, n in runs_asked:
        if mode == "mixed" and n > 0 and n > groups:  # refused: the mixed method gives every rank whole groups
            continue
        runs = [runner.run(sample, extra, mode, n) for _ in range(repeats)]
        s, out, _, rss = runs[0]
        rows, files = rolling_rows(out), sorted(os.listdir(out))
        if ref is None:
            ref = (rows, files)
        if mode == own_mode and n == 0:
            groups = len(s["solver"]["factorizations"])
        roll = s["results"]["rolling"]
        label = "%s, 1 process" % mode if n == 0 else "petsc %s, %d rank%s" % (mode, n, "" if n == 1 else "s")
        lines.append("| %s | %s | %d | %s | %s | %.10g | %.10g | %s | %s | %.2f | %.0f |" % (
            label, s["status"], s["solver"]["newton_iterations"],
            "%.1f" % per_newton(s) if s["solver"]["cg_iterations_total"] else "", rank_factorizations(s),
            roll["roll_force"], roll["roll_torque"],
            "(reference)" if ref[0] is rows else "%.1e" % largest_difference(ref[0], rows),
            "(reference)" if ref[0] is rows else ("yes" if files == ref[1] else "no"),
            statistics.median(r[2] for r in runs), rss))


def subdomains(runner, lines, counts, repeats):
    """The 72 x 12 pass (10 mm) with its slab in P subdomains along the rolling direction, P + 1 ranks (the roll on one
    of them): how the mixed method's interface iterations and each rank's factorizations go as P grows."""
    log("subdomains")
    lines += ["", "### Slab 72 x 12 in P subdomains, P + 1 groups on P + 1 ranks (10 mm of travel)", "",
              "| P | ranks | method | status | Newton iterations | interface CG per Newton iteration "
              "| factorizations: rank max / min | roll force | wall s (median of %d) | peak RSS per rank MiB |" % repeats,
              "|---|---|---|---|---|---|---|---|---|---|"]
    for p in counts:
        extra = ["--set", "process.slab_partition=%dx1" % p]
        for mode, more in (("mixed", []), ("mixed", ["--preconditioner", "dirichlet"]), ("mumps", [])):
            runs = [runner.run("rolling-2d-72x12-dd.json", extra + more, mode, p + 1) for _ in range(repeats)]
            s, _, _, rss = runs[0]
            lines.append("| %d | %d | %s | %s | %d | %s | %s | %.10g | %.2f | %.0f |" % (
                p, p + 1, mode + (", Dirichlet" if more else ""), s["status"], s["solver"]["newton_iterations"],
                "%.1f" % per_newton(s) if s["solver"]["cg_iterations_total"] else "", rank_factorizations(s),
                s["results"]["rolling"]["roll_force"], statistics.median(r[2] for r in runs), rss))


# Weak scaling: the slab refined lengthwise with its subdomains, P + 1 ranks (the roll on one of them). Per family:
# its title, sample, the options for P, and the preconditioner variants run.
WEAK_FAMILIES = {
    "weak": ("Weak scaling: slab 18 P x 12 in P subdomains of 18 x 12, P + 1 ranks (10 mm of travel)",
             "rolling-2d-72x12-dd.json",
             lambda p: ["--set", "process.slab_partition=%dx1" % p, "--set", "process.slab_nx=%d" % (18 * p)],
             ([], ["--preconditioner", "dirichlet"])),
    "weak3d": ("Weak scaling in 3D: slab 8 P x 8 x 4 (half width) in P x 1 x 1 subdomains of 8 x 8 x 4, P + 1 ranks "
               "(2 mm of travel in 0.5 mm steps)",
               "rolling-3d-16x8x4.json",
               lambda p: ["--set", "process.slab_partition=%dx1x1" % p, "--set", "process.slab_nx=%d" % (8 * p),
                          "--set", "process.travel=2"],
               (["--preconditioner", "dirichlet"],)),
    # the slab made longer with its subdomains, its elements as they are: every rank the same subdomain, the contact
    # zone the same pass (the families above refine the slab lengthwise and change the pass with P)
    "weaklong": ("Weak scaling, longer slab: slab 150 P mm long, 36 P x 12 (the sample's elements), in P subdomains "
                 "of 36 x 12, P + 1 ranks (10 mm of travel)",
                 "rolling-2d-72x12-dd.json",
                 lambda p: ["--set", "process.slab_partition=%dx1" % p, "--set", "process.slab_nx=%d" % (36 * p),
                            "--set", "process.slab_length=%d" % (150 * p)],
                 ([], ["--preconditioner", "dirichlet"])),
    "weak3dlong": ("Weak scaling in 3D, longer slab: slab 150 P mm long, 8 P x 8 x 4 (the sample's elements), in "
                   "P x 1 x 1 subdomains of 8 x 8 x 4, P + 1 ranks (2 mm of travel in 0.5 mm steps)",
                   "rolling-3d-16x8x4.json",
                   lambda p: ["--set", "process.slab_partition=%dx1x1" % p, "--set", "process.slab_nx=%d" % (8 * p),
                              "--set", "process.slab_length=%d" % (150 * p), "--set", "process.travel=2"],
                   (["--preconditioner", "dirichlet"],)),
}


def weak(runner, lines, family, counts, repeats):
    """Interface iterations per Newton iteration of the mixed method as the slab and its subdomains grow together."""
    title, sample, options, variants = WEAK_FAMILIES[family]
    log(family)
    lines += ["", "### " + title, "",
              "| P | ranks | dofs | method | status | Newton iterations | interface CG per Newton iteration "
              "| factorizations: rank max / min | roll force | wall s (median of %d) |" % repeats,
              "|---|---|---|---|---|---|---|---|---|---|"]
    failures = []
    for p in counts:
        for more in variants:
            runs = [runner.run(sample, options(p) + more, "mixed", p + 1) for _ in range(repeats)]
            s, _, _, _ = runs[0]
            lines.append("| %d | %d | %d | %s | %s | %d | %s | %s | %.10g | %.2f |" % (
                p, p + 1, s["model"]["dofs"], "mixed" + (", Dirichlet" if more else ""), s["status"],
                s["solver"]["newton_iterations"], "%.1f" % per_newton(s), rank_factorizations(s),
                s.get("results", {}).get("rolling", {}).get("roll_force", float("nan")),
                statistics.median(r[2] for r in runs)))
            if s["status"] != "converged":
                failures.append("P = %d, %s: %s" % (p, "Dirichlet" if more else "no preconditioner", s["message"]))
    lines += [""] + ["- " + f for f in failures]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "petsc-contact-bench-output.md"))
    ap.add_argument("--ranks", default="1,2,4,8")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--with-3d", action="store_true")
    ap.add_argument("--sections", default="cases,subdomains,weak")
    a = ap.parse_args()
    sections = a.sections.split(",")
    ranks = [int(r) for r in a.ranks.split(",")]
    rollsim = os.path.join(a.build, "app", "rollsim")
    version = subprocess.run([rollsim, "--version"], capture_output=True, text=True).stdout.strip()
    lines = ["# `--petsc-method mumps`: the rolling pass through PETSc (output of tests/bench/run_petsc_contact_benchmarks.py)",
             "", "Measured %s on %s (%s, %d cores, load average %s); %s." % (
                 time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), platform.node(), platform.machine(),
                 os.cpu_count(), " ".join("%.2f" % x for x in os.getloadavg()), version)]
    with tempfile.TemporaryDirectory(prefix="petsc-contact-") as work:
        runner = Runner(rollsim, work)
        if "cases" in sections:
            for title, sample, extra, own in CASES_2D:
                case(runner, lines, title, sample, extra, own, ranks, a.repeats)
        if "subdomains" in sections:
            subdomains(runner, lines, [1, 2, 4, 8], a.repeats)
        for family in WEAK_FAMILIES:
            if family in sections:
                weak(runner, lines, family, [1, 2, 4, 8], a.repeats)
        if a.with_3d:
            case(runner, lines, *CASE_3D, [2], 1)
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    log("wrote", a.out)


if __name__ == "__main__":
    main()
