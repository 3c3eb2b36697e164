#!/usr/bin/env python3
"""The 3D pass's ALE window on meshes refined together -> docs/ale-3d-convergence-output.md (BENCHMARKS-ROLLING.md).

samples/rolling-3d-16x8x4.json as an ALE window on a fixed roll (process.roll_mesh: fixed), each mesh 1.5 times the
one before in every direction — the slab's columns, width and thickness elements, the roll's elements around and
along the barrel —, 1 mm steps, to the steady state by the whole rule (force, torque, the free side's shape). Per
mesh: status, where it became steady, force, torque, mean and widest spread, Newton iterations, CPU and peak memory;
for each three consecutive meshes and each measure, Richardson's observed order p = ln(e1/e2)/ln 1.5 (e1, e2 the
differences of the coarser and the finer pair) and limit f3 + (f3 − f2)/(1.5^p − 1), or why there is none
(differences of opposite signs, or one not smaller than the other: outside the asymptotic range). Wusatowski's spread
and Sims's force of the pass beside them. Usage:
  tests/bench/run_ale_3d_convergence.py [--rollsim BIN] [--meshes N] [--out docs/ale-3d-convergence-output.md]
Builds nothing; it fails only if a run cannot start.
"""
import argparse
import json
import math
import pathlib
import tempfile

from rolling_runs import run_pass  # beside this script

ROOT = pathlib.Path(__file__).resolve().parents[2]
MESHES = [  # slab columns, width, thickness elements; roll around, along the half barrel
    (14, 8, 4, 100, 6),
    (21, 12, 6, 150, 9),
    (32, 18, 9, 225, 14),
    (48, 27, 14, 338, 21),
]
MEASURES = [("roll_force", "force [MN]", 1e-6), ("roll_torque", "torque [kN·m]", 1e-6),
            ("mean_spread", "mean spread [mm]", 1.0), ("spread", "widest spread [mm]", 1.0)]


def project(mesh):
    nx, nw, nt, around, axial = mesh
    p = json.loads((ROOT / "samples/rolling-3d-16x8x4.json").read_text())
    p["name"] = f"ale-{nx}x{nw}x{nt}"
    p["process"].update(formulation="ale", roll_mesh="fixed", slab_nx=nx, slab_nw=nw, slab_nt=nt,
                        roll_n_around=around, roll_n_axial=axial, travel=600, travel_increment=1,
                        stop_at_steady_state=True)
    p["output"] = {"vtu": False}
    return p


def run(rollsim, mesh, tmp):
    path = tmp / f"{mesh[0]}.json"
    path.write_text(json.dumps(project(mesh)))
    return run_pass(rollsim, path, tmp / (path.stem + "-out"))


def richardson(f1, f2, f3, ratio=1.5):
    e1, e2 = f2 - f1, f3 - f2
    if e1 == 0 or e2 == 0 or e1 * e2 < 0:
        return "differences of opposite signs: not in the asymptotic range"
    if abs(e2) >= abs(e1):
        return "the finer difference is not the smaller: not in the asymptotic range"
    p = math.log(abs(e1) / abs(e2)) / math.log(ratio)
    if p < 0.5:
        return f"order {p:.2f}: the differences barely shrink, no limit"
    limit = f"order {p:.2f}, limit {f3 + e2 / (ratio ** p - 1):.5g}"
    return limit + (" (an order this high is pre-asymptotic: not to be trusted)" if p > 4 else "")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rollsim", default=str(ROOT / "build/app/rollsim"))
    ap.add_argument("--meshes", type=int, default=len(MESHES))
    ap.add_argument("--out", default=str(ROOT / "docs/ale-3d-convergence-output.md"))
    a = ap.parse_args()
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="ale-3d-"))
    rows = []
    lines = ["| window (roll) | status | steady at [mm] | " + " | ".join(label for _, label, _ in MEASURES) +
             " | Newton its | CPU [s] | peak MiB |", "|---" * (len(MEASURES) + 6) + "|"]
    for mesh in MESHES[:a.meshes]:
        r = run(a.rollsim, mesh, tmp)
        rows.append(r)
        values = " | ".join(f"{r[k] * scale:.5g}" if r[k] is not None else "–" for k, _, scale in MEASURES)
        lines.append(f"| {mesh[0]} × {mesh[1]} × {mesh[2]} ({mesh[3]} × 3 × {mesh[4]}) | {r['status']} | "
                     f"{'%.4g' % r['steady_at'] if r['steady_at'] is not None else '–'} | {values} | {r['newton']} | "
                     f"{r['cpu']:.1f} | {r['peak']:.0f} |")
        print(lines[-1], flush=True)
    extrapolated = ["| measure | meshes | Richardson (ratio 1.5) |", "|---|---|---|"]
    for k, label, scale in MEASURES:
        for i in range(len(rows) - 2):
            f = [rows[i + j][k] for j in range(3)]
            if None in f:
                continue
            extrapolated.append(f"| {label} | {MESHES[i][0]}, {MESHES[i + 1][0]}, {MESHES[i + 2][0]} columns | "
                                f"{richardson(*(v * scale for v in f))} |")
    theory = rows[-1]["theory"] if rows else {}
    text = ("# The 3D pass's ALE window refined (tests/bench/run_ale_3d_convergence.py)\n\n"
            "A fixed roll, 1 mm steps, each mesh 1.5 times the one before in every direction; the means from the "
            "steady state on. Wusatowski's spread of the pass: "
            f"{theory.get('wusatowski_spread', float('nan')):.3f} mm; Sims's force: "
            f"{theory.get('sims_roll_force', float('nan')) * 1e-6:.3f} MN.\n\n" + "\n".join(lines) + "\n\n" +
            "\n".join(extrapolated) + "\n")
    pathlib.Path(a.out).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
