#!/usr/bin/env bash
# Lazy solid synthesis on real GIMP exemplars: a full volume at RESOLUTION³ (the unit cube, one
# exemplar tile across), its wall time and voxels per second, `texsynth eval` of its axis-aligned
# slices against the exemplar, next to the 2D parallel method's metrics at the same size.
# Usage: bench/lazy_solid_table.sh [BUILD_DIR] [OUTPUT_DIR] [RESOLUTION] [-- extra lazy flags]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-$(mktemp -d)}
resolution=${3:-64}
shift $(($# < 3 ? $# : 3))
[ "${1:-}" = "--" ] && shift
extra=("$@")
mkdir -p "$out"
texsynth="$build/bin/texsynth"
patterns=/usr/share/gimp/2.0/patterns
exemplars=(Stone/pink_marble Stone/granite1 Stone/stone33 Wood/wood1 Wood/burlwood Paper/crinklepaper)
[ -x "$texsynth" ] || { echo "build first: $texsynth is missing" >&2; exit 1; }
[ -d "$patterns" ] || { echo "gimp-data is not installed (scripts/install-deps.sh)" >&2; exit 1; }
export TEXSYNTH_CACHE="$out/cache"

metrics() {  # coherence completeness histogram periodicity sharpness of an image, or a volume's mean row
  if [[ $2 == *.nrrd ]]; then
    "$texsynth" eval "$1" "$2" --quiet | awk '$1 == "mean" { print $2, $3, $4, $5, $6 }'
  else
    "$texsynth" eval "$1" "$2" --quiet | awk '/^(coherence|completeness|histogram|periodicity|sharpness)/ { printf "%s ", $2 }'
  fi
}

echo "# Lazy solid synthesis, ${resolution}³ volumes, $(nproc) cores ${extra[*]:+(flags: ${extra[*]})}"
echo
echo "| exemplar | method | time | voxels/s | coherence | completeness | histogram | periodicity | sharpness |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
for name in "${exemplars[@]}"; do
  pat="$patterns/$name.pat"
  stem=$(basename "$name")
  side=$("$texsynth" info "$pat" --json | awk -F': ' '/"width"/ { gsub(",", "", $2); print $2 }')
  volume="$out/${stem}_lazy.nrrd"
  start=$(date +%s.%N)
  "$texsynth" solid "$pat" --method lazy --tiles "$(awk -v r="$resolution" -v s="$side" 'BEGIN { print r / s }')" \
    --volume "$volume" --resolution "$resolution" --stats "$out/${stem}_stats.json" --quiet "${extra[@]}"
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  rate=$(awk -v s="$seconds" -v r="$resolution" 'BEGIN { printf "%.0f", r * r * r / s }')
  read -r c co h p sh <<<"$(metrics "$pat" "$volume")"
  printf "| %s | lazy (slices) | %s s | %s | %s | %s | %s | %s | %s |\n" "$stem" "$seconds" "$rate" "$c" "$co" "$h" "$p" "$sh"
  image="$out/${stem}_parallel.png"
  "$texsynth" image "$pat" --method parallel --tileable never --size "$resolution" -o "$image" --quiet
  read -r c co h p sh <<<"$(metrics "$pat" "$image")"
  printf "| %s | 2D parallel | | | %s | %s | %s | %s | %s |\n" "$stem" "$c" "$co" "$h" "$p" "$sh"
done
echo
echo "Volumes, stats (per level voxels and corrections) and images: $out"
