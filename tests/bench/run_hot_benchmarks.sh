#!/usr/bin/env bash
# Heat conduction in the hot pass (issue 33) -> docs/BENCHMARKS-HOT.md. Every run is samples/rolling-2d-heat.json
# (plane strain, slab 36 x 8 graded 1.5 toward the roll, Shida steel from 1100 °C, roll at 60 °C, 30 rpm, 1 mm steps)
# or a variant of it written into a temporary folder; only the last increment's VTU is written (uncompressed, so
# that the surface's temperatures can be read from it).
#   share:     the heat's share of the run (summary.json's timing.heat_s against total_s and against total_s −
#              heat_s; issue 33's goal: at most 15 % of the mechanical time) and its factorizations (one per
#              converged step), median of REPEAT runs: the sample, 48 x 12 with thickness_grading 1.25 (a top
#              element of 0.92 mm, as the sample's 1.0) and 72 x 12 with the sample's 1.5 (0.19 mm; it stops early,
#              and the share is that of the steps it made).
#   selective: the selective update with temperature-dependent tangents: Newton iterations, tangent evaluations
#              and factorizations per group, with heat and without it (the sample minus process.heat_transfer: the
#              slab still heats adiabatically), to TRAVEL_CMP mm (the pass without heat stops short of 120 mm)
#              and to 120 mm; the roll force at the end.
#   coupling:  the staggered coupling's step error: travel_increment 1 against 0.5 mm, the same travel: roll force,
#              the slab's mean, its surface past the exit and the roll's surface temperature; beside the pass
#              without heat (the mechanical step's own effect on the force).
#   chill:     the surface chill against the slab's mesh: thickness_grading 1, 1.5, 2 on slab_nt 8, and slab_nt 12
#              with 1.25 and 1.5; to TRAVEL_CMP mm (the surface at the exit plane is steady by then) and to 200 mm
#              (the window past the exit is steady from about 150 mm; in 0.5 mm steps where 1 mm stops short): the
#              top element's thickness against the penetration depth √(α t_c), beside two semi-infinite bodies
#              joined by the contact conductance (closed form at the exit, a fine 1D grid for the window past it).
#   roll:      the roll's surface temperature against its ring mesh, roll_n_radial 6, 12, 24, 48, to 120 mm.
#   cpu:       CPU seconds and peak memory (/usr/bin/time) of the pass with heat and without, to TRAVEL_CMP mm,
#              REPEAT pairs run in turn (A B A B …), medians and the median of the pairs' ratios.
# Usage: ROLLSIM=build/app/rollsim tests/bench/run_hot_benchmarks.sh [share|selective|coupling|chill|roll|cpu|all]
#        [--rollsim BIN] [--repeat N] [--travel-cmp MM]
# This script builds nothing. Timing is not a test: it fails only if it cannot run rollsim at all.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
ROLLSIM=${ROLLSIM:-$ROOT/build/app/rollsim}
REPEAT=3
TRAVEL_CMP=80
PART=${1:-all}
[[ $PART == -h || $PART == --help ]] && { sed -n 2,28p "$0"; exit 0; }
(($#)) && shift
while (($#)); do
  case $1 in
    --rollsim) ROLLSIM=$2; shift 2 ;;
    --repeat) REPEAT=$2; shift 2 ;;
    --travel-cmp) TRAVEL_CMP=$2; shift 2 ;;
    -h|--help) sed -n 2,28p "$0"; exit 0 ;;
    *) echo "run_hot_benchmarks: unknown argument $1" >&2; exit 2 ;;
  esac
done
[[ -x $ROLLSIM ]] || { echo "run_hot_benchmarks: no rollsim at $ROLLSIM (set ROLLSIM or --rollsim)" >&2; exit 2; }
ROLLSIM=$(realpath "$ROLLSIM")
SAMPLE=$ROOT/samples/rolling-2d-heat.json
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
export PYTHONPATH=$WORK

# The readers every report shares: a run's files, the VTU's top surface, a travel-weighted mean of rolling.csv.
cat >"$WORK/hot.py" <<'PY'
import csv, json, math, re, statistics, struct

