#!/usr/bin/env python3
"""Behaviour unchanged, checked: every sample's summary.json before and after a change, value by value.

  compare_summaries.py run BIN OUT [CASE…] run every sample (and a few solver variants of the main job) with BIN into
                                          OUT/<case>/, one thread, long passes shortened (CASES below)
  compare_summaries.py compare OLD NEW    compare OUT folders of two runs: every summary.json value equal to the last
                                          digit, except what measures the machine (times, rates, memory, the BLAS's
                                          name), and every CSV byte for byte — exit 1 and the differing paths when any
                                          differs (keys only the new run writes are listed, not counted)

A refactoring is run as: build the commit before, `run` into A; build after, `run` into B; `compare A B`. The
shortening is the same on both sides, so the comparison is exact; it only keeps the whole set within minutes.
"""
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

# keys whose values measure the machine or the moment, not the computation (compared by presence only)
MACHINE_KEYS = {"timing", "blas", "dgemm_peak_gflops", "peak_probe_s", "factor_gflops", "factor_peak_fraction",
                "choice_s", "memory", "peak_memory_mb", "seconds", "wall_s", "cpu_s", "total_s", "time_s",
                "run"}  # run: which run made the results (its start, command, pid, host)


def cases():
    """(name, sample file, edits of the JSON): every sample, long ones shortened, and solver variants of the main
    job so that every option word is read through the code being changed."""
    out = []
    for f in sorted((ROOT / "samples").glob("*.json")):
        d = json.loads(f.read_text())
        edits = {}
        p = d.get("process")
        if p and d["dimension"] == 3:  # a 3D pass: its first four increments (the 2D ones run whole)
            edits["process.travel"] = 4 * p.get("travel_increment", 1)
        if p and f.stem == "rolling-3d-24x12x8":  # feti on the finest 3D slab: one increment is 4-5 CPU min
            edits["process.travel"] = p.get("travel_increment", 1)
        if p and f.stem == "rolling-2d-140x25":
            edits["process.travel"] = 3
        if f.stem == "necking-bar-3d":
            edits["analysis.increments"] = 35
        out.append((f.stem, f, edits))
    main = ROOT / "samples" / "rolling-2d-36x6.json"
    short = {"process.travel": 20}
    variants = {
        "direct-always": {"solver.mode": "direct", "solver.update": "always"},
        "mixed-dense": {"solver.interface_solver": "dense"},
        "mixed-previous": {"solver.interface_start": "previous", "solver.update": "selective:0.05"},
        "feti-dirichlet": {"solver.mode": "feti", "process.slab_partition": "2x1",
                           "solver.preconditioner": "dirichlet", "solver.projector": "preconditioner"},
        "feti-lumped-redundant": {"solver.mode": "feti", "process.slab_partition": "3x1",
                                  "solver.preconditioner": "lumped", "solver.multipliers": "redundant"},
        "skyline": {"solver.mode": "skyline", "solver.update": "always"},
        "rigid-coulomb": {"process.roll": "rigid", "process.friction": "coulomb", "process.friction_coefficient": 0.4,
                          "analysis.first_tangent": "fresh", "analysis.line_search": False},
    }
    for name, v in variants.items():
        out.append(("rolling-2d-36x6-" + name, main, {**short, **v}))
    return out


def edited(sample, edits):
    d = json.loads(Path(sample).read_text())
    for path, value in edits.items():
        node = d
        keys = path.split(".")
        for k in keys[:-1]:
            node = node.setdefault(k, {})
        node[keys[-1]] = value
    return d


def run(binary, out, only=None):
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    failed = 0
    for name, sample, edits in cases():
        if only and name not in only:
            continue
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as tmp:
            json.dump(edited(sample, edits), tmp)
        start = time.time()
        r = subprocess.run([binary, "run", tmp.name, "--out", str(out / name), "--threads", "1", "--quiet"],
                           capture_output=True, text=True, timeout=1800)
        os.unlink(tmp.name)
        (out / name).mkdir(exist_ok=True)
        (out / name / "exit_code").write_text(f"{r.returncode}\n{r.stderr}")
        print(f"{name:45s} exit {r.returncode}  {time.time() - start:6.1f} s", flush=True)
        failed += r.returncode not in (0, 2, 3, 4, 6)  # a refusal or a failure is compared like a result
    return 1 if failed else 0


def differences(a, b, path=""):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            p = f"{path}.{k}" if path else k
            if k not in a and k in b:
                yield f"+{p}"  # a key the new run adds: listed, not a difference
            elif k not in b:
                yield f"{p}: only in old"
            elif k not in MACHINE_KEYS:
                yield from differences(a[k], b[k], p)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            yield f"{path}: {len(a)} items, now {len(b)}"
        for i, (x, y) in enumerate(zip(a, b)):
            yield from differences(x, y, f"{path}[{i}]")
    elif a != b:
        yield f"{path}: {a!r} -> {b!r}"


def compare(old, new):
    old, new = Path(old), Path(new)
    bad = 0
    compared = 0
    added = {}
    tables = 0
    for case in sorted(p.name for p in old.iterdir() if p.is_dir()):
        for f in ("exit_code", "summary.json"):
            a, b = old / case / f, new / case / f
            if not a.exists():
                continue
            if not b.exists():
                print(f"{case}/{f}: missing in {new}")
                bad += 1
                continue
            if f == "exit_code":
                ca, cb = a.read_text().split("\n")[0], b.read_text().split("\n")[0]
                if ca != cb:
                    print(f"{case}: exit code {ca} -> {cb}")
                    bad += 1
                continue
            found = list(differences(json.loads(a.read_text()), json.loads(b.read_text())))
            diffs = [d for d in found if not d.startswith("+")]
            for d in found:
                if d.startswith("+"):
                    added[d[1:]] = added.get(d[1:], 0) + 1
            compared += 1
            for d in diffs[:20]:
                print(f"{case}: {d}")
            bad += bool(diffs)
        for table in sorted((old / case).glob("*.csv")):  # convergence.csv and a process's tables, byte for byte
            other = new / case / table.name
            tables += 1
            if not other.exists() or other.read_bytes() != table.read_bytes():
                print(f"{case}/{table.name}: {'missing' if not other.exists() else 'differs'} in {new}")
                bad += 1
    for key, n in sorted(added.items()):
        print(f"added: {key} (in {n} summaries)")
    print(f"{compared} summaries and {tables} CSV files compared, {bad} differ")
    return 1 if bad or compared == 0 else 0


if __name__ == "__main__":
    if len(sys.argv) >= 4 and sys.argv[1] == "run":  # trailing case names: only those
        sys.exit(run(sys.argv[2], sys.argv[3], sys.argv[4:]))
    if len(sys.argv) == 4 and sys.argv[1] == "compare":
        sys.exit(compare(sys.argv[2], sys.argv[3]))
    print(__doc__)
    sys.exit(2)
