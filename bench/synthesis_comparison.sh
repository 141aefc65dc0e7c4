#!/usr/bin/env bash
# Pixel-based 2D synthesis side by side on real GIMP exemplars: texsynth's parallel (L&H 2005),
# optimize with the discrete solver (Han et al.) and with the least-squares solver (Kwatra et
# al. 2005), and G'MIC's syntexturize_matchpatch (Debian gmic) as an outside peer. For every
# exemplar and output size: wall time of the whole command (exemplar analysis cached, as in
# normal use; the one-off analysis time is listed apart) and `texsynth eval` metrics; plus a
# montage exemplar | parallel | discrete | least squares | G'MIC per exemplar and size.
# Usage: bench/synthesis_comparison.sh [BUILD_DIR] [OUTPUT_DIR] [SIZES...]   (default sizes 256 512)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-$(mktemp -d)}
shift $(($# < 2 ? $# : 2))
sizes=("${@:-256}")
[ $# -eq 0 ] && sizes=(256 512)
mkdir -p "$out"
out=$(cd "$out" && pwd)
texsynth="$(pwd)/$build/bin/texsynth"
patterns=/usr/share/gimp/2.0/patterns
exemplars=(Stone/pink_marble Stone/marble1 Stone/granite1 Stone/stone33 Stone/brick Wood/bark Wood/wood1 Wood/burlwood)
methods=(parallel discrete least-squares gmic)
[ -x "$texsynth" ] || { echo "build first: $texsynth is missing" >&2; exit 1; }
[ -d "$patterns" ] || { echo "gimp-data is not installed (scripts/install-deps.sh)" >&2; exit 1; }
command -v gmic >/dev/null || { echo "gmic is not installed (scripts/install-deps.sh)" >&2; exit 1; }
export TEXSYNTH_CACHE="$out/cache"
rm -rf "$TEXSYNTH_CACHE"

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b - a }'; }
metrics() {
  "$texsynth" eval "$1" "$2" --quiet | awk '/^(coherence|completeness|histogram|periodicity|sharpness)/ { printf "%s ", $2 }'
}
# One synthesis of `method` at size $3 into $4 (exemplar .pat $1, its PNG copy $2).
synthesize() {
  local pat=$1 png=$2 size=$3 image=$4
  case $5 in
    parallel) "$texsynth" image "$pat" --method parallel --tileable never --size "$size" -o "$image" --quiet ;;
    discrete) "$texsynth" image "$pat" --method optimize --tileable never --size "$size" -o "$image" --quiet ;;
    least-squares)
      "$texsynth" image "$pat" --method optimize --solver least-squares --tileable never --size "$size" -o "$image" \
        --quiet ;;
    gmic) gmic -v - srand 1 "$png" syntexturize_matchpatch "$size,$size" -o "$image" >/dev/null 2>&1 ;;
  esac
}

echo "# Pixel-based synthesis, $(nproc) cores; wall time per command with the exemplar analysis cached"
echo
echo "| exemplar | size | method | time | coherence | completeness | histogram | periodicity | sharpness |"
echo "|---|---:|---|---:|---:|---:|---:|---:|---:|"
summary="$out/summary.tsv"
: >"$summary"
for name in "${exemplars[@]}"; do
  pat="$patterns/$name.pat"
  stem=$(basename "$name")
  png="$out/${stem}_exemplar.png"
  info=$("$texsynth" info "$pat" --json)
  width=$(awk -F': ' '/"width"/ { gsub(",", "", $2); print $2 }' <<<"$info")
  height=$(awk -F': ' '/"height"/ { gsub(",", "", $2); print $2 }' <<<"$info")
  "$texsynth" image "$pat" --method tile-deform --lambda 0 --tileable never --size "${width}x${height}" -o "$png" --quiet
  # The one-off analyses, timed apart.
  for method in parallel discrete least-squares; do
    start=$(now)
    synthesize "$pat" "$png" 64 "$out/warmup.png" "$method"
    echo "analysis	$stem	$method	$(elapsed "$start" "$(now)")" >>"$summary"
  done
  for size in "${sizes[@]}"; do
    row=("$png")
    for method in "${methods[@]}"; do
      image="$out/${stem}_${size}_${method}.png"
      start=$(now)
      synthesize "$pat" "$png" "$size" "$image" "$method"
      seconds=$(elapsed "$start" "$(now)")
      read -r coherence completeness histogram periodicity sharpness <<<"$(metrics "$pat" "$image")"
      printf "| %s | %s | %s | %s s | %s | %s | %s | %s | %s |\n" "$stem" "$size" "$method" "$seconds" "$coherence" \
        "$completeness" "$histogram" "$periodicity" "$sharpness"
      printf "run\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" "$stem" "$size" "$method" "$seconds" "$coherence" \
        "$completeness" "$histogram" "$periodicity" "$sharpness" >>"$summary"
      row+=("$image")
    done
    gmic -v - "${row[@]}" append x,0 -o "$out/${stem}_${size}_montage.png" >/dev/null 2>&1
  done
done

echo
echo "One-off exemplar analysis (first run, seconds):"
awk -F'\t' '$1 == "analysis" { printf "  %-14s %-14s %s\n", $2, $3, $4 }' "$summary"
echo
echo "Means over the exemplars (time as geometric mean):"
awk -F'\t' '$1 == "run" { key = $3 " " $4; n[key]++; lt[key] += log($5); c[key] += $6; p[key] += $9; s[key] += $10
                          if (!(key in seen)) { seen[key] = 1; order[++k] = key } }
  END { printf "  %-24s %10s %10s %12s %10s\n", "size method", "time", "coherence", "periodicity", "sharpness"
        for (i = 1; i <= k; i++) { key = order[i]
          printf "  %-24s %9.3fs %10.3f %12.3f %10.3f\n", key, exp(lt[key] / n[key]), c[key] / n[key], p[key] / n[key],
            s[key] / n[key] } }' \
  "$summary"
echo
echo "Images and montages (exemplar | parallel | discrete | least squares | G'MIC): $out"
