#!/usr/bin/env bash
# The studio gallery: texsynth studio in headless chromium on the bunny with its example sketch and
# GIMP's pink_marble (the sketch and the field's glyphs; the lazy solid following the field; the model
# cut open), stored as JPEG in docs/gallery/studio_*.jpg.
# Usage: scripts/gallery-studio.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-docs/gallery}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
node scripts/gallery-studio.mjs "$build/bin/texsynth" "$work"
for name in studio_sketch studio_lazy studio_cut; do
  gmic -v - "$work/$name.png" -o "$out/$name.jpg,88" >/dev/null
done
echo "gallery: $out/studio_sketch.jpg $out/studio_lazy.jpg $out/studio_cut.jpg"
