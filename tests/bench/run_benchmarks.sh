#!/usr/bin/env bash
# Benchmarks of issues 3 and 14 -> docs/BENCHMARKS.md: `rollsim bench` stages, the factorizations against the DGEMM
# peak (rollsim_factor_bench: CHOLMOD's settings, Eigen, MUMPS), and `rollsim run` (direct, skyline) vs CalculiX.
#
# Usage: tests/bench/run_benchmarks.sh [ROLLSIM] [--repeat N] [--threads "1 2"] [--baseline ROLLSIM_BEFORE]
#                                      [--samples "cantilever-2d-240x60 ..."]
#   ROLLSIM  the rollsim binary (default build/app/rollsim); this script builds nothing. rollsim_factor_bench is
#            taken from the same build tree (tests/bench/), its section skipped when it is not there.
#   --baseline  an earlier rollsim binary: its `bench` and `direct` runs interleaved with ours, for before/after
#            ratios measured in the same session.
# Needs ccx (CalculiX), /usr/bin/time, python3 (standard library, to read summary.json), awk.
# Timing is not a test: nothing here fails on a slow machine; it fails only if a run fails or the
# skyline/CHOLMOD consistency checks of `rollsim bench` fail.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
SAMPLES=(cantilever-2d-120x120 cantilever-2d-240x60 cantilever-3d-16x16x16 cantilever-3d-32x16x8)
declare -A PAPER_DOFS=([cantilever-2d-120x120]=29039 [cantilever-2d-240x60]=29279
                       [cantilever-3d-16x16x16]=13855 [cantilever-3d-32x16x8]=14671)
REPEAT=3
THREADS="1 2"
# rollsim_factor_bench's variants: the first is the reference of the max-diff column
FACTOR_VARIANTS="cholmod;cholmod-defaults;cholmod:ordering=nodes;cholmod:ordering=amd;cholmod:nrelax=8/32/96;skyline;eigen-ldlt;mumps"
ROLLSIM=""
BASELINE=""
while (($#)); do
  case $1 in
    --repeat) REPEAT=$2; shift 2 ;;
    --threads) THREADS=$2; shift 2 ;;
    --baseline) BASELINE=$(realpath "$2"); shift 2 ;;
    --samples) read -ra SAMPLES <<< "$2"; shift 2 ;;  # a subset, e.g. to try the script quickly
    -h|--help) sed -n 2,12p "$0"; exit 0 ;;
    *) ROLLSIM=$1; shift ;;
  esac
done
ROLLSIM=$(realpath "${ROLLSIM:-$ROOT/build/app/rollsim}")
FACTOR_BENCH=$(dirname "$(dirname "$ROLLSIM")")/tests/bench/rollsim_factor_bench
for tool in "$ROLLSIM" ccx /usr/bin/time python3; do
  command -v "$tool" > /dev/null || { echo "run_benchmarks: $tool not found" >&2; exit 2; }
done
CORES=$(nproc --all)  # before any OMP_NUM_THREADS: nproc obeys it
LOAD_START=$(cut -d' ' -f1-3 /proc/loadavg)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
OUT=$ROOT/docs/BENCHMARKS.md

