#!/usr/bin/env bash
# The flow-animation gallery: `texsynth animate` in 2D (a vortex on pink marble, a source on
# burlap: texture must appear at its centre) and on a mesh (lava-like chocolate swirl flowing
# down CGAL's bunny). Each gets a GIF and a filmstrip of four frames as JPEG in
# docs/gallery/animation_<name>.{gif,jpg}.
# Usage: scripts/gallery-animation.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-docs/gallery}
bin="$build/bin/texsynth"
patterns=/usr/share/gimp/2.0/patterns
meshes=.data/meshes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# name frames exemplar [animate flags...]: the GIF, and frames 0, 1/3, 2/3 and the last side by side.
animate() {
  local name=$1 frames=$2 exemplar=$3
  shift 3
  echo "gallery: $name"
  "$bin" animate "$patterns/$exemplar.pat" --frames "$frames" "$@" -o "$work/$name/%03d.png" \
    -o "$out/animation_$name.gif" --fps 16 --quiet
  local picks=()
  for t in 0 $((frames / 3)) $((2 * frames / 3)) $((frames - 1)); do picks+=("$work/$name/$(printf %03d "$t").png"); done
  gmic -v - "${picks[@]}" append x -o "$out/animation_$name.jpg,88" >/dev/null
}

animate vortex_pink_marble 72 Stone/pink_marble --flow vortex:strength=2 --size 192
animate source_burlap 72 Fabric/burlap --flow source:strength=1.5 --size 192
animate bunny_lava 60 Food/choc_swirl --mesh "$meshes/bunny00.off" --flow downhill:strength=1 --render-size 320
echo "wrote $out/animation_*.gif and .jpg"