def summary(out):
    try:
        return json.load(open(out + "/summary.json"))
    except OSError:
        return None

def rows(out):
    try:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(out + "/rolling.csv"))]
    except OSError:
        return []

def at(out, travel):
    """rolling.csv's row at this travel (None: the run did not get there)."""
    return next((r for r in rows(out) if abs(r["travel"] - travel) < 1e-6), None)

def mean(out, key, lo, hi):
    """Travel-weighted mean of a rolling.csv column over lo < travel <= hi."""
    s, prev = 0.0, lo
    for r in rows(out):
        if lo < r["travel"] <= hi + 1e-9:
            s += r[key] * (r["travel"] - prev)
            prev = r["travel"]
    return s / (hi - lo) if prev >= hi - 1e-9 else float("nan")

def cutbacks(out):
    try:
        return sum(1 for r in csv.DictReader(open(out + "/convergence.csv")) if r["iteration"] == "1" and r["attempt"] != "0")
    except OSError:
        return 0

def reached(out):
    """The travel of the last completed increment: rolling.csv's, or the progress line (a run that ended in an
    internal error writes no table)."""
    r = rows(out)
    if r:
        return r[-1]["travel"]
    try:
        done = re.findall(r"travel ([\d.]+) of [\d.]+ mm done", open(out + ".err").read())
    except OSError:
        done = []
    return float(done[-1]) if done else 0.0

def ended(out):
    """How a run ended: converged, or its status and the travel it reached."""
    d = summary(out)
    if d and d["status"] == "converged":
        return "converged"
    status = d["status"] if d and d["status"] != "running" else "internal error"
    return f"{status} at {reached(out):g} mm"

def why(out):
    """The run's own words when it did not converge: summary.json's message, else its last line on stderr."""
    d = summary(out)
    if d and d.get("message"):
        return d["message"]
    try:
        return open(out + ".err").read().strip().splitlines()[-1].replace("rollsim: ", "")
    except (OSError, IndexError):
        return "no output"

def fmt(x, spec):
    return "–" if x is None or x != x else format(x, spec)

