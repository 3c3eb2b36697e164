#!/usr/bin/env bash
# Contact benchmark of issue 4 -> docs/BENCHMARKS-CONTACT.md: the paper's Tables I-III (Example 1, block
# indentation), the floating and Hertz samples, the factorization of the saddle-point matrix (all in one process:
# tests/bench/contact_bench.cpp), and the peak memory of `rollsim run` per solver and sample (/usr/bin/time -v).
#
# Usage: tests/bench/run_contact_benchmarks.sh [--rollsim BIN] [--bench BIN] [--repeat N]
#   --rollsim  the rollsim binary (default build/app/rollsim)
#   --bench    the benchmark program (default build/tests/bench/rollsim_contact_bench; built with the tests)
#   --repeat   repeats per measurement, medians reported (default 5)
# This script builds nothing. Timing is not a test: it fails only if a run fails.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
SAMPLES=(block-indent-2d-50x30 block-indent-2d-70x50 block-indent-2d-90x70 block-indent-3d-10x6x4
         block-indent-3d-20x6x4 block-indent-3d-20x12x4 block-push-2d-50x30 cylinder-indent-2d)
SOLVERS=(skyline direct mixed)
REPEAT=5
ROLLSIM=$ROOT/build/app/rollsim
BENCH=$ROOT/build/tests/bench/rollsim_contact_bench
while (($#)); do
  case $1 in
    --rollsim) ROLLSIM=$2; shift 2 ;;
    --bench) BENCH=$2; shift 2 ;;
    --repeat) REPEAT=$2; shift 2 ;;
    -h|--help) sed -n 2,10p "$0"; exit 0 ;;
    *) echo "run_contact_benchmarks: unknown argument $1" >&2; exit 2 ;;
  esac
done
ROLLSIM=$(realpath "$ROLLSIM")
[[ -x $BENCH ]] || { echo "run_contact_benchmarks: $BENCH is not built (cmake -DROLLSIM_BUILD_TESTS=ON -DROLLSIM_BUILD_BENCH=ON build && cmake --build build)" >&2; exit 2; }
BENCH=$(realpath "$BENCH")
for tool in "$ROLLSIM" "$BENCH" /usr/bin/time awk; do
  command -v "$tool" > /dev/null || { echo "run_contact_benchmarks: $tool not found" >&2; exit 2; }
done
CORES=$(nproc --all)
LOAD_START=$(cut -d' ' -f1-3 /proc/loadavg)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
OUT=$ROOT/docs/BENCHMARKS-CONTACT.md
log() { echo "run_contact_benchmarks: $*" >&2; }
calc() { awk "BEGIN {printf \"$1\", $2}"; }  # calc FORMAT EXPRESSION

# ---------------------------------------------------------------- 1. the in-process benchmark
log "$BENCH --repeat $REPEAT"
"$BENCH" --repeat "$REPEAT" --csv "$WORK/contact.csv" > "$WORK/bench.md"

# ---------------------------------------------------------------- 2. peak memory, one process per solver and sample
# peak SAMPLE SOLVER: "rss_kib wall_s cpu_s" of `rollsim run`, or "refused" when rollsim rejects the model (exit 2)
peak() {
  local tv=$WORK/time-v.txt rc=0
  /usr/bin/time -v -o "$tv" "$ROLLSIM" run "$ROOT/samples/$1.json" --solver "$2" --out "$WORK/run-$1-$2" --quiet \
    > /dev/null 2> "$WORK/stderr.txt" || rc=$?
  if ((rc == 2)); then echo refused; return; fi
  if ((rc != 0)); then log "failed: rollsim run $1 --solver $2"; cat "$WORK/stderr.txt" >&2; exit 1; fi
  awk -F': ' '/Maximum resident set size/ {rss = $2} /Elapsed \(wall clock\)/ {n = split($2, t, ":");
    wall = (n == 3) ? t[1] * 3600 + t[2] * 60 + t[3] : t[1] * 60 + t[2]} /User time|System time/ {cpu += $2}
    END {print rss, wall, cpu}' "$tv"
}
/usr/bin/time -v -o "$WORK/floor.txt" "$ROLLSIM" --version > /dev/null
FLOOR=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$WORK/floor.txt")
: > "$WORK/peak.txt"
for s in "${SAMPLES[@]}"; do
  for solver in "${SOLVERS[@]}"; do echo "$s $solver $(peak "$s" "$solver")" >> "$WORK/peak.txt"; done
done
log "peak memory runs done"

peak_field() { awk -v s="$1" -v k="$2" -v f="$3" '$1 == s && $2 == k {print $f}' "$WORK/peak.txt"; }
mib() { [[ $1 == refused ]] && echo "refused (floating body)" || calc %.1f "$1 / 1024"; }

