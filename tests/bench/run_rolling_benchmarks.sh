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
#   table14, table16, table17: the paper's 3D tables over TRAVEL mm in 1 mm steps (cg_tolerance 1e-10, roll 100 x 3 x 6):
#            XIV direct, Mixed I and Mixed II on slabs 16x8x4 … 18x10x6 (--meshes to choose); XVI the slab 18x10x6 by
#            direct, mixed and FETI in 2x1x1, 1x2x1, 2x2x1, 3x2x1 (length x width x thickness), DD-I and DD-II; XVII
#            the slab 24x12x8, DD-II, every partition of the paper. CPU seconds (user + system, one thread, as the
#            paper's), the window's partition-table prediction beside the FETI rows, and the roll force of each.
# Usage: tests/bench/run_rolling_benchmarks.sh [table13|table14|table15|table16|table17|convergence|friction] [--rollsim BIN]
#        [--repeat N] [--travel MM] [--meshes "16x8x4 18x10x6"]
# This script builds nothing. Timing is not a test: it fails only if a run fails.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
ROLLSIM=$ROOT/build/app/rollsim
REPEAT=3
TRAVEL=20
MESHES="16x8x4 16x8x5 16x10x5 18x10x6"
PART=${1:-table13}
(($#)) && shift
while (($#)); do
  case $1 in
    --rollsim) ROLLSIM=$2; shift 2 ;;
    --repeat) REPEAT=$2; shift 2 ;;
    --travel) TRAVEL=$2; shift 2 ;;
    --meshes) MESHES=$2; shift 2 ;;
    -h|--help) sed -n 2,23p "$0"; exit 0 ;;
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

# project3d NAME NXxNWxNT -> $WORK/NAME.json: the 3D sample's pass with this slab, TRAVEL mm in 1 mm steps
project3d() {
  python3 - "$ROOT/samples/rolling-3d-16x8x4.json" "$WORK/$1.json" "$2" "$TRAVEL" <<'PY'
import json, sys
src, dst, mesh, travel = sys.argv[1:]
nx, nw, nt = map(int, mesh.split("x"))
p = json.load(open(src))
p["process"].update(slab_nx=nx, slab_nw=nw, slab_nt=nt, travel=float(travel), travel_increment=1.0)
p["solver"].update(cg_tolerance=1e-10)
json.dump(p, open(dst, "w"))
PY
}

# run3d NAME MODE PART UPDATE: REPEAT runs of $WORK/NAME.json on one thread, CPU time and peak memory beside each
run3d() {
  local extra=()
  [[ $3 != - ]] && extra=(--partition "slab=$3")
  for r in $(seq "$REPEAT"); do
    OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 /usr/bin/time -f "%U %S %M" -o "$WORK/$1-$2-$3-$4-$r.time" \
      "$ROLLSIM" run "$WORK/$1.json" --quiet --threads 1 --out "$WORK/$1-$2-$3-$4-$r" --solver "$2" --update "$4" \
      "${extra[@]}" >/dev/null 2>&1 || true
  done
  # the window's partition table for the same map (partition.json): its predicted cost against one domain
  [[ $3 == - ]] || "$ROLLSIM" mesh "$WORK/$1.json" --quiet --partition "slab=$3" --out "$WORK/$1-$3-mesh" >/dev/null
}

