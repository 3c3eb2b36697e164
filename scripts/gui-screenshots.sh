#!/usr/bin/env bash
# Regenerates the window's pictures in docs/images/ that docs/GUI.md shows, with the binary's own offscreen
# screenshot under Xvfb, at 1280 x 800: bash scripts/gui-screenshots.sh [BUILD_DIR] (default: build), from the
# repository's root. About a minute: two of the pictures run their project first.
set -euo pipefail
build=${1:-build}
bin="$build/app/rollsim"
out=docs/images
command -v xvfb-run >/dev/null || { echo "gui-screenshots: xvfb-run is missing (apt-get install xvfb)" >&2; exit 2; }
[ -x "$bin" ] || { echo "gui-screenshots: no $bin (build first: bash scripts/build.sh)" >&2; exit 2; }
[ -d "$out" ] || { echo "gui-screenshots: run from the repository's root (no $out here)" >&2; exit 2; }

# shot NAME [PROJECT] [OPTIONS...]: the window as NAME.png, written under a temporary name and renamed when complete
shot() {
  local name=$1
  shift
  local tmp="$out/.$name.partial.png"
  xvfb-run -a -s "-screen 0 1280x1024x24" "$bin" gui "$@" --screenshot "$tmp" --size 1280x800 >/dev/null
  mv "$tmp" "$out/$name.png"
  echo "wrote $out/$name.png"
}

shot window-partitions samples/block-indent-dd-2d-50x30.json --partitions
shot window-newton samples/cylinder-plastic-2d.json --run --color-by plastic_strain
shot window-rolling-forecast samples/rolling-2d-36x6.json
shot window-rolling samples/rolling-2d-36x6.json --run