def vtu(path):
    """The arrays of an uncompressed appended VTU (rollsim's output.compression none)."""
    b = open(path, "rb").read()
    i = b.index(b'<AppendedData encoding="raw">')
    head, data = b[:i].decode(), b[b.index(b"_", i) + 1:]
    out, section = {}, ""
    for m in re.finditer(r'<(PointData|CellData|Points|Cells|FieldData)\b|<DataArray([^>]*)>', head):
        if m.group(1):
            section = m.group(1)
            continue
        a = m.group(2)
        name = re.search(r'Name="([^"]*)"', a).group(1)
        f, w = {"Float64": ("d", 8), "Int32": ("i", 4), "Int64": ("q", 8), "UInt8": ("B", 1)}[re.search(r'type="([^"]*)"', a).group(1)]
        nc = int((re.search(r'NumberOfComponents="(\d+)"', a) or [0, 1])[1])
        off = int(re.search(r'offset="(\d+)"', a).group(1))
        n = struct.unpack_from("<I", data, off)[0]
        v = list(struct.unpack_from("<%d%s" % (n // w, f), data, off + 4))
        out[(section, name)] = [v[k:k + nc] for k in range(0, len(v), nc)] if nc > 1 else v
    return out

def slab_columns(out, vtu_name="result.vtu"):
    """The slab's columns of nodes at the end (current x, y and temperature, bottom to top), along x."""
    d = vtu(out + "/" + vtu_name)
    P, U = d[("Points", "Points")], d[("PointData", "displacement")]
    T, B = d[("PointData", "temperature")], d[("PointData", "body_id")]
    cols = {}
    for i in range(len(P)):
        if B[i] == 0:
            cols.setdefault(round(P[i][0], 6), []).append((P[i][0] + U[i][0], P[i][1] + U[i][1], T[i]))
    return [sorted(c, key=lambda n: n[1]) for _, c in sorted(cols.items())]

def top_surface(out):
    """The slab's top surface at the end: (current x, temperature) along x."""
    return sorted((c[-1][0], c[-1][2]) for c in slab_columns(out))

def section_mean(out, lo, hi):
    """The slab's section mean temperature (trapezoid over y, each column of nodes) averaged over lo < x <= hi."""
    means = []
    for c in slab_columns(out):
        if lo < c[-1][0] <= hi:
            s = sum(0.5 * (a[2] + b[2]) * (b[1] - a[1]) for a, b in zip(c, c[1:]))
            means.append(s / (c[-1][1] - c[0][1]))
    return sum(means) / len(means) if means else float("nan")

def layer_mean(out, lo, hi, depth):
    """The mean temperature of the slab's top `depth` mm (linear between nodes along each column), averaged over the
    columns at lo < x <= hi."""
    means = []
    for c in slab_columns(out):
        if not lo < c[-1][0] <= hi:
            continue
        top, s = c[-1][1], 0.0
        for a, b in zip(c, c[1:]):
            y0, y1 = max(a[1], top - depth), b[1]
            if y1 > y0:
                at_y = lambda y: a[2] + (b[2] - a[2]) * (y - a[1]) / (b[1] - a[1])
                s += 0.5 * (at_y(y0) + at_y(y1)) * (y1 - y0)
        means.append(s / depth)
    return sum(means) / len(means) if means else float("nan")

def top_element(process):
    """The slab's top element across the half thickness [mm]: sizes ∝ g^-i from the mid-plane, the top one smallest."""
    nt, g = process.get("slab_nt", 8), process.get("thickness_grading", 1)
    half = process.get("slab_thickness", 100) / 2
    return half / nt if g == 1 else half * (1 - 1 / g) / (1 - g ** -nt) * g ** -(nt - 1)

def at_x(profile, x):
    for (x0, t0), (x1, t1) in zip(profile, profile[1:]):
        if x0 <= x <= x1:
            return t0 + (t1 - t0) * (x - x0) / (x1 - x0)
    return float("nan")

def closed_form(T1, T2, k1, c1, k2, c2, h, t):
    """Two semi-infinite bodies at T1 and T2 joined through a conductance h from t = 0: their surface temperatures,
    T1 − (T1 − T2) e2/(e1 + e2) [1 − exp(H² t) erfc(H √t)] and T2 + (T1 − T2) e1/(e1 + e2) […], e = √(k ρc),
    H = h (1/e1 + 1/e2) (the Laplace transform of the one-sided case, Carslaw & Jaeger §2.7, with the other body's
    resistance in series)."""
    e1, e2 = math.sqrt(k1 * c1), math.sqrt(k2 * c2)
    x = h * (1 / e1 + 1 / e2) * math.sqrt(t)
    f = 1 - math.exp(x * x) * math.erfc(x)
    return T1 - (T1 - T2) * e2 / (e1 + e2) * f, T2 + (T1 - T2) * e1 / (e1 + e2) * f

def thomas(a, b, c, d):
    n = len(d)
    cp, dp = [0.0] * n, [0.0] * n
    cp[0], dp[0] = c[0] / b[0], d[0] / b[0]
    for i in range(1, n):
        m = b[i] - a[i] * cp[i - 1]
        cp[i] = c[i] / m
        dp[i] = (d[i] - a[i] * dp[i - 1]) / m
    x = [0.0] * n
    x[-1] = dp[-1]
    for i in range(n - 2, -1, -1):
        x[i] = dp[i] - cp[i] * x[i + 1]
    return x

def one_d(T1, T2, k1, c1, k2, c2, h, tc, after, h_air, T_air, L=6.0, n=600, steps=800):
    """The same two bodies on a fine 1D grid (L mm each, n elements, lumped, backward Euler): in contact for tc,
    then the slab's face in air (h_air) for `after`. Returns the surfaces at the exit, and the slab's surface
    averaged over `after` (what the window past the exit averages) and at its end, and the heat the slab lost in
    contact per unit area."""
    N, dx = 2 * (n + 1), L / n
    T = [T1] * (n + 1) + [T2] * (n + 1)
    cap = [c1 * dx] * (n + 1) + [c2 * dx] * (n + 1)
    for i in (0, n, n + 1, N - 1):
        cap[i] *= 0.5

    def step(T, dt, link, hs):
        a, c = [0.0] * N, [0.0] * N
        b = [cap[i] / dt for i in range(N)]
        d = [cap[i] / dt * T[i] for i in range(N)]
        for i in range(N - 1):
            g = (h if link else 0.0) if i == n else (k1 if i < n else k2) / dx
            b[i] += g; b[i + 1] += g; c[i] -= g; a[i + 1] -= g
        b[n] += hs
        d[n] += hs * T_air
        return thomas(a, b, c, d)

    for _ in range(steps):
        T = step(T, tc / steps, True, 0.0)
    exit_ = (T[n], T[n + 1])
    lost = sum(cap[i] * (T1 - T[i]) for i in range(n + 1))  # the heat the slab gave the roll [per unit area]
    acc = 0.5 * T[n]
    for s in range(steps):
        T = step(T, after / steps, False, h_air)
        acc += T[n] * (0.5 if s == steps - 1 else 1.0)
    return exit_, acc / steps, T[n], lost
PY

# variant NAME [KEY=VALUE | -heat]... -> $WORK/NAME.json: the sample with these process fields (-heat: without
# process.heat_transfer), writing only the last increment's VTU, uncompressed
variant() {
  python3 - "$SAMPLE" "$WORK/$1.json" "${@:2}" <<'PY'
import json, sys
src, dst, *fields = sys.argv[1:]
p = json.load(open(src))
p["output"] = {"increments": "last", "compression": "none"}
for f in fields:
    if f == "-heat":
        del p["process"]["heat_transfer"]
        continue
    k, v = f.split("=")
    p["process"][k] = int(v) if v.isdigit() and k != "travel" else float(v)
json.dump(p, open(dst, "w"), indent=1)
PY
}

# run NAME [OUT]: rollsim run $WORK/NAME.json into $WORK/OUT (default NAME) once; /usr/bin/time's figures and its
# progress lines beside it
converged() { python3 -c "import sys; from hot import ended; sys.exit(ended('$WORK/$1') != 'converged')"; }
run() {
  local out=${2:-$1}
  [[ -e $WORK/$out.time ]] && return 0
  /usr/bin/time -f "%e %U %S %M" -o "$WORK/$out.time" "$ROLLSIM" run "$WORK/$1.json" --out "$WORK/$out" \
    >/dev/null 2>"$WORK/$out.err" || true
}

share() {
  variant s-36x8
  variant s-48x12-g1.25 slab_nx=48 slab_nt=12 thickness_grading=1.25
  variant s-72x12-g1.5 slab_nx=72 slab_nt=12
  for v in s-36x8 s-48x12-g1.25 s-72x12-g1.5; do
    for r in $(seq "$REPEAT"); do run "$v" "$v-$r"; done
  done
  echo "| slab mesh | top element mm | dofs | how it ended | converged steps | heat factorizations | Newton iterations | heat s | total s | heat / total | heat / (total − heat) | goal ≤ 15 % | peak MiB |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  python3 - "$WORK" "$REPEAT" <<'PY'
import json, statistics, sys
from hot import *
work, repeat = sys.argv[1], int(sys.argv[2])
notes = []
for name, label in (("s-36x8", "36 × 8, grading 1.5 (the sample)"), ("s-48x12-g1.25", "48 × 12, grading 1.25"),
                    ("s-72x12-g1.5", "72 × 12, grading 1.5")):
    runs = [f"{work}/{name}-{r}" for r in range(1, repeat + 1)]
    top = top_element(json.load(open(f"{work}/{name}.json"))["process"])
    d = summary(runs[0])
    if ended(runs[0]) != "converged":
        notes.append(f"- {label}: {why(runs[0])}")
    if not d or "timing" not in d:
        print(f"| {label} | {top:.2f} | | {ended(runs[0])} | | | | | | | | | |")
        continue
    t = [summary(r)["timing"] for r in runs]
    heat = statistics.median(x["heat_s"] for x in t)
    total = statistics.median(x["total_s"] for x in t)
    share = statistics.median(x["heat_s"] / x["total_s"] for x in t)
    mech = statistics.median(x["heat_s"] / (x["total_s"] - x["heat_s"]) for x in t)
    peak = max(int(open(r + ".time").read().split()[-1]) for r in runs) / 1024
    print(f"| {label} | {top:.2f} | {d['model']['dofs']} | {ended(runs[0])} | {len(rows(runs[0]))} | "
          f"{d['timing']['heat_factorizations']} | {d['solver']['newton_iterations']} | {heat:.3f} | {total:.2f} | "
          f"{100 * share:.1f} % | {100 * mech:.1f} % | {'met' if mech <= 0.15 else 'not met'} | {peak:.0f} |")
print("\n".join([""] + notes) if notes else "")
PY
}

selective() {
  variant heat
  variant noheat -heat
  variant heat-cmp travel="$TRAVEL_CMP"
  variant noheat-cmp -heat travel="$TRAVEL_CMP"
  for v in heat-cmp noheat-cmp heat noheat; do run "$v"; done
  echo "| pass | how it ended | Newton iterations | cut-backs | tangent evaluations slab / roll | factorizations slab / roll | slab evaluations per iteration | roll force at the end N/mm | mean over the last 20 mm |"
  echo "|---|---|---|---|---|---|---|---|---|"
  python3 - "$WORK" "$TRAVEL_CMP" <<'PY'
import sys
from hot import *
work, cmp_ = sys.argv[1], float(sys.argv[2])
notes = []
for name, label, travel in (("heat-cmp", f"with heat, to {cmp_:g} mm", cmp_), ("noheat-cmp", f"without heat, to {cmp_:g} mm", cmp_),
                            ("heat", "with heat, to 120 mm", 120.0), ("noheat", "without heat, to 120 mm", 120.0)):
    out = f"{work}/{name}"
    d = summary(out)
    if ended(out) != "converged":
        notes.append(f"- {label}: {why(out)}")
    if not d or "solver" not in d:
        print(f"| {label} | {ended(out)} | | | | | | | |")
        continue
    s = d["solver"]
    ev, fac = s["stiffness_evaluations"], s["factorizations"]
    print(f"| {label} | {ended(out)} | {s['newton_iterations']} | {cutbacks(out)} | {ev.get('slab', 0)} / {ev.get('roll', 0)} | "
          f"{fac.get('slab', 0)} / {fac.get('roll', 0)} | {ev.get('slab', 0) / s['newton_iterations']:.3f} | "
          f"{rows(out)[-1]['roll_force']:.0f} | {fmt(mean(out, 'roll_force', travel - 20, travel), '.0f')} |")
print("\n".join([""] + notes) if notes else "")
PY
}

coupling() {
  variant heat
  variant heat-half travel_increment=0.5
  variant noheat-cmp -heat travel="$TRAVEL_CMP"
  variant noheat-cmp-half -heat travel="$TRAVEL_CMP" travel_increment=0.5
  for v in heat heat-half noheat-cmp noheat-cmp-half; do run "$v"; done
  echo "| quantity | at travel mm | 1 mm steps | 0.5 mm steps | relative difference | difference against the change since the start |"
  echo "|---|---|---|---|---|---|"
  python3 - "$WORK" "$TRAVEL_CMP" <<'PY'
import sys
from hot import *
work, cmp_ = sys.argv[1], float(sys.argv[2])
notes = []
for name in ("heat", "heat-half", "noheat-cmp", "noheat-cmp-half"):
    if ended(f"{work}/{name}") != "converged":
        notes.append(f"- {name}: {ended(work + '/' + name)}: {why(work + '/' + name)}")
start = {"slab_temperature": 1100.0, "surface_temperature": 1100.0, "roll_temperature": 60.0}
label = {"roll_force": "roll force N/mm", "slab_temperature": "slab mean °C",
         "surface_temperature": "slab surface past the exit °C", "roll_temperature": "roll surface, hottest node °C"}
a, b = f"{work}/heat", f"{work}/heat-half"
for t in (cmp_, 120.0):
    ra, rb = at(a, t), at(b, t)
    if not (ra and rb):
        continue
    for k in label:
        x, y = ra[k], rb[k]
        change = (f"{y - x:+.3f} K: {abs(y - x) / abs(x - start[k]):.2%} of the {abs(x - start[k]):.1f} K "
                  f"{'drop' if x < start[k] else 'rise'}") if k in start else "–"
        print(f"| {label[k]} | {t:g} | {x:.2f} | {y:.2f} | {(y - x) / x:+.2e} | {change} |")
for name_a, name_b, what, lo, hi in ((a, b, "with heat", 100.0, 120.0), (a, b, "with heat", cmp_ - 20, cmp_),
                                     (f"{work}/noheat-cmp", f"{work}/noheat-cmp-half", "without heat", cmp_ - 20, cmp_)):
    x, y = mean(name_a, "roll_force", lo, hi), mean(name_b, "roll_force", lo, hi)
    print(f"| {what}: roll force N/mm, mean over {lo:g}–{hi:g} mm | {hi:g} | {fmt(x, '.1f')} | {fmt(y, '.1f')} | "
          f"{fmt((y - x) / x, '+.2e')} | – |")
print("\n".join([""] + notes) if notes else "")
PY
}

chill() {
  # each mesh to TRAVEL_CMP mm (the exit plane's surface is steady by then: the arc takes about 78 mm of travel) and
  # to 200 mm (the window past the exit too, from about 150 mm), in 1 mm steps, or in 0.5 mm where 1 mm stops short
  for m in "8 1" "8 1.5" "8 2" "12 1.25" "12 1.5"; do
    read -r nt g <<<"$m"
    variant "c-$nt-$g-cmp" slab_nt="$nt" thickness_grading="$g" travel="$TRAVEL_CMP"
    variant "c-$nt-$g" slab_nt="$nt" thickness_grading="$g" travel=200
    variant "c-$nt-$g-half" slab_nt="$nt" thickness_grading="$g" travel=200 travel_increment=0.5
    run "c-$nt-$g-cmp"
    run "c-$nt-$g"
    converged "c-$nt-$g" || run "c-$nt-$g-half"
  done
  "$ROLLSIM" check "$SAMPLE" >"$WORK/check.txt"
  python3 - "$WORK" "$TRAVEL_CMP" <<'PY'
import json, math, re, sys
from hot import *
work, cmp_ = sys.argv[1], float(sys.argv[2])
check = open(work + "/check.txt").read()
tc = float(re.search(r"time in the roll gap\s+([\d.]+) ms", check).group(1)) / 1000
L = float(re.search(r"contact length\s+([\d.]+) mm", check).group(1))
v = float(re.search(r"roll surface speed\s+([\d.]+) m/s", check).group(1)) * 1000
p = json.load(open(work + "/c-8-1.5.json"))["process"]
k1, c1, k2, c2, h = 28.0, p["slab_heat_capacity"], 40.0, 3.6, 20.0  # the heat_transfer defaults
alpha = k1 / c1
depth = math.sqrt(alpha * tc)
T0, Tr = p["slab_temperature"], 60.0
s_exit, r_exit = closed_form(T0, Tr, k1, c1, k2, c2, h, tc)
one_sided = closed_form(T0, Tr, k1, c1, 1e12, 1e12, h, tc)[0]
d = summary(work + "/c-8-1.5")
slip = d["results"]["rolling"]["forward_slip"] if d and "results" in d else 0.06
after = L / (v * (1 + slip))
Ts = 273.15 + 900  # the air's convection 0.015 and radiation (ε 0.8) linearised at a 900 °C surface
h_air = 0.015 + 0.8 * 5.670374419e-11 * (Ts ** 2 + 293.15 ** 2) * (Ts + 293.15)
(e_s, e_r), window, end, lost = one_d(T0, Tr, k1, c1, k2, c2, h, tc, after, h_air, 20.0)
(sink_exit, _), sink_window, _, _ = one_d(T0, Tr, k1, c1, 1e5, 1e5, h, tc, after, h_air, 20.0)  # the roll a sink
h1 = p.get("slab_thickness", 100) * (1 - p["reduction"])
print(f"Time in the roll gap t_c = {1000 * tc:.1f} ms (`rollsim check`); α = k/ρc = {k1:g}/{c1:g} = {alpha:.2f} mm²/s, so "
      f"√(α t_c) = {depth:.3f} mm in the slab ({math.sqrt(k2 / c2 * tc):.3f} mm in the roll, α = {k2 / c2:.1f} mm²/s).")
print()
print(f"Reference: two semi-infinite bodies, the slab at {T0:g} °C and the roll at {Tr:g} °C, joined through "
      f"h_c = {h:g} kW/(m² K) for t_c. In closed form the slab's surface leaves the gap at {s_exit:.1f} °C "
      f"(a chill of {T0 - s_exit:.0f} K) and the roll's at {r_exit:.1f} °C. With the roll held at {Tr:g} °C (an "
      f"infinite sink) the slab's surface would leave at {one_sided:.1f} °C (chill {T0 - one_sided:.0f} K). A 1D grid of 0.01 mm gives "
      f"{e_s:.1f} / {e_r:.1f} °C at the exit. It then keeps the slab's surface in air for {1000 * after:.1f} ms: "
      f"that is the window of {L:g} mm past the exit at the exit speed ωR (1 + {100 * slip:.1f} % forward slip). "
      f"Averaged over that window the surface is {window:.1f} °C (a chill of {T0 - window:.0f} K); at the window's "
      f"end it is {end:.1f} °C. With the roll a sink the window averages {sink_window:.1f} °C (chill "
      f"{T0 - sink_window:.0f} K; exit {sink_exit:.1f} °C). The heat the slab loses in contact, spread over its {h1 / 2:g} mm half thickness, "
      f"lowers its section mean by {lost / (c1 * h1 / 2):.1f} K. This reference has no plastic heat, no friction "
      f"heat and no deformation of the chilled layer.")
print()
print(f"At {cmp_:g} mm of travel (1 mm steps):")
print()
print(f"| slab_nt, grading | top element mm | top / √(α t_c) | how it ended | surface node at the exit plane °C | its chill K (1D: {T0 - s_exit:.0f}; roll a sink: {T0 - sink_exit:.0f}) | surface past the exit °C | section mean past the exit °C | roll surface °C, hottest (1D: {r_exit:.0f} at the exit) |")
print("|---|---|---|---|---|---|---|---|---|")
meshes = (("8", "1"), ("8", "1.5"), ("8", "2"), ("12", "1.25"), ("12", "1.5"))
notes = []
for nt, g in meshes:
    out = f"{work}/c-{nt}-{g}-cmp"
    size = top_element(json.load(open(out + ".json"))["process"])
    row = f"| {nt}, {g} | {size:.2f} | {size / depth:.2f} | {ended(out)} |"
    if ended(out) != "converged":
        notes.append(f"- slab_nt {nt}, grading {g}, to {cmp_:g} mm: {why(out)}")
        print(row + " | | | | |")
        continue
    r = rows(out)[-1]
    node = at_x(top_surface(out), 0.0)
    print(f"{row} {node:.1f} | {T0 - node:.0f} | {r['surface_temperature']:.1f} | {section_mean(out, 0, L):.1f} | "
          f"{r['roll_temperature']:.1f} |")
print("\n".join([""] + notes) if notes else "")
print()
print("To 200 mm (the window past the exit averaged over 160–200 mm, where it is steady):")
print()
print(f"| slab_nt, grading | steps mm | how it ended | surface past the exit °C | chill K (1D: {T0 - window:.0f}; roll a sink: {T0 - sink_window:.0f}) | chill of the top 3 / 5 / 10 mm's mean K | section mean past the exit °C | roll surface °C, hottest | roll force N/mm |")
print("|---|---|---|---|---|---|---|---|---|")
notes = []
for nt, g in meshes:
    out = f"{work}/c-{nt}-{g}"
    if ended(out) != "converged":
        notes.append(f"- slab_nt {nt}, grading {g}, 1 mm steps: {ended(out)}: {why(out)}")
        if summary(out + "-half") or rows(out + "-half"):
            out += "-half"
            if ended(out) != "converged":
                notes.append(f"- slab_nt {nt}, grading {g}, 0.5 mm steps: {ended(out)}: {why(out)}")
    step = "0.5" if out.endswith("-half") else "1"
    if ended(out) != "converged":
        print(f"| {nt}, {g} | {step} | {ended(out)} | | | | | | |")
        continue
    surf = mean(out, "surface_temperature", 160, 200)
    layers = " / ".join(f"{T0 - layer_mean(out, 0, L, t):.0f}" for t in (3, 5, 10))
    print(f"| {nt}, {g} | {step} | converged | {surf:.1f} | {T0 - surf:.0f} | {layers} | {section_mean(out, 0, L):.1f} | "
          f"{rows(out)[-1]['roll_temperature']:.1f} | {mean(out, 'roll_force', 160, 200):.0f} |")
print("\n".join([""] + notes) if notes else "")
PY
}

roll() {
  for n in 6 12 24 48; do
    variant "r-$n" roll_n_radial="$n"
    run "r-$n"
  done
  echo "| roll_n_radial | radial element mm | how it ended | roll surface °C, hottest node | slab surface past the exit °C | roll force N/mm, mean over 100–120 mm | Newton iterations |"
  echo "|---|---|---|---|---|---|---|"
  python3 - "$WORK" <<'PY'
import sys
from hot import *
work = sys.argv[1]
notes = []
for n in (6, 12, 24, 48):
    out = f"{work}/r-{n}"
    r, d = rows(out), summary(out)
    if ended(out) != "converged":
        notes.append(f"- roll_n_radial {n}: {why(out)}")
    if not r:
        print(f"| {n} | {150 / n:.2f} | {ended(out)} | | | | |")
        continue
    its = d["solver"]["newton_iterations"] if d and "solver" in d else ""
    print(f"| {n} | {150 / n:.2f} | {ended(out)} | {r[-1]['roll_temperature']:.1f} | {r[-1]['surface_temperature']:.1f} | "
          f"{fmt(mean(out, 'roll_force', 100, 120), '.0f')} | {its} |")
print("\n".join([""] + notes) if notes else "")
PY
}

cpu() {
  variant heat-cmp travel="$TRAVEL_CMP"
  variant noheat-cmp -heat travel="$TRAVEL_CMP"
  for r in $(seq "$REPEAT"); do  # in turn, so that a drift of the machine's speed touches both alike
    run heat-cmp "cpu-heat-$r"
    run noheat-cmp "cpu-noheat-$r"
  done
  echo "| pass (to $TRAVEL_CMP mm) | CPU s (user + system), median of $REPEAT | min – max | wall s, median | peak MiB | CPU with heat / without, median of the pairs (min – max) |"
  echo "|---|---|---|---|---|---|"
  python3 - "$WORK" "$REPEAT" <<'PY'
import statistics, sys
work, repeat = sys.argv[1], int(sys.argv[2])
def fig(name, r):
    e, u, s, m = open(f"{work}/cpu-{name}-{r}.time").read().split()[-4:]
    return float(u) + float(s), float(e), int(m) / 1024
ratios = [fig("heat", r)[0] / fig("noheat", r)[0] for r in range(1, repeat + 1)]
for name, label in (("heat", "with heat"), ("noheat", "without heat")):
    f = [fig(name, r) for r in range(1, repeat + 1)]
    cpu = [x[0] for x in f]
    ratio = f"{statistics.median(ratios):.3f} ({min(ratios):.3f} – {max(ratios):.3f})" if name == "heat" else "1"
    print(f"| {label} | {statistics.median(cpu):.2f} | {min(cpu):.2f} – {max(cpu):.2f} | "
          f"{statistics.median(x[1] for x in f):.2f} | {max(x[2] for x in f):.0f} | {ratio} |")
PY
}

case $PART in
  share) share ;;
  selective) selective ;;
  coupling) coupling ;;
  chill) chill ;;
  roll) roll ;;
  cpu) cpu ;;
  all)
    echo "rollsim: $("$ROLLSIM" --version | tr '\n' ' ')"
    echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores, $(free -g | awk '/Mem:/ {print $2}') GiB;" \
      "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg); $(date -u +%F)"
    echo
    for p in share selective coupling chill roll cpu; do
      echo "### $p"
      echo
      $p
      echo
    done
    echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
    ;;
  *) echo "run_hot_benchmarks: unknown part $PART (share, selective, coupling, chill, roll, cpu or all)" >&2; exit 2 ;;
esac
