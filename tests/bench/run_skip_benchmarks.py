#!/usr/bin/env python3
"""What each "skip" switch of issue 14 item 5 saves -> the "Skipping what a scene does not need" section of
docs/BENCHMARKS.md.

Each case runs one project twice per round — A (the switch on: the work skipped) and B (off: the work done) — in
alternating order, REPEAT rounds; whole-process wall seconds (start-up included), median per variant and the median
of the per-round ratios A/B (pairing keeps the ratio meaningful when the shared machine's speed drifts). Beside them,
the counts that say what was skipped (factorizations, tangent evaluations, files written, dofs).
Usage: tests/bench/run_skip_benchmarks.py [--rollsim BIN] [--repeat N] [--only SUBSTRING]
Builds nothing; timing is not a test: it fails only if a run fails.
"""
import argparse
import copy
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]


def sample(name):
    return json.loads((ROOT / "samples" / f"{name}.json").read_text())


def travel(p, mm):
    p["process"]["travel"] = mm
    return p


def small_cylinder(p):
    for b in p["bodies"]:
        if b["name"] == "cylinder":
            b["kinematics"] = "small"  # an elastic indenter at small strain: a constant tangent
    return p


def full_width(p):
    """The 3D pass across the whole width at the sample's resolution: twice the elements across twice the width —
    what the model would cost without the width symmetry plane (the plane then lies at the slab's edge)."""
    q = p["process"]
    q["slab_nw"] = 2 * q.get("slab_nw", 8)
    q["slab_width"] = 2 * q.get("slab_width", 350)
    q["barrel_width"] = 2 * q.get("barrel_width", 400)
    q["roll_n_axial"] = 2 * q.get("roll_n_axial", 8)
    return p


def with_(path, value):
    def f(p):
        node = p
        for k in path[:-1]:
            node = node.setdefault(k, {})
        node[path[-1]] = value
        return p
    return f


def chain(*fs):
    def f(p):
        for g in fs:
            p = g(p)
        return p
    return f


# name, base project, common transform, (A label, A transform, A args), (B label, B transform, B args)
CASES = [
    ("converged groups kept (selective)", "cylinder-plastic-2d", lambda p: p,
     ("update selective", lambda p: p, ["--solver", "mixed", "--update", "selective"]),
     ("update always", lambda p: p, ["--solver", "mixed", "--update", "always"])),
    ("elastic group factored once", "cylinder-plastic-2d", small_cylinder,
     ("constant_tangents keep", with_(["analysis", "constant_tangents"], "keep"),
      ["--solver", "mixed", "--update", "selective"]),
     ("constant_tangents refactor", with_(["analysis", "constant_tangents"], "refactor"),
      ["--solver", "mixed", "--update", "selective"])),
    ("contact search by boxes, 2D pass", "rolling-2d-36x6", lambda p: travel(p, 10),
     ("contact_search boxes", with_(["analysis", "contact_search"], "boxes"), []),
     ("contact_search all", with_(["analysis", "contact_search"], "all"), [])),
    ("contact search by boxes, 3D indentation", "cylinder-plastic-3d", lambda p: p,
     ("contact_search boxes", with_(["analysis", "contact_search"], "boxes"), []),
     ("contact_search all", with_(["analysis", "contact_search"], "all"), [])),
    ("contact search by boxes, 3D pass", "rolling-3d-16x8x4", lambda p: travel(p, 4),
     ("contact_search boxes", with_(["analysis", "contact_search"], "boxes"), []),
     ("contact_search all", with_(["analysis", "contact_search"], "all"), [])),
    ("width symmetry, 3D pass", "rolling-3d-16x8x4", lambda p: travel(p, 4),
     ("half width (symmetry)", lambda p: p, []), ("full width, same resolution", full_width, [])),
    ("increments not written", "rolling-2d-36x6", lambda p: travel(p, 20),
     ("output.increments last", with_(["output", "increments"], "last"), []),
     ("output.increments all", with_(["output", "increments"], "all"), [])),
    ("result.vtu not written", "cantilever-3d-16x16x16", lambda p: p,
     ("output.vtu false", with_(["output", "vtu"], False), []), ("output.vtu true", with_(["output", "vtu"], True), [])),
]


def run(rollsim, pfile, args, out):
    start = time.perf_counter()
    p = subprocess.run([rollsim, "run", str(pfile), "--out", str(out), "--quiet"] + args, stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE, text=True, timeout=1800)
    wall = time.perf_counter() - start
    if p.returncode != 0:
        sys.exit(f"run failed ({p.returncode}): {pfile} {args}\n{p.stderr}")
    s = json.loads((out / "summary.json").read_text())
    files = len(list(out.iterdir()))
    return wall, s, files


def counts(s, files):
    sv = s["solver"]
    fact = "/".join(str(v) for v in sv["factorizations"].values())
    ev = "/".join(str(v) for v in sv.get("stiffness_evaluations", {}).values()) or "—"
    return f"{s['model']['dofs']} dofs, factorizations {fact}, tangents {ev}, {files} files"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rollsim", default=str(ROOT / "build/app/rollsim"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--only", default="")
    a = ap.parse_args()
    work = pathlib.Path(tempfile.mkdtemp(prefix="skip-bench-"))
    print(f"Generated by `tests/bench/run_skip_benchmarks.py --repeat {a.repeat}`: whole-process wall seconds, median "
          f"of {a.repeat} rounds, A and B alternating; A/B = median of the per-round ratios (below 1: the switch "
          "saves).\n")
    print("| what is skipped | project | A (skips) | B (does the work) | A s | B s | A / B | A: counts | B: counts |")
    print("|---|---|---|---|---|---|---|---|---|")
    for i, (what, name, common, (la, fa, aa), (lb, fb, ab)) in enumerate(CASES):
        if a.only not in what:
            continue
        files = []
        for tag, f in (("a", fa), ("b", fb)):
            pf = work / f"{i}{tag}.json"
            pf.write_text(json.dumps(f(common(copy.deepcopy(sample(name))))))
            files.append(pf)
        ta, tb, ratios = [], [], []
        for rep in range(a.repeat):
            order = [(0, aa), (1, ab)] if rep % 2 == 0 else [(1, ab), (0, aa)]
            got = {}
            for k, args in order:
                got[k] = run(a.rollsim, files[k], args, work / f"out{k}")
            ta.append(got[0][0])
            tb.append(got[1][0])
            ratios.append(got[0][0] / got[1][0])
            last = got
        print(f"| {what} | {name} | {la} | {lb} | {statistics.median(ta):.3f} | {statistics.median(tb):.3f} | "
              f"{statistics.median(ratios):.3f} | {counts(last[0][1], last[0][2])} | {counts(last[1][1], last[1][2])} |",
              flush=True)


if __name__ == "__main__":
    main()
