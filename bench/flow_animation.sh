#!/usr/bin/env bash
# Flow animation by discrete optimization (texsynth animate: Han et al.'s solver with Kwatra et
# al.'s temporal term E_c, weighted by --coherence = lambda): per-frame speed, and temporal
# coherence against fidelity to the exemplar.
#
# 1. Speed: 2D at 512² (pink_marble, flows vortex, source and uniform, 30 frames) and on the
#    bunny00 mesh retiled to 48K vertices (pink_marble, flows downhill and swirl, 20 rendered
#    frames), all at the default lambda: first, mean and max seconds per frame from --stats, with
#    the mean advection and solve seconds, kept share and temporal change of frames 1 on. Goals:
#    mean <= 0.1 s per 2D frame at 512², <= 0.5 s per surface frame at 48K (the paper: 0.6-0.7 s per
#    E+M step on a GPU). The surface runs once untimed first (one frame), so that the timed runs
#    load the retiled hierarchy from the cache; per-frame times never include it anyway.
# 2. Coherence vs fidelity at 256², 120 frames: 4 exemplars x 3 flows x lambda in {0, default,
#    1e6}. Per run: the mean temporal change (mean |frame t+1 - frame t carried along the flow|,
#    8-bit levels, from --stats) and the `texsynth eval` coherence of frames 1, 30, 60 and 120.
#    lambda = 0 makes every frame an independent static synthesis (the flow only enters the
#    temporal measure) and is ~10x slower per frame, so it runs once per exemplar, with the vortex
#    flow, and its columns serve every flow of that exemplar. Static coherence = the mean of its
#    frames' coherences. Goal per exemplar and flow, at the default lambda: mean coherence over
#    frames 30-120 within 1.2x of static AND temporal change at least 5x lower than independent
#    frames.
# Prints progress on stderr, the tables on stdout, and writes them to OUTPUT_DIR/results.md with
# speed.tsv, coherence.tsv, every run's frames and stats, and the eval JSON.
#
# Usage: bench/flow_animation.sh [BUILD_DIR] [OUTPUT_DIR] [--quick]
#   BUILD_DIR (default build) and OUTPUT_DIR (default a new temporary directory) are taken from
#   the repository root when relative. --quick: 30 frames in part 2, coherence of frames 1, 15, 30
#   (part 1 unchanged). A full run takes ~10-15 minutes on 2 cores, --quick ~5-7 (7 on 2 busy cores).
# Environment:
#   EXEMPLARS="Stone/pink_marble Fabric/burlap Stone/rock Food/choc_swirl"  part 2's GIMP patterns
#   FLOWS="vortex:strength=2 source:strength=1.5 uniform:dx=1.3,dy=0.4"    part 2's flows (the first
#                                   one also drives the lambda = 0 run)
#   MESH_DIR=.data/meshes
# Every command uses all cores (no --threads).
# Cheapest check: EXEMPLARS=Stone/rock FLOWS=vortex:strength=2 bench/flow_animation.sh build /tmp/bench_flow --quick
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
quick=0
args=()
for arg in "$@"; do
  case $arg in
    --quick) quick=1 ;;
    -*) echo "unknown option '$arg' (usage: bench/flow_animation.sh [BUILD_DIR] [OUTPUT_DIR] [--quick])" >&2; exit 1 ;;
    *) args+=("$arg") ;;
  esac
