#!/usr/bin/env python3
"""The run forecast (`rollsim check`'s last line, the window's Forecast tab) against the runs themselves: predicted
and measured Newton iterations and seconds for samples of every kind — the table of docs/BENCHMARKS.md, "The run
forecast". Also prints what the forecast's rates are fitted from (per-element tangent time, factorization rate).

  tests/bench/run_forecast.py [BIN]      (BIN: build/app/rollsim)
"""
import json
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BIN = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build/app/rollsim")

CASES = [
    ("rolling-2d-36x6", []),
    ("rolling-2d-48x8", ["--set", "process.travel=40"]),
    ("rolling-3d-16x8x4", ["--set", "process.travel=6"]),
    ("rolling-2d-ale", []),
    ("rolling-3d-ale", []),
    ("cylinder-plastic-2d", []),
    ("block-plastic-3d", []),
    ("cantilever-plastic-2d", []),
    ("necking-bar-3d", []),
    ("cantilever-3d-16x16x16", []),
    ("cantilever-2d-120x120", []),
    ("block-indent-2d-90x70", []),
]


def forecast(project, sets):
    # `check` takes no --set: the overrides go into a copy of the project
    out = subprocess.run([BIN, "check", str(project)], check=True, capture_output=True, text=True).stdout
    line = [l for l in out.splitlines() if l.startswith("forecast:")][0]
    it = float(re.search(r"about (\d+) (Newton iterations|solves?)", line).group(1))
    flop = re.search(r"factors of ([\d.e+]+) (M|G)flop", line)
    print("#", project.name, flop.group(0), file=sys.stderr)
    m = re.search(r"about ([\d.e+]+) (s|min)$", line)  # the last: "about 1 solve" begins with "s" too
    seconds = float(m.group(1)) * (60 if m.group(2) == "min" else 1)
    return it, seconds


def with_sets(work, name, sets):
    p = json.loads((ROOT / "samples" / f"{name}.json").read_text())
    for i in range(0, len(sets), 2):
        path, value = sets[i + 1].split("=")
        node = p
        keys = path.split(".")
        for k in keys[:-1]:
            node = node.setdefault(k, {})
        node[keys[-1]] = json.loads(value)
    f = work / f"{name}.json"
    f.write_text(json.dumps(p))
    return f


def main():
    with tempfile.TemporaryDirectory() as d:
        work = Path(d)
        print("| sample | dofs | increments | Newton iterations: forecast / run | seconds: forecast / run | ratio |")
        print("|---|---|---|---|---|---|")
        fits = []
        for name, sets in CASES:
            project = with_sets(work, name, sets)
            it, predicted = forecast(project, sets)
            out = work / f"out-{name}"
            start = time.perf_counter()
            subprocess.run([BIN, "run", str(project), "--out", str(out), "--quiet"], stdout=subprocess.DEVNULL)
            wall = time.perf_counter() - start
            s = json.loads((out / "summary.json").read_text())
            solver, timing, model = s["solver"], s["timing"], s["model"]
            iterations = solver.get("newton_iterations") or solver.get("active_set_iterations") or len(s["increments"])
            label = name + (" (" + " ".join(sets[1::2]) + ")" if sets else "")
            print(f"| {label} | {model['dofs']} | {len(s['increments'])} | {it:.0f} / {iterations} | "
                  f"{predicted:.3g} / {wall:.3g} | {predicted / wall:.2f} |")
            fits.append((name, model, solver, timing, wall))
        print()
        print("| sample | elements | tangents | stiffness s | per element-tangent µs | factorizations | factor flops "
              "| factorize s | GFlop/s |")
        print("|---|---|---|---|---|---|---|---|---|")
        for name, model, solver, timing, wall in fits:
            evals = solver.get("stiffness_evaluations", {})
            tangents = sum(evals.values()) / max(1, len(evals))
            facts = sum(solver.get("factorizations", {}).values())
            per = f"{timing['stiffness_s'] / (tangents * model['elements']) * 1e6:.3g}" if tangents else "— (linear)"
            print(f"| {name} | {model['elements']} | {tangents:.0f} | {timing['stiffness_s']:.3g} | {per} | {facts} "
                  f"| {solver.get('factor_flops', 0):.3g} | {timing['factorize_s']:.3g} | "
                  f"{solver.get('factor_gflops', 0):.3g} |")


if __name__ == "__main__":
    main()
