#!/usr/bin/env bash
# Quality of the random-access 2D methods on real GIMP exemplars: `texsynth eval` of 512x512
# outputs from plain tiling (tile-deform with lambda 0), tile-deform and tile-blend.
# Usage: bench/quality_table.sh [BUILD_DIR] [OUTPUT_DIR]   (the images are kept in OUTPUT_DIR)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
texsynth="$build/bin/texsynth"
patterns=/usr/share/gimp/2.0/patterns
exemplars=(Stone/pink_marble Stone/granite1 Stone/stone33 Stone/slate Wood/bark Wood/wood1 Wood/burlwood Paper/crinklepaper)
[ -x "$texsynth" ] || { echo "build first: $texsynth is missing" >&2; exit 1; }
[ -d "$patterns" ] || { echo "gimp-data is not installed (scripts/install-deps.sh)" >&2; exit 1; }

# "coherence completeness histogram periodicity" of one output.
metrics() {
  "$texsynth" eval "$1" "$2" --quiet | awk '/^(coherence|completeness|histogram|periodicity)/ { printf "%s ", $2 }'
}

echo "# 512x512 outputs, texsynth eval (7x7 patches, RGB 0..255; lower is better everywhere)"
echo
echo "| exemplar | method | coherence | completeness | histogram | periodicity | synthesis |"
echo "|---|---|---:|---:|---:|---:|---:|"
for name in "${exemplars[@]}"; do
  exemplar="$patterns/$name.pat"
  stem=$(basename "$name")
  for method in tiling tile-deform tile-blend; do
    case $method in
      tiling) args=(--method tile-deform --lambda 0) ;;
      *) args=(--method "$method") ;;
    esac
    image="$out/${stem}_${method}.png"
    seconds=$("$texsynth" image "$exemplar" "${args[@]}" --size 512 --tileable never -o "$image" --json |
      awk -F': ' '/"seconds"/ { gsub(",", "", $2); print $2 }')
    read -r coherence completeness histogram periodicity <<<"$(metrics "$exemplar" "$image")"
    printf "| %s | %s | %s | %s | %s | %s | %.3f s |\n" "$stem" "$method" "$coherence" "$completeness" "$histogram" \
      "$periodicity" "$seconds"
  done
done
echo
echo "images: $out"
