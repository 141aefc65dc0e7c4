#!/usr/bin/env bash
# The surface-synthesis gallery: `texsynth surface` on four CGAL meshes with structured and
# stochastic GIMP exemplars, one oriented by a sketched field, rendered at the default size (two
# 768² views) and stored as JPEG in docs/gallery/surface_<mesh>_<exemplar>.jpg; bunny_brick is
# the README's first surface command.
# Usage: scripts/gallery-surface.sh [BUILD_DIR] [OUTPUT_DIR]
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

# name mesh exemplar vertices [extra flags...]
render() {
  local name=$1 mesh=$2 exemplar=$3 vertices=$4
  shift 4
  echo "gallery: $name"
  "$bin" surface "$patterns/$exemplar.pat" --mesh "$meshes/$mesh.off" --vertices "$vertices" "$@" \
    -o "$work/$name.ply" --render "$work/$name.png" --views 2 --quiet
  gmic -v - "$work/$name.png" -o "$out/surface_$name.jpg,88" >/dev/null
}

render bunny_burlap bunny00 Fabric/burlap 48000
render elephant_rock elephant Stone/rock 200000
render cow_pine cow Wood/pine 48000
render cow_pine_sketch cow Wood/pine 48000 --sketch examples/sketches/cow.json
render armadillo_leaves armadillo Plant/leaves 48000
render bunny_brick bunny00 Stone/brick 48000
echo "wrote $out/surface_*.jpg"
