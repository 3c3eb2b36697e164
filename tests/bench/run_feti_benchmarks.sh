#!/usr/bin/env bash
# FETI benchmarks of issue 5 -> docs/BENCHMARKS-FETI.md: rollsim_feti_bench (paper Tables VI-XI, iteration anchors,
# threads, crossover; one process per section) and the peak memory of `rollsim run` (FETI vs direct) under
# /usr/bin/time -v.
#
# Usage: tests/bench/run_feti_benchmarks.sh [--build DIR] [--repeat N] [--sections LIST] [--memory-cube N]
#                                          [--idle-wait S] [--out FILE]
#   --build        build directory holding app/rollsim and tests/bench/rollsim_feti_bench (default: build); this
#                  script builds nothing
#   --repeat       repeats per timing (medians), default 3
#   --sections     rollsim_feti_bench sections, run one process each in this order (default:
#                  paper,plate,anchors,threads,crossover); "none" runs none
#   --memory-cube  elements per side of the largest 3D cube of the peak-memory runs (default 40); 0 skips them
#   --idle-wait    seconds to wait, at most, for an idle machine before the threads section (default 600; 0: no wait)
#   --out          the report (default docs/BENCHMARKS-FETI.md)
# Needs /usr/bin/time, python3 (standard library: writes the large cantilevers, reads summary.json), awk.
# Timing is not a test: nothing here fails on a slow machine or on a missed target; it fails only if a run fails.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
COMMAND="tests/bench/run_feti_benchmarks.sh $*"
BUILD=$ROOT/build
REPEAT=3
SECTIONS=paper,plate,anchors,threads,crossover
CUBE=40
IDLE_WAIT=600
OUT=$ROOT/docs/BENCHMARKS-FETI.md
while (($#)); do
  case $1 in
    --build) BUILD=$(realpath "$2"); shift 2 ;;
    --repeat) REPEAT=$2; shift 2 ;;
    --sections) SECTIONS=$2; shift 2 ;;
    --memory-cube) CUBE=$2; shift 2 ;;
    --idle-wait) IDLE_WAIT=$2; shift 2 ;;
    --out) OUT=$(realpath -m "$2"); shift 2 ;;
    -h|--help) sed -n 2,17p "$0"; exit 0 ;;
    *) echo "run_feti_benchmarks: unknown argument $1" >&2; exit 2 ;;
  esac
done
ROLLSIM=$BUILD/app/rollsim
BENCH=$BUILD/tests/bench/rollsim_feti_bench
[[ -x $BENCH ]] || { echo "run_feti_benchmarks: $BENCH is not built (cmake -DROLLSIM_BUILD_TESTS=ON -DROLLSIM_BUILD_BENCH=ON build && cmake --build build)" >&2; exit 2; }
for tool in "$ROLLSIM" "$BENCH" /usr/bin/time python3 awk; do
  command -v "$tool" > /dev/null || { echo "run_feti_benchmarks: $tool not found" >&2; exit 2; }
done
CORES=$(nproc --all)
LOAD_START=$(cut -d' ' -f1-3 /proc/loadavg)
DATE_START=$(date -u '+%Y-%m-%d %H:%M UTC')
START=$(date +%s)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

