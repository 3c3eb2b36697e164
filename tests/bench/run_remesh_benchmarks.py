#!/usr/bin/env python3
"""Remeshing against each case's own mesh -> the table of docs/VALIDATION.md, "Remeshing".

Every case runs twice, once each (the counts do not depend on the machine; the seconds are one run's): on its own mesh,
and with analysis.remesh_quality (0.5 unless --quality). Reported per run: status, the load factor reached, Newton
iterations, remeshes (and how many moved their nodes), the platen force at the end where the case has one, and the run's
total_s from summary.json. For ratios of CPU time use tests/bench/paired_timing.py on the projects this script leaves in --keep.
Usage: tests/bench/run_remesh_benchmarks.py [--rollsim BIN] [--quality Q] [--only SUBSTRING] [--keep DIR]
Builds nothing; it fails only if a run cannot start.
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
STEEL = {"name": "steel", "E": 200000.0, "nu": 0.3, "yield_stress": 250.0}


def upsetting(n):
    """A 10 × 10 mm block upset 5 mm (50 %) between sticking faces in 50 steps, n × n elements."""
    return {"name": f"upsetting-{n}x{n}", "dimension": 2,
            "materials": [dict(STEEL, hardening_modulus=2000.0)],
            "bodies": [{"name": "block", "material": "steel", "formulation": "bbar", "kinematics": "finite",
                        "mesh": {"type": "block", "nx": n, "ny": n, "lx": 10.0, "ly": 10.0}}],
            "boundary_conditions": [
                {"type": "displacement", "body": "block", "set": "ymin", "ux": 0.0, "uy": 0.0},
                {"type": "displacement", "body": "block", "set": "ymax", "ux": 0.0, "uy": -5.0}],
            "analysis": {"type": "newton", "increments": 50, "max_remeshes": 200},
            "solver": {"mode": "direct"}, "output": {"vtu": False}}


def punch(nx, ny):
    """A flat punch (10 mm half width, E 2e6) pressed 10 mm into a plastic base 50 × 30 on rollers, frictionless."""
    return {"name": f"punch-{nx}x{ny}", "dimension": 2,
            "materials": [dict(STEEL, name="base", hardening_modulus=2000.0),
                          {"name": "punch", "E": 2.0e6, "nu": 0.3}],
            "bodies": [{"name": "base", "material": "base", "formulation": "bbar", "kinematics": "finite",
                        "mesh": {"type": "block", "nx": nx, "ny": ny, "lx": 50.0, "ly": 30.0}},
                       {"name": "punch", "material": "punch", "kinematics": "finite",
                        "mesh": {"type": "block", "nx": 4, "ny": 4, "lx": 10.0, "ly": 8.0, "origin": [0.0, 30.0]}}],
            "contacts": [{"name": "punch-base", "type": "frictionless", "slave_body": "base", "slave_surface": "ymax",
                          "master_body": "punch", "master_surface": "ymin", "search_distance": 5.0,
                          "sliding": "large"}],
            "boundary_conditions": [
                {"type": "displacement", "body": "base", "set": "ymin", "uy": 0.0},
                {"type": "symmetry", "body": "base", "set": "xmin", "normal": "x"},
                {"type": "symmetry", "body": "punch", "set": "xmin", "normal": "x"},
                {"type": "displacement", "body": "punch", "set": "ymax", "ux": 0.0, "uy": -10.0}],
            "analysis": {"type": "newton", "increments": 40},
            "solver": {"mode": "direct"}, "output": {"vtu": False}}


def tension(nx, ny):
    """A plane-strain strip 10 × 40 mm (half model) pulled 14 mm by gripped ends."""
    return {"name": f"tension-{nx}x{ny}", "dimension": 2,
            "materials": [dict(STEEL, hardening_modulus=300.0)],
            "bodies": [{"name": "strip", "material": "steel", "formulation": "bbar", "kinematics": "finite",
                        "mesh": {"type": "block", "nx": nx, "ny": ny, "lx": 5.0, "ly": 20.0}}],
            "boundary_conditions": [
                {"type": "displacement", "body": "strip", "set": "ymin", "uy": 0.0},
                {"type": "displacement", "body": "strip", "set": "xmin", "ux": 0.0},
                {"type": "displacement", "body": "strip", "set": "ymax", "ux": 0.0, "uy": 14.0}],
            "analysis": {"type": "newton", "increments": 70},
            "solver": {"mode": "direct"}, "output": {"vtu": False}}


CASES = [upsetting(20), upsetting(40), upsetting(80), punch(20, 12), punch(40, 24), tension(10, 20), tension(20, 40)]


def run(rollsim, project, folder):
    path = folder / f"{project['name']}.json"
    path.write_text(json.dumps(project, indent=1))
    out = folder / project["name"]
    subprocess.run([rollsim, "run", str(path), "--out", str(out)], stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=False)
    s = json.loads((out / "summary.json").read_text())
    inc = s.get("increments", [])
    remeshes = s.get("remeshes", [])
    moved = sum(1 for m in remeshes if m["nodes"].startswith("moved"))
    force = ""
    for body, sets in (inc[-1].get("reactions", {}) if inc else {}).items():
        if "ymax" in sets and body in ("block", "punch"):
            force = f"{sets['ymax'][1]:.1f}"
    return (f"{s['status']}, {inc[-1]['load_factor']:.3f}" if inc else s["status"],
            sum(i.get("newton_iterations", 0) for i in inc), f"{len(remeshes)} ({moved})", force,
            f"{s['timing']['total_s']:.2f}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rollsim", default=str(ROOT / "build" / "app" / "rollsim"))
    ap.add_argument("--quality", type=float, default=0.5)
    ap.add_argument("--only", default="")
    ap.add_argument("--keep", default="")
    a = ap.parse_args()
    folder = pathlib.Path(a.keep) if a.keep else pathlib.Path(tempfile.mkdtemp(prefix="rollsim-remesh-"))
    folder.mkdir(parents=True, exist_ok=True)
    print("| case | run | status, end | Newton iterations | remeshes (moved) | platen force at the end | total_s |")
    print("|---|---|---|---|---|---|---|")
    for case in CASES:
        if a.only not in case["name"]:
            continue
        remeshed = json.loads(json.dumps(case))
        remeshed["name"] += "-remeshed"
        remeshed["analysis"]["remesh_quality"] = a.quality
        for label, project in (("own mesh", case), ("remeshed", remeshed)):
            row = run(a.rollsim, project, folder)
            print(f"| {case['name']} | {label} | " + " | ".join(str(c) for c in row) + " |", flush=True)
    print(f"(projects and results in {folder})", file=sys.stderr)


if __name__ == "__main__":
    main()
