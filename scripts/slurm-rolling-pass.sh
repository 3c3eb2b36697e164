#!/bin/bash
# A rolling pass over MPI on a cluster (issue 37): submit with `sbatch scripts/slurm-rolling-pass.sh PROJECT [OUT]`, or
# run it as it is on a workstation (it then takes ROLLSIM_RANKS ranks, default 2). Run from the rollsim checkout.
#
#SBATCH --job-name=rollsim-pass
#SBATCH --nodes=1
#SBATCH --ntasks=5
#SBATCH --cpus-per-task=1
#SBATCH --time=02:00:00
#SBATCH --output=rollsim-pass-%j.log
#
# Ranks and groups. `--petsc-method mixed` (the default here) is the paper's mixed method over MPI: group g — a body,
# or a subdomain of a partitioned body — is assembled and factored on rank g mod P, so P should not exceed the number
# of groups: the slab's subdomains (`process.slab_partition`; a project of bodies: their `partition`) plus one for
# the roll. ROLLSIM_PARTITION=4x1 tears the slab into four: five groups for the five tasks
# asked above. `ROLLSIM_PETSC_METHOD=mumps` factors the whole system with MUMPS instead, on any number of ranks.
# Bad input is refused by every rank with one message (exit 2). Every rank reads the project; rank 0 writes OUT
# (summary.json, rolling.csv, results.pvd, …), whose summary.json lists each group's rank and each rank's
# factorizations (solver.ranks).
set -euo pipefail
project=${1:?usage: slurm-rolling-pass.sh PROJECT [OUT]}
out=${2:-pass-${SLURM_JOB_ID:-$$}}
ranks=${SLURM_NTASKS:-${ROLLSIM_RANKS:-2}}
method=${ROLLSIM_PETSC_METHOD:-mixed}
rollsim=${ROLLSIM_BINARY:-build/app/rollsim}
partition=()
if [[ -n ${ROLLSIM_PARTITION:-} ]]; then partition=(--set "process.slab_partition=${ROLLSIM_PARTITION}"); fi
# Open MPI started inside an allocation takes its hosts and slots from SLURM; outside one, --oversubscribe lets a
# workstation run more ranks than cores (slower, same answers)
extra=()
if [[ -z ${SLURM_JOB_ID:-} ]]; then extra=(--oversubscribe); fi
if [[ $(id -u) == 0 ]]; then extra+=(--allow-run-as-root); fi
exec mpirun -n "$ranks" "${extra[@]}" "$rollsim" run "$project" "${partition[@]}" --solver petsc \
  --petsc-method "$method" --interface-solver krylov --out "$out" --quiet