# ---------------------------------------------------------------- helpers
log() { echo "run_benchmarks: $*" >&2; }
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
calc() { awk "BEGIN {printf \"$1\", $2}"; }  # calc FORMAT EXPRESSION
json() { python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(eval(sys.argv[2], {"d": d}))' "$@"; }

# measure LOG CMD...: appends "wall_s peak_rss_kib cpu_s" of one run (wall: nanosecond clock around it; RSS and
# user + system CPU time: time -v)
measure() {
  local log=$1 tv=$WORK/time-v.txt t0 t1
  shift
  t0=$(date +%s%N)
  /usr/bin/time -v -o "$tv" "$@" > "$WORK/stdout.txt" 2> "$WORK/stderr.txt" || {
    log "failed: $*"; cat "$WORK/stderr.txt" >&2; exit 1; }
  t1=$(date +%s%N)
  echo "$(calc %.4f "($t1 - $t0) / 1e9") $(awk -F': ' '/Maximum resident set size/ {rss = $2}
    /User time|System time/ {cpu += $2} /System time/ {sys = $2} /Minor .*page faults/ {pf = $2}
    END {print rss, cpu, sys, pf}' "$tv")" >> "$log"
}
col_median() { awk -v c="$2" '{print $c}' "$1" | median; }  # col_median FILE COLUMN
col_max() { awk -v c="$2" '$c > m {m = $c} END {print m}' "$1"; }

# CalculiX's "total force (fx,fy,fz) for set NAME" block: component COMP (1-based) of set NAME
ccx_total() {
  awk -v set="$2" -v c="$3" '/total force/ && $0 ~ "for set " set " " {grab = 1; next}
                              grab && NF {print $c; exit}' "$1"
}

# ---------------------------------------------------------------- 1. stages (in-process)
stage_bench() {
  local files=()
  for s in "${SAMPLES[@]}"; do files+=("$ROOT/samples/$s.json"); done
  log "rollsim bench --repeat $REPEAT (1 thread)"
  "$ROLLSIM" bench --repeat "$REPEAT" --threads 1 --csv "$WORK/stages.csv" "${files[@]}" > "$WORK/bench.txt"
  if [[ -n $BASELINE ]]; then
    log "baseline: rollsim bench --repeat $REPEAT (1 thread)"
    "$BASELINE" bench --repeat "$REPEAT" --threads 1 --csv "$WORK/stages-before.csv" "${files[@]}" > /dev/null
    "$ROLLSIM" bench --repeat "$REPEAT" --threads 1 --csv "$WORK/stages-again.csv" "${files[@]}" > /dev/null
  fi
}

# ---------------------------------------------------------------- 1b. factorizations against the DGEMM peak
factor_bench() {
  local files=() t
  [[ -x $FACTOR_BENCH ]] || { log "$FACTOR_BENCH is not built (-DROLLSIM_BUILD_BENCH=ON): factorization table skipped"; return 0; }
  for s in "${SAMPLES[@]}"; do files+=("$ROOT/samples/$s.json"); done
  for t in $THREADS; do
    log "rollsim_factor_bench --threads $t"
    OMP_NUM_THREADS=$t OPENBLAS_NUM_THREADS=$t "$FACTOR_BENCH" --repeat "$REPEAT" --threads "$t" \
      --variants "$FACTOR_VARIANTS" "${files[@]}" > "$WORK/factor-t$t.md"
  done
}

# ---------------------------------------------------------------- 2. end to end
# run_e2e SAMPLE THREADS R: repeat R of direct, skyline and ccx, interleaved (drift on a shared machine hits all
# three); main runs the thread counts of a sample back to back in every repeat, so that "2 threads against 1" compares
# runs seconds apart, not two blocks minutes apart. A subshell, so that the thread variables stay local.
run_e2e() (
  s=$1 t=$2 r=$3 dir=$WORK/$1-t$2
  if ((r == 1)); then
    mkdir -p "$dir/ccx"
    "$ROLLSIM" export-ccx "$ROOT/samples/$s.json" "$dir/ccx/model.inp" > /dev/null
  fi
  export OMP_NUM_THREADS=$t OPENBLAS_NUM_THREADS=$t CCX_NPROC_EQUATION_SOLVER=$t CCX_NPROC_STIFFNESS=$t \
         CCX_NPROC_RESULTS=$t
  for mode in direct skyline; do
    measure "$dir/$mode.times" "$ROLLSIM" run "$ROOT/samples/$s.json" --solver "$mode" --out "$dir/$mode" \
      --threads "$t" --quiet
    cp "$dir/$mode/summary.json" "$dir/$mode-summary-$r.json"
  done
  if [[ -n $BASELINE ]]; then
    measure "$dir/before.times" "$BASELINE" run "$ROOT/samples/$s.json" --solver direct --out "$dir/before" \
      --threads "$t" --quiet
  fi
  (cd "$dir/ccx" && measure "$dir/ccx.times" ccx -i model)
  cp "$WORK/stdout.txt" "$dir/ccx-$r.log"
  measure "$dir/startup.times" "$ROLLSIM" --version  # process start-up alone: exec, the libraries, exit
)

# ---------------------------------------------------------------- 3. the report
comp_of() { [[ $1 == *-2d-* ]] && echo 1 || echo 2; }    # index of the y (2D) / z (3D) reaction in summary.json
target_of() { [[ $1 == *-2d-* ]] && echo 8 || echo 2; }  # issue 14: 8x on the 2D squares, 2x on the 3D cubes
first_threads() { echo "$THREADS" | awk '{print $1}'; }
csv_field() {  # csv_field SAMPLE SOLVER COLUMN [CSV], from the `rollsim bench` CSV
  awk -F, -v s="$1" -v k="$2" -v f="$3" 'NR == 1 {for (i = 1; i <= NF; i++) h[$i] = i; next}
                                          $1 == s && $2 == k {print $h[f]}' "${4:-$WORK/stages.csv}"
}

ccx_solver_sentence() {
  local t logf solver
  logf=$(ls "$WORK"/*-t"$(first_threads)"/ccx-1.log | head -1)
  solver=$(grep -o 'using the [a-z ]*solver' "$logf" | head -1 | sed 's/using the //')
  printf 'it factors "using the %s" (its log). Its threads follow OMP_NUM_THREADS and ' "$solver"
  printf 'CCX_NPROC_EQUATION_SOLVER / _STIFFNESS / _RESULTS, set to the same number as rollsim'"'"'s --threads and '
  printf 'OPENBLAS_NUM_THREADS in every run; its log confirms'
  for t in $THREADS; do
    logf=$(ls "$WORK"/*-t"$t"/ccx-1.log | head -1)
    printf ' "%s" (%s)' "$(grep -o 'Using up to [0-9]* cpu(s) for spooles' "$logf" | head -1)" "$t"
  done
}

machine_section() {
  local cpu blas version ccxv
  cpu=$(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo)
  blas=$("$ROLLSIM" --version | sed -n 's/^BLAS: //p')
  version=$("$ROLLSIM" --version | sed -n 's/^rollsim //p')
  ccxv=$( (ccx -v 2> /dev/null || true) | awk '/Version/ {print $NF}')
  cat << EOF
# Benchmarks

Generated by \`tests/bench/run_benchmarks.sh\` on $(date -u +%Y-%m-%d) (do not edit by hand; rerun the script).

- Machine: $cpu, $CORES cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo); shared: load
  average $LOAD_START at the start, $(cut -d' ' -f1-3 /proc/loadavg) at the end. Only ratios measured in the same
  session mean something; every time is the median of $REPEAT runs.
- rollsim $version, BLAS in use: $blas.
- CalculiX $ccxv (Debian's \`calculix-ccx\`): $(ccx_solver_sentence).

EOF
}

factor_table() {
  local peak
  cat << 'EOF'
## Stages in-process: skyline (the paper's ACTCOL baseline) vs direct (CHOLMOD), `rollsim bench`, 1 thread

Same assembled K for both. nnz(L): skyline = stored profile incl. diagonal. flops: the factorization's
prediction; for the skyline also counted in its loop (the two must be equal). max diff = max |u_sky − u_chol| /
max |u_chol| (must be < 1e-10). GFlop/s = flops / factorize seconds; % of peak: of the DGEMM rate that
`rollsim bench` measures in the same process before the samples (best of 40 calls, n = 256):
EOF
  peak=$(csv_field "${SAMPLES[0]}" cholmod dgemm_peak_gflops)
  printf '%.1f GFlop/s on 1 thread.\n\n' "$peak"
  echo "| sample | dofs (paper) | ordering skyline / CHOLMOD | nnz(L) skyline | nnz(L) CHOLMOD |" \
       "flops skyline (counted = predicted) | flops CHOLMOD | flops skyline / CHOLMOD | max diff |" \
       "GFlop/s skyline / CHOLMOD | % of DGEMM peak skyline / CHOLMOD |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  local s f1 f2 same
  for s in "${SAMPLES[@]}"; do
    f1=$(csv_field "$s" skyline flops)
    f2=$(csv_field "$s" cholmod flops)
    same=$(awk -v a="$f1" -v b="$(csv_field "$s" skyline counted_flops)" 'BEGIN {print (a == b) ? "equal" : "DIFFER"}')
    printf '| %s | %s (%s) | %s / %s | %s | %s | %s (%s) | %s | %s | %s |\n' "$s" "$(csv_field "$s" skyline dofs)" \
      "${PAPER_DOFS[$s]}" "$(csv_field "$s" skyline ordering)" "$(csv_field "$s" cholmod ordering)" \
      "$(calc %.3g "$(csv_field "$s" skyline nnz_factor)")" "$(calc %.3g "$(csv_field "$s" cholmod nnz_factor)")" \
      "$(calc %.3g "$f1")" "$same" "$(calc %.3g "$f2")" "$(calc %.2f "$f1 / $f2")" \
      "$(calc %.1e "$(csv_field "$s" skyline max_rel_diff)")" | sed 's/ |$//' | tr -d '\n'
    printf ' | %.2f / %.2f | %.1f %% / %.1f %% |\n' "$(csv_field "$s" skyline factor_gflops)" \
      "$(csv_field "$s" cholmod factor_gflops)" "$(calc %.4f "100 * $(csv_field "$s" skyline factor_gflops) / $peak")" \
      "$(calc %.4f "100 * $(csv_field "$s" cholmod factor_gflops) / $peak")"
  done
  echo
}

# stage_table TITLE COLUMN...: seconds per stage, skyline vs direct, with the ratio
stage_table() {
  local title=$1 s c a b row
  shift
  printf '**%s** (seconds)\n\n| sample |' "$title"
  for c in "$@"; do printf ' %s skyline | %s direct | skyline / direct |' "${c%_s}" "${c%_s}"; done
  printf '\n|---|%s\n' "$(for c in "$@"; do printf -- '---|---|---|'; done)"
  for s in "${SAMPLES[@]}"; do
    row="| $s |"
    for c in "$@"; do
      a=$(csv_field "$s" skyline "$c")
      b=$(csv_field "$s" cholmod "$c")
      row+=" $(calc %.4f "$a") | $(calc %.4f "$b") | $(calc %.2f "$a / $b") |"
    done
    echo "$row"
  done
  echo
}

stage_section() {
  factor_table
  cat << 'EOF'
Assembly: pattern = Assembler construction (sparsity and scatter map, once per model), values = assemble()
(element stiffness and scatter); it is the same code for both solvers, so its ratio only shows the noise.
Analyze = ordering and symbolic factorization.

EOF
  stage_table "Assembly" pattern_s values_s
  stage_table "Analyze" analyze_s
  stage_table "Factorize" factorize_s
  stage_table "Solve" solve_s
}

factor_section() {
  local t
  [[ -f $WORK/factor-t$(first_threads).md ]] || return 0
  cat << 'EOF'
## Factorization: CHOLMOD's settings and the peers against the DGEMM peak (`rollsim_factor_bench`)

The same assembled K (body 0 of each sample) factored by every variant in one process; medians of the repeats.
`cholmod` is what `direct`, `mixed` and `feti` use: CHOLMOD's supernodal Cholesky, ordered by METIS nested
dissection on the node graph (solve/NodeOrdering.h) where nodes have ≥ 12 neighbours (3D) and by AMD below (2D),
CHOLMOD's amalgamation, CHOLMOD's OpenMP loops on the calling thread (base/Blas.h). `cholmod-defaults` is CHOLMOD as rollsim called it before issue 14 (its own choice of AMD, or
METIS on the dof graph when AMD fills too much; with this build's OpenMP teams off too — they are process-wide).
`cholmod:…` changes one setting of `cholmod`. Peers: Eigen's SimplicialLDLT (AMD), MUMPS 5.5 (Debian's
libmumps-dev, one MPI rank, METIS). flops: each solver's own count (MUMPS: RINFOG(3); Eigen: Σ c_j² over L's
columns, CHOLMOD's convention), so GFlop/s compares machine use, factorize seconds compare the answer's cost.
max diff: max |u − u_cholmod| / max |u_cholmod|.

EOF
  for t in $THREADS; do
    printf '**%s thread(s)** — ' "$t"
    cat "$WORK/factor-t$t.md"
    echo
  done
}

before_section() {
  local s t d b a
  [[ -n $BASELINE ]] || return 0
  cat << 'EOF'
## Before and after (this session): the `--baseline` binary against this one

In-process stages (`rollsim bench`, 1 thread, CHOLMOD rows; the two binaries ran one after the other, ours twice
around the baseline: the median of our two runs is compared), and whole `rollsim run --solver direct` processes
(interleaved with the other programs of the end-to-end table: same medians).

| sample | analyze before / after s | ratio | factorize before / after s | ratio | GFlop/s before / after |
|---|---|---|---|---|---|
EOF
  for s in "${SAMPLES[@]}"; do
    local fa fb aa ab
    ab=$(csv_field "$s" cholmod analyze_s "$WORK/stages-before.csv")
    aa=$(printf '%s\n%s\n' "$(csv_field "$s" cholmod analyze_s)" "$(csv_field "$s" cholmod analyze_s "$WORK/stages-again.csv")" | median)
    fb=$(csv_field "$s" cholmod factorize_s "$WORK/stages-before.csv")
    fa=$(printf '%s\n%s\n' "$(csv_field "$s" cholmod factorize_s)" "$(csv_field "$s" cholmod factorize_s "$WORK/stages-again.csv")" | median)
    printf '| %s | %.4f / %.4f | **%.2f×** | %.4f / %.4f | **%.2f×** | %.2f / %.2f |\n' "$s" "$ab" "$aa" \
      "$(calc %.4f "$ab / $aa")" "$fb" "$fa" "$(calc %.4f "$fb / $fa")" \
      "$(calc %.4f "$(csv_field "$s" cholmod flops "$WORK/stages-before.csv") / $fb / 1e9")" \
      "$(calc %.4f "$(csv_field "$s" cholmod flops) / $fa / 1e9")"
  done
  printf '\n| sample | threads | direct before s | direct after s | before / after | CPU s before / after | system s before / after | minor page faults before / after |\n'
  printf '|---|---|---|---|---|---|---|---|\n'
  for t in $THREADS; do
    for s in "${SAMPLES[@]}"; do
      d=$WORK/$s-t$t
      b=$(col_median "$d/before.times" 1)
      a=$(col_median "$d/direct.times" 1)
      printf '| %s | %s | %.3f | %.3f | **%.2f×** | %.3f / %.3f | %.3f / %.3f | %.0f / %.0f |\n' "$s" "$t" "$b" "$a" \
        "$(calc %.4f "$b / $a")" "$(col_median "$d/before.times" 3)" "$(col_median "$d/direct.times" 3)" \
        "$(col_median "$d/before.times" 4)" "$(col_median "$d/direct.times" 4)" \
        "$(col_median "$d/before.times" 5)" "$(col_median "$d/direct.times" 5)"
    done
  done
  echo
}

# e2e_row SAMPLE THREADS: one row of the end-to-end table; records the ratio in targets.txt
e2e_row() {
  local s=$1 t=$2 d=$WORK/$1-t$2 wd wk wc target ratio met range
  wd=$(col_median "$d/direct.times" 1)
  wk=$(col_median "$d/skyline.times" 1)
  wc=$(col_median "$d/ccx.times" 1)
  target=$(target_of "$s")
  ratio=$(calc %.2f "$wc / $wd")
  met=$(awk -v r="$ratio" -v g="$target" 'BEGIN {print (r >= g) ? "met" : "missed"}')
  range=$(paste "$d/direct.times" "$d/ccx.times" | awk '{print $6 / $1}' | sort -g |  # 5 columns each
    awk 'NR == 1 {lo = $1} {hi = $1} END {printf "%.1f–%.1f", lo, hi}')
  echo "$s $t $ratio $target $met $wd $wc ${range/–/ }" >> "$WORK/targets.txt"
  printf '| %s | %s | %.3f | %.3f | %.3f | **%.2f×** (%s) | %.2f× | %.2f× | %s× %s | %.0f / %.0f / %.0f |\n' "$s" "$t" \
    "$wd" "$wk" "$wc" "$ratio" "$range" "$(calc %.4f "$wc / $wk")" \
    "$(calc %.4f "$(col_median "$d/ccx.times" 3) / $(col_median "$d/direct.times" 3)")" "$target" "$met" \
    "$(calc %.1f "$(col_max "$d/direct.times" 2) / 1024")" \
    "$(calc %.1f "$(col_max "$d/skyline.times" 2) / 1024")" "$(calc %.1f "$(col_max "$d/ccx.times" 2) / 1024")"
}

e2e_section() {
  cat << 'EOF'
## End to end: rollsim direct vs rollsim skyline vs CalculiX

Wall time of the whole process: rollsim reads the project, builds, solves, writes summary.json and result.vtu;
CalculiX reads the .inp that `rollsim export-ccx` writes (same nodes, CPE4 plane strain of unit thickness / C3D8,
same supports), solves, writes the .dat (total reactions) and the .frd (U and S, the fields result.vtu holds).
The three programs run interleaved, a sample's thread counts back to back in every repeat, each under `/usr/bin/time -v` (peak RSS); the wall time is taken around it
with a nanosecond clock. In brackets: the range of CalculiX / direct over the interleaved run pairs (the noise of
this shared machine). CPU time = user + system (medians), less sensitive than wall time to other jobs on the machine.
Target of issue 14 (on wall time): CalculiX / direct ≥ 8 on the 2D squares, ≥ 2 on the 3D cubes, at 1 and 2 threads.

EOF
  echo "| sample | threads | direct s | skyline s | CalculiX s | CalculiX / direct | CalculiX / skyline |" \
       "CalculiX / direct, CPU time | target | peak MiB direct / skyline / CalculiX |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  local t s
  for t in $THREADS; do
    for s in "${SAMPLES[@]}"; do e2e_row "$s" "$t"; done
  done
  echo
}

# digits_equal A B: whether both print the same with CalculiX's 7 significant digits, else how many agree
digits_equal() {
  awk -v a="$1" -v b="$2" 'BEGIN {x = sprintf("%.6E", a); y = sprintf("%.6E", b); if (x == y) {print "all 7"; exit}
    n = 0; for (i = 1; i <= length(x) && substr(x, i, 1) == substr(y, i, 1); i++) if (substr(x, i, 1) ~ /[0-9]/) n++
    print n " of 7"}'
}

reaction_section() {
  local s d c rd rk rc
  cat << 'EOF'
## Reactions: total force on the clamped set xmin, y (2D) / z (3D), 1st thread count

CalculiX prints 7 significant digits (`*NODE PRINT, TOTALS=ONLY`, RF); ours are printed the same way here. Relative
difference = |rollsim − CalculiX| / |CalculiX|, bounded below by CalculiX's rounding (up to 5e-7).

EOF
  echo "| sample | unknowns rollsim / CalculiX | rollsim direct | rollsim skyline | CalculiX | printed digits equal |" \
       "relative difference |"
  echo "|---|---|---|---|---|---|---|"
  for s in "${SAMPLES[@]}"; do
    d=$WORK/$s-t$(first_threads)
    c=$(comp_of "$s")
    rd=$(json "$d/direct-summary-1.json" "repr(d['results']['reactions']['beam']['xmin'][$c])")
    rk=$(json "$d/skyline-summary-1.json" "repr(d['results']['reactions']['beam']['xmin'][$c])")
    rc=$(ccx_total "$d/ccx/model.dat" N_BEAM_XMIN $((c + 1)))
    printf '| %s | %s / %s | %s | %s | %s | %s | %s |\n' "$s" \
      "$(json "$d/direct-summary-1.json" "d['model']['dofs']")" \
      "$(awk '/number of equations/ {getline; print $1; exit}' "$d/ccx-1.log")" "$(calc %.6E "$rd")" \
      "$(calc %.6E "$rk")" "$rc" "$(digits_equal "$rd" "$rc")" \
      "$(awk -v a="$rd" -v b="$rc" 'BEGIN {d = (a - b) / b; printf "%.1e", d < 0 ? -d : d}')"
  done
  echo
}

# timing_median DIR FIELD: median over the repeats of summary.json timing.FIELD of the direct runs
timing_median() {
  local r
  for ((r = 1; r <= REPEAT; r++)); do json "$1/direct-summary-$r.json" "d['timing']['$2']"; done | median
}

# profile_row SAMPLE THREADS: one row of the profile table; records the largest part in profile.txt
profile_row() {
  local s=$1 t=$2 d=$WORK/$1-t$2 wall total st an fa so re rest proc big startup
  wall=$(col_median "$d/direct.times" 1)
  total=$(timing_median "$d" total_s)
  st=$(timing_median "$d" stiffness_s)
  an=$(timing_median "$d" analyze_s)
  fa=$(timing_median "$d" factorize_s)
  so=$(timing_median "$d" solve_s)
  re=$(timing_median "$d" recovery_s)
  rest=$(calc %.4f "$total - $st - $an - $fa - $so - $re")
  proc=$(calc %.4f "$wall - $total")
  startup=$(col_median "$d/startup.times" 1)
  big=$(printf '%s process\n%s stiffness\n%s analyze\n%s factorize\n%s solve\n%s recovery\n%s rest\n' "$proc" "$st" \
    "$an" "$fa" "$so" "$re" "$rest" | sort -g | tail -1 |
    awk -v w="$wall" '{printf "%s %.3f s (%.0f %%)", $2, $1, 100 * $1 / w}')
  echo "$s $t $big" >> "$WORK/profile.txt"
  printf '| %s | %s | %.3f | %.3f (%.3f) | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %s | %.3f / %.3f | %.1f (%.0f %%) |\n' \
    "$s" "$t" "$wall" "$proc" "$startup" "$st" "$an" "$fa" "$so" "$re" "$rest" "$big" "$(col_median "$d/direct.times" 3)" \
    "$(col_median "$d/direct.times" 4)" "$(timing_median_solver "$d" factor_gflops)" \
    "$(calc %.4f "100 * $(timing_median_solver "$d" factor_peak_fraction)")"
}

# timing_median_solver DIR FIELD: median over the repeats of summary.json solver.FIELD of the direct runs
timing_median_solver() {
  local r
  for ((r = 1; r <= REPEAT; r++)); do json "$1/direct-summary-$r.json" "d['solver'].get('$2', 0)"; done | median
}

profile_section() {
  local s t
  cat << 'EOF'
## Where rollsim direct spends its time (medians of summary.json `timing`, seconds)

process = wall time outside main() (exec, loading CHOLMOD/OpenBLAS/VTK, exit), in brackets the wall time of
`rollsim --version` (start-up and exit alone, run interleaved with the others); rest = inside main() but outside the
analysis stages (read and validate the project, build the mesh, the DGEMM probe of `factor_gflops`, write
summary.json and result.vtu). CPU / system: the process's user + system and system CPU seconds (`time -v`).
factor GFlop/s: summary.json `solver.factor_gflops`, and its `factor_peak_fraction` of the DGEMM peak that `run`
measures after the analysis (`timing.peak_probe_s`, ~10 ms).

| sample | threads | wall | process | stiffness | analyze | factorize | solve | recovery | rest | largest part | CPU / system s | factor GFlop/s (% of peak) |
|---|---|---|---|---|---|---|---|---|---|---|---|---|
EOF
  for t in $THREADS; do
    for s in "${SAMPLES[@]}"; do profile_row "$s" "$t"; done
  done
  echo
}

# verdict_line SAMPLE: met/missed per thread count, with what a miss would need and where the time goes
verdict_line() {
  local s=$1 t ratio target met wd wc lo hi line notes need
  line="- $s, direct ≥ $(target_of "$s")× faster than CalculiX end to end:"
  while read -r _ t ratio target met wd wc lo hi; do
    notes=()
    if awk -v l="$lo" -v h="$hi" -v g="$target" 'BEGIN {exit !(l < g && g <= h)}'; then notes+=(borderline); fi
    if [[ $met == missed ]]; then
      need=$(calc %.3f "$wc / $target")
      notes+=("needs ≤ $need s, $(calc %.0f "100 * ($wd - $need) / $wd") % less")
      notes+=("largest part $(awk -v s="$s" -v t="$t" '$1 == s && $2 == t {$1 = $2 = ""; print}' "$WORK/profile.txt" |
        sed 's/^ *//')")
      awk -v s="$s" -v t="$t" '$1 == s && $2 == t {print $3}' "$WORK/profile.txt" >> "$WORK/missed.txt"
    fi
    line+=" **$met** at $t thread(s) with ${ratio}×"
    if ((${#notes[@]})); then line+=" ($(IFS=';'; echo "${notes[*]}" | sed 's/;/; /g'))"; fi
    line+=";"
  done < <(awk -v s="$s" '$1 == s' "$WORK/targets.txt")
  echo "${line%;}."
}

# threads_line: issue 14's "2 threads never slower than 1", direct, per sample (medians of the wall times; the runs
# of one repeat are seconds apart, so the range of 2 / 1 over the repeats shows the noise, as "borderline" does above)
threads_line() {
  local s one two cpu1 cpu2 range line=""
  [[ $THREADS == "1 2" ]] || return 0
  for s in "${SAMPLES[@]}"; do
    one=$(col_median "$WORK/$s-t1/direct.times" 1)
    two=$(col_median "$WORK/$s-t2/direct.times" 1)
    cpu1=$(col_median "$WORK/$s-t1/direct.times" 3)
    cpu2=$(col_median "$WORK/$s-t2/direct.times" 3)
    range=$(paste -d' ' "$WORK/$s-t1/direct.times" "$WORK/$s-t2/direct.times" |
            awk -v n="$(awk 'END {print NF}' "$WORK/$s-t1/direct.times")" '{r = $(n + 1) / $1
              if (NR == 1 || r < lo) lo = r; if (NR == 1 || r > hi) hi = r} END {printf "%.2f-%.2f", lo, hi}')
    line+=" $s $(awk -v a="$one" -v b="$two" -v c="$cpu1" -v d="$cpu2" -v r="$range" 'BEGIN {
      split(r, x, "-"); printf "%s (%.3f s on 1, %.3f s on 2; 2 / 1 over the repeats %s%s; CPU %.2f / %.2f s)",
      (b <= a) ? "met" : "missed", a, b, r, (x[1] <= 1 && x[2] > 1) ? ", borderline" : "", c, d}');"
  done
  echo "- direct on 2 threads never slower than on 1:${line%;}."
}

verdict_section() {
  local s equal parts
  printf '## Targets of issue 14 (end to end): met or missed\n\n'
  printf 'From the medians above; "borderline" where the per-run range straddles the target, i.e. another session on\n'
  printf 'this shared machine may well give the other verdict.\n\n'
  : > "$WORK/missed.txt"
  for s in "${SAMPLES[@]}"; do verdict_line "$s"; done
  threads_line
  equal=$(grep -c 'all 7' "$WORK/BENCHMARKS.md" || true)
  echo "- Reactions equal to CalculiX's printed digits: $equal of ${#SAMPLES[@]} samples agree in all 7 (table above)."
  parts=$(sort -u "$WORK/missed.txt" | paste -sd, - | sed 's/,/, /g')
  if [[ -n $parts ]]; then
    echo
    echo "Largest part of the run wherever a target is missed: $parts (profile table above)."
  fi
  echo
}

# ---------------------------------------------------------------- main
stage_bench
factor_bench
for ((r = 1; r <= REPEAT; r++)); do
  for s in "${SAMPLES[@]}"; do
    for t in $THREADS; do run_e2e "$s" "$t" "$r"; done
  done
  log "end to end, repeat $r of $REPEAT done"
done
{
  machine_section
  stage_section
  factor_section
  before_section
  e2e_section
  reaction_section
  profile_section
} > "$WORK/BENCHMARKS.md"
verdict_section >> "$WORK/BENCHMARKS.md"
mv "$WORK/BENCHMARKS.md" "$OUT"
log "wrote $OUT"
