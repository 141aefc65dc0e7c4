#!/usr/bin/env bash
# Lazy solid synthesis on real GIMP exemplars: a full volume at RESOLUTION³ (the unit cube, one
# exemplar pixel per voxel), its wall time, and `texsynth eval` of its axis-aligned slices
# against the exemplar, next to 2D `optimize` at RESOLUTION² on the same exemplar; the last two
# columns are the goals of the lazy solid (sharpness >= 0.85, coherence <= 1.2x 2D optimize).
# Usage: bench/lazy_solid_table.sh [BUILD_DIR] [OUTPUT_DIR] [RESOLUTION] [-- extra lazy flags]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-$(mktemp -d)}
resolution=${3:-128}
shift $(($# < 3 ? $# : 3))
[ "${1:-}" = "--" ] && shift
extra=("$@")
mkdir -p "$out"
texsynth="$build/bin/texsynth"
patterns=/usr/share/gimp/2.0/patterns
# The README's six, plus a weave and a rock.
exemplars=(Stone/pink_marble Stone/granite1 Stone/stone33 Wood/wood1 Wood/burlwood Paper/crinklepaper Fabric/burlap
  Stone/rock)
[ -x "$texsynth" ] || { echo "build first: $texsynth is missing" >&2; exit 1; }
[ -d "$patterns" ] || { echo "gimp-data is not installed (scripts/install-deps.sh)" >&2; exit 1; }
export TEXSYNTH_CACHE="$out/cache"

metrics() {  # coherence sharpness lattice of an image, or a volume's mean row
  if [[ $2 == *.nrrd ]]; then
    "$texsynth" eval "$1" "$2" --quiet | awk '$1 == "mean" { print $2, $6, $7 }'
  else
    "$texsynth" eval "$1" "$2" --quiet | awk '/^coherence/ { c = $2 } /^sharpness/ { s = $2 } /^lattice/ { l = $2 }
      END { print c, s, l }'
  fi
}

echo "# Lazy solid synthesis, ${resolution}³ volumes against 2D optimize at ${resolution}², $(nproc) cores" \
  "${extra[*]:+(flags: ${extra[*]})}"
echo
echo "| exemplar | lazy time | lazy coherence | 2D coherence | ratio (goal <= 1.2) | lazy sharpness (goal >= 0.85) |" \
  "2D sharpness | lazy lattice | 2D lattice |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
for name in "${exemplars[@]}"; do
  pat="$patterns/$name.pat"
  stem=$(basename "$name")
  side=$("$texsynth" info "$pat" --json | awk -F': ' '/"width"/ { gsub(",", "", $2); print $2 }')
  volume="$out/${stem}_lazy.nrrd"
  "$texsynth" solid "$pat" --method lazy --slice z=0.5 --resolution 4 -o "$out/warmup.png" --quiet "${extra[@]}"
  start=$(date +%s.%N)
  "$texsynth" solid "$pat" --method lazy --tiles "$(awk -v r="$resolution" -v s="$side" 'BEGIN { print r / s }')" \
    --volume "$volume" --resolution "$resolution" --slice z=0.5 -o "$out/${stem}_lazy_slice.png" \
    --stats "$out/${stem}_stats.json" --quiet "${extra[@]}"
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  read -r c s l <<<"$(metrics "$pat" "$volume")"
  image="$out/${stem}_optimize.png"
  "$texsynth" image "$pat" --method optimize --size "$resolution" -o "$image" --quiet
  read -r c2 s2 l2 <<<"$(metrics "$pat" "$image")"
  ratio=$(awk -v a="$c" -v b="$c2" 'BEGIN { printf "%.2f", a / b }')
  printf "| %s | %s s | %s | %s | %s | %s | %s | %s | %s |\n" "$stem" "$seconds" "$c" "$c2" "$ratio" "$s" "$s2" "$l" "$l2"
done
echo
echo "Volumes (eval: 4 slices per axis), z = 0.5 slices, stats and 2D images: $out"
