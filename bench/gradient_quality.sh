#!/usr/bin/env bash
# Quality of gradient-solid synthesis side by side with the other solid methods and 2D texture
# optimization, on real GIMP exemplars: per exemplar, RES³ volumes (.nrrd) from `texsynth solid
# --method gradient`, `--method lazy` and `--method tile-deform`, and a RES x RES image from `texsynth
# image --method optimize`, all at one exemplar pixel per voxel (tile-deform and lazy get --tiles
# RES/exemplar side; gradient always works at that scale). `texsynth eval` measures each against its
# exemplar: volumes on SLICES slices per axis (eval --slices, the mean of the three axes), the image
# as it is. Prints one Markdown table, rows exemplar x method: coherence, completeness, histogram,
# sharpness, periodicity (the share of patches repeated at the most common offset), lattice (the
# strongest shifted repeat of the luminance detail) and the wall seconds of the synthesis command,
# the exemplar analysis cached (a warm-up run per exemplar and method fills a fresh cache first;
# its one-off time is listed under the table).
#
# Brick mask: GIMP ships no mask for Stone/brick; its joints are the darkest 15% of its pixels, which
# `make_test_volumes --dark-mask-from` writes as a mask (build/bench/make_test_volumes). BRICK_MASK names
# another joints mask image (bright on the joints). The mask goes to gradient and lazy.
#
# Builds nothing: cmake --build build --target texsynth.
# Usage: bench/gradient_quality.sh [--quick] [EXEMPLAR...]
#   EXEMPLAR: a GIMP pattern name (Stone/pink_marble) or an image file; default Stone/pink_marble
#   Stone/granite1 Stone/rock Stone/brick Food/choc_swirl Wood/wood2 Paper/crinklepaper Stone/terra.
# Environment (relative paths are taken from the current directory):
#   TEXSYNTH=build/bin/texsynth   the binary (default: the repository's build/bin/texsynth)
#   OUT=$(mktemp -d)              work directory (volumes, images, eval JSON, the analysis cache)
#   RES=128                       volume side and image size
#   SLICES=4                      eval slices per axis of a volume
#   LAZY=1                        0 skips lazy (minutes per 128³ volume on 2 cores)
#   QUICK=0                       1 (or --quick): RES=32 and only the first 2 exemplars, to test the script
#   THREADS                       passed as --threads when set (default: all cores)
#   BRICK_MASK                    a joints mask for Stone/brick (see above)
# Cheapest check: QUICK=1 LAZY=0 bench/gradient_quality.sh
set -euo pipefail
absolute() { case $1 in /*) echo "$1" ;; *) echo "$PWD/$1" ;; esac; }
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
texsynth=$(absolute "${TEXSYNTH:-$root/build/bin/texsynth}")
out=$(absolute "${OUT:-$(mktemp -d)}")
brick_mask=""
[ -n "${BRICK_MASK:-}" ] && brick_mask=$(absolute "$BRICK_MASK")
quick=${QUICK:-0}
args=()
for a in "$@"; do
  case $a in
    --quick) quick=1 ;;
    -*) echo "unknown option: $a" >&2; exit 2 ;;
    *) case $a in *.* | /*) args+=("$(absolute "$a")") ;; *) args+=("$a") ;; esac ;;
  esac
done
cd "$root"
patterns=/usr/share/gimp/2.0/patterns
exemplars=("${args[@]}")
[ ${#args[@]} -eq 0 ] && exemplars=(Stone/pink_marble Stone/granite1 Stone/rock Stone/brick Food/choc_swirl Wood/wood2
  Paper/crinklepaper Stone/terra)
res=${RES:-128}
if [ "$quick" = 1 ]; then
  res=32
  exemplars=("${exemplars[@]:0:2}")
fi
slices=${SLICES:-4}
methods=(gradient tile-deform optimize)
[ "${LAZY:-1}" != 0 ] && methods=(gradient lazy tile-deform optimize)
globals=(--quiet)
[ -n "${THREADS:-}" ] && globals+=(--threads "$THREADS")
[ -x "$texsynth" ] || { echo "build first: $texsynth is missing" >&2; exit 1; }
command -v python3 >/dev/null || { echo "python3 is missing" >&2; exit 1; }
[ -z "$brick_mask" ] || [ -f "$brick_mask" ] || { echo "BRICK_MASK $brick_mask is missing" >&2; exit 1; }
mkdir -p "$out"
if [ -z "$brick_mask" ] && [ -x "$root/build/bench/make_test_volumes" ]; then
  brick_mask="$out/brick_joints.png"
  "$root/build/bench/make_test_volumes" --dark-mask-from "$patterns/Stone/brick.pat" "$brick_mask" 0.15 >/dev/null
fi
for name in "${exemplars[@]}"; do
  case $name in /*) pat=$name ;; *) pat="$patterns/$name.pat" ;; esac
  [ -f "$pat" ] || { echo "exemplar $pat is missing (scripts/install-deps.sh installs gimp-data)" >&2; exit 1; }
done
mkdir -p "$out"
export TEXSYNTH_CACHE="$out/cache"
rm -rf "$TEXSYNTH_CACHE"

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }
json_field() { python3 -c "import json, sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

# One synthesis: method $1 of exemplar $2 at size $3 into $4; $5: --tiles for tile-deform and lazy;
# $6: a mask or "". A .png output with a solid method is a z=0.5 slice (the warm-ups).
synthesize() {
  local method=$1 pat=$2 size=$3 output=$4 tiles=$5 mask=$6
  local masked=()
  [ -n "$mask" ] && masked=(--mask "$mask")
  local write=(--volume "$output")
  [[ $output == *.png ]] && write=(--slice z=0.5 -o "$output")
  case $method in
    gradient)
      [[ $output == *.png ]] && write=(-o "${output%.png}.tsgs")
      "$texsynth" solid "$pat" --method gradient --resolution "$size" "${write[@]}" "${masked[@]}" "${globals[@]}" ;;
    lazy) "$texsynth" solid "$pat" --method lazy --resolution "$size" --tiles "$tiles" "${write[@]}" "${masked[@]}" \
      "${globals[@]}" ;;
    tile-deform) "$texsynth" solid "$pat" --method tile-deform --resolution "$size" --tiles "$tiles" "${write[@]}" \
      "${globals[@]}" ;;
    optimize) "$texsynth" image "$pat" --method optimize --tileable never --size "$size" -o "$output" "${globals[@]}" ;;
  esac
}

echo "# Solid synthesis quality: ${res}³ volumes (eval on $slices slices per axis) and ${res}² optimize images, $(nproc) cores"
echo
echo "| exemplar | method | coherence | completeness | histogram | sharpness | periodicity | lattice | seconds |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
warmups="$out/warmups.tsv"
notes=()
: >"$warmups"
for name in "${exemplars[@]}"; do
  case $name in /*) pat=$name ;; *) pat="$patterns/$name.pat" ;; esac
  stem=$(basename "$pat")
  stem=${stem%.*}
  info="$out/${stem}_info.json"
  "$texsynth" info "$pat" --json >"$info"
  side=$(python3 -c "import json, sys; d = json.load(open(sys.argv[1])); print(max(d['width'], d['height']))" "$info")
  tiles=$(awk -v r="$res" -v s="$side" 'BEGIN { printf "%.6g", r / s }')
  mask=""
  if [ "$stem" = brick ]; then
    if [ -n "$brick_mask" ]; then
      mask=$brick_mask
      notes+=("brick: gradient and lazy with the joints mask $brick_mask")
    else
      notes+=("brick: no mask (GIMP ships none and texsynth cannot derive one; set BRICK_MASK)")
    fi
  fi
  for method in "${methods[@]}"; do
    # Warm-up: fills the analysis cache (tile-deform has none), timed apart.
    if [ "$method" != tile-deform ]; then
      warm_size=16
      [ "$method" = lazy ] && warm_size=4
      start=$(now)
      synthesize "$method" "$pat" "$warm_size" "$out/${stem}_${method}_warmup.png" "$tiles" "$mask"
      printf "%s\t%s\t%s\n" "$stem" "$method" "$(elapsed "$start" "$(now)")" >>"$warmups"
    fi
    output="$out/${stem}_${method}.nrrd"
    [ "$method" = optimize ] && output="$out/${stem}_${method}.png"
    start=$(now)
    synthesize "$method" "$pat" "$res" "$output" "$tiles" "$mask"
    seconds=$(elapsed "$start" "$(now)")
    per_axis=(--slices "$slices")
    [ "$method" = optimize ] && per_axis=()  # eval takes --slices for volumes only
    "$texsynth" eval "$pat" "$output" "${per_axis[@]}" --json "${globals[@]}" >"${output%.*}_eval.json"
    python3 - "${output%.*}_eval.json" "$stem" "$method" "$seconds" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
m = doc["mean"] if "mean" in doc else doc["metrics"]  # a volume's slices, or the image
print(f"| {sys.argv[2]} | {sys.argv[3]} | {m['coherence']:.2f} | {m['completeness']:.2f} | {m['histogram']:.2f} "
      f"| {m['sharpness']:.3f} | {m['periodicity']:.3f} | {m['lattice']:.3f} | {float(sys.argv[4]):.2f} |")
PY
  done
done
echo
echo "Lower is better for coherence, completeness, histogram (0..255), periodicity and lattice; sharpness is the mean"
echo "gradient magnitude over the exemplar's (1 = as crisp). Seconds: the synthesis command, analysis cached."
echo "Volumes: the unit cube at ${res}³, one exemplar pixel per voxel; optimize: --tileable never."
for note in "${notes[@]}"; do echo "$note"; done
echo
echo "One-off warm-up (exemplar analysis, then cached), seconds:"
awk -F'\t' '{ printf "  %-16s %-12s %s\n", $1, $2, $3 }' "$warmups"
echo
echo "Volumes, images and eval JSON: $out"
