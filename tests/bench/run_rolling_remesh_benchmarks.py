#!/usr/bin/env python3
"""A Lagrangian rolling pass with and without remeshing -> docs/rolling-remesh-bench-output.md (docs/VALIDATION.md,
"Remeshing", "A rolling pass").

1. The hot pass with heat (samples/rolling-2d-heat.json: Shida steel at 1100 °C, 20 %, 30 rpm, heat in slab and roll,
   slab graded toward the roll) on three slabs refined together in length and thickness (36 x 6, 54 x 9, 72 x 12), each
   run over its 120 mm of travel without remeshing and with analysis.remesh_quality 0.5 and 0.9.
2. The cold main job (samples/rolling-2d-36x6.json) without and with remesh_quality 0.95 (a remesh every ~8 mm on a
   mesh that never needs one): what the transfer alone does to the pass's answer.
Per run: status, the travel reached, remeshes, the travel-weighted means of roll force and torque over the last 30 mm
reached (the hot pass is not steady by 120 mm: its force still creeps up with the chilled surface), the top surface's
mean temperature past the exit at the end, Newton iterations and total_s (one run each: a fact of this run, not a timing comparison).
Usage: tests/bench/run_rolling_remesh_benchmarks.py [--rollsim BIN] [--out docs/rolling-remesh-bench-output.md]
"""
import argparse
import csv
import json
import pathlib
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
HOT_MESHES = [(36, 6), (54, 9), (72, 12)]


def hot(n, quality):
    p = json.loads((ROOT / "samples/rolling-2d-heat.json").read_text())
    p["process"].update(slab_nx=n[0], slab_nt=n[1])
    if quality:
        p["analysis"] = {"remesh_quality": quality}
    p["output"] = {"vtu": False}
    return p


def cold(quality):
    p = json.loads((ROOT / "samples/rolling-2d-36x6.json").read_text())
    if quality:
        p["analysis"] = {"remesh_quality": quality}
    p["output"] = {"vtu": False}
    return p


def window_mean(rows, key, span):
    """The travel-weighted mean of `key` over the last `span` mm of the rows (each row standing for the step before
    it)."""
    end = rows[-1]["travel"]
    total = weight = 0.0
    for before, row in zip([{"travel": 0.0}] + rows[:-1], rows):
        lo = max(before["travel"], end - span)
        if row["travel"] > lo:
            total += row[key] * (row["travel"] - lo)
            weight += row["travel"] - lo
    return total / weight if weight else float("nan")


def run(rollsim, project, out):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(project, f)
    subprocess.run([rollsim, "run", f.name, "--out", str(out), "--quiet"], check=False,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    pathlib.Path(f.name).unlink()
    s = json.loads((out / "summary.json").read_text())
    rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(out / "rolling.csv"))] \
        if (out / "rolling.csv").exists() else []
    return {"status": s["status"], "message": s.get("message", ""),
            "travel": rows[-1]["travel"] if rows else 0.0, "remeshes": len(s.get("remeshes", [])),
            "force": window_mean(rows, "roll_force", 30) if rows else float("nan"),
            "torque": window_mean(rows, "roll_torque", 30) / 1e3 if rows else float("nan"),
            "temperature": rows[-1].get("surface_temperature", float("nan")) if rows else float("nan"),
            "newton": sum(i.get("newton_iterations", 0) for i in s["increments"]),
            "seconds": s["timing"]["total_s"]}


def table(title, runs):
    lines = [f"### {title}", "",
             "| case | status | travel [mm] | remeshes | force, last 30 mm [N/mm] | torque [N·m/mm] | surface T past the exit [°C] "
             "| Newton its | total_s |", "|---|---|---|---|---|---|---|---|---|"]
    for name, r in runs:
        lines.append(f"| {name} | {r['status']} | {r['travel']:.2f} | {r['remeshes']} | {r['force']:.1f} | "
                     f"{r['torque']:.2f} | {r['temperature']:.1f} | {r['newton']} | {r['seconds']:.1f} |")
    stopped = [(n, r["message"]) for n, r in runs if r["status"] != "converged"]
    lines += [""] + [f"- {n}: {m}" for n, m in stopped]
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rollsim", default=str(ROOT / "build/app/rollsim"))
    ap.add_argument("--out", default=str(ROOT / "docs/rolling-remesh-bench-output.md"))
    a = ap.parse_args()
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="remesh-bench-"))
    hot_runs, cold_runs = [], []
    for n in HOT_MESHES:
        for q in (0, 0.5, 0.9):
            name = f"hot {n[0]} x {n[1]}, " + (f"remesh_quality {q}" if q else "no remesh")
            hot_runs.append((name, run(a.rollsim, hot(n, q), tmp / name.replace(" ", "_").replace(",", ""))))
            print(name, hot_runs[-1][1], flush=True)
    for q in (0, 0.95):
        name = "main job 36 x 6, " + (f"remesh_quality {q}" if q else "no remesh")
        cold_runs.append((name, run(a.rollsim, cold(q), tmp / name.replace(" ", "_").replace(",", ""))))
        print(name, cold_runs[-1][1], flush=True)
    text = ("# Rolling passes with and without remeshing\n\nWritten by tests/bench/run_rolling_remesh_benchmarks.py "
            "(docs/VALIDATION.md, \"Remeshing\").\n\n" + table("The hot pass with heat, three meshes", hot_runs) +
            "\n" + table("The cold main job: the transfer's own effect", cold_runs))
    pathlib.Path(a.out).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
