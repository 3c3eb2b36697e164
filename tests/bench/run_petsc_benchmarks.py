#!/usr/bin/env python3
"""Benchmarks of issue 15 (solver `petsc`) -> docs/petsc-bench-output.md, the tables docs/BENCHMARKS-PETSC.md reads.

Usage: tests/bench/run_petsc_benchmarks.py [--build DIR] [--out FILE] [--sections LIST] [--memory-cube N]
  --build        build directory holding app/rollsim built with -DROLLSIM_WITH_PETSC=ON (default: build)
  --out          the tables (default docs/petsc-bench-output.md; docs/BENCHMARKS-PETSC.md discusses them)
  --sections     agreement,iterations,weak,memory,newton (default: all five)
  --repeats      runs of each newton case whose median wall time is quoted (default 3)
  --memory-cube  elements per side of the 3D cube of the peak-memory runs (default 32)

Every number is measured by running `rollsim run` (under `mpirun -n P --oversubscribe` for `petsc`) and reading its
summary.json and result.vtu; nothing is typed in. Timing is not a test: this script fails only if a run fails.
Needs mpirun, /usr/bin/time and python3 (standard library only).
"""
import argparse
import base64
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")


def log(*a):
    print("run_petsc_benchmarks:", *a, file=sys.stderr, flush=True)


class Runner:
    def __init__(self, rollsim, work):
        self.rollsim, self.work, self.count = rollsim, work, 0

    def run(self, project, solver, ranks=1, extra=(), memory=False):
        """Runs rollsim; returns (summary, out dir, wall seconds, peak RSS per process in MiB)."""
        self.count += 1
        out = os.path.join(self.work, "run%d" % self.count)
        cmd = [self.rollsim, "run", project, "--solver", solver, "--out", out, "--quiet", *extra]
        if memory:
            cmd = ["/usr/bin/time", "-v", *cmd]
        if solver == "petsc":
            cmd = ["mpirun", "-n", str(ranks), "--oversubscribe", *cmd]
        t0 = time.time()
        p = subprocess.run(cmd, capture_output=True, text=True)
        wall = time.time() - t0
        if p.returncode != 0:
            log("FAILED:", " ".join(cmd), "\n", p.stderr[-3000:])
            raise SystemExit(1)
        rss = [int(m) / 1024 for m in re.findall(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr)]
        with open(os.path.join(out, "summary.json")) as f:
            return json.load(f), out, wall, rss


