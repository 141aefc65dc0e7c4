#!/usr/bin/env bash
# Surface texture synthesis by discrete optimization (texsynth surface) against Table 2 of Han et
# al., "Fast example-based surface texture synthesis via discrete optimization", and its quality
# against solid textures and 2D synthesis.
#
# 1. Speed (Table 2): 64² and 128² GIMP exemplars on the CGAL meshes retiled to VERTICES (48K),
#    plus one LARGE_VERTICES (200K) run: hierarchy seconds (cold: the first run on each mesh and
#    vertex count starts from a fresh TEXSYNTH_CACHE holding only the exemplar analyses; warm: the
#    later runs load it from the cache), preparation seconds (tangent field and resampled
#    neighborhoods), mean seconds per E+M step at the finest level and over all levels (steps with
#    iteration >= 1 in --stats), and total synthesis seconds; beside the paper's numbers and ours.
# 2. Quality: every pair of QUALITY_MESHES x QUALITY_EXEMPLARS at the surface command's defaults
#    (VERTICES, --seed SEED) gets a row: the synthesis seconds (--stats), the surface coherence,
#    completeness, histogram and flatness of the result (`texsynth eval EXEMPLAR colored.ply
#    --json`; "n/a" for a measure this eval does not report), the same for each of SOLIDS colored
#    onto the very same retiled vertices (the surface command's own output mesh, at one exemplar
#    pixel per vertex spacing), 2D `texsynth image --method optimize` at IMAGE_SIZE² on the same
#    exemplar (once per exemplar; its coherence also on the surface's footing: the 2D image copied
#    onto the retiled plane below and measured as a surface), the ratios surface / 2D of histogram
#    and coherence (against the image and against its plane copy), and a pass column against the
#    targets flatness <= 0.05, histogram <= 1.5x 2D's, coherence <= 1.3x 2D's on the plane;
#    then a summary line: pairs passing each target and the worst pair per measure
#    (bench/surface_quality_table.py writes the table). Every pair is rendered (--render, 2 views of
#    RENDER_SIZE) to OUTPUT_DIR/renders/MESH_EXEMPLAR.png, and all of them into one contact sheet,
#    OUTPUT_DIR/renders/sheet.png (G'MIC; a row per exemplar, a column per mesh). The floor (in the
#    analysis table) is the exemplar itself copied onto a flat retiled plane (each vertex the
#    exemplar pixel under it, through --apply-coords): what a perfect vertex-color texture scores
#    once its patches are resampled between irregularly placed vertices (1.1-3.6x 2D's image
#    coherence), which is why 2D's coherence is compared on such a plane too.
# The one-off exemplar analyses are run first (on that plane) and listed apart.
# Prints progress on stderr, the tables on stdout, and writes them to OUTPUT_DIR/results.md with
# runs.tsv (Table 2), quality.tsv (one row per pair, every column of the quality table),
# analyses.tsv, the exemplars, meshes, eval JSON and stats.
#
# Usage: bench/surface_synthesis.sh [BUILD_DIR] [OUTPUT_DIR]
#   BUILD_DIR (default build) and OUTPUT_DIR (default a new temporary directory) are taken from
#   the repository root when relative.
# Environment:
#   THREADS=2                    --threads of every command (the goal is stated for 2 cores)
#   SEED=3                       --seed of every command
#   VERTICES=48000               retiled vertex count of the Table 2 runs and of the quality pairs
#   LARGE_VERTICES=200000        the large run (0 skips it), on LARGE_RUN (mesh:exemplar)
#   RUNS="bunny00:granite64 ..." Table 2 runs as mesh:exemplar (meshes from MESH_DIR, .off)
#   QUALITY_MESHES="bunny00 elephant armadillo dino pig cow"
#   QUALITY_EXEMPLARS="burlap96 cracked128 leopard leaves64 bark pink_marble128 brick64 granite64"
#   SOLIDS=tile-blend            solids colored onto the retiled vertices (also: tile-deform)
#   RENDER_SIZE=384  VIEWS=2     the pairs' renders
#   IMAGE_SIZE=256  SAMPLES=4000 (eval --samples)  MESH_DIR=.data/meshes
# Exemplars (from /usr/share/gimp/2.0/patterns, made exactly as named; "crop" is the top-left
# corner, "resize" G'MIC's bicubic): granite64 and rock64 (crops of granite1, rock), brick64 (brick
# 96² resized), burlap96 (Fabric/burlap, woven, as it is), leopard (Animal/leopard 64x62, dark spots
# on a flat ground, as it is), leaves64 (Plant/leaves 50² resized), bark (Wood/bark 82x90, as it
# is), pine (64x56, as it is), pink_marble128 and slate128 (as they are), cracked128 (crop of
# cracked: a flat gray ground with sparse dark cracks).
# Time on 2 cores: the quality section costs about 13 s a pair (its synthesis run 6 s, two evals,
# the solid) and 15-40 s an exemplar (analysis, floor, 2D optimize, its eval and its plane copy:
# 25 s for a 128² one): about 13 minutes for the default 48 pairs, 3 for 1 mesh x 8 exemplars.
# Cheapest check (one pair, one Table 2 run, under a minute):
#   RUNS="cow:rock64" LARGE_VERTICES=0 QUALITY_MESHES=cow QUALITY_EXEMPLARS=rock64 \
#   VERTICES=12000 bench/surface_synthesis.sh build /tmp/bench_surface_quick
# A quality subset at the real settings (4 pairs, about 2 minutes):
#   RUNS="cow:rock64" LARGE_VERTICES=0 QUALITY_MESHES="cow dino" QUALITY_EXEMPLARS="burlap96 cracked128" \
#   bench/surface_synthesis.sh build /tmp/bench_surface_subset
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-}
[ -n "$out" ] || out=$(mktemp -d)
case $build in /*) texsynth="$build/bin/texsynth" ;; *) texsynth="$(pwd)/$build/bin/texsynth" ;; esac
patterns=/usr/share/gimp/2.0/patterns
mesh_dir=${MESH_DIR:-$(pwd)/.data/meshes}
threads=${THREADS:-2}
seed=${SEED:-3}
vertices=${VERTICES:-48000}
large_vertices=${LARGE_VERTICES:-200000}
large_run=${LARGE_RUN:-bunny00:pink_marble128}
image_size=${IMAGE_SIZE:-256}
samples=${SAMPLES:-4000}
render_size=${RENDER_SIZE:-384}
views=${VIEWS:-2}
read -r -a solids <<<"${SOLIDS:-tile-blend}"
read -r -a runs <<<"${RUNS:-bunny00:granite64 bunny00:brick64 bunny00:pink_marble128 bunny00:cracked128 \
elephant:granite64 elephant:brick64 elephant:pink_marble128 elephant:cracked128 cow:rock64 cow:pine \
armadillo:rock64 armadillo:slate128}"
read -r -a quality_meshes <<<"${QUALITY_MESHES:-bunny00 elephant armadillo dino pig cow}"
read -r -a quality_exemplars <<<"${QUALITY_EXEMPLARS:-burlap96 cracked128 leopard leaves64 bark pink_marble128 brick64 granite64}"

# Exemplar name -> "GIMP pattern, how to make it (copy | crop | resize), width height".
declare -A recipe=(
  [granite64]="Stone/granite1 crop 64 64" [rock64]="Stone/rock crop 64 64" [brick64]="Stone/brick resize 64 64"
  [pine]="Wood/pine copy 64 56" [pink_marble128]="Stone/pink_marble copy 128 128"
  [slate128]="Stone/slate copy 128 128" [cracked128]="Stone/cracked crop 128 128"
  [burlap96]="Fabric/burlap copy 96 96" [leopard]="Animal/leopard copy 64 62"
  [leaves64]="Plant/leaves resize 64 64" [bark]="Wood/bark copy 82 90"
)

# Prerequisites, each with what to do about it.
[ -x "$texsynth" ] || { echo "build first: $texsynth is missing" >&2; exit 1; }
[ -d "$patterns" ] || { echo "gimp-data is not installed (scripts/install-deps.sh)" >&2; exit 1; }
command -v gmic >/dev/null || { echo "gmic is not installed (scripts/install-deps.sh)" >&2; exit 1; }
command -v python3 >/dev/null || { echo "python3 is not installed (it reads the JSON stats)" >&2; exit 1; }
[[ $vertices =~ ^[1-9][0-9]*$ ]] || { echo "VERTICES '$vertices' is not a positive integer" >&2; exit 1; }
[[ $large_vertices =~ ^[0-9]+$ ]] || { echo "LARGE_VERTICES '$large_vertices' is not an integer" >&2; exit 1; }
[[ $threads =~ ^[1-9][0-9]*$ ]] || { echo "THREADS '$threads' is not a positive integer" >&2; exit 1; }
[[ $seed =~ ^[0-9]+$ ]] || { echo "SEED '$seed' is not an integer" >&2; exit 1; }
[[ $render_size =~ ^[1-9][0-9]*$ ]] || { echo "RENDER_SIZE '$render_size' is not a positive integer" >&2; exit 1; }
[[ $views =~ ^[1-4]$ ]] || { echo "VIEWS '$views' is not 1 to 4" >&2; exit 1; }
for method in "${solids[@]}"; do
  case $method in tile-deform | tile-blend) ;; *) echo "SOLIDS: '$method' is not tile-deform or tile-blend" >&2; exit 1 ;; esac
done
all_runs=("${runs[@]}")
[ "$large_vertices" -gt 0 ] && all_runs+=("$large_run")
used_exemplars=()
for run in "${all_runs[@]}"; do
  [[ $run == *:* ]] || { echo "run '$run' is not mesh:exemplar (RUNS, LARGE_RUN)" >&2; exit 1; }
  used_exemplars+=("${run#*:}")
  [ -f "$mesh_dir/${run%%:*}.off" ] || { echo "no mesh $mesh_dir/${run%%:*}.off (MESH_DIR; libcgal-demo)" >&2; exit 1; }
done
declare -A quality_pair=()  # mesh:exemplar -> 1: rendered by whichever run synthesizes it first
for mesh in "${quality_meshes[@]}"; do
  [ -f "$mesh_dir/$mesh.off" ] || { echo "no mesh $mesh_dir/$mesh.off (QUALITY_MESHES)" >&2; exit 1; }
  for name in "${quality_exemplars[@]}"; do quality_pair[$mesh:$name]=1; done
done
used_exemplars+=("${quality_exemplars[@]}")
read -r -a used_exemplars <<<"$(printf "%s\n" "${used_exemplars[@]}" | awk '!seen[$0]++' | tr '\n' ' ')"
for name in "${used_exemplars[@]}"; do
  [ -n "${recipe[$name]:-}" ] || { echo "unknown exemplar '$name' (known: ${!recipe[*]})" >&2; exit 1; }
done

mkdir -p "$out"/{exemplars,runs,quality,plane,renders}
out=$(cd "$out" && pwd)
cache="$out/cache"
rm -rf "$cache" "$out"/cache-cold-*
mkdir -p "$cache"
export TEXSYNTH_CACHE="$cache"
bench_start=$(date +%s.%N)
progress() { printf "[%6.1f s] %s\n" "$(awk -v a="$bench_start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')" "$*" >&2; }
ts() { "$texsynth" "$@" --threads "$threads" --seed "$seed" --quiet; }
json_get() {  # FILE EXPRESSION: a Python expression over the JSON `d`
  python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2"
}
# Measures from eval's JSON (FILE SECTION KEY...): each KEY of d[SECTION] (else of d) as %.3f,
# "n/a" where this eval does not report it.
measures() {
  python3 - "$@" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
section = d.get(sys.argv[2], {})
def get(key):
    v = section.get(key, d.get(key))
    return "%.3f" % v if isinstance(v, (int, float)) and not isinstance(v, bool) else "n/a"
print(" ".join(get(key) for key in sys.argv[3:]))
PY
}
# Surface measures of a colored mesh (EXEMPLAR MESH JSON, eval's JSON kept in JSON):
# coherence rotation_invariant completeness histogram flatness.
surface_eval() {
  "$texsynth" eval "$1" "$2" --samples "$samples" --threads "$threads" --json --quiet >"$3"
  measures "$3" surface coherence rotation_invariant completeness histogram flatness
}
# --tiles that puts one exemplar pixel on one vertex spacing of MESH ($1, spacing $2, exemplar $3).
tiles_for() {
  "$texsynth" info "$1" --json | python3 -c '
import json, sys
d = json.load(sys.stdin)
longest = max(b - a for a, b in zip(d["bounds_min"], d["bounds_max"]))
w, h = map(int, sys.argv[2].split("x"))
print(longest / (float(sys.argv[1]) * max(w, h)))' "$2" "$3"
}

# --- Exemplars, exactly as named.
for name in "${used_exemplars[@]}"; do
  read -r pattern how width height <<<"${recipe[$name]}"
  pat="$patterns/$pattern.pat"
  [ -f "$pat" ] || { echo "no GIMP pattern $pat" >&2; exit 1; }
  png="$out/exemplars/$name.png"
  case $how in
    # tile-deform with no deformation is a 1:1 copy of the window at the origin.
    copy | crop) ts image "$pat" --method tile-deform --lambda 0 --tileable never --size "${width}x${height}" -o "$png" ;;
    resize)
      read -r w0 h0 < <("$texsynth" info "$pat" --json | python3 -c 'import json,sys; d=json.load(sys.stdin); print(d["width"], d["height"])')
      ts image "$pat" --method tile-deform --lambda 0 --tileable never --size "${w0}x${h0}" -o "$out/exemplars/${name}_source.png"
      gmic -v - "$out/exemplars/${name}_source.png" resize "$width,$height,1,100%,5" cut 0,255 -o "$png" >/dev/null 2>&1
      ;;
  esac
  size=$("$texsynth" info "$png" --json | python3 -c 'import json,sys; d=json.load(sys.stdin); print("%dx%d" % (d["width"], d["height"]))')
  [ "$size" = "${width}x${height}" ] || { echo "$png is $size, not ${width}x${height}" >&2; exit 1; }
done
progress "exemplars ready: ${used_exemplars[*]}"

# --- One-off analyses, on a flat plane retiled to about (side - 10)² vertices (the coherent floor).
plane="$out/plane/plane.off"
python3 - "$plane" <<'PY'
import sys
n = 8
with open(sys.argv[1], "w") as f:
    f.write(f"OFF\n{(n + 1) ** 2} {2 * n * n} 0\n")
    for y in range(n + 1):
        for x in range(n + 1):
            f.write(f"{x / n} {y / n} 0\n")
    for y in range(n):
        for x in range(n):
            v = y * (n + 1) + x
            f.write(f"3 {v} {v + 1} {v + n + 2}\n3 {v} {v + n + 2} {v + n + 1}\n")
PY
# Copies SOURCE (an image W x H) pixel by pixel onto the plane retiled to (min(W, H) - 10)² vertices
# (each vertex the source pixel under it, source x along +x, its y down along -y, as the default
# orientation lays it, through --apply-coords) and prints its surface measures against EXEMPLAR:
# copy_onto_plane SOURCE W H TAG EXEMPLAR_NAME. The retiling runs on EXEMPLAR_NAME (analysis cached).
copy_onto_plane() {
  local source=$1 w=$2 h=$3 tag=$4 name=$5 side
  side=$(($2 < $3 ? $2 : $3))
  ts surface "$out/exemplars/$name.png" --mesh "$plane" --vertices $(((side - 10) * (side - 10))) \
    -o "$out/plane/$tag.obj" --stats "$out/plane/$tag.json"
  python3 - "$out/plane/$tag.obj" "$(json_get "$out/plane/$tag.json" 'd["levels"][-1]["spacing"]')" \
    "$w" "$h" "$out/plane/${tag}_coords.ply" <<'PY'
import math, sys
obj, s, w, h, ply = sys.argv[1], float(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
vertices, faces = [], []
for line in open(obj):
    f = line.split()
    if f and f[0] == "v":
        vertices.append(tuple(map(float, f[1:4])))
    elif f and f[0] == "f":
        faces.append([int(c.split("/")[0]) - 1 for c in f[1:]])
with open(ply, "w") as out:
    out.write(f"ply\nformat ascii 1.0\nelement vertex {len(vertices)}\n")
    out.write("".join(f"property float {p}\n" for p in ("x", "y", "z", "source_u", "source_v")))
    out.write(f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    for x, y, z in vertices:
        px = min(w - 1, max(0, math.floor(x / s)))
        py = min(h - 1, max(0, math.floor((1 - y) / s)))
        out.write(f"{x} {y} {z} {(px + 0.5) / w} {(py + 0.5) / h}\n")
    for face in faces:
        out.write(f"{len(face)} " + " ".join(map(str, face)) + "\n")
PY
  ts surface "$source" --apply-coords "$out/plane/${tag}_coords.ply" -o "$out/plane/${tag}_copy.ply"
  surface_eval "$out/exemplars/$name.png" "$out/plane/${tag}_copy.ply" "$out/plane/${tag}_copy_eval.json"
}
printf "exemplar\tsize\tanalysis_seconds\tfloor_coherence\tfloor_rotation_invariant\n" >"$out/analyses.tsv"
for name in "${used_exemplars[@]}"; do
  read -r _ _ width height <<<"${recipe[$name]}"
  png="$out/exemplars/$name.png"
  read -r floor_plain floor _ <<<"$(copy_onto_plane "$png" "$width" "$height" "$name" "$name")"
  analysis=$(json_get "$out/plane/$name.json" '"%.1f" % d["analysis_seconds"]')
  printf "%s\t%sx%s\t%s\t%s\t%s\n" "$name" "$width" "$height" "$analysis" "$floor_plain" "$floor" >>"$out/analyses.tsv"
  progress "analysis $name: $analysis s; exemplar copied onto a plane: coherence $floor_plain / $floor"
done

# --- Table 2 runs. The first run on each mesh and vertex count gets a cold hierarchy.
runs_header="mesh\texemplar\tsize\tvertices\tcold\thierarchy\tprepare\tem_finest\tem_all\tem_steps\tsynthesis\twall\tanalysis\n"
# shellcheck disable=SC2059  # the header's tabs
printf "$runs_header" >"$out/runs.tsv"
declare -A built=()
surface_run() {  # MESH EXEMPLAR VERTICES [TSV, default runs.tsv: the Table 2 rows]
  local mesh=$1 name=$2 count=$3 tag="$1_$2_$3" tsv=${4:-$out/runs.tsv} cold=0 start render=()
  read -r _ _ width height <<<"${recipe[$name]}"
  # A quality pair is rendered by its one run (outputs are outside every --stats column but wall).
  if [ "$count" = "$vertices" ] && [ -n "${quality_pair[$mesh:$name]:-}" ]; then
    render=(--render "$out/renders/${mesh}_$name.png" --render-size "$render_size" --views "$views")
  fi
  if [ -z "${built[$mesh:$count]:-}" ]; then
    cold=1
    export TEXSYNTH_CACHE="$out/cache-cold-$mesh-$count"
    mkdir -p "$TEXSYNTH_CACHE"
    find "$cache" -maxdepth 1 -name 'exemplar-*' -exec cp -l {} "$TEXSYNTH_CACHE/" \;
  fi
  start=$(date +%s.%N)
  ts surface "$out/exemplars/$name.png" --mesh "$mesh_dir/$mesh.off" --vertices "$count" -o "$out/runs/$tag.ply" \
    --stats "$out/runs/$tag.json" "${render[@]}"
  local wall
  wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  if [ $cold = 1 ]; then
    find "$TEXSYNTH_CACHE" -maxdepth 1 -name 'hierarchy-*' -exec cp {} "$cache/" \;
    rm -rf "$TEXSYNTH_CACHE"
    export TEXSYNTH_CACHE="$cache"
    built[$mesh:$count]=1
  fi
  python3 - "$out/runs/$tag.json" "$mesh" "$name" "${width}x${height}" "$cold" "$wall" >>"$tsv" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
mesh, name, size, cold, wall = sys.argv[2:]
steps = [s for s in d["steps"] if s["iteration"] >= 1]  # E+M steps
finest = max(s["level"] for s in d["steps"])
at_finest = [s["seconds"] for s in steps if s["level"] == finest]
mean = lambda xs: sum(xs) / len(xs) if xs else float("nan")
if d.get("hierarchy_cached") != (cold == "0"):
    print(f"warning: {sys.argv[1]}: hierarchy_cached is {d.get('hierarchy_cached')} on a "
          f"{'cold' if cold == '1' else 'warm'} run", file=sys.stderr)
print("\t".join([mesh, name, size, str(d["levels"][-1]["vertices"]), cold, f"{d['hierarchy_seconds']:.2f}",
                 f"{d['prepare_seconds']:.2f}", f"{mean(at_finest):.3f}", f"{mean([s['seconds'] for s in steps]):.3f}",
                 str(len(steps)), f"{d['synthesis_seconds']:.2f}", wall, f"{d['analysis_seconds']:.2f}"]))
PY
  progress "surface $mesh $name $count: $(tail -n 1 "$tsv" | awk -F'\t' '{ printf "hierarchy %s s (%s), prepare %s s, E+M %s s finest / %s s all, synthesis %s s", $6, $5 == 1 ? "cold" : "warm", $7, $8, $9, $11 }')"
}
for run in "${runs[@]}"; do surface_run "${run%%:*}" "${run#*:}" "$vertices"; done
if [ "$large_vertices" -gt 0 ]; then
  # Twice: cold, then warm (the hierarchy from the cache).
  surface_run "${large_run%%:*}" "${large_run#*:}" "$large_vertices"
  surface_run "${large_run%%:*}" "${large_run#*:}" "$large_vertices"
fi

# --- Quality: every mesh x exemplar pair, its retiled vertices colored by surface synthesis and by
# SOLIDS; 2D optimize once per exemplar. Pairs not among the Table 2 runs are synthesized here (their
# speed rows go to quality/runs.tsv, not into Table 2).
# shellcheck disable=SC2059  # the header's tabs
printf "$runs_header" >"$out/quality/runs.tsv"
printf "mesh\texemplar\tsize\tvertices\tseconds\tcoherence\trotation_invariant\tcompleteness\thistogram\tflatness\trender\n" \
  >"$out/quality/surface.tsv"
printf "mesh\texemplar\tmethod\tcoherence\trotation_invariant\tcompleteness\thistogram\tflatness\n" >"$out/quality/solids.tsv"
for mesh in "${quality_meshes[@]}"; do
  for name in "${quality_exemplars[@]}"; do
    read -r _ _ width height <<<"${recipe[$name]}"
    png="$out/exemplars/$name.png"
    tag="${mesh}_${name}_${vertices}"
    [ -f "$out/runs/$tag.ply" ] || surface_run "$mesh" "$name" "$vertices" "$out/quality/runs.tsv"
    retiled="$out/runs/$tag.ply"
    read -r c r m h f <<<"$(surface_eval "$png" "$retiled" "$out/quality/${tag}_surface_eval.json")"
    read -r seconds count <<<"$(json_get "$out/runs/$tag.json" '"%.2f %d" % (d["synthesis_seconds"], d["levels"][-1]["vertices"])')"
    render_file="renders/${mesh}_$name.png"
    [ -f "$out/$render_file" ] || render_file=""
    printf "%s\t%s\t%sx%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" "$mesh" "$name" "$width" "$height" "$count" "$seconds" \
      "$c" "$r" "$m" "$h" "$f" "$render_file" >>"$out/quality/surface.tsv"
    line="surface ${seconds} s: coherence $c, completeness $m, histogram $h, flatness $f"
    spacing=$(json_get "$out/runs/$tag.json" 'd["levels"][-1]["spacing"]')
    tiles=$(tiles_for "$retiled" "$spacing" "${width}x${height}")
    for method in "${solids[@]}"; do
      colored="$out/quality/${tag}_$method.ply"
      ts solid "$png" --method "$method" --mesh "$retiled" --tiles "$tiles" -o "$colored"
      read -r c r m h f <<<"$(surface_eval "$png" "$colored" "$out/quality/${tag}_${method}_eval.json")"
      printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" "$mesh" "$name" "$method" "$c" "$r" "$m" "$h" "$f" >>"$out/quality/solids.tsv"
      line+="; $method $c / $h / $f"
    done
    progress "quality $mesh $name: $line"
  done
done
read -r -a distinct_exemplars <<<"$(printf "%s\n" "${quality_exemplars[@]}" | awk 'NF && !seen[$0]++' | tr '\n' ' ')"
printf "exemplar\tsize\tseconds\tcoherence\tcompleteness\thistogram\tflatness\tplane_coherence\n" >"$out/quality/image.tsv"
for name in "${distinct_exemplars[@]}"; do
  read -r _ _ width height <<<"${recipe[$name]}"
  image="$out/quality/${name}_optimize_${image_size}.png"
  start=$(date +%s.%N)
  ts image "$out/exemplars/$name.png" --method optimize --tileable never --size "$image_size" -o "$image"
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  "$texsynth" eval "$out/exemplars/$name.png" "$image" --threads "$threads" --json --quiet >"$out/quality/${name}_optimize_eval.json"
  read -r c m h f <<<"$(measures "$out/quality/${name}_optimize_eval.json" metrics coherence completeness histogram flatness)"
  # The same image on the surface's footing: copied onto the retiled plane, measured as a surface.
  read -r plane_c _ <<<"$(copy_onto_plane "$image" "$image_size" "$image_size" "${name}_optimize" "$name")"
  printf "%s\t%sx%s\t%s\t%s\t%s\t%s\t%s\t%s\n" "$name" "$width" "$height" "$seconds" "$c" "$m" "$h" "$f" "$plane_c" \
    >>"$out/quality/image.tsv"
  progress "2D optimize $name ${image_size}² ($seconds s): coherence $c (on a plane $plane_c), histogram $h"
done

# --- Contact sheet of the renders (G'MIC): a row per exemplar (the exemplar, then a column per
# mesh), each render at half size; a gray cell where a render is missing.
if [ ${#quality_meshes[@]} -gt 0 ] && [ ${#quality_exemplars[@]} -gt 0 ]; then
  cell=$((render_size / 2))
  rows=()
  for name in "${distinct_exemplars[@]}"; do
    args=("$out/exemplars/$name.png" 'to_rgb[-1]' 'resize2dy[-1]' "$cell,1" 'resize[-1]' "$cell,$cell,1,3,0,0,0.5,0.5"
      'text[-1]' "\"$name\",4,4,16,1,255,255,255")
    for mesh in "${quality_meshes[@]}"; do
      if [ -f "$out/renders/${mesh}_$name.png" ]; then
        args+=("$out/renders/${mesh}_$name.png" 'to_rgb[-1]' 'resize2dy[-1]' "$cell,2")
      else
        args+=(input "$((cell * views)),$cell,1,3,200")
      fi
      args+=('text[-1]' "\"$mesh/$name\",4,4,16,1,0,0,0")
    done
    gmic -v - "${args[@]}" append x -o "$out/renders/row_$name.png" >/dev/null 2>&1 && rows+=("$out/renders/row_$name.png")
  done
  if [ ${#rows[@]} -gt 0 ] && gmic -v - "${rows[@]}" append y -o "$out/renders/sheet.png" >/dev/null 2>&1; then
    rm -f "${rows[@]}"
    progress "contact sheet: $out/renders/sheet.png"
  else
    progress "contact sheet: G'MIC failed, renders are in $out/renders"
  fi
fi

# --- Tables.
python3 - "$out" "$threads" "$vertices" "$(nproc)" "$image_size" "$samples" >"$out/results.md" <<'PY'
import csv, math, sys
out, threads, vertices, cores, image_size, samples = sys.argv[1:]
read = lambda name: list(csv.DictReader(open(f"{out}/{name}"), delimiter="\t"))
runs, analyses = read("runs.tsv"), read("analyses.tsv")
mean = lambda xs: sum(xs) / len(xs) if xs else float("nan")

print(f"# Surface synthesis, {threads} threads on {cores} cores\n")
print("## Table 2: speed\n")
print("Hierarchy: cold = built (fresh cache), warm = loaded from the cache. E+M: mean seconds per E+M step "
      "(--stats steps with iteration >= 1) at the finest level and over all levels. Synthesis: the whole "
      "coarse-to-fine optimization (not hierarchy, preparation or the one-off exemplar analysis).\n")
print("| mesh | exemplar | vertices | hierarchy cold | hierarchy warm | preparation | E+M finest | E+M all levels | E+M steps | synthesis | wall |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for r in runs:
    cold, warm = (r["hierarchy"] + " s", "") if r["cold"] == "1" else ("", r["hierarchy"] + " s")
    print(f"| {r['mesh']} | {r['exemplar']} ({r['size']}) | {r['vertices']} | {cold} | {warm} | {r['prepare']} s | "
          f"{r['em_finest']} s | {r['em_all']} s | {r['em_steps']} | {r['synthesis']} s | {r['wall']} s |")
small = [r for r in runs if abs(int(r["vertices"]) - int(vertices)) <= 0.15 * int(vertices)]
if small:
    finest = [float(r["em_finest"]) for r in small]
    every = [float(r["em_all"]) for r in small]
    synth = [float(r["synthesis"]) for r in small]
    print(f"\nAt ~{int(vertices) // 1000}K vertices ({len(small)} run{'s' * (len(small) != 1)}): E+M step {min(finest):.3f}-{max(finest):.3f} s "
          f"at the finest level (mean {mean(finest):.3f}), {mean(every):.3f} s over all levels; whole synthesis "
          f"{min(synth):.1f}-{max(synth):.1f} s (mean {mean(synth):.1f}).\n")
    ok_step, ok_total = max(finest) <= 0.3, max(synth) <= 10
    print("| | per E+M step at 48K | whole 48K synthesis |")
    print("|---|---:|---:|")
    print("| paper, least squares [Kwatra 2005], P4 3.2 GHz | 7.9-79.8 s | |")
    print("| paper, k-coherence discrete solver, CPU (P4 3.2 GHz) | 1.83-2.97 s | |")
    print("| paper, GPU (GeForce 7800 GT) | 0.59-0.70 s | |")
    print(f"| texsynth, {threads} threads (finest level, worst run) | {max(finest):.3f} s | {max(synth):.1f} s |")
    print(f"| goal | <= 0.3 s {'(met)' if ok_step else '(NOT met)'} | <= 10 s {'(met)' if ok_total else '(NOT met)'} |")

print("\nOne-off exemplar analysis (cached afterwards) and the floor: the exemplar itself copied onto a flat "
      "retiled plane (each vertex the pixel under it), surface coherence plain / rotation-invariant:\n")
print("| exemplar | size | analysis | floor |")
print("|---|---|---:|---:|")
for a in analyses:
    print(f"| {a['exemplar']} | {a['size']} | {a['analysis_seconds']} s | {a['floor_coherence']} / "
          f"{a['floor_rotation_invariant']} |")

PY
python3 bench/surface_quality_table.py "$out" --vertices "$vertices" --seed "$seed" --threads "$threads" \
  --samples "$samples" --image-size "$image_size" --solids "${solids[@]}" >>"$out/results.md"
cat "$out/results.md"
progress "$(tail -n 1 "$out/results.md")"
progress "done; tables in $out/results.md"