log() { echo "run_feti_benchmarks: $*" >&2; }
calc() { awk "BEGIN {printf \"$1\", $2}"; }  # calc FORMAT EXPRESSION
json() { python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(eval(sys.argv[2], {"d": d}))' "$@"; }

# ---------------------------------------------------------------- 1. the program
# idle_wait LIMIT: waits until other jobs use less than 15 % of the machine over 10 s (at most LIMIT seconds);
# prints how long it waited and whether the machine became idle
idle_wait() {
  local limit=$1 t0 a b busy total
  t0=$(date +%s)
  while :; do
    read -ra a < /proc/stat
    sleep 10
    read -ra b < /proc/stat
    busy=$(((b[1] + b[2] + b[3]) - (a[1] + a[2] + a[3])))
    total=$((busy + b[4] - a[4]))
    echo $(($(date +%s) - t0)) > "$WORK/waited.txt"
    if ((100 * busy < 15 * total)); then
      echo "became idle after $(($(date +%s) - t0)) s"
      return
    fi
    if (($(date +%s) - t0 >= limit)); then
      echo "did not become idle within $limit s (other jobs used $((100 * busy / total)) % of it in the last 10 s)"
      return
    fi
  done
}

# the sections run one process each, in document order; before `threads` (2 threads vs 1: meaningless when another
# session holds a core) the script waits up to IDLE_WAIT seconds for the machine to become idle
: > "$WORK/body.md"
: > "$WORK/conclusions.md"
IDLE_NOTE=""
for section in ${SECTIONS//,/ }; do
  [[ $section == none ]] && continue
  if [[ $section == threads ]] && ((IDLE_WAIT > 0)); then
    log "waiting up to $IDLE_WAIT s for an idle machine before the threads section"
    IDLE_NOTE=$(idle_wait "$IDLE_WAIT")
    log "machine $IDLE_NOTE"
  fi
  log "rollsim_feti_bench --repeat $REPEAT --sections $section"
  "$BENCH" --repeat "$REPEAT" --sections "$section" > "$WORK/bench-$section.md"
  # the program prints its conclusions after this line; they go last, after the memory section
  awk '/^<!-- conclusions -->$/ {exit} {print}' "$WORK/bench-$section.md" >> "$WORK/body.md"
  awk 'c {print} /^<!-- conclusions -->$/ {c = 1}' "$WORK/bench-$section.md" >> "$WORK/conclusions.md"
  if [[ $section == threads && -n $IDLE_NOTE ]]; then
    echo "Before this section the script waited for an idle machine: it $IDLE_NOTE." >> "$WORK/body.md"
    echo >> "$WORK/body.md"
  fi
done

# ---------------------------------------------------------------- 2. peak memory, end to end
# cube N: a 3D cantilever cube of N³ unit elements like tests/bench/data/cantilever-3d-24x24x24.json
cube() {
  python3 - "$ROOT/tests/bench/data/cantilever-3d-24x24x24.json" "$1" "$WORK/cantilever-3d-$1.json" << 'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
n = int(sys.argv[2])
d["name"] = f"cantilever-3d-{n}x{n}x{n}"
d["description"] = f"generated by run_feti_benchmarks.sh from cantilever-3d-24x24x24.json with {n}^3 elements"
m = d["bodies"][0]["mesh"]
for k in ("nx", "ny", "nz"): m[k] = n
for k in ("lx", "ly", "lz"): m[k] = float(n)
s = d["bodies"][0]["node_sets"][0]
s["box_min"], s["box_max"] = [n, 0, n], [n, n, n]
for p in d.get("probes", []):
    p["at"] = [c * n / 24.0 for c in p["at"]]
json.dump(d, open(sys.argv[3], "w"), indent=2)
EOF
  echo "$WORK/cantilever-3d-$1.json"
}

/usr/bin/time -v -o "$WORK/floor.txt" "$ROLLSIM" --version > /dev/null
FLOOR=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$WORK/floor.txt")

# memory_row KEY LABEL PROJECT ARGS...: one `rollsim run` under /usr/bin/time -v, 2 threads; a table row on stdout,
# "KEY rss_kib wall_s" appended to memory.txt
memory_row() {
  local key=$1 label=$2 project=$3 tv=$WORK/time-v.txt out=$WORK/run rss wall its
  shift 3
  rm -rf "$out"
  OPENBLAS_NUM_THREADS=2 /usr/bin/time -v -o "$tv" "$ROLLSIM" run "$project" --out "$out" --threads 2 --quiet "$@" \
    > "$WORK/stdout.txt" 2> "$WORK/stderr.txt" || { log "failed: $label"; cat "$WORK/stderr.txt" >&2; exit 1; }
  rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$tv")
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":");
    print (n == 3) ? t[1] * 3600 + t[2] * 60 + t[3] : t[1] * 60 + t[2]}' "$tv")
  its=$(json "$out/summary.json" "d['solver'].get('cg_iterations_total', '—') if d['solver'].get('mode') == 'feti' else '—'")
  echo "| $label | $(json "$out/summary.json" "d['model']['dofs']") | \`${*}\` | $its | $wall | $(calc %.0f "$rss / 1024") |"
  echo "$key $rss $wall" >> "$WORK/memory.txt"
}