def vtu_displacement(path):
    """The point array 'displacement' of a VTU written by vtkio (appended data, raw or base64, no compression)."""
    data = open(path, "rb").read()
    head_end = data.index(b"<AppendedData")
    head = data[:head_end].decode()
    m = re.search(r'<DataArray[^>]*Name="displacement"[^>]*>', head)
    tag = m.group(0)
    offset = int(re.search(r'offset="(\d+)"', tag).group(1))
    dtype = re.search(r'type="(\w+)"', tag).group(1)
    header = re.search(r'header_type="(\w+)"', head)
    hsize = 8 if header and header.group(1) == "UInt64" else 4
    app = data[head_end:]
    encoding = re.search(rb'encoding="(\w+)"', app).group(1)
    start = app.index(b"_") + 1
    fmt = {"Float64": ("d", 8), "Float32": ("f", 4)}[dtype]
    if encoding == b"raw":
        blob = app[start + offset:]
        n = struct.unpack("<Q" if hsize == 8 else "<I", blob[:hsize])[0]
        return struct.unpack("<%d%s" % (n // fmt[1], fmt[0]), blob[hsize:hsize + n])
    text = app[start + offset:].split(b"<", 1)[0].strip()
    raw = base64.b64decode(text[: ((hsize + 2) // 3) * 4])
    n = struct.unpack("<Q" if hsize == 8 else "<I", raw[:hsize])[0]
    blob = base64.b64decode(text)
    return struct.unpack("<%d%s" % (n // fmt[1], fmt[0]), blob[hsize:hsize + n])


def max_rel_diff(a, b):
    scale = max(abs(x) for x in a)
    return max(abs(x - y) for x, y in zip(a, b)) / scale


def write_project(work, sample, name, mesh):
    with open(os.path.join(ROOT, sample)) as f:
        j = json.load(f)
    j["name"] = name
    body = j["bodies"][0]
    old = [body["mesh"].get(k) for k in ("lx", "ly", "lz")]
    body["mesh"].update(mesh)
    new = [body["mesh"].get(k) for k in ("lx", "ly", "lz")]
    for ns in body.get("node_sets", []):  # the sets' points and boxes move with the lengths
        for key in ("nearest", "box_min", "box_max"):
            if key in ns:
                ns[key] = [x * (n / o if o else 1.0) for x, o, n in zip(ns[key], old, new)]
    j.pop("probes", None)
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(j, f)
    return path


def its(summary):
    return summary["solver"]["cg_iterations_total"]


def agreement(r, lines):
    lines += ["## 1. Same displacements as `direct` on every linear contact-free sample", "",
              "max |u_petsc − u_direct| / max |u_direct| over every node of result.vtu, `--cg-tolerance 1e-8` (PETSc's "
              "rtol), P = 1, 2, 4, 8 ranks, one subdomain per rank. Partitions: structured along the long side(s); "
              "the plate with a hole by METIS (`metis:P`). The contact samples (tied and frictionless) and the "
              "Newton samples are refused (exit 2) and not listed.", "",
              "| sample | P | partition | dofs | BDDC its | BDDC max diff | FETI-DP its | FETI-DP max diff |",
              "|---|---|---|---|---|---|---|---|"]
    samples = [("samples/cantilever-2d-120x120.json", ["1x1", "2x1", "2x2", "4x2"]),
               ("samples/cantilever-2d-240x60.json", ["1x1", "2x1", "4x1", "8x1"]),
               ("samples/plate-hole-2d.json", ["1x1", "metis:2", "metis:4", "metis:8"]),
               ("samples/cantilever-3d-16x16x16.json", ["1x1x1", "2x1x1", "2x2x1", "2x2x2"]),
               ("samples/cantilever-3d-32x16x8.json", ["1x1x1", "2x1x1", "4x1x1", "4x2x1"])]
    worst = 0
    for sample, parts in samples:
        path = os.path.join(ROOT, sample)
        direct, dout, _, _ = r.run(path, "direct")
        u0 = vtu_displacement(os.path.join(dout, "result.vtu"))
        for P, part in zip([1, 2, 4, 8], parts):
            row = [os.path.basename(sample)[:-5], str(P), part, str(direct["model"]["dofs"])]
            for method in ["bddc", "fetidp"]:
                s, out, _, _ = r.run(path, "petsc", P, ["--partition", part, "--petsc-method", method,
                                                        "--cg-tolerance", "1e-8"])
                d = max_rel_diff(u0, vtu_displacement(os.path.join(out, "result.vtu")))
                worst = max(worst, d)
                row += [str(its(s)), "%.1e" % d]
            lines.append("| " + " | ".join(row) + " |")
            log("agreement", row)
    lines += ["", "Largest difference over every sample, P and method: **%.1e**." % worst, ""]


def iterations(r, lines):
    lines += ["## 2. Iterations beside our FETI (same mesh, same partition, relative tolerance 1e-6)", "",
              "Ours: `--solver feti --preconditioner none|lumped|dirichlet --cg-tolerance 1e-6` (projected CG on the "
              "non-redundant glue multipliers, the relative residual of the interface problem). PETSc: `--solver "
              "petsc --cg-tolerance 1e-6` — BDDC: CG on the whole problem, PCBDDC with its defaults (vertices, "
              "edges and, in 3D, faces as primal constraints; the rigid-body near-null space adds rotations on them; "
              "exact local solves); FETI-DP: KSPFETIDP, CG on the multipliers with the Dirichlet preconditioner and "
              "the inner BDDC's primal space as coarse space. PETSc's CG checks the preconditioned residual norm. "
              "Time: wall time of the whole `rollsim run` (mpirun start-up included for petsc), 2 cores; P > 2 "
              "ranks are oversubscribed.", "",
              "| mesh | partition | P | feti none | feti lumped | feti dirichlet | PETSc BDDC | PETSc FETI-DP | "
              "dirichlet / FETI-DP | wall s: feti dirichlet / BDDC / FETI-DP |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    cases = [("samples/cantilever-2d-120x120.json", "cantilever 2D 120×120", {}, ["2x2", "3x3", "4x4", "6x6", "8x8"]),
             ("tests/bench/data/cantilever-3d-24x24x24.json", "cantilever 3D 24×24×24", {}, ["2x2x2", "3x3x3"])]
    for sample, label, mesh, parts in cases:
        path = os.path.join(ROOT, sample)
        for part in parts:
            P = 1
            for k in re.findall(r"\d+", part):
                P *= int(k)
            row = [label, part, str(P)]
            feti = {}
            for pre in ["none", "lumped", "dirichlet"]:
                s, _, wall, _ = r.run(path, "feti", 1, ["--partition", part, "--preconditioner", pre,
                                                        "--cg-tolerance", "1e-6"])
                feti[pre] = (its(s), wall)
                row.append(str(its(s)))
            petsc = {}
            for method in ["bddc", "fetidp"]:
                s, _, wall, _ = r.run(path, "petsc", P, ["--partition", part, "--petsc-method", method,
                                                         "--cg-tolerance", "1e-6"])
                petsc[method] = (its(s), wall)
                row.append(str(its(s)))
            row.append("%.2f" % (feti["dirichlet"][0] / max(petsc["fetidp"][0], 1)))
            row.append("%.2f / %.2f / %.2f" % (feti["dirichlet"][1], petsc["bddc"][1], petsc["fetidp"][1]))
            lines.append("| " + " | ".join(row) + " |")
            log("iterations", row)
    lines.append("")


def weak(r, work, lines):
    lines += ["## 3. Weak scaling (fixed subdomain size, P growing)", "",
              "Every subdomain 40×40 Q4 elements (2D cantilever, 120 long per 120 high scaled with the mesh: unit "
              "elements) or 12×12×12 H8 (3D); `--cg-tolerance 1e-6`. Time: `solve s` is the strategy's set-up "
              "(MATIS, BDDC / FETI-DP set-up with the local factorizations and the coarse problem) plus its solves, "
              "from summary.json (rank 0); `wall s` the whole `mpirun … rollsim run`. **This machine has 2 cores: "
              "every P > 2 is oversubscribed** (P processes share 2 cores), so the times above P = 2 grow about "
              "like P/2 by construction and say nothing about scaling; the iteration counts do.", "",
              "| dim | P | partition | elements | dofs | BDDC its | BDDC solve s | BDDC wall s | FETI-DP its | "
              "FETI-DP solve s | FETI-DP wall s |",
              "|---|---|---|---|---|---|---|---|---|---|---|"]
    cases2 = [(1, 1), (2, 1), (2, 2), (4, 2), (4, 4)]
    cases3 = [(1, 1, 1), (2, 1, 1), (2, 2, 1), (2, 2, 2)]
    for case in cases2 + cases3:
        dim = len(case)
        n = 40 if dim == 2 else 12
        mesh = {"nx": case[0] * n, "ny": case[1] * n, "lx": float(case[0] * n), "ly": float(case[1] * n)}
        sample = "samples/cantilever-2d-120x120.json"
        if dim == 3:
            mesh.update({"nz": case[2] * n, "lz": float(case[2] * n)})
            sample = "tests/bench/data/cantilever-3d-24x24x24.json"
        part = "x".join(str(c) for c in case)
        P = 1
        for c in case:
            P *= c
        path = write_project(work, sample, "weak-%s" % part, mesh)
        row = ["%dD" % dim, str(P), part, "×".join(str(c * n) for c in case)]
        for method in ["bddc", "fetidp"]:
            s, _, wall, _ = r.run(path, "petsc", P, ["--partition", part, "--petsc-method", method,
                                                     "--cg-tolerance", "1e-6"])
            if len(row) == 4:
                row.append(str(s["model"]["dofs"]))
            t = s["timing"]
            row += [str(its(s)), "%.2f" % (t.get("factorize_s", 0) + t.get("solve_s", 0)), "%.2f" % wall]
        lines.append("| " + " | ".join(row) + " |")
        log("weak", row)
    lines.append("")


def memory(r, work, cube, lines):
    lines += ["## 4. Peak memory per rank against `direct`", "",
              "The 3D cantilever cube %d×%d×%d (H8), `/usr/bin/time -v` around every process (Maximum resident set "
              "size). Every petsc rank also holds the whole mesh model (each rank parses the project and builds the "
              "mesh model; it assembles only its own subdomain)." % (cube, cube, cube), "",
              "| run | P | dofs | peak RSS per process MiB (min – max) | sum over ranks MiB | wall s |",
              "|---|---|---|---|---|---|"]
    path = write_project(work, "tests/bench/data/cantilever-3d-24x24x24.json", "memory-cube",
                         {"nx": cube, "ny": cube, "nz": cube, "lx": float(cube), "ly": float(cube),
                          "lz": float(cube)})
    s, _, wall, rss = r.run(path, "direct", 1, [], memory=True)
    lines.append("| direct (CHOLMOD) | 1 | %d | %.0f | %.0f | %.1f |" % (s["model"]["dofs"], rss[0], rss[0], wall))
    for part, P in [("2x2x2", 8)]:
        for method in ["bddc", "fetidp"]:
            s, _, wall, rss = r.run(path, "petsc", P, ["--partition", part, "--petsc-method", method,
                                                       "--cg-tolerance", "1e-6"], memory=True)
            lines.append("| petsc %s %s | %d | %d | %.0f – %.0f | %.0f | %.1f |" % (
                method, part, P, s["model"]["dofs"], min(rss), max(rss), sum(rss), wall))
            log("memory", method, rss)
    lines.append("")


def reactions(summary):
    return [v for body in summary["results"]["reactions"].values() for vec in body.values() for v in vec]


def newton(r, work, repeats, lines):
    lines += ["## 5. Inside the Newton driver (a J2-plastic cantilever, no contact)", "",
              "`samples/cantilever-plastic-2d.json` (plane strain, B-bar, E 200000, σ_y 250, H 2000, the free end "
              "pushed down 0.5 = 6× the first-yield deflection in 10 increments) and the same beam with twice the "
              "elements each way. `direct` (CHOLMOD) on one process against `--solver petsc` (BDDC, "
              "`--cg-tolerance 1e-10`) on P = 1, 2, 4 ranks, one subdomain each, update policy `always`. Every "
              "rank runs the Newton driver; each assembles its own subdomain's tangent; PETSc solves. "
              "*Newton its*: the iterations of each increment (summary.json); *Krylov its*: PETSc's CG iterations "
              "over the run and per linear solve; *max diff*: max |u − u_direct| / max |u_direct| over every node, "
              "and the same for every reaction component. *time / direct*: median wall time of %d runs of the "
              "whole `rollsim run` (mpirun start-up included) over direct's median. **P = 4 runs 4 processes on "
              "2 cores (oversubscribed)**, P = 2 shares them with the machine's other jobs." % repeats, "",
              "| mesh | P | partition | Newton its per increment | same as direct | Krylov its (per solve) | "
              "max diff u | max diff reactions | time / direct |",
              "|---|---|---|---|---|---|---|---|---|"]

    def median_run(path, solver, ranks, extra):
        runs = [r.run(path, solver, ranks, extra) for _ in range(repeats)]
        walls = sorted(x[2] for x in runs)
        return runs[0][0], runs[0][1], walls[len(walls) // 2]

    for label, mesh in [("80×16", {}), ("160×32", {"nx": 160, "ny": 32})]:
        path = os.path.join(ROOT, "samples/cantilever-plastic-2d.json")
        if mesh:
            path = write_project(work, "samples/cantilever-plastic-2d.json", "plastic-" + label, mesh)
        d, dout, dwall = median_run(path, "direct", 1, [])
        dits = [inc["newton_iterations"] for inc in d["increments"]]
        u0 = vtu_displacement(os.path.join(dout, "result.vtu"))
        lines.append("| %s | direct | – | %s | – | – | – | – | 1 (%.2f s) |" % (label, " ".join(map(str, dits)), dwall))
        for P, part in [(1, "1x1"), (2, "2x1"), (4, "2x2")]:
            s, out, wall = median_run(path, "petsc", P, ["--partition", part, "--cg-tolerance", "1e-10"])
            sits = [inc["newton_iterations"] for inc in s["increments"]]
            same = len(sits) == len(dits) and all(abs(a - b) <= 1 for a, b in zip(sits, dits))
            solves = s["solver"]["newton_iterations"]
            du = max_rel_diff(u0, vtu_displacement(os.path.join(out, "result.vtu")))
            dr = max_rel_diff(reactions(d), reactions(s))
            row = [label, str(P), part, " ".join(map(str, sits)),
                   ("yes" if sits == dits else "±1") if same else "**no**",
                   "%d (%.1f)" % (its(s), its(s) / max(solves, 1)), "%.1e" % du, "%.1e" % dr, "%.2f" % (wall / dwall)]
            lines.append("| " + " | ".join(row) + " |")
            log("newton", row)
    lines.append("")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "petsc-bench-output.md"))
    ap.add_argument("--sections", default="agreement,iterations,weak,memory,newton")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--memory-cube", type=int, default=32)
    a = ap.parse_args()
    rollsim = os.path.join(os.path.abspath(a.build), "app", "rollsim")
    for tool in [rollsim, shutil.which("mpirun"), "/usr/bin/time"]:
        if not tool or not os.path.exists(tool):
            log("missing", tool)
            return 2
    work = tempfile.mkdtemp(prefix="rollsim-petsc-bench-")
    r = Runner(rollsim, work)
    start = time.time()
    load0 = open("/proc/loadavg").read().split()[:3]
    body = []
    sections = a.sections.split(",")
    if "agreement" in sections:
        agreement(r, body)
    if "iterations" in sections:
        iterations(r, body)
    if "weak" in sections:
        weak(r, work, body)
    if "memory" in sections:
        memory(r, work, a.memory_cube, body)
    if "newton" in sections:
        newton(r, work, a.repeats, body)
    load1 = open("/proc/loadavg").read().split()[:3]
    version = subprocess.run([rollsim, "--version"], capture_output=True, text=True).stdout.strip().splitlines()
    petsc = subprocess.run(["pkg-config", "--modversion", "PETSc"], capture_output=True, text=True).stdout.strip()
    mpi = subprocess.run(["mpirun", "--version"], capture_output=True, text=True).stdout.strip().splitlines()[0]
    head = ["# PETSc benchmarks (issue 15: `--solver petsc`, BDDC and FETI-DP over MPI)", "",
            "Generated by `tests/bench/run_petsc_benchmarks.py` — do not edit the tables by hand. To regenerate "
            "(after `scripts/build.sh` with PETSc installed):", "",
            "    tests/bench/run_petsc_benchmarks.py --build build", "",
            "- Date: %s. Bench time: %.1f min, %d runs." % (time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
                                                         (time.time() - start) / 60, r.count),
            "- Machine: %d cores, shared with other jobs: load average %s at the start, %s at the end. "
            "Ranks beyond 2 are oversubscribed (`mpirun --oversubscribe`)." % (os.cpu_count(), " ".join(load0),
                                                                              " ".join(load1)),
            "- %s; PETSc %s (Debian libpetsc-real-dev); %s." % (", ".join(version), petsc, mpi), ""]
    with open(a.out, "w") as f:
        f.write("\n".join(head + body) + "\n")
    shutil.rmtree(work, ignore_errors=True)
    log("wrote", a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
