#!/usr/bin/env python3
"""`solver.mode: auto` against every mode, on every sample -> the "solver.mode: auto" section of docs/BENCHMARKS.md.

Each sample (samples/*.json) runs as `rollsim run SAMPLE --solver MODE --quiet` in every mode — skyline, direct,
mixed, feti when a body is partitioned (without a partition feti is mixed) — and with `--solver auto`, the modes
interleaved and rotated per repeat; the time is the run's in-process time (summary.json timing.total_s: what the mode
changes; process start-up, the same for every mode, is left out), median of
REPEAT runs (one run when a mode of the sample took longer than LONG s in the first round: the "runs" column).
A rolling sample's pass is shortened to TRAVEL mm of roll travel (its increments unchanged) to keep the
table affordable. The table says which mode was fastest, what auto chose and its predicted costs, and how much slower
auto's choice ran than the fastest of auto's candidates (direct, mixed, feti) and than the fastest of all.
A run longer than TIMEOUT s is cut and shown as "> TIMEOUT" (slower than every finished mode).
Usage: tests/bench/run_auto_benchmarks.py [--rollsim BIN] [--repeat N] [--travel MM] [--timeout S] [--long S]
       [--only SUBSTRING] [--skip SUBSTRING]
Builds nothing; timing is not a test: it fails only if a run of auto fails.
"""
import argparse
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]


def partitioned(project):
    if any("partition" in b or "partition_map" in b for b in project.get("bodies", [])):
        return True
    proc = project.get("process", {})
    return "slab_partition" in proc or "slab_partition_map" in proc


def run(rollsim, project_file, mode, out, timeout):
    start = time.perf_counter()
    try:
        p = subprocess.run([rollsim, "run", str(project_file), "--solver", mode, "--out", str(out), "--quiet"],
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"code": -1, "wall": timeout, "summary": {}, "err": [f"over {timeout:g} s"]}
    wall = time.perf_counter() - start
    summary = out / "summary.json"
    s = json.loads(summary.read_text()) if summary.exists() else {}
    return {"code": p.returncode, "wall": wall, "summary": s, "err": p.stderr.strip().splitlines()[-1:] }


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rollsim", default=str(ROOT / "build/app/rollsim"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--travel", type=float, default=10.0)
    ap.add_argument("--only", default="", help="comma-separated substrings: the samples whose name holds one")
    ap.add_argument("--skip", default="", help="leave out the samples whose name contains this")
    ap.add_argument("--long", type=float, default=20.0, help="a sample with a run longer than this runs one round")
    ap.add_argument("--timeout", type=float, default=120.0, help="a run longer than this is cut and marked")
    a = ap.parse_args()
    work = pathlib.Path(tempfile.mkdtemp(prefix="auto-bench-"))
    rows, skipped = [], []
    for sample in sorted((ROOT / "samples").glob("*.json")):
        if not any(o in sample.name for o in a.only.split(",")) or (a.skip and a.skip in sample.name):
            continue
        project = json.loads(sample.read_text())
        if "process" in project:
            project["process"]["travel"] = min(a.travel, project["process"].get("travel", a.travel))
        pfile = work / sample.name
        pfile.write_text(json.dumps(project))
        modes = ["skyline", "direct", "mixed"] + (["feti"] if partitioned(project) else []) + ["auto"]
        times = {m: [] for m in modes}
        walls = {m: [] for m in modes}
        last = {}
        repeats = a.repeat
        for rep in range(a.repeat):
            if rep == 1 and max(r["wall"] for r in last.values()) > a.long:
                repeats = 1  # a long sample: one round (its margins are wide enough to read)
                break
            order = modes[rep % len(modes):] + modes[:rep % len(modes)]
            for m in order:
                if m in last and last[m]["code"] == -1:
                    continue  # timed out once: not again
                r = run(a.rollsim, pfile, m, work / "out", a.timeout)
                last[m] = r
                if r["code"] == 0:
                    times[m].append(r["summary"]["timing"]["total_s"])
                    walls[m].append(r["wall"])
        if last["auto"]["code"] != 0:
            print(f"auto failed on {sample.name}: {last['auto']['err']}", file=sys.stderr)
            if last["auto"]["code"] != -1:
                sys.exit(1)
            skipped.append(sample.stem)  # over the time bound: listed under the table
            continue
        med = {m: statistics.median(t) for m, t in times.items() if len(t) == repeats}
        wall = {m: statistics.median(t) for m, t in walls.items() if len(t) == repeats}
        au = last["auto"]["summary"]["solver"]["auto"]
        rows.append({"repeats": repeats, "sample": sample.stem, "dofs": last["auto"]["summary"]["model"]["dofs"], "modes": modes,
                     "med": med, "wall": wall, "chosen": au["chosen"], "predicted": au["predicted_flops"],
                     "choice_s": au["choice_s"],
                     "failed": {m: (last[m]["err"][0] if last[m]["err"] else f"exit {last[m]['code']}")
                                for m in modes if m not in med}})
        print(f"# {sample.stem}: {med} auto->{au['chosen']} {rows[-1]}", file=sys.stderr, flush=True)
    report(rows, a)
    if skipped:
        print(f"- Not in the table: auto ran longer than {a.timeout:g} s on " + ", ".join(skipped) + ".")