# report3d NAME PAPER_CSV "MODE PART UPDATE"...: one row per variant against the first (direct), beside the paper's
report3d() {
  python3 - "$WORK" "$REPEAT" "$@" <<'PY'
import csv, glob, json, statistics, sys
work, repeat, name, paper, *variants = sys.argv[1:]
repeat = int(repeat)
ref = {}
for r in csv.DictReader(l for l in open(paper) if not l.startswith("#")):
    ref[(r.get("partition") or r.get("slab_mesh_XxYxZ"), r.get("variant") or "")] = r
base = None
for v in variants:
    mode, part, update = v.split()
    runs = [f"{work}/{name}-{mode}-{part}-{update}-{r}" for r in range(1, repeat + 1)]
    d = json.load(open(runs[0] + "/summary.json"))
    variant = {"always": "I", "selective": "II"}[update]
    label = part if mode == "feti" else mode
    domains = {"direct": 1, "mixed": 2}.get(mode) or eval(part.replace("x", "*")) + 1
    if d["status"] != "converged":
        print(f"| {domains} | {label} | {variant} | {d['status']}: {d.get('message', '')[:100]} | | | | | | | | |")
        continue
    cpu = statistics.median(sum(map(float, open(r + ".time").read().split()[:2])) for r in runs)
    wall = statistics.median(json.load(open(r + "/summary.json"))["timing"]["total_s"] for r in runs)
    peak = max(int(open(r + ".time").read().split()[2]) for r in runs) / 1024
    base = base or cpu
    s = d["solver"]
    fac = ", ".join(f"{g} {n}" for g, n in s["factorizations"].items())
    if name.startswith("t14"):
        row = ref.get((name.split("-")[1], ""))
        col = {"direct always": "direct", "mixed always": "mixed1", "mixed selective": "mixed2"}.get(f"{mode} {update}")
        paper_ratio = f"{float(row[col]) / float(row['direct']):.3f}" if row and col else "–"
    else:
        key = ("direct", "") if mode == "direct" else (label, variant if "dd1" in paper else "")
        key = None if mode == "direct" and update == "selective" else key  # the paper refactored its direct always
        direct = ref.get(("direct", ""))
        paper_ratio = f"{float(ref[key]['cpu_s']) / float(direct['cpu_s']):.3f}" if key in ref and direct else "–"
    predicted = "–"
    table = glob.glob(f"{work}/{name}-{part}-mesh/partition.json")
    if table:
        predicted = f"{json.load(open(table[0]))['bodies'][0]['predicted_ratio']:.3f}"
    print(f"| {domains} | {label} | {variant} | {s['newton_iterations']} | {fac} | {s.get('cg_iterations_total', 0)} | "
          f"{cpu:.1f} | {wall:.1f} | {peak:.0f} | {cpu / base:.3f} | {paper_ratio} | {predicted} | "
          f"{d['results']['rolling']['roll_force']:.1f} |")
PY
}

table3d_header() {
  echo "| domains | partition | variant | Newton iterations | factorizations per group | CG iterations | CPU s (median of $REPEAT) | in-process s | peak MiB | CPU vs direct | paper vs direct | predicted (partition table) | roll force N |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
}

table14() {
  for mesh in $MESHES; do
    echo "slab $mesh:"
    table3d_header
    project3d "t14-$mesh" "$mesh"
    local variants=("direct - always" "direct - selective" "mixed - always" "mixed - selective")
    for v in "${variants[@]}"; do run3d "t14-$mesh" $v; done
    report3d "t14-$mesh" "$ROOT/tests/bench/paper/t14_rolling3d_mixed.csv" "${variants[@]}"
  done
}

table16() {
  table3d_header
  project3d t16 18x10x6
  local variants=("direct - always" "direct - selective" "mixed - always" "mixed - selective")
  for part in 2x1x1 1x2x1 2x2x1 3x2x1; do variants+=("feti $part always" "feti $part selective"); done
  for v in "${variants[@]}"; do run3d t16 $v; done
  report3d t16 "$ROOT/tests/bench/paper/t16_rolling3d_dd1.csv" "${variants[@]}"
}

table17() {
  table3d_header
  project3d t17 24x12x8
  local variants=("direct - always" "direct - selective" "mixed - selective")
  for part in 2x1x1 1x2x1 3x1x1 1x3x1 2x2x1 1x4x1 3x2x1 2x3x1 2x4x1 3x3x1 3x4x1; do variants+=("feti $part selective"); done
  for v in "${variants[@]}"; do run3d t17 $v; done
  report3d t17 "$ROOT/tests/bench/paper/t17_rolling3d_dd2.csv" "${variants[@]}"
}

case $PART in
  table13) table13 ;;
  table14) table14 ;;
  table15) table15 ;;
  table16) table16 ;;
  table17) table17 ;;
  convergence) convergence ;;
  friction) friction ;;
  *) echo "run_rolling_benchmarks: unknown part $PART (table13, table14, table15, table16, table17, convergence or friction)" >&2; exit 2 ;;
esac
