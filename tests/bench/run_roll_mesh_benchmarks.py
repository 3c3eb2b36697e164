#!/usr/bin/env python3
"""A fixed roll against a turning one -> docs/roll-mesh-bench-output.md (docs/BENCHMARKS-ROLLING.md, "A fixed roll").

process.roll_mesh: turning (the roll's mesh turns with its hub: finite kinematics, its tangent assembled anew as it
turns) against fixed (the mesh stays, its surface's material turns through the contact: small kinematics, assembled
and factored once, the slab held to the roll's circle rather than its chords). Each case is a sample as it is, run both
ways: the plane-strain main job (also on finer turning rolls, whose chords come nearer the circle), the plane-strain
ALE window, the 3D pass and a 3D ALE window. Per run: status, force, torque, forward slip, mean spread (3D), Newton
iterations, the roll's factorizations and total_s; then tests/bench/paired_timing.py times each pair whole (--runs
paired runs after a warm-up, medians, peak memory) unless --no-time. Usage:
  tests/bench/run_roll_mesh_benchmarks.py [--rollsim BIN] [--runs N] [--no-time] [--out docs/roll-mesh-bench-output.md]
Builds nothing; it fails only if a run cannot start.
"""
import argparse
import json
import pathlib
import sys
import tempfile

from rolling_runs import paired_projects, run_pass  # beside this script

ROOT = pathlib.Path(__file__).resolve().parents[2]
CASES = [  # name, sample, process fields over the sample's, timed in pairs
    ("2D main job (36 × 6, roll 120)", "rolling-2d-36x6.json", {}, True),
    ("2D main job, roll 240", "rolling-2d-36x6.json", {"roll_n_around": 240}, False),
    ("2D main job, roll 480", "rolling-2d-36x6.json", {"roll_n_around": 480}, False),
    ("2D ALE window (30 × 9, 2.5 mm)", "rolling-2d-ale.json", {}, True),
    ("3D pass (16 × 8 × 4, 0.5 mm)", "rolling-3d-16x8x4.json", {}, True),
    ("3D ALE window (14 × 8 × 4, 1 mm)", "rolling-3d-16x8x4.json",
     {"formulation": "ale", "slab_nx": 14, "travel": 220, "travel_increment": 1, "stop_at_steady_state": True}, True),
]


def project(sample, fields, roll_mesh):
    p = json.loads((ROOT / "samples" / sample).read_text())
    p["process"].update(fields)
    p["process"]["roll_mesh"] = roll_mesh
    p["name"] = f"{pathlib.Path(sample).stem}-{roll_mesh}"
    p["output"] = {"vtu": False}
    return p


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rollsim", default=str(ROOT / "build/app/rollsim"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--no-time", action="store_true")
    ap.add_argument("--out", default=str(ROOT / "docs/roll-mesh-bench-output.md"))
    a = ap.parse_args()
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="roll-mesh-bench-"))
    fmt = lambda v, f: f.format(v) if v is not None else "–"
    lines = ["| case | roll mesh | status | force | torque | forward slip | mean spread [mm] | Newton its | "
             "roll factorizations | run [s] |", "|---|---|---|---|---|---|---|---|---|---|"]
    timing = ["| case | fixed CPU [s] | turning CPU [s] | fixed / turning CPU | wall | peak MiB (fixed / turning) |",
              "|---|---|---|---|---|---|"]
    for name, sample, fields, timed in CASES:
        paths, rows = {}, {}
        for mesh in ("turning", "fixed"):
            p = tmp / f"{len(lines)}-{mesh}.json"
            p.write_text(json.dumps(project(sample, fields, mesh)))
            paths[mesh] = p
            rows[mesh] = run_pass(a.rollsim, p, tmp / p.stem)
            r = rows[mesh]
            lines.append(f"| {name} | {mesh} | {r['status']} | {fmt(r['roll_force'], '{:.6g}')} | "
                         f"{fmt(r['roll_torque'], '{:.6g}')} | "
                         f"{fmt(r['forward_slip'] and 100 * r['forward_slip'], '{:.2f} %')} | "
                         f"{fmt(r['mean_spread'], '{:.3f}')} | {r['newton']} | {fmt(r['roll_factors'], '{}')} | "
                         f"{r['seconds']:.2f} |")
        t, f = rows["turning"], rows["fixed"]
        if t["roll_force"] and f["roll_force"]:
            lines.append(f"| {name} | fixed / turning | | {f['roll_force'] / t['roll_force']:.4f} | "
                         f"{f['roll_torque'] / t['roll_torque']:.4f} | {f['forward_slip'] / t['forward_slip']:.3f} | | "
                         f"{f['newton'] / t['newton']:.3f} | | {f['seconds'] / t['seconds']:.3f} |")
        if timed and not a.no_time:
            g = paired_projects(a.rollsim, paths["fixed"], paths["turning"], a.runs, tmp)
            timing.append(f"| {name} | {g['A cpu s']} | {g['B cpu s']} | {g['A/B cpu']} | {g['A/B wall']} | "
                          f"{g['A peak MiB']} / {g['B peak MiB']} |")
        print(lines[-1], file=sys.stderr)
    text = ("# A fixed roll against a turning one (tests/bench/run_roll_mesh_benchmarks.py)\n\n"
            "Each sample as it is, with process.roll_mesh turning (its default) and fixed; forces and torques are the "
            "samples' reported ones (2D per unit width, N and N·mm; 3D whole slab).\n\n" + "\n".join(lines) + "\n")
    if not a.no_time:
        text += (f"\nWhole runs timed in pairs (tests/bench/paired_timing.py, {a.runs} paired runs after a warm-up, "
                 "medians):\n\n" + "\n".join(timing) + "\n")
    pathlib.Path(a.out).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
