#!/usr/bin/env bash
# Regenerates the window's pictures in docs/images/ that docs/GUI.md (and README.md) show, with the binary's own
# offscreen screenshot under Xvfb, at 1280 x 800: bash scripts/gui-screenshots.sh [BUILD_DIR] (default: build), from
# the repository's root. About 25 s: three of the pictures run their project first (the rolling pass about 14 s).
set -euo pipefail
build=${1:-build}
bin="$build/app/rollsim"
out=docs/images
command -v xvfb-run >/dev/null || { echo "gui-screenshots: xvfb-run is missing (apt-get install xvfb)" >&2; exit 2; }
[ -x "$bin" ] || { echo "gui-screenshots: no $bin (build first: bash scripts/build.sh)" >&2; exit 2; }
[ -d "$out" ] && [ -d samples ] || { echo "gui-screenshots: run from the repository's root (no $out here)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"; rm -f "$out"/.*.partial.png' EXIT

# shot NAME [PROJECT] [OPTIONS...]: the window as NAME.png, written under a temporary name and renamed when complete
shot() {
  local name=$1
  shift
  local tmp="$out/.$name.partial.png"
  echo "+ xvfb-run -a -s \"-screen 0 1280x1024x24\" $bin gui $* --screenshot $out/$name.png --size 1280x800"
  xvfb-run -a -s "-screen 0 1280x1024x24" "$bin" gui "$@" --screenshot "$tmp" --size 1280x800 >/dev/null ||
    { echo "gui-screenshots: $bin failed on $name" >&2; exit 1; }
  [ -s "$tmp" ] || { echo "gui-screenshots: $bin wrote no $tmp" >&2; exit 1; }
  mv "$tmp" "$out/$name.png"
  echo "wrote $out/$name.png ($(($(stat -c %s "$out/$name.png") / 1024)) kB)"
}

# the contact + FETI sample with its base in 7 irregular METIS parts, as a painted map has (the sample's own 5x3
# gives 15 slices), run so that the CG residual of the FETI solve is drawn (GUI.md's and README's captions)
partitioned="$work/block-indent-dd-2d-50x30.json"
sed 's/"partition": "5x3"/"partition": "metis:7"/' samples/block-indent-dd-2d-50x30.json >"$partitioned"
grep -q '"partition": "metis:7"' "$partitioned" ||
  { echo "gui-screenshots: samples/block-indent-dd-2d-50x30.json no longer has \"partition\": \"5x3\"" >&2; exit 1; }

shot window-partitions "$partitioned" --partitions --run
shot window-newton samples/cylinder-plastic-2d.json --run --color-by plastic_strain
# the main job (README): before its run, the Forecast raised; after it, deformed, plastic strain, framed on the gap
shot window-rolling-forecast samples/rolling-2d-36x6.json
shot window-rolling samples/rolling-2d-36x6.json --run
