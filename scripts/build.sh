#!/usr/bin/env bash
# Configures and builds rollsim (Release) into build/ (or $ROLLSIM_BUILD_DIR).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${ROLLSIM_BUILD_DIR:-build}
# the petsc strategy when PETSc is installed (scripts/install-deps.sh installs it); -DROLLSIM_WITH_PETSC=OFF overrides
PETSC=()
if pkg-config --exists PETSc 2>/dev/null; then PETSC=(-DROLLSIM_WITH_PETSC=ON); fi
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release "${PETSC[@]}" "$@" >/dev/null
cmake --build "$BUILD" -j"$(nproc)"
