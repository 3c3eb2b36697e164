#!/usr/bin/env bash
# Rolling benchmark of issue 13 -> docs/BENCHMARKS-ROLLING.md.
#   table13: the paper's Table XIII — the plane-strain pass on slab meshes 36x6 … 72x12 (roll mesh fixed, 120 x 6)
#            over TRAVEL mm in 1 mm increments, solved by direct + always (the paper's direct), mixed + always
#            (Mixed I), direct + selective and mixed + selective (Mixed II): Newton iterations, factorizations per
#            body, in-process time (median of REPEAT runs), peak memory, and the time against direct with the same
#            update policy (the same tangents, so the same Newton path) beside the paper's ratio to its direct.
#   table15: the paper's Table XV — the same pass and meshes 48x8 … 72x12 with the selective update: direct, Mixed II
#            and FETI with the slab torn into 2, 3, 4 subdomains along its length (DD-II; the roll one more group):
#            factorizations per group, CG iterations, in-process time, and the roll force of each (the modes agree).
#   convergence: the pass to steady state (150 mm) on three meshes refined together (slab 36x6, 54x9, 72x12; roll
#            120, 180, 240 around; increments 1, 0.75, 0.5 mm), direct: steady force, torque, forward slip, exit
#            thickness, volume change.
#   friction: the 36x6 pass to steady state (120 mm, 0.5 mm steps): sticking, Coulomb μ 0.4 / 0.3 (direct's
#            consistent friction tangent; μ 0.3 also by mixed, lagged) / 0.25, and a rigid against an elastic roll
#            (Hitchcock) with a mild hardening H = 100 MPa: steady means, Newton iterations and cut-backs.
# Usage: tests/bench/run_rolling_benchmarks.sh [table13|table15|convergence|friction] [--rollsim BIN] [--repeat N] [--travel MM]
# This script builds nothing. Timing is not a test: it fails only if a run fails.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
ROLLSIM=$ROOT/build/app/rollsim
REPEAT=3
TRAVEL=20
PART=${1:-table13}
(($#)) && shift
while (($#)); do
  case $1 in
    --rollsim) ROLLSIM=$2; shift 2 ;;
    --repeat) REPEAT=$2; shift 2 ;;
    --travel) TRAVEL=$2; shift 2 ;;
    -h|--help) sed -n 2,17p "$0"; exit 0 ;;
    *) echo "run_rolling_benchmarks: unknown argument $1" >&2; exit 2 ;;
  esac
done
ROLLSIM=$(realpath "$ROLLSIM")
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# project NAME NX NT AROUND INCREMENT TRAVEL -> $WORK/NAME.json (the default sample's pass with these meshes)
project() {
  python3 - "$ROOT/samples/rolling-2d-36x6.json" "$WORK/$1.json" "$@" <<'PY'
import json, sys
src, dst, name, nx, nt, around, inc, travel = sys.argv[1:]
p = json.load(open(src))
p["name"] = name
p["process"].update(slab_nx=int(nx), slab_nt=int(nt), roll_n_around=int(around),
                    travel_increment=float(inc), travel=float(travel))
json.dump(p, open(dst, "w"))
PY
}

