#!/usr/bin/env python3
"""Every sample with the solver's defaults: does it still run, and when it does not, does its message point the way?

  check-samples-defaults.py BIN OUT [--travel-cap MM] [SAMPLE…]

Runs each sample of samples/ (or the named ones) with BIN into OUT/<case>/:
  <sample>/no-solver   its `solver` section removed (every solver option at its default)
  <sample>/coulomb     the same with `process.friction: coulomb` (rolling samples only; μ at its default)
A case passes when it ends `converged`, or when its message names a remedy in the project's terms — a smaller
process.travel_increment, more analysis.increments, a tighter solver.cg_tolerance — and the case with that remedy
applied (the step halved, the increments doubled, the tolerance a hundredth) converges. Prints a table, exits 1 when a
case fails. --travel-cap shortens the rolling passes (a 3D pass in 0.5 mm steps takes minutes per 20 mm; the table
says which were shortened). Not part of ctest: the whole set takes tens of minutes.
"""
import argparse
import json
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

# a remedy named in a message, and how to apply it to the project
REMEDIES = [
    (re.compile(r"a smaller process\.travel_increment \(now ([0-9.e+-]+) mm\)"),
     lambda d, v: d["process"].__setitem__("travel_increment", float(v) / 2), "process.travel_increment / 2"),
    (re.compile(r"more analysis\.increments \(now ([0-9]+)\)"),
     lambda d, v: d.setdefault("analysis", {}).__setitem__("increments", 2 * int(v)), "analysis.increments × 2"),
    (re.compile(r"a tighter solver\.cg_tolerance \(now ([0-9.e+-]+)\)"),
     lambda d, v: d.setdefault("solver", {}).__setitem__("cg_tolerance", float(v) / 100),
     "solver.cg_tolerance / 100"),
]


def cases(names, cap):
    out = []
    for f in sorted((ROOT / "samples").glob("*.json")):
        if names and f.stem not in names:
            continue
        d = json.loads(f.read_text())
        d.pop("solver", None)
        for body in d.get("bodies", []):  # the copy runs from a temporary file: a mesh file named from the sample's
            mesh = body.get("mesh", {})    # folder is named absolutely
            if "file" in mesh and not Path(mesh["file"]).is_absolute():
                mesh["file"] = str(f.parent / mesh["file"])
        note = ""
        p = d.get("process")
        if p and cap and p.get("travel", 100) > cap:
            p["travel"] = cap
            note = f"travel {cap:g} mm"
        out.append((f.stem + "/no-solver", d, note))
        if p:
            c = json.loads(json.dumps(d))
            c["process"]["friction"] = "coulomb"
            out.append((f.stem + "/coulomb", c, note))
    return out


def run(binary, project, out):
    out.mkdir(parents=True, exist_ok=True)
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as t:
        json.dump(project, t)
    start = time.time()
    r = subprocess.run([binary, "run", t.name, "--out", str(out), "--quiet"], capture_output=True, text=True)
    Path(t.name).unlink()
    summary = out / "summary.json"
    s = json.loads(summary.read_text()) if summary.exists() else {}
    return s.get("status", f"exit {r.returncode}"), s.get("message", r.stderr.strip()), time.time() - start


def remedy(message):
    for pattern, apply, words in REMEDIES:
        m = pattern.search(message)
        if m:
            return apply, m.group(1), words
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binary")
    ap.add_argument("out", type=Path)
    ap.add_argument("samples", nargs="*")
    ap.add_argument("--travel-cap", type=float, default=0.0)
    a = ap.parse_args()
    rows, failed, total = [], 0, time.time()
    for name, project, note in cases(set(a.samples), a.travel_cap):
        status, message, seconds = run(a.binary, project, a.out / name)
        verdict, then = ("pass", "") if status == "converged" else ("FAIL", "")
        if status != "converged":
            r = remedy(message)
            if r:
                apply, value, words = r
                fixed = json.loads(json.dumps(project))
                apply(fixed, value)
                status2, message2, seconds2 = run(a.binary, fixed, a.out / (name + "-remedy"))
                seconds += seconds2
                then = f"{words}: {status2}"
                verdict = "pass" if status2 == "converged" else "FAIL"
            else:
                then = "no remedy named: " + message[:160]
        failed += verdict != "pass"
        rows.append((name, note, status, then, f"{seconds:.0f}", verdict))
        print(f"| {' | '.join(rows[-1])} |", flush=True)
    print(f"\n| case | shortened | status | remedy named: after it | s | verdict |\n|---|---|---|---|---|---|")
    for row in rows:
        print(f"| {' | '.join(row)} |")
    print(f"\n{len(rows)} cases, {failed} failed, {time.time() - total:.0f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