done
[ ${#args[@]} -le 2 ] || { echo "usage: bench/flow_animation.sh [BUILD_DIR] [OUTPUT_DIR] [--quick]" >&2; exit 1; }
build=${args[0]:-build}
out=${args[1]:-}
[ -n "$out" ] || out=$(mktemp -d)
case $build in /*) texsynth="$build/bin/texsynth" ;; *) texsynth="$(pwd)/$build/bin/texsynth" ;; esac
patterns=/usr/share/gimp/2.0/patterns
mesh_dir=${MESH_DIR:-$(pwd)/.data/meshes}
read -r -a exemplars <<<"${EXEMPLARS:-Stone/pink_marble Fabric/burlap Stone/rock Food/choc_swirl}"
read -r -a flows <<<"${FLOWS:-vortex:strength=2 source:strength=1.5 uniform:dx=1.3,dy=0.4}"
speed_pattern=Stone/pink_marble
speed_flows=(vortex:strength=2 source:strength=2 "uniform:dx=1.3,dy=0.4")
speed_size=512
speed_frames=30
surface_mesh=bunny00
surface_flows=(downhill swirl)
surface_frames=20
size=256
independent_lambda=0
pure_lambda=1000000
if [ $quick = 1 ]; then
  frames=30
  checked=(1 15 30)
else
  frames=120
  checked=(1 30 60 120)
fi

# Prerequisites, each with what to do about it.
[ -x "$texsynth" ] || { echo "build first: $texsynth is missing" >&2; exit 1; }
[ -d "$patterns" ] || { echo "gimp-data is not installed (scripts/install-deps.sh)" >&2; exit 1; }
command -v python3 >/dev/null || { echo "python3 is not installed (it reads the JSON stats)" >&2; exit 1; }
[ -f "$mesh_dir/$surface_mesh.off" ] || { echo "no mesh $mesh_dir/$surface_mesh.off (MESH_DIR; libcgal-demo)" >&2; exit 1; }
[ ${#exemplars[@]} -gt 0 ] || { echo "EXEMPLARS is empty" >&2; exit 1; }
[ ${#flows[@]} -gt 0 ] || { echo "FLOWS is empty" >&2; exit 1; }
for name in "${exemplars[@]}" "$speed_pattern"; do
  [ -f "$patterns/$name.pat" ] || { echo "no GIMP pattern $patterns/$name.pat (EXEMPLARS)" >&2; exit 1; }
done
labels=()
for flow in "${flows[@]}"; do labels+=("${flow%%:*}"); done
[ "$(printf "%s\n" "${labels[@]}" | sort -u | wc -l)" -eq ${#flows[@]} ] ||
  { echo "FLOWS '${flows[*]}' names a kind of flow twice" >&2; exit 1; }

mkdir -p "$out"/{speed,coherence}
out=$(cd "$out" && pwd)
export TEXSYNTH_CACHE="$out/cache"
rm -rf "$TEXSYNTH_CACHE"
mkdir -p "$TEXSYNTH_CACHE"
bench_start=$(date +%s.%N)
progress() { printf "[%6.1f s] %s\n" "$(awk -v a="$bench_start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')" "$*" >&2; }
now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }
json_get() {  # FILE EXPRESSION: a Python expression over the JSON `d`
  python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2"
}
# One animation into DIR ($1): frames DIR/%03d.png, stats DIR/stats.json, wall seconds DIR/wall.
animate() {
  local dir=$1 start
  shift
  rm -rf "$dir"
  mkdir -p "$dir"
  start=$(now)
  "$texsynth" animate "$@" -o "$dir/%03d.png" --stats "$dir/stats.json" --quiet
  elapsed "$start" "$(now)" >"$dir/wall"
}
frame_file() { printf "%03d.png" $(($1 - 1)); }  # frame counted from 1 -> its file

# --- 1. Speed at the default lambda.
printf "kind\tflow\tdir\n" >"$out/speed.tsv"
for flow in "${speed_flows[@]}"; do
  dir="$out/speed/2d_${flow%%:*}"
  animate "$dir" "$patterns/$speed_pattern.pat" --flow "$flow" --size "$speed_size" --frames "$speed_frames"
  printf "2D %s²\t%s\t%s\n" "$speed_size" "$flow" "$dir" >>"$out/speed.tsv"
  progress "2D $flow: mean $(json_get "$dir/stats.json" '"%.3f" % d["mean_frame_seconds"]') s per frame (wall $(cat "$dir/wall") s)"
done
# Untimed: fills the cache with the retiled hierarchy of the mesh.
animate "$out/speed/surface_warmup" "$patterns/$speed_pattern.pat" --mesh "$mesh_dir/$surface_mesh.off" \
  --flow "${surface_flows[0]}" --frames 1
progress "surface warm-up (hierarchy $(json_get "$out/speed/surface_warmup/stats.json" '"%.1f" % d["hierarchy_seconds"]') s, cached afterwards)"
for flow in "${surface_flows[@]}"; do
  dir="$out/speed/surface_${flow%%:*}"
  animate "$dir" "$patterns/$speed_pattern.pat" --mesh "$mesh_dir/$surface_mesh.off" --flow "$flow" \
    --frames "$surface_frames"
  printf "surface %s\t%s\t%s\n" "$surface_mesh" "$flow" "$dir" >>"$out/speed.tsv"
  progress "surface $flow: mean $(json_get "$dir/stats.json" '"%.3f" % d["mean_frame_seconds"]') s per frame (wall $(cat "$dir/wall") s)"
done

# --- 2. Temporal coherence against fidelity.
printf "exemplar\tflow\tlambda\tdir\n" >"$out/coherence.tsv"
declare -A evaluated=()  # "pattern md5" of an evaluated frame -> its eval JSON
coherence_run() {  # PATTERN FLOW LAMBDA (empty: the default)
  local name=$1 flow=$2 lambda=$3 stem dir frame
  stem=$(basename "$name")
  dir="$out/coherence/${stem}_${flow%%:*}_${lambda:-default}"
  local extra=()
  [ -n "$lambda" ] && extra=(--coherence "$lambda")
  animate "$dir" "$patterns/$name.pat" --flow "$flow" --size "$size" --frames "$frames" "${extra[@]}"
  for frame in "${checked[@]}"; do
    # Frame 1 (a static synthesis with the same seed) is the same image in every run of an
    # exemplar: one eval per distinct image.
    local key
    key="$name $(md5sum <"$dir/$(frame_file "$frame")")"
    if [ -n "${evaluated[$key]:-}" ]; then
      cp "${evaluated[$key]}" "$dir/eval_$frame.json"
    else
      "$texsynth" eval "$patterns/$name.pat" "$dir/$(frame_file "$frame")" --json --quiet >"$dir/eval_$frame.json"
      evaluated[$key]="$dir/eval_$frame.json"
    fi
  done
  printf "%s\t%s\t%s\t%s\n" "$stem" "$flow" "${lambda:-default}" "$dir" >>"$out/coherence.tsv"
  progress "$stem ${flow%%:*} lambda ${lambda:-default}: change $(json_get "$dir/stats.json" '"%.2f" % d["mean_temporal_change"]'), \
$(json_get "$dir/stats.json" '"%.3f" % d["mean_frame_seconds"]') s per frame (wall $(cat "$dir/wall") s); coherence \
$(for frame in "${checked[@]}"; do json_get "$dir/eval_$frame.json" '"%.3f" % d["metrics"]["coherence"]'; done | tr '\n' ' ')"
}
for name in "${exemplars[@]}"; do
  coherence_run "$name" "${flows[0]}" "$independent_lambda"
  for flow in "${flows[@]}"; do
    coherence_run "$name" "$flow" ""
    coherence_run "$name" "$flow" "$pure_lambda"
  done
done

# --- Tables.
commands=$(cat <<EOF
- 2D speed: \`texsynth animate $patterns/$speed_pattern.pat --flow FLOW --size $speed_size --frames $speed_frames -o RUN/%03d.png --stats RUN/stats.json --quiet\`
- surface warm-up (untimed): \`texsynth animate $patterns/$speed_pattern.pat --mesh $mesh_dir/$surface_mesh.off --flow ${surface_flows[0]} --frames 1 -o RUN/%03d.png --stats RUN/stats.json --quiet\`
- surface speed: \`texsynth animate $patterns/$speed_pattern.pat --mesh $mesh_dir/$surface_mesh.off --flow FLOW --frames $surface_frames -o RUN/%03d.png --stats RUN/stats.json --quiet\`
- coherence runs: \`texsynth animate $patterns/EXEMPLAR.pat --flow FLOW --size $size --frames $frames [--coherence LAMBDA] -o RUN/%03d.png --stats RUN/stats.json --quiet\`
- coherence of a frame: \`texsynth eval $patterns/EXEMPLAR.pat RUN/NNN.png --json --quiet\` (key metrics.coherence)
EOF
)
python3 - "$out/speed.tsv" "$out/coherence.tsv" "$(nproc)" "$independent_lambda" "$pure_lambda" "$frames" "$size" \
  "${checked[*]}" "$commands" "$TEXSYNTH_CACHE" >"$out/results.md" <<'PY'
import csv, json, os, sys
speed_tsv, coherence_tsv, cores, independent, pure, frames, size, checked, commands, cache = sys.argv[1:]
checked = [int(c) for c in checked.split()]
load = lambda path: json.load(open(path))
mean = lambda xs: sum(xs) / len(xs) if xs else float("nan")

print(f"# Flow animation (texsynth animate), {cores} cores (nproc), all of them used\n")
print("Commands (TEXSYNTH_CACHE set to a fresh directory in the output folder):\n")
print(commands)

print("\n## Per-frame speed at the default lambda\n")
print("Seconds from --stats: first = frame 0 (a whole static synthesis; the one-off exemplar analysis "
      "is apart); mean, max and the advection / solve split over frames 1 on (per-frame times exclude "
      "writing and, on the mesh, retiling and rendering: render is the rendering time per frame). "
      "Kept: mean share of pixels / vertices the solver kept from the advected frame. Change: mean "
      "temporal change in 8-bit levels. Wall: the whole command.\n")
print("| run | flow | frames | first | mean | max | advect | solve | render | kept | change | wall | goal |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
for r in csv.DictReader(open(speed_tsv), delimiter="\t"):
    d = load(os.path.join(r["dir"], "stats.json"))
    later = [f for f in d["frames"] if f["frame"] > 0]
    wall = open(os.path.join(r["dir"], "wall")).read().strip()
    surface = r["kind"].startswith("surface")
    goal = 0.5 if surface else 0.1
    render = f"{d['render_seconds'] / len(d['frames']):.3f} s" if "render_seconds" in d else ""
    if surface:
        run = f"{r['kind']} ({d['vertices']} vertices{', hierarchy cached' if d.get('hierarchy_cached') else ', hierarchy built'})"
    else:
        run = r["kind"]
    met = "met" if d["mean_frame_seconds"] <= goal else "NOT met"
    print(f"| {run} | {r['flow']} | {len(d['frames'])} | {d['first_frame_seconds']:.3f} s | "
          f"{d['mean_frame_seconds']:.3f} s | {d['max_frame_seconds']:.3f} s | "
          f"{mean([f['advect_seconds'] for f in later]):.3f} s | {mean([f['solve_seconds'] for f in later]):.3f} s | "
          f"{render} | {d['mean_kept']:.2f} | {d['mean_temporal_change']:.2f} | {wall} s | mean <= {goal} s: {met} |")
print("\nGoals: mean <= 0.1 s per 2D frame at 512²; mean <= 0.5 s per surface frame at ~48K vertices "
      "(the paper: 0.6-0.7 s per E+M step on a GeForce 7800 GT).")

runs = list(csv.DictReader(open(coherence_tsv), delimiter="\t"))
for r in runs:
    r["stats"] = load(os.path.join(r["dir"], "stats.json"))
    r["coh"] = [load(os.path.join(r["dir"], f"eval_{c}.json"))["metrics"]["coherence"] for c in checked]
    r["change"] = r["stats"]["mean_temporal_change"]
independent_runs = {r["exemplar"]: r for r in runs if r["lambda"] == independent}
default_lambda = next((r["stats"]["coherence"] for r in runs if r["lambda"] == "default"), float("nan"))
later = checked[1:]
print(f"\n## Temporal coherence against fidelity, {size}², {frames} frames\n")
print(f"Change: mean temporal change (stats mean_temporal_change: mean |frame t+1 - frame t carried along "
      f"the flow|, 8-bit levels; lower = steadier). coh@N: `texsynth eval` coherence of frame N counted "
      f"from 1 (file {{N-1:03d}}.png; lower = closer to the exemplar). Static: the exemplar's mean "
      f"coherence over the lambda = {independent} frames. Ratio: mean coherence of frames "
      f"{', '.join(map(str, later))} / static (1 = as faithful as independent frames). Vs independent: "
      f"lambda = {independent}'s change / this change (how many times steadier). Default lambda = "
      f"{default_lambda:g}.\n")
print("| exemplar | flow | lambda | change | " + " | ".join(f"coh@{c}" for c in checked) +
      " | ratio | vs independent |")
print("|---|---|---:|---:|" + "---:|" * len(checked) + "---:|---:|")
static = {e: mean(r["coh"]) for e, r in independent_runs.items()}
rows = []
for r in runs:
    e = r["exemplar"]
    ind = independent_runs[e]
    ratio = mean(r["coh"][1:]) / static[e]
    steadier = ind["change"] / r["change"] if r["change"] > 0 else float("inf")
    r["ratio"], r["steadier"] = ratio, steadier
    if r["lambda"] == independent:
        lam, flow = f"{independent} (independent)", f"{r['flow']} (serves every flow)"
    else:
        lam, flow = (f"{r['stats']['coherence']:g} (default)" if r["lambda"] == "default" else r["lambda"]), r["flow"]
    print(f"| {e} | {flow} | {lam} | {r['change']:.2f} | " + " | ".join(f"{c:.3f}" for c in r["coh"]) +
          f" | {ratio:.2f} | {steadier:.2f}x |")
print(f"\nlambda = {independent} runs once per exemplar, with the first flow ({runs[0]['flow'] if runs else ''}): "
      f"its frames are independent static syntheses, the flow enters only the temporal measure, so its "
      f"change, coherences and static coherence serve as the independent-frame reference for every flow "
      f"of that exemplar.")

print(f"\n## Goal: the default lambda keeps coherence within 1.2x of static (mean over frames "
      f"{later[0]}-{later[-1]}) AND temporal change at least 5x lower than independent frames\n")
print("| exemplar | flow | ratio | vs independent | goal |")
print("|---|---|---:|---:|---|")
met = total = 0
for r in runs:
    if r["lambda"] != "default":
        continue
    ok = r["ratio"] <= 1.2 and r["steadier"] >= 5
    met += ok
    total += 1
    print(f"| {r['exemplar']} | {r['flow']} | {r['ratio']:.2f} | {r['steadier']:.2f}x | {'yes' if ok else 'no'} |")
print(f"\nGoal met on {met}/{total} exemplar and flow pairs.")
PY
cat "$out/results.md"
progress "done; tables in $out/results.md"