memory_section() {
  local s2=$ROOT/samples/cantilever-2d-120x120.json s3=$ROOT/tests/bench/data/cantilever-3d-24x24x24.json big
  local feti=(--solver feti --preconditioner dirichlet --cg-tolerance 1e-6)
  cat << EOF
## 6. Peak memory, end to end (\`rollsim run\`, /usr/bin/time -v)

The whole process (read, build, solve, write summary.json and result.vtu) under \`/usr/bin/time -v\` (maximum
resident set size), \`--threads 2\` and OPENBLAS_NUM_THREADS=2, one run each. FETI: Dirichlet, non-redundant,
tolerance 1e-6, CHOLMOD in the subdomains. The floor is the peak of \`rollsim --version\` (the program and its
libraries, no model): $(calc %.0f "$FLOOR / 1024") MiB.$( ((CUBE > 0)) && echo " The ${CUBE}³ cube is the largest 3D case run here
(written by this script from tests/bench/data/cantilever-3d-24x24x24.json); larger cubes fit in memory but not in the
time budget of this benchmark (see the extrapolation below the table).")

| case | dofs | arguments | CG its | wall s | peak RSS MiB |
|---|---|---|---|---|---|
EOF
  : > "$WORK/memory.txt"
  log "peak memory runs"
  memory_row d2 "2D 120² direct" "$s2" --solver direct
  memory_row f2 "2D 120² FETI 4×4" "$s2" "${feti[@]}" --partition 4x4
  memory_row d3 "3D 24³ direct" "$s3" --solver direct
  memory_row f3 "3D 24³ FETI 4×4×4" "$s3" "${feti[@]}" --partition 4x4x4
  if ((CUBE > 0)); then
    big=$(cube "$CUBE")
    local k=$((CUBE / 8 > 2 ? CUBE / 8 : 2))
    memory_row db "3D ${CUBE}³ direct" "$big" --solver direct
    memory_row fb "3D ${CUBE}³ FETI ${k}×${k}×${k}" "$big" "${feti[@]}" --partition "${k}x${k}x${k}"
  fi
  echo
  if ((CUBE > 24)); then
    # the largest cube direct would fit in: peak ∝ dofs^p from the 24³ and CUBE³ runs, dofs ≈ 3 (n + 1)³
    local r24 rb w24 wb
    r24=$(awk '$1 == "d3" {print $2}' "$WORK/memory.txt")
    rb=$(awk '$1 == "db" {print $2}' "$WORK/memory.txt")
    w24=$(awk '$1 == "d3" {print $3}' "$WORK/memory.txt")
    wb=$(awk '$1 == "db" {print $3}' "$WORK/memory.txt")
    awk -v r1="$r24" -v r2="$rb" -v w1="$w24" -v w2="$wb" -v n2="$CUBE" \
        -v mem="$(awk '/MemTotal/ {print $2}' /proc/meminfo)" 'BEGIN {
      g = ((n2 + 1) / 25) ^ 3
      p = log(r2 / r1) / log(g); q = log(w2 / w1) / log(g)
      n = n2; while (r2 * (((n + 1) / (n2 + 1)) ^ 3) ^ p < 0.8 * mem) n++
      n--; t = w2 * (((n + 1) / (n2 + 1)) ^ 3) ^ q
      printf "- Extrapolation from the 24³ and %d³ `direct` runs (not run): peak ∝ dofs^%.2f and wall time ∝ " \
             "dofs^%.2f, so the largest cube whose `direct` run stays under 80 %% of this machine'"'"'s memory is " \
             "about %d³, at about %.0f min for one `direct` run.\n", n2, p, q, n, t / 60
    }'
  fi
  local pair d f
  for pair in "d2 f2 2D 120²" "d3 f3 3D 24³" "db fb 3D ${CUBE}³"; do
    read -r d f label <<< "$pair"
    d=$(awk -v k="$d" '$1 == k {print $2}' "$WORK/memory.txt")
    f=$(awk -v k="$f" '$1 == k {print $2}' "$WORK/memory.txt")
    [[ -n $d && -n $f ]] || continue
    echo "- $label: FETI / direct = $(calc %.2f "$f / $d") of the peak, $(calc %.2f "($f - $FLOOR) / ($d - $FLOOR)") above the floor."
  done
  echo
}

# memory_finding: the conclusions' bullet on peak memory (the largest cube run)
memory_finding() {
  local key_d=db key_f=fb label="${CUBE}³" d f
  ((CUBE > 0)) || { key_d=d3; key_f=f3; label="24³"; }
  d=$(awk -v k="$key_d" '$1 == k {print $2}' "$WORK/memory.txt")
  f=$(awk -v k="$key_f" '$1 == k {print $2}' "$WORK/memory.txt")
  [[ -n $d && -n $f ]] || return 0
  echo "- **Peak memory** (\`rollsim run\`, 3D $label cube, the largest run): FETI $(calc %.0f "$f / 1024") MiB, direct" \
       "$(calc %.0f "$d / 1024") MiB — FETI / direct = $(calc %.2f "$f / $d") ($(calc %.2f "($f - $FLOOR) / ($d - $FLOOR)")" \
       "above the $(calc %.0f "$FLOOR / 1024") MiB floor of the program)."
}

memory_section > "$WORK/memory.md"
memory_finding > "$WORK/memory-finding.md"

# ---------------------------------------------------------------- 3. the report
machine_section() {
  local cpu blas version
  cpu=$(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo)
  blas=$("$ROLLSIM" --version | sed -n 's/^BLAS: //p')
  version=$("$ROLLSIM" --version | head -1)
  cat << EOF
# FETI benchmarks (issue 5: paper Tables VI–XI, iteration anchors, threads, crossover, memory)

Generated by \`tests/bench/run_feti_benchmarks.sh\` — do not edit by hand. To regenerate (after building \`rollsim\`
and \`rollsim_feti_bench\` with \`-DROLLSIM_BUILD_TESTS=ON\`):

    $COMMAND

The numbers come from \`rollsim_feti_bench\` (\`tests/bench/feti_bench.cpp\`, one process per section 1–5) and, for
peak memory, from \`rollsim run\` under \`/usr/bin/time -v\` (section 6). The paper's values are read at run time
from \`tests/bench/paper/t06..t11*.csv\`; nothing of ours is typed in.

- Date: $DATE_START. Total bench time: $(calc %.1f "($(date +%s) - $START) / 60") min, of which
  $(calc %.1f "$(cat "$WORK/waited.txt" 2> /dev/null || echo 0) / 60") min waiting for an idle machine before the threads section.
- Machine: $cpu, $CORES cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo). Shared with
  other jobs: load average (1, 5, 15 min) $LOAD_START at the start, $(cut -d' ' -f1-3 /proc/loadavg) at the end.
  Only ratios measured in the same session mean something; the variants are interleaved within every repeat.
- $version, BLAS: $blas.
- Repeats: median of $REPEAT per timing (at least 9 for the millisecond plate runs; 1 for the largest crossover
  meshes); iteration counts and counts are exact.
- The paper's times are CPU seconds of a 1997 Indigo2 with a skyline solver; only its ratios compare.

EOF
}
{
  machine_section
  cat "$WORK/body.md" "$WORK/memory.md"
  echo "## What this shows"
  echo
  cat "$WORK/conclusions.md" "$WORK/memory-finding.md"
} > "$WORK/BENCHMARKS-FETI.md"
mv "$WORK/BENCHMARKS-FETI.md" "$OUT"
log "wrote $OUT"
