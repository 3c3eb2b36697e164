#!/usr/bin/env bash
# Installs the Debian 12 packages rollsim needs, only those missing (run as root).
set -euo pipefail
PACKAGES=(
  build-essential cmake pkg-config
  libeigen3-dev libsuitesparse-dev libmetis-dev libopenblas-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev libssl-dev
  libcairo2-dev qtbase5-dev libqt5charts5-dev libvtk9-dev libvtk9-qt-dev libopenmpi-dev openmpi-bin
  libpetsc-real-dev libgmsh-dev
  xvfb xauth libgl1-mesa-dri
  calculix-ccx time clang-format
)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "rollsim: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