def report(rows, a):
    print(f"Generated by `tests/bench/run_auto_benchmarks.py --repeat {a.repeat} --travel {a.travel:g} --timeout "
          f"{a.timeout:g} --long {a.long:g}`: in-process seconds (summary.json timing.total_s), median of {a.repeat} "
          "(runs column), modes interleaved; auto wall = its whole process, start-up included; rolling passes shortened to {a.travel:g} mm of "
          "travel. \"—\" = the mode refused or failed (skyline refuses floating bodies). auto's candidates: direct, "
          "mixed, feti (only with a partitioned body). Loss = time of auto's choice / time of the fastest candidate.\n")
    print("| sample | dofs | runs | skyline s | direct s | mixed s | feti s | auto s | auto wall s | fastest | auto chose | predicted "
          "direct / mixed / feti [Gflop] | loss vs fastest candidate | loss vs fastest of all |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    hits, losses, losses_all = 0, [], []
    for r in rows:
        med = r["med"]
        cands = {m: t for m, t in med.items() if m in ("direct", "mixed", "feti")}
        every = {m: t for m, t in med.items() if m != "auto"}
        best = min(cands, key=cands.get)
        best_all = min(every, key=every.get)
        chosen_t = med.get(r["chosen"], a.timeout)
        loss = chosen_t / cands[best]
        loss_all = chosen_t / every[best_all]
        hits += r["chosen"] == best
        if r["chosen"] != best:
            losses.append((r["sample"], loss))
        losses_all.append(loss_all)
        cell = lambda m: f"{med[m]:.3f}" if m in med else (
            (f"> {a.timeout:g}" if r["failed"].get(m, "").startswith("over") else "—") if m in r["modes"] else "")
        pred = " / ".join(f"{r['predicted'][m] / 1e9:.3g}" if m in r["predicted"] else "—"
                          for m in ("direct", "mixed", "feti"))
        print(f"| {r['sample']} | {r['dofs']} | {r['repeats']} | {cell('skyline')} | {cell('direct')} | {cell('mixed')} | "
              f"{cell('feti')} | {cell('auto')} | {r['wall'].get('auto', float('nan')):.3f} | {best_all} | {r['chosen']} | {pred} | {loss:.2f} | {loss_all:.2f} |")
    n = len(rows)
    print()
    print(f"- auto picked the fastest of its candidates on **{hits} of {n}** samples.")
    if losses:
        print("- Where it did not, its choice ran " + ", ".join(f"{s} {l:.2f}×" for s, l in losses) +
              " the fastest candidate's time.")
    print(f"- Against the fastest of all modes (skyline included): median loss {statistics.median(losses_all):.2f}×, "
          f"worst {max(losses_all):.2f}×.")
    print(f"- Choosing cost (factor estimates, summary.json solver.auto.choice_s): at most "
          f"{max(r['choice_s'] for r in rows) * 1e3:.1f} ms.")


if __name__ == "__main__":
    main()
