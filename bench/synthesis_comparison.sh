#!/usr/bin/env bash
# Pixel-based 2D synthesis side by side on real GIMP exemplars: texsynth's parallel (L&H 2005) and
# optimize with the discrete solver (Han et al.), against G'MIC's syntexturize_matchpatch (Debian
# gmic, all threads, OMP_WAIT_POLICY=PASSIVE unless set) as an outside peer. For every exemplar
# and output size: wall time of the whole command (exemplar analysis cached, as in normal use; the
# one-off analysis time is listed apart) and the `texsynth eval` metrics (coherence, its 90th
# percentile over the patches where seams live, completeness, histogram, sharpness, lattice,
# periodicity). Prints one Markdown table of every run, then per size
# the means per method (time as geometric mean) and, per texsynth method, on how many exemplars it
# is at least as good as G'MIC, and its speed against G'MIC. Writes summary.tsv, the images, a
# montage per exemplar and size (exemplar at 1:1 | one output per method, in METHODS order) and one
# contact sheet per size (every exemplar's montage stacked), all in OUTPUT_DIR.
# Usage: bench/synthesis_comparison.sh [BUILD_DIR] [OUTPUT_DIR] [SIZES...]   (default sizes 256 512)
#   BUILD_DIR (default build) and OUTPUT_DIR (default a new temporary directory) are taken from the
#   repository root when relative.
# Environment:
#   METHODS="parallel optimize gmic"   methods in montage order; also least-squares (optimize
#                                      --solver least-squares, Kwatra et al. 2005)
#   EXEMPLARS="Stone/rock ..."         GIMP pattern names (default: the 12 below)
# Cheapest check: EXEMPLARS="Stone/rock Plant/leaves" bench/synthesis_comparison.sh build "" 256
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-}
[ -n "$out" ] || out=$(mktemp -d)
shift $(($# < 2 ? $# : 2))
sizes=("$@")
[ $# -eq 0 ] && sizes=(256 512)
case $build in /*) texsynth="$build/bin/texsynth" ;; *) texsynth="$(pwd)/$build/bin/texsynth" ;; esac
patterns=/usr/share/gimp/2.0/patterns
read -r -a exemplars <<<"${EXEMPLARS:-Stone/rock Stone/cracked Plant/leaves Wood/bark Wood/corkboard Wood/pine \
Stone/pink_marble Stone/granite1 Stone/brick Fabric/burlap Food/java Stone/slate}"
read -r -a methods <<<"${METHODS:-parallel optimize gmic}"

# Prerequisites, each with what to do about it.
[ -x "$texsynth" ] || { echo "build first: $texsynth is missing" >&2; exit 1; }
[ -d "$patterns" ] || { echo "gimp-data is not installed (scripts/install-deps.sh)" >&2; exit 1; }
command -v gmic >/dev/null || { echo "gmic is not installed (scripts/install-deps.sh)" >&2; exit 1; }
command -v python3 >/dev/null || { echo "python3 is not installed (it reads eval's JSON)" >&2; exit 1; }
[ ${#methods[@]} -gt 0 ] || { echo "METHODS is empty" >&2; exit 1; }
for method in "${methods[@]}"; do
  case $method in
    parallel | optimize | least-squares | gmic) ;;
    *) echo "unknown method '$method' in METHODS (parallel, optimize, least-squares, gmic)" >&2; exit 1 ;;
  esac
done
for name in "${exemplars[@]}"; do
  [ -f "$patterns/$name.pat" ] || { echo "no GIMP pattern $patterns/$name.pat (EXEMPLARS)" >&2; exit 1; }
done
for size in "${sizes[@]}"; do
  [[ $size =~ ^[1-9][0-9]*$ ]] || { echo "size '$size' is not a positive integer" >&2; exit 1; }
done
mkdir -p "$out"
out=$(cd "$out" && pwd)
export TEXSYNTH_CACHE="$out/cache"
rm -rf "$TEXSYNTH_CACHE"

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b - a }'; }
# One synthesis by `method` ($5) at size $3 into $4 (exemplar .pat $1, its PNG copy $2).
synthesize() {
  local pat=$1 png=$2 size=$3 image=$4
  case $5 in
    parallel) "$texsynth" image "$pat" --method parallel --tileable never --size "$size" -o "$image" --quiet ;;
    optimize) "$texsynth" image "$pat" --method optimize --tileable never --size "$size" -o "$image" --quiet ;;
    least-squares)
      "$texsynth" image "$pat" --method optimize --solver least-squares --tileable never --size "$size" -o "$image" \
        --quiet ;;
    # libgomp's default spinning barriers collapse when anything else holds a core (22 s instead
    # of 0.6 s for leaves at 256² on 2 busy cores): wait passively unless told otherwise.
    gmic) OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-PASSIVE} gmic -v - srand 1 "$png" syntexturize_matchpatch "$size,$size" \
      -o "$image" >/dev/null 2>&1 ;;
  esac
}
# The eval metrics of `image` against `pat`, tab-separated in the summary's order.
metrics() {
  "$texsynth" eval "$1" "$2" --json --quiet | python3 -c '
import json, sys
m = json.load(sys.stdin)["metrics"]
print("\t".join(f"{m[k]:.4f}" for k in ("coherence", "coherence_p90", "completeness", "histogram", "sharpness", "lattice", "periodicity")))'
}

summary="$out/summary.tsv"
printf "kind\texemplar\tsize\tmethod\tseconds\tcoherence\tcoherence_p90\tcompleteness\thistogram\tsharpness\tlattice\tperiodicity\n" \
  >"$summary"
echo "# Pixel-based synthesis, $(nproc) cores; wall time per command with the exemplar analysis cached"
echo
echo "| exemplar | size | method | time | coherence | coherence p90 | completeness | histogram | sharpness | lattice | periodicity |"
echo "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|"
for name in "${exemplars[@]}"; do
  pat="$patterns/$name.pat"
  stem=$(basename "$name")
  png="$out/${stem}_exemplar.png"
  read -r width height < <("$texsynth" info "$pat" --json | python3 -c '
import json, sys
d = json.load(sys.stdin)
print(d["width"], d["height"])')
  # G'MIC reads no .pat: a 1:1 PNG copy (tile-deform with no deformation, at the exemplar's size).
  "$texsynth" image "$pat" --method tile-deform --lambda 0 --tileable never --size "${width}x${height}" -o "$png" --quiet
  # The one-off analyses, timed apart (each fills the cache for its method).
  for method in "${methods[@]}"; do
    [ "$method" = gmic ] && continue
    start=$(now)
    synthesize "$pat" "$png" 64 "$out/warmup.png" "$method"
    printf "analysis\t%s\t\t%s\t%s\t\t\t\t\t\t\t\n" "$stem" "$method" "$(elapsed "$start" "$(now)")" >>"$summary"
  done
  for size in "${sizes[@]}"; do
    row=("$png")
    for method in "${methods[@]}"; do
      image="$out/${stem}_${size}_${method}.png"
      start=$(now)
      synthesize "$pat" "$png" "$size" "$image" "$method"
      seconds=$(elapsed "$start" "$(now)")
      values=$(metrics "$pat" "$image")
      printf "run\t%s\t%s\t%s\t%s\t%s\n" "$stem" "$size" "$method" "$seconds" "$values" >>"$summary"
      printf "| %s | %s | %s | %s s | %s |\n" "$stem" "$size" "$method" "$seconds" "${values//$'\t'/ | }"
      row+=("$image")
    done
    # Exemplar at 1:1, then the outputs, 4 black pixels around each, tops aligned (gray to RGB).
    gmic -v - "${row[@]}" to_rgb expand_xy 4,0 append x,0 -o "$out/${stem}_${size}_montage.png" >/dev/null 2>&1
  done
done
rm -f "$out/warmup.png"
for size in "${sizes[@]}"; do
  sheet=()
  for name in "${exemplars[@]}"; do sheet+=("$out/$(basename "$name")_${size}_montage.png"); done
  gmic -v - "${sheet[@]}" append y,0 -o "$out/contact_sheet_${size}.png" >/dev/null 2>&1
done

python3 - "$summary" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
runs = [r for r in rows if r["kind"] == "run"]
metrics = ["coherence", "coherence_p90", "completeness", "histogram", "sharpness", "lattice", "periodicity"]
methods = list(dict.fromkeys(r["method"] for r in runs))
sizes = list(dict.fromkeys(r["size"] for r in runs))
geomean = lambda xs: math.exp(sum(math.log(max(x, 1e-6)) for x in xs) / len(xs))
label = lambda m: "G'MIC" if m == "gmic" else m

print("\nOne-off exemplar analysis (first run, seconds):")
for r in rows:
    if r["kind"] == "analysis":
        print(f"  {r['exemplar']:<14} {r['method']:<14} {r['seconds']}")
for size in sizes:
    at = {(r["exemplar"], r["method"]): r for r in runs if r["size"] == size}
    exemplars = list(dict.fromkeys(r["exemplar"] for r in runs if r["size"] == size))
    print(f"\n## {size}²: means over {len(exemplars)} exemplars (time: geometric mean; lower is better except "
          "sharpness, where 1 = as crisp as the exemplar)\n")
    print("| method | time | " + " | ".join(metrics) + " |")
    print("|---|---:|" + "---:|" * len(metrics))
    for m in methods:
        sel = [at[(e, m)] for e in exemplars]
        means = [sum(float(r[k]) for r in sel) / len(sel) for k in metrics]
        print(f"| {label(m)} | {geomean([float(r['seconds']) for r in sel]):.3f} s | "
              + " | ".join(f"{v:.3f}" for v in means) + " |")
    if "gmic" not in methods:
        continue
    n = len(exemplars)
    print(f"\n## {size}²: texsynth against G'MIC, exemplars out of {n} where the method is at least as good\n")
    print("| method | coherence ≤ | coherence p90 ≤ | completeness ≤ | histogram ≤ | lattice ≤ | sharpness ≥ 0.95 | "
          "speed vs G'MIC |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for m in methods:
        if m == "gmic":
            continue
        counts = [sum(float(at[(e, m)][k]) <= float(at[(e, "gmic")][k]) for e in exemplars)
                  for k in ("coherence", "coherence_p90", "completeness", "histogram", "lattice")]
        sharp = sum(float(at[(e, m)]["sharpness"]) >= 0.95 for e in exemplars)
        speed = geomean([float(at[(e, "gmic")]["seconds"]) / max(float(at[(e, m)]["seconds"]), 1e-6)
                         for e in exemplars])
        print(f"| {m} | " + " | ".join(f"{c}/{n}" for c in counts) + f" | {sharp}/{n} | {speed:.2f}× |")
    sharp = sum(float(at[(e, "gmic")]["sharpness"]) >= 0.95 for e in exemplars)
    print(f"\nG'MIC itself: sharpness ≥ 0.95 on {sharp}/{n}. Speed: G'MIC time / method time, geometric mean.")
PY
echo
echo "Images, montages (exemplar | ${methods[*]}), contact sheets and summary.tsv: $out"
