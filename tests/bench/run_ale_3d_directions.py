#!/usr/bin/env python3
"""What each discretisation choice of the 3D ALE window moves -> docs/ale-3d-directions-output.md.

samples/rolling-3d-ale.json (columns 10 mm apart over the arc growing by 1.3 away from it, 8 x 4 elements across the
half width and half thickness, a fixed roll of 100 x 3 x 6, 1 mm steps, to the steady state by the whole rule) and the
same window with one choice changed at a time: the columns halved, the thickness or width elements doubled, the roll
refined by 1.5, the steps halved, the zone before the arc doubled (the arc's spacing kept), the zones' columns
uniform. Per run: status, steady travel, force, torque, mean and widest spread, and each one's change against the
sample in per cent, Newton iterations, CPU and peak memory of the run (its own rusage). Usage:
  tests/bench/run_ale_3d_directions.py [--rollsim BIN] [--out docs/ale-3d-directions-output.md]
Builds nothing; it fails only if a run cannot start.
"""
import argparse
import json
import pathlib
import tempfile

from rolling_runs import run_pass  # beside this script

ROOT = pathlib.Path(__file__).resolve().parents[2]
ARC = (300 * 13.2) ** 0.5  # the nominal contact length √(R Δh) [mm]
VARIANTS = [  # name, process fields changed from the sample's
    ("the sample", {}),
    ("columns halved (56)", {"slab_nx": 56}),
    ("thickness elements doubled (8)", {"slab_nt": 8}),
    ("width elements doubled (16)", {"slab_nw": 16}),
    ("roll refined by 1.5 (150 x 3 x 9)", {"roll_n_around": 150, "roll_n_axial": 9}),
    ("steps halved (0.5 mm)", {"travel_increment": 0.5}),
    ("zone before the arc 200 mm (36 columns)", {"ale_entry_length": ARC + 200, "slab_nx": 36}),
    ("zones uniform (ale_grading 1)", {"ale_grading": 1.0}),
]
MEASURES = [("roll_force", "force [MN]", 1e-6), ("roll_torque", "torque [kN·m]", 1e-6),
            ("mean_spread", "mean spread [mm]", 1.0), ("spread", "widest spread [mm]", 1.0)]


def run(rollsim, name, fields, tmp):
    p = json.loads((ROOT / "samples/rolling-3d-ale.json").read_text())
    p["process"].update(fields)
    p["output"] = {"vtu": False}
    path = tmp / f"{len(list(tmp.iterdir()))}.json"
    path.write_text(json.dumps(p))
    row = run_pass(rollsim, path, tmp / (path.stem + "-out"))
    row.update(name=name)
    return row


def cell(row, base, key, scale):
    if row[key] is None:
        return "–"
    if row is base or not base[key]:
        return f"{row[key] * scale:.4g}"
    return f"{row[key] * scale:.4g} ({100 * (row[key] / base[key] - 1):+.1f} %)"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rollsim", default=str(ROOT / "build/app/rollsim"))
    ap.add_argument("--out", default=str(ROOT / "docs/ale-3d-directions-output.md"))
    a = ap.parse_args()
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="ale-3d-dir-"))
    lines = ["| window | status | steady at [mm] | " + " | ".join(label for _, label, _ in MEASURES) +
             " | Newton its | CPU [s] | peak MiB |", "|---" * (len(MEASURES) + 6) + "|"]
    rows = []
    for name, fields in VARIANTS:
        rows.append(run(a.rollsim, name, fields, tmp))
        r = rows[-1]
        values = " | ".join(cell(r, rows[0], k, scale) for k, _, scale in MEASURES)
        lines.append(f"| {name} | {r['status']} | {'%.4g' % r['steady_at'] if r['steady_at'] is not None else '–'} | "
                     f"{values} | {r['newton']} | {r['cpu']:.1f} | {r['peak']:.0f} |")
        print(lines[-1], flush=True)
    theory = rows[0]["theory"]
    text = ("# The 3D ALE window: one choice changed at a time (tests/bench/run_ale_3d_directions.py)\n\n"
            "samples/rolling-3d-ale.json and the same window with one choice changed; the means from the steady "
            "state on, the change against the sample in brackets. Wusatowski's spread of the pass: "
            f"{theory.get('wusatowski_spread', float('nan')):.3f} mm; Sims's force: "
            f"{theory.get('sims_roll_force', float('nan')) * 1e-6:.3f} MN.\n\n" + "\n".join(lines) + "\n")
    pathlib.Path(a.out).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
