#!/usr/bin/env bash
# Paper Example 5 (Table XII) -> docs/BENCHMARKS-NONLINEAR.md: sample block-plastic-3d with `direct` refactoring at
# every iteration, `mixed` (one group per body) and `feti` with the base partitioned as in Table XII, each with the
# `always` (DD-I / Mixed I) and `selective` (DD-II / Mixed II) update: steps, Newton iterations, factorizations and
# tangents of the base's groups and the block, CG iterations, contact force, in-process times, peak memory. Then the
# whole-process ratio of the fastest variant against `direct` + `always`, paired, by hand with tests/bench/paired_timing.py.
#
# Usage: tests/bench/run_example5_benchmarks.sh [--rollsim BIN] [--repeat N] [--partitions "1x1x2 1x2x1 ..."]
#        [--feti-only] (skip the direct and mixed rows)
# This script builds nothing. Timing is not a test: it fails only if a run fails.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
ROLLSIM=$ROOT/build/app/rollsim
REPEAT=3
PARTITIONS="1x1x2 1x2x1 1x2x2 2x2x2 1x3x1 1x3x2"
FETI_ONLY=0
while (($#)); do
  case $1 in
    --rollsim) ROLLSIM=$2; shift 2 ;;
    --repeat) REPEAT=$2; shift 2 ;;
    --partitions) PARTITIONS=$2; shift 2 ;;
    --feti-only) FETI_ONLY=1; shift ;;
    -h|--help) sed -n 2,9p "$0"; exit 0 ;;
    *) echo "run_example5_benchmarks: unknown argument $1" >&2; exit 2 ;;
  esac
done
ROLLSIM=$(realpath "$ROLLSIM")
SAMPLE=$ROOT/samples/block-plastic-3d.json
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

row() {  # label, then the run's arguments
  local label=$1 out=$WORK/run
  shift
  rm -rf "$out"
  /usr/bin/time -f "%M" -o "$out.mem" "$ROLLSIM" run "$SAMPLE" --quiet --out "$out" "$@" >/dev/null || true
  python3 - "$out" "$label" <<'PY'
import json, sys
out, label = sys.argv[1:]
d = json.load(open(out + "/summary.json"))
inc, s = d.get("increments", []), d["solver"]
f, t = s.get("factorizations", {}), s.get("stiffness_evaluations", {})
base_f = sum(v for k, v in f.items() if k.startswith("base")); base_t = sum(v for k, v in t.items() if k.startswith("base"))
groups = sum(1 for k in f if k.startswith("base"))
peak = int(open(out + ".mem").read().split()[-1]) / 1024
force = d.get("results", {}).get("contact", {}).get("block-base", {}).get("normal_force", float("nan"))
tm = d["timing"]
if d["status"] != "converged":  # where and why it stopped, beside the table (on stderr)
    print(f"{label}: {d['status']}: {d.get('message', '')}", file=sys.stderr)
print(f"| {label} | {d['status']} | {len(inc)} | {s.get('newton_iterations', 0)} | {base_f} ({groups} groups) / {f.get('block', 0)} | "
      f"{base_t} / {t.get('block', 0)} | {s.get('cg_iterations_total', 0)} | {force:.1f} | {tm['stiffness_s']:.1f} | "
      f"{tm['factorize_s']:.1f} | {tm['total_s']:.1f} | {peak:.0f} |")
PY
}

echo "| variant | status | steps | Newton iterations | factorizations base / block | tangents base / block | CG iterations | contact force | assembly s | factorize s | total s | peak MiB |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
if ((!FETI_ONLY)); then
  row "direct, always" --solver direct --update always
  row "direct, selective" --solver direct --update selective
  row "mixed, always (Mixed I)" --solver mixed --update always
  row "mixed, selective (Mixed II)" --solver mixed --update selective
fi
for p in $PARTITIONS; do
  row "feti $p, always (DD-I)" --solver feti --partition "base=$p" --update always
  row "feti $p, selective (DD-II)" --solver feti --partition "base=$p" --update selective
done
