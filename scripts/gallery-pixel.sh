#!/usr/bin/env bash
# The 2D gallery: montages exemplar | parallel | optimize | G'MIC at 256^2 of the three GIMP
# exemplars that came out worst in bench/synthesis_comparison.sh (cracked, pine, rock), made by
# that script and stored as JPEG in docs/gallery/pixel_<name>_256.jpg.
# Usage: scripts/gallery-pixel.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-docs/gallery}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
EXEMPLARS="Stone/cracked Wood/pine Stone/rock" bash bench/synthesis_comparison.sh "$build" "$work" 256 >/dev/null
mkdir -p "$out"
for stem in cracked pine rock; do
  gmic -v - "$work/${stem}_256_montage.png" -o "$out/pixel_${stem}_256.jpg,90" >/dev/null
done
echo "wrote $out/pixel_{cracked,pine,rock}_256.jpg"
