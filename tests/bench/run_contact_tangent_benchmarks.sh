#!/usr/bin/env bash
# Newton iterations with and without the contact's geometric stiffness (analysis.contact_tangent: none, groups, full)
# and with the first tangent of a step under `always` (analysis.first_tangent: fresh, converged) -> the tables of
# docs/BENCHMARKS-NONLINEAR.md ("The contact's geometric stiffness", its 3D part from sliding3d, cylinder3d and rolling3d)
# and docs/BENCHMARKS-ROLLING.md ("Why `always` failed"). Counts, not times: each row is one run; status, where the run ended, steps, cut-backs, Newton iterations,
# factorizations and tangent evaluations per group (summary.json's order) and the contact force.
#
# Usage: tests/bench/run_contact_tangent_benchmarks.sh [sliding|cylinder|rolling|rolling36|rigid|sliding3d|cylinder3d|
#        rolling3d]
#        [--rollsim BIN]
# This script builds nothing. It fails only if a run cannot start.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
ROLLSIM=$ROOT/build/app/rollsim
PART=${1:-sliding}
(($#)) && shift
while (($#)); do
  case $1 in
    --rollsim) ROLLSIM=$2; shift 2 ;;
    -h|--help) sed -n 2,11p "$0"; exit 0 ;;
    *) echo "run_contact_tangent_benchmarks: unknown argument $1" >&2; exit 2 ;;
  esac
done
ROLLSIM=$(realpath "$ROLLSIM")
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# edit SRC DST KEY=VALUE... : a copy of project SRC with these fields set (dotted paths; numbers as numbers)
edit() {
  python3 - "$@" <<'PY'
import json, sys
src, dst, *fields = sys.argv[1:]
p = json.load(open(src))
for f in fields:
    path, v = f.split("=", 1)
    *parents, key = path.split(".")
    node = p
    for k in parents:
        node = node[int(k)] if k.isdigit() else node.setdefault(k, {})
    try:
        v = float(v)
    except ValueError:
        pass
    node[key] = v
json.dump(p, open(dst, "w"))
PY
}

# row LABEL PROJECT SOLVER UPDATE SCALE: one run, one table row (SCALE: what load factor 1 is, e.g. the travel in mm)
row() {
  local label=$1 project=$2 solver=$3 update=$4 scale=$5
  local out=$WORK/out-$RANDOM
  "$ROLLSIM" run "$project" --quiet --out "$out" --solver "$solver" --update "$update" >/dev/null 2>&1 || true
  python3 - "$out" "$label" "$solver" "$update" "$scale" <<'PY'
import json, sys
out, label, solver, update, scale = sys.argv[1:]
try:
    d = json.load(open(out + "/summary.json"))
except OSError:
    print(f"| {label} | {solver} + {update} | no summary.json | | | | | | |")
    sys.exit()
inc = d["increments"]
reached = inc[-1]["load_factor"] * float(scale) if inc else 0.0
f = d["solver"].get("factorizations", {})
t = d["solver"].get("stiffness_evaluations", {})
contact = d.get("results", {}).get("contact", {})
force = ", ".join(f"{v['normal_force']:.4f}" for v in contact.values()) if contact else ""
print(f"| {label} | {solver} + {update} | {d['status']} | {reached:g} | {len(inc)} | "
      f"{sum(i['cutbacks'] for i in inc)} | {d['solver']['newton_iterations']} | "
      f"{' / '.join(str(v) for v in f.values())} | {' / '.join(str(v) for v in t.values())} | {force} |")
PY
}

header() {
  echo "| variant | solver + update | status | reached | steps | cut-backs | Newton iterations | factorizations per group | tangents per group | contact force |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
}

# the block pressed 0.02 into a base and pushed 10 along it (20 segments) in 20 steps (tests/core/analysis)
sliding() {
  python3 - "$WORK/slider.json" <<'PY'
import json, sys
block = lambda name, mesh: {"name": name, "material": name, "kinematics": "finite", "mesh": mesh}
p = {"name": "slider", "dimension": 2,
     "materials": [{"name": "base", "E": 1000.0, "nu": 0.3}, {"name": "slider", "E": 2000.0, "nu": 0.3}],
     "bodies": [block("base", {"type": "block", "nx": 60, "ny": 2, "lx": 30.0, "ly": 2.0}),
                block("slider", {"type": "block", "nx": 3, "ny": 2, "lx": 1.5, "ly": 1.0, "origin": [7.25, 2.0]})],
     "contacts": [{"name": "slide", "type": "frictionless", "slave_body": "slider", "slave_surface": "ymin",
                   "master_body": "base", "master_surface": "ymax", "search_distance": 0.2, "sliding": "large"}],
     "boundary_conditions": [
         {"type": "displacement", "body": "base", "set": "ymin", "ux": 0.0, "uy": 0.0},
         {"type": "displacement", "body": "slider", "set": "ymax", "ux": 10.0, "uy": -0.02}],
     "analysis": {"type": "newton", "increments": 20, "tolerance": 1e-9},
     "solver": {"mode": "direct", "cg_tolerance": 1e-10}}
json.dump(p, open(sys.argv[1], "w"))
PY
  header
  edit "$WORK/slider.json" "$WORK/s-large.json"
  row "large (rows fixed through a step)" "$WORK/s-large.json" direct always 10
  for t in none groups full; do
    edit "$WORK/slider.json" "$WORK/s-$t.json" contacts.0.sliding=large_every_iteration analysis.contact_tangent=$t
    for mode in direct skyline mixed; do
      [[ $t == full && $mode == mixed ]] && continue
      row "every iteration, contact_tangent $t" "$WORK/s-$t.json" "$mode" always 10
    done
  done
}

# the paper's Example 2 in 2D with large sliding searched at every iteration
cylinder() {
  header
  for t in none groups full; do
    edit "$ROOT/samples/cylinder-plastic-2d.json" "$WORK/c-$t.json" contacts.0.sliding=large_every_iteration \
      analysis.contact_tangent=$t
    row "contact_tangent $t" "$WORK/c-$t.json" direct always 1
    row "contact_tangent $t" "$WORK/c-$t.json" direct selective 1
    [[ $t == full ]] && continue
    row "contact_tangent $t" "$WORK/c-$t.json" mixed always 1
    row "contact_tangent $t" "$WORK/c-$t.json" mixed selective 1
  done
}

# Table XIII's 48 x 8 pass (the 36 x 6 sample's, slab E 210 GPa, roll 120 x 6), 20 mm in 1 mm steps
rolling() {
  header
  for first in fresh converged; do
    edit "$ROOT/samples/rolling-2d-36x6.json" "$WORK/r-$first.json" process.slab_nx=48 process.slab_nt=8 \
      process.travel=20 process.travel_increment=1 analysis.first_tangent=$first
    for mode in direct mixed; do row "first_tangent $first" "$WORK/r-$first.json" "$mode" always 20; done
    row "first_tangent $first" "$WORK/r-$first.json" direct selective 20
    for t in none groups full; do
      edit "$WORK/r-$first.json" "$WORK/r-$first-$t.json" process.sliding=large_every_iteration \
        analysis.contact_tangent=$t
      row "first_tangent $first, every iteration, contact_tangent $t" "$WORK/r-$first-$t.json" direct always 20
    done
  done
}

# the sample's 36 x 6 pass searched at every iteration, sticking and Coulomb μ 0.3, to TRAVEL mm (default the whole
# 120), one thread; the last column is the run's CPU seconds (user + system)
rolling36() {
  local travel=${TRAVEL:-120}
  echo "| friction | contact_tangent | status | reached | steps | cut-backs | Newton iterations | factorizations per group | contact force | CPU s |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  for friction in sticking coulomb; do
    for t in none groups full; do
      local project=$WORK/r36-$friction-$t.json out=$WORK/out-$RANDOM
      local mu=""  # μ only with Coulomb friction: with sticking it would have no effect, and is refused
      [ "$friction" = coulomb ] && mu=process.friction_coefficient=0.3
      edit "$ROOT/samples/rolling-2d-36x6.json" "$project" process.travel="$travel" process.friction=$friction \
        $mu process.sliding=large_every_iteration analysis.contact_tangent=$t
      OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 /usr/bin/time -f "%U %S" -o "$WORK/time" "$ROLLSIM" run "$project" \
        --quiet --out "$out" --solver direct --update always >/dev/null 2>&1 || true
      python3 - "$out" "$friction" "$t" "$travel" "$WORK/time" <<'PY'
import json, sys
out, friction, t, travel, time = sys.argv[1:]
d = json.load(open(out + "/summary.json"))
inc = d["increments"]
cpu = sum(float(x) for x in open(time).read().split()[-2:])
f = d["solver"].get("factorizations", {})
force = ", ".join(f"{v['normal_force']:.4f}" for v in d.get("results", {}).get("contact", {}).values())
print(f"| {friction} | {t} | {d['status']} | {inc[-1]['load_factor'] * float(travel) if inc else 0:g} | {len(inc)} | "
      f"{sum(i['cutbacks'] for i in inc)} | {d['solver']['newton_iterations']} | "
      f"{' / '.join(str(v) for v in f.values())} | {force} | {cpu:.1f} |")
PY
    done
  done
}

# the 36 x 6 pass with a rigid roll and a perfectly plastic slab, and Coulomb μ 0.25 (0.5 mm steps, 120 mm)
rigid() {
  header
  for first in fresh converged; do
    edit "$ROOT/samples/rolling-2d-36x6.json" "$WORK/g-$first.json" process.roll=rigid process.travel=120 \
      process.travel_increment=0.5 analysis.first_tangent=$first
    row "rigid roll, first_tangent $first" "$WORK/g-$first.json" direct always 120
    edit "$ROOT/samples/rolling-2d-36x6.json" "$WORK/m-$first.json" process.friction=coulomb \
      process.friction_coefficient=0.25 process.travel=120 process.travel_increment=0.5 analysis.first_tangent=$first
    row "Coulomb 0.25, first_tangent $first" "$WORK/m-$first.json" direct always 120
  done
}

# 3D: a 1.5 x 1.5 x 1 block pressed 0.02 into a 12 x 3 x 1 base and pushed 5 along it (10 faces) in 20 steps
# (tests/core/analysis/test_contact_tangent.cpp)
sliding3d() {
  python3 - "$WORK/slider3d.json" <<'PY'
import json, sys
block = lambda name, mesh: {"name": name, "material": name, "kinematics": "finite", "mesh": mesh}
p = {"name": "slider3d", "dimension": 3,
     "materials": [{"name": "base", "E": 1000.0, "nu": 0.3}, {"name": "slider", "E": 2000.0, "nu": 0.3}],
     "bodies": [block("base", {"type": "block", "nx": 24, "ny": 3, "nz": 1, "lx": 12.0, "ly": 3.0, "lz": 1.0}),
                block("slider", {"type": "block", "nx": 3, "ny": 2, "nz": 1, "lx": 1.5, "ly": 1.5, "lz": 1.0,
                                 "origin": [3.25, 0.75, 1.0]})],
     "contacts": [{"name": "slide", "type": "frictionless", "slave_body": "slider", "slave_surface": "zmin",
                   "master_body": "base", "master_surface": "zmax", "search_distance": 0.2, "sliding": "large"}],
     "boundary_conditions": [
         {"type": "displacement", "body": "base", "set": "zmin", "ux": 0.0, "uy": 0.0, "uz": 0.0},
         {"type": "displacement", "body": "slider", "set": "zmax", "ux": 5.0, "uy": 0.0, "uz": -0.02}],
     "analysis": {"type": "newton", "increments": 20, "tolerance": 1e-9},
     "solver": {"mode": "direct", "cg_tolerance": 1e-10}}
json.dump(p, open(sys.argv[1], "w"))
PY
  header
  row "large (rows fixed through a step)" "$WORK/slider3d.json" direct always 5
  for t in none groups full; do
    edit "$WORK/slider3d.json" "$WORK/s3-$t.json" contacts.0.sliding=large_every_iteration analysis.contact_tangent=$t
    for mode in direct skyline mixed; do
      [[ $t == full && $mode == mixed ]] && continue
      row "every iteration, contact_tangent $t" "$WORK/s3-$t.json" "$mode" always 5
    done
  done
}

# the paper's Example 2 in 3D (quarter model: the base slides over the cylinder's faces) searched at every iteration
cylinder3d() {
  header
  row "small (the sample)" "$ROOT/samples/cylinder-plastic-3d.json" direct always 1
  for t in none groups full; do
    edit "$ROOT/samples/cylinder-plastic-3d.json" "$WORK/c3-$t.json" contacts.0.sliding=large_every_iteration \
      analysis.contact_tangent=$t
    row "every iteration, contact_tangent $t" "$WORK/c3-$t.json" direct always 1
    [[ $t == full ]] && continue
    row "every iteration, contact_tangent $t" "$WORK/c3-$t.json" mixed selective 1
  done
}

# the 3D pass (sample rolling-3d-16x8x4) cut down to its first 15 mm of travel, 0.5 mm steps
rolling3d() {
  header
  edit "$ROOT/samples/rolling-3d-16x8x4.json" "$WORK/r3.json" process.travel=15
  row "large (the sample's)" "$WORK/r3.json" direct always 15
  for t in none groups full; do
    edit "$WORK/r3.json" "$WORK/r3-$t.json" process.sliding=large_every_iteration analysis.contact_tangent=$t
    row "every iteration, contact_tangent $t" "$WORK/r3-$t.json" direct always 15
    [[ $t == full ]] && continue
    row "every iteration, contact_tangent $t" "$WORK/r3-$t.json" mixed selective 15
  done
}

case $PART in
  sliding) sliding ;;
  cylinder) cylinder ;;
  rolling) rolling ;;
  rolling36) rolling36 ;;
  rigid) rigid ;;
  sliding3d) sliding3d ;;
  cylinder3d) cylinder3d ;;
  rolling3d) rolling3d ;;
  *) echo "run_contact_tangent_benchmarks: unknown part $PART (sliding, cylinder, rolling, rolling36, rigid, sliding3d," \
       "cylinder3d or rolling3d)" >&2; exit 2 ;;
esac
