#!/usr/bin/env python3
"""ALE against Lagrangian steady rolling -> docs/ale-bench-output.md (docs/BENCHMARKS-ROLLING.md, "ALE").

The paper's plane-strain pass (samples/rolling-2d-36x6.json: 300 mm roll, 100 -> 86.8 mm, sigma_0 100 MPa, sticking)
on three meshes refined together (slab elements, roll elements, steps), once Lagrangian (the whole 300 mm slab rolled
through the gap) and once ALE (process.formulation: ale, the window's default reach, its columns about as long as the
Lagrangian slab's elements, its steps its own: up to half a column spacing), both ending at their steady state
(process.stop_at_steady_state); one pair sets each formulation's cheapest run whose force is within 1 % of the finest
Lagrangian's side by side. Per run: status, the travel where it became steady, the steady force, torque, forward slip
and exit thickness, the volume balance (ALE: the window's flux out over its flux in - 1), Newton iterations and
total_s. Then tests/bench/paired_timing.py times each pair whole (--runs paired runs, medians, peak memory) unless
--no-time. Usage:
  tests/bench/run_ale_benchmarks.py [--rollsim BIN] [--runs N] [--no-time] [--only-last] [--out docs/ale-bench-output.md]
Builds nothing; it fails only if a run cannot start.
"""
import argparse
import json
import pathlib
import sys
import tempfile

from rolling_runs import paired_projects, run_pass  # beside this script

ROOT = pathlib.Path(__file__).resolve().parents[2]
MESHES = [  # Lagrangian slab, roll elements around, step [mm]; ALE window, roll, step (ALE's steps may be up to half its
    # column spacing: then no node enters the arc). The windows' columns are about as long as the Lagrangian elements.
    ((36, 6), 120, 1.0, (20, 6), 120, 1.0),
    ((36, 6), 120, 1.0, (20, 6), 120, 2.0),
    ((54, 9), 180, 0.75, (30, 9), 180, 1.5),
    ((54, 9), 180, 0.75, (30, 9), 180, 2.5),
    ((72, 12), 240, 0.5, (40, 12), 240, 1.0),
    ((72, 12), 240, 0.5, (40, 12), 240, 2.0),
    ((72, 12), 240, 1.0, (30, 9), 180, 2.5),  # each formulation's cheapest run within 1 % of the finest Lagrangian force
    ((72, 12), 240, 1.0, (40, 12), 240, 1.0),  # the finest mesh in the steps of the coarsest (samples/rolling-2d-ale.json)
]


def project(formulation, n, around, step):
    p = json.loads((ROOT / "samples/rolling-2d-36x6.json").read_text())
    p["name"] = f"{formulation}-{n[0]}x{n[1]}"
    p["process"].update(slab_nx=n[0], slab_nt=n[1], roll_n_around=around, travel_increment=step, travel=150,
                        stop_at_steady_state=True)
    if formulation == "ale":
        p["process"]["formulation"] = "ale"
    p["output"] = {"vtu": False}
    return p


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rollsim", default=str(ROOT / "build/app/rollsim"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--no-time", action="store_true")
    ap.add_argument("--only-last", action="store_true", help="the last mesh only (its rows to add by hand)")
    ap.add_argument("--out", default=str(ROOT / "docs/ale-bench-output.md"))
    a = ap.parse_args()
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="ale-bench-"))
    lines = ["| Lagrangian / ALE: slab, roll around, step | run | status | steady from [mm] | force [N/mm] | torque [kN·m/m] | "
             "forward slip | exit [mm] | volume balance | Newton its | run [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    timing = ["| mesh | ALE CPU [s] | Lagrangian CPU [s] | ALE / Lagrangian CPU | wall | peak MiB (ALE / Lag.) |",
              "|---|---|---|---|---|---|"]
    meshes = MESHES[-1:] if a.only_last else MESHES
    for lag_n, lag_around, lag_step, ale_n, ale_around, ale_step in meshes:
        paths = {}
        rows = {}
        for formulation, n, around, step in (("lagrangian", lag_n, lag_around, lag_step),
                                             ("ale", ale_n, ale_around, ale_step)):
            p = tmp / f"{formulation}-{n[0]}x{n[1]}-{around}-{step:g}.json"
            p.write_text(json.dumps(project(formulation, n, around, step)))
            paths[formulation] = p
            rows[formulation] = run_pass(a.rollsim, p, tmp / p.stem)
        mesh = (f"{lag_n[0]} × {lag_n[1]}, {lag_around}, {lag_step:g} mm / "
                f"{ale_n[0]} × {ale_n[1]}, {ale_around}, {ale_step:g} mm")
        for formulation, r in rows.items():
            fmt = lambda v, f: f.format(v) if v is not None else "–"
            lines.append(f"| {mesh} | {formulation} | {r['status']} | {fmt(r['steady_at'], '{:.1f}')} | "
                         f"{fmt(r['roll_force'], '{:.1f}')} | "
                         f"{fmt(r['roll_torque'] and r['roll_torque'] / 1e3, '{:.1f}')} | "
                         f"{fmt(r['forward_slip'] and 100 * r['forward_slip'], '{:.2f} %')} | "
                         f"{fmt(r['exit_thickness'], '{:.3f}')} | {fmt(r['volume_change'], '{:.1e}')} | "
                         f"{r['newton']} | {r['seconds']:.2f} |")
        l, e = rows["lagrangian"], rows["ale"]
        if l["roll_force"] and e["roll_force"]:
            lines.append(f"| {mesh} | ALE / Lagrangian | | | {e['roll_force'] / l['roll_force']:.4f} | "
                         f"{e['roll_torque'] / l['roll_torque']:.4f} | {e['forward_slip'] / l['forward_slip']:.3f} | "
                         f"{e['exit_thickness'] / l['exit_thickness']:.4f} | | {e['newton'] / l['newton']:.3f} | "
                         f"{e['seconds'] / l['seconds']:.3f} |")
        if not a.no_time:
            t = paired_projects(a.rollsim, paths["ale"], paths["lagrangian"], a.runs, tmp)
            timing.append(f"| {mesh} | {t['A cpu s']} | {t['B cpu s']} | {t['A/B cpu']} | {t['A/B wall']} | "
                          f"{t['A peak MiB']} / {t['B peak MiB']} |")
        print(lines[-1], file=sys.stderr)
    text = ("# ALE against Lagrangian steady rolling (tests/bench/run_ale_benchmarks.py)\n\n"
            "Both formulations end where the pass is steady (process.stop_at_steady_state); the values are the means "
            "over the last window of half a nominal contact length of travel.\n\n" + "\n".join(lines) + "\n")
    if not a.no_time:
        text += (f"\nWhole runs timed in pairs (tests/bench/paired_timing.py, {a.runs} paired runs after a warm-up, medians):\n\n"
                 + "\n".join(timing) + "\n")
    pathlib.Path(a.out).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