table13() {
  echo "| slab mesh | dofs | variant | Newton iterations | factorizations slab / roll | in-process s (median of $REPEAT) | peak MiB | vs direct, same policy | paper vs direct |"
  echo "|---|---|---|---|---|---|---|---|---|"
  for mesh in 36x6 48x8 60x10 72x12; do
    nx=${mesh%x*} nt=${mesh#*x}
    project "t13-$mesh" "$nx" "$nt" 120 1 "$TRAVEL"
    for v in "direct always" "mixed always" "direct selective" "mixed selective"; do
      read -r mode update <<<"$v"
      for r in $(seq "$REPEAT"); do
        /usr/bin/time -f "%M" -o "$WORK/$mesh-$mode-$update-$r.mem" "$ROLLSIM" run "$WORK/t13-$mesh.json" --quiet \
          --out "$WORK/$mesh-$mode-$update-$r" --solver "$mode" --update "$update" >/dev/null 2>&1 || true
      done
    done
    python3 - "$WORK" "$mesh" "$REPEAT" "$ROOT/tests/bench/paper/t13_rolling2d_mixed.csv" <<'PY'
import csv, json, statistics, sys
work, mesh, repeat, paper = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
rows = {r["slab_mesh_XxZ"]: r for r in csv.DictReader(l for l in open(paper) if not l.startswith("#"))}
p = rows.get(mesh)
times = {}
label = {"direct always": "direct", "mixed always": "Mixed I", "direct selective": "direct + selective",
         "mixed selective": "Mixed II"}
base = {"direct always": "direct always", "mixed always": "direct always", "direct selective": "direct selective",
        "mixed selective": "direct selective"}  # the same update policy: the same Newton path
for v in label:
    mode, update = v.split()
    runs = [f"{work}/{mesh}-{mode}-{update}-{r}" for r in range(1, repeat + 1)]
    d = json.load(open(runs[0] + "/summary.json"))
    if d["status"] != "converged":  # the run's own words: where it stopped and why
        reached = d["increments"][-1]["load_factor"] * json.load(open(f"{work}/t13-{mesh}.json"))["process"]["travel"] if d.get("increments") else 0
        print(f"| {mesh} | {d['model']['dofs']} | {label[v]} | {d['status']} after {reached:.1f} mm: "
              f"{d.get('message', '')[:90]} | | | | | |")
        continue
    times[v] = statistics.median(json.load(open(r + "/summary.json"))["timing"]["total_s"] for r in runs)
    peak = max(int(open(r + ".mem").read().split()[-1]) for r in runs) / 1024
    f = d["solver"]["factorizations"]
    fac = " / ".join(str(f.get(b, 0)) for b in ("slab", "roll"))
    ratio = f"{times[v] / times[base[v]]:.3f}" if base[v] in times else "–"
    ref = {"direct always": "1", "mixed always": p and f"{float(p['mixed1']) / float(p['direct']):.3f}",
           "direct selective": "–", "mixed selective": p and f"{float(p['mixed2']) / float(p['direct']):.3f}"}[v]
    print(f"| {mesh} | {d['model']['dofs']} | {label[v]} | {d['solver']['newton_iterations']} | {fac} | "
          f"{times[v]:.2f} | {peak:.0f} | {ratio} | {ref or '–'} |")
PY
  done
}

table15() {
  echo "| slab mesh | variant | Newton iterations | factorizations per group | CG iterations | in-process s (median of $REPEAT) | vs direct + selective | roll force N/mm | paper: total vs direct |"
  echo "|---|---|---|---|---|---|---|---|---|"
  for mesh in 48x8 60x10 72x12; do
    nx=${mesh%x*} nt=${mesh#*x}
    project "t15-$mesh" "$nx" "$nt" 120 1 "$TRAVEL"
    for v in "direct -" "mixed -" "feti 2x1" "feti 3x1" "feti 4x1"; do
      read -r mode part <<<"$v"
      extra=()
      [[ $part != - ]] && extra=(--partition "slab=$part")
      for r in $(seq "$REPEAT"); do
        "$ROLLSIM" run "$WORK/t15-$mesh.json" --quiet --out "$WORK/$mesh-$mode-$part-$r" --solver "$mode" \
          --update selective "${extra[@]}" >/dev/null 2>&1 || true
      done
    done
    python3 - "$WORK" "$mesh" "$REPEAT" "$ROOT/tests/bench/paper/t15_rolling2d_dd.csv" <<'PY'
import csv, json, statistics, sys
work, mesh, repeat, paper = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
rows = [r for r in csv.DictReader(l for l in open(paper) if not l.startswith("#"))
        if r["slab_mesh"] == mesh and r["quantity"] == "total"]
p = rows[0] if rows else None
column = {"direct -": "direct", "mixed -": "mixed2", "feti 2x1": "dom2", "feti 3x1": "dom3", "feti 4x1": "dom4"}
base = None
for v, col in column.items():
    mode, part = v.split()
    runs = [f"{work}/{mesh}-{mode}-{part}-{r}" for r in range(1, repeat + 1)]
    d = json.load(open(runs[0] + "/summary.json"))
    name = "direct + selective" if mode == "direct" else "Mixed II" if mode == "mixed" else f"DD-II, slab {part}"
    if d["status"] != "converged":
        print(f"| {mesh} | {name} | {d['status']}: {d.get('message', '')[:80]} | | | | | | |")
        continue
    t = statistics.median(json.load(open(r + "/summary.json"))["timing"]["total_s"] for r in runs)
    base = base or t
    s = d["solver"]
    fac = ", ".join(f"{g} {n}" for g, n in s["factorizations"].items())
    ref = f"{float(p[col]) / float(p['direct']):.3f}" if p else "–"
    print(f"| {mesh} | {name} | {s['newton_iterations']} | {fac} | {s['cg_iterations_total']} | {t:.2f} | "
          f"{t / base:.3f} | {d['results']['rolling']['roll_force']:.6f} | {ref} |")
PY
  done
}

convergence() {
  echo "| slab mesh | roll around | increment mm | dofs | steady from mm | roll force N/mm | torque kN·m/m | forward slip % | exit thickness mm | volume change | run s |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  for m in "36 6 120 1" "54 9 180 0.75" "72 12 240 0.5"; do
    read -r nx nt around inc <<<"$m"
    project "c$nx" "$nx" "$nt" "$around" "$inc" 150
    "$ROLLSIM" run "$WORK/c$nx.json" --quiet --out "$WORK/c$nx" --solver direct >/dev/null
    python3 - "$WORK/c$nx" "$nx" "$nt" "$around" "$inc" <<'PY'
import json, sys
out, nx, nt, around, inc = sys.argv[1:]
d = json.load(open(out + "/summary.json"))
r = d["results"]["rolling"]
steady = r["steady_state_increment"]
travel = d["increments"][steady - 1]["load_factor"] * 150 if steady else float("nan")
print(f"| {nx}x{nt} | {around} | {inc} | {d['model']['dofs']} | {travel:.1f} | {r['roll_force']:.0f} | "
      f"{r['roll_torque'] / 1000:.1f} | {100 * r['forward_slip']:.2f} | {r['exit_thickness']:.3f} | "
      f"{r['volume_change']:.1e} | {d['timing']['total_s']:.1f} |")
PY
  done
}

# variant NAME SOLVER KEY=VALUE... -> runs the 36x6 pass, 0.5 mm steps, 120 mm, with these process fields; one row
variant() {
  local name=$1 solver=$2
  shift 2
  python3 - "$ROOT/samples/rolling-2d-36x6.json" "$WORK/$name.json" "$@" <<'PY'
import json, sys
src, dst, *fields = sys.argv[1:]
p = json.load(open(src))
p["process"].update(travel=120.0, travel_increment=0.5)
for f in fields:
    k, v = f.split("=")
    p["process"][k] = float(v) if v[0].isdigit() else v
json.dump(p, open(dst, "w"))
PY
  "$ROLLSIM" run "$WORK/$name.json" --quiet --out "$WORK/$name" --solver "$solver" >/dev/null 2>&1 || true
  python3 - "$WORK/$name" "$name" "$solver" <<'PY'
import csv, json, sys
out, name, solver = sys.argv[1:]
try:
    d = json.load(open(out + "/summary.json"))
except OSError:
    print(f"| {name} | {solver} | no summary.json: the run ended without writing one | | | | | | |")
    sys.exit()
rows = list(csv.DictReader(open(out + "/convergence.csv")))
its, cut = len(rows), sum(1 for r in rows if r["iteration"] == "1" and r["attempt"] != "0")
if d["status"] != "converged":
    print(f"| {name} | {solver} | {d['status']}: {d.get('message', '')[:100]} | | | | | | |")
    sys.exit()
r = d["results"]["rolling"]
travel = d["increments"][r["steady_state_increment"] - 1]["load_factor"] * 120
print(f"| {name} | {solver} | {travel:.1f} | {r['roll_force']:.1f} | {r['roll_torque'] / 1000:.2f} | "
      f"{100 * r['forward_slip']:.2f} | {r['exit_thickness']:.3f} | {r['contact_length']:.1f} | {its} ({cut}) |")
PY
}

friction() {
  echo "| pass | solver | steady from mm | roll force N/mm | torque kN·m/m | forward slip % | exit mm | contact length mm | Newton iterations (cut-backs) |"
  echo "|---|---|---|---|---|---|---|---|---|"
  variant sticking direct
  variant coulomb-0.4 direct friction=coulomb friction_coefficient=0.4
  variant coulomb-0.3 direct friction=coulomb friction_coefficient=0.3
  variant coulomb-0.3 mixed friction=coulomb friction_coefficient=0.3
  variant coulomb-0.25 direct friction=coulomb friction_coefficient=0.25
  variant rigid-H100 direct roll=rigid slab_hardening=100
  variant elastic-H100 direct slab_hardening=100
}

case $PART in
  table13) table13 ;;
  table15) table15 ;;
  convergence) convergence ;;
  friction) friction ;;
  *) echo "run_rolling_benchmarks: unknown part $PART (table13, table15, convergence or friction)" >&2; exit 2 ;;
esac