memory_section() {
  local s d m k
  cat << EOF
## Peak memory: \`rollsim run\`, one process per solver and sample

\`/usr/bin/time -v\` (maximum resident set size) around \`rollsim run SAMPLE --solver S\` (reads the project,
builds, solves, writes summary.json and result.vtu), one run each. The floor is the peak RSS of \`rollsim --version\`
(the program and its libraries without a model): $(calc %.1f "$FLOOR / 1024") MiB. Wall times of these single runs
are in brackets, for orientation only (the timings above are the in-process medians).

| sample | skyline MiB | direct MiB | mixed MiB | mixed / direct (above the floor) | mixed / skyline (above the floor) |
|---|---|---|---|---|---|
EOF
  for s in "${SAMPLES[@]}"; do
    k=$(peak_field "$s" skyline 3)
    d=$(peak_field "$s" direct 3)
    m=$(peak_field "$s" mixed 3)
    printf '| %s | %s | %s (%s s) | %s (%s s) | %s | %s |\n' "$s" \
      "$(mib "$k")$([[ $k == refused ]] || echo " ($(peak_field "$s" skyline 4) s)")" \
      "$(mib "$d")" "$(peak_field "$s" direct 4)" "$(mib "$m")" "$(peak_field "$s" mixed 4)" \
      "$(calc %.2f "($m - $FLOOR) / ($d - $FLOOR)")" \
      "$([[ $k == refused ]] && echo — || calc %.2f "($m - $FLOOR) / ($k - $FLOOR)")"
  done
  echo
}

# memory_sentence: the summary bullet on peak memory
memory_sentence() {
  awk -v floor="$FLOOR" '
    {rss[$1, $2] = $3; seen[$1] = 1}
    END {
      for (s in seen) {
        n++
        r = (rss[s, "mixed"] - floor) / (rss[s, "direct"] - floor)
        if (r < 1) less++
        if (n == 1 || r < lo) lo = r
        if (n == 1 || r > hi) hi = r
        if (rss[s, "skyline"] != "refused") {
          ns++
          q = (rss[s, "mixed"] - floor) / (rss[s, "skyline"] - floor)
          if (q < 1) lesssky++
          if (ns == 1 || q < qlo) qlo = q
          if (ns == 1 || q > qhi) qhi = q
        }
      }
      printf "- **Peak memory** (`rollsim run`, above the %.0f MiB floor of the program): `mixed` needs less than " \
             "`direct` on %d of %d samples (ratio %.2f to %.2f) and less than `skyline` on %d of %d (ratio %.2f to " \
             "%.2f); `skyline` refuses the %d floating samples.\n", floor / 1024, less, n, lo, hi, lesssky, ns, qlo,
             qhi, n - ns
    }' "$WORK/peak.txt"
}

machine_section() {
  local cpu blas version
  cpu=$(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo)
  blas=$("$ROLLSIM" --version | sed -n 's/^BLAS: //p')
  version=$("$ROLLSIM" --version | sed -n 's/^rollsim //p')
  cat << EOF
# Contact benchmarks (paper Example 1: Tables I–III; floating and Hertz samples; factorization of (1))

Generated by \`tests/bench/run_contact_benchmarks.sh\` on $(date -u +%Y-%m-%d) (do not edit by hand; rerun the script).
The numbers come from \`rollsim_contact_bench\` (\`tests/bench/contact_bench.cpp\`, one process) and, for peak memory,
from \`rollsim run\` under \`/usr/bin/time -v\`. The paper's values are read from \`tests/bench/paper/*.csv\`.

- Machine: $cpu, $CORES cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo); shared: load
  average $LOAD_START at the start, $(cut -d' ' -f1-3 /proc/loadavg) at the end. Only ratios measured in the same
  session mean something; every time is the median of $REPEAT runs, the solvers interleaved.
- rollsim $version, BLAS in use: $blas; 1 thread everywhere.
- The paper's times are CPU seconds on a 1997 Indigo2; only its ratios compare. Its "direct" is the skyline
  (ACTCOL): its mixed/direct ratio is to be read beside our mixed/skyline. Our \`direct\` (UMFPACK LU, AMD) is a
  modern baseline the paper did not have.

EOF
}

# ---------------------------------------------------------------- 3. the report
{
  machine_section
  # the program's summary, with the memory bullet appended to its list
  awk -v mem="$(memory_sentence)" '
    /^## Summary/ {insum = 1}
    insum && /^- / {bullets = 1}
    insum && bullets && /^$/ {print mem; insum = 0}
    {print}' "$WORK/bench.md"
  memory_section
} > "$WORK/BENCHMARKS-CONTACT.md"
mv "$WORK/BENCHMARKS-CONTACT.md" "$OUT"
log "wrote $OUT"
