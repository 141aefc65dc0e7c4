#!/usr/bin/env bash
# A first-time user's first picture of a model with the lazy solid, on defaults:
# `texsynth solid EXEMPLAR --method lazy --mesh MESH --render r.png`, twice. The first run starts
# with only the exemplar analysis cached (a warm-up on the unit cube computes it) and synthesizes
# the coarsest level over the model's box; the second reads that level from the disk cache.
# Prints per run the wall time, peak memory and per level voxels and seconds.
# Usage: bench/lazy_first_picture.sh [BUILD_DIR] [OUTPUT_DIR] [--mesh M] [--exemplar PAT] [-- extra lazy flags]
# Defaults: CGAL's elephant, GIMP's walnut (the issue's command).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source bench/lazy_bench_args.sh
[ "$mesh" = .data/meshes/bunny00.off ] && [[ " ${rest[*]} " != *" --mesh "* ]] && mesh=.data/meshes/elephant.off
[ "$exemplar" = /usr/share/gimp/2.0/patterns/Stone/pink_marble.pat ] && exemplar=/usr/share/gimp/2.0/patterns/Wood/walnut.pat
[ ${#rest[@]} -eq 0 ] || { echo "unknown argument: ${rest[0]}" >&2; exit 2; }
lazy_bench_prepare

echo "# First picture: $(basename "$exemplar" .pat) on $(basename "$mesh" .off), defaults, $(nproc) cores" \
  "${extra[*]:+(flags: ${extra[*]})}"
echo
echo "| run | wall time | peak memory | coarsest level | per level above it: voxels synthesized, corrections, seconds |"
echo "|---|---:|---:|---|---|"
for run in first second; do
  /usr/bin/time -f "%e %M" -o "$out/time_$run.txt" "$texsynth" solid "$exemplar" --method lazy --mesh "$mesh" \
    --render "$out/render_$run.png" --stats "$out/stats_$run.json" --quiet "${extra[@]}"
  python3 - "$run" "$out/time_$run.txt" "$out/stats_$run.json" <<'PY'
import json, sys
run, timing, stats = sys.argv[1], open(sys.argv[2]).read().split(), json.load(open(sys.argv[3]))
levels = stats["lazy"][0]["levels"]
coarsest = levels[0]
where = "from the disk cache" if coarsest.get("from_disk_cache") else f"synthesized: {coarsest['voxels_synthesized'] / 1e6:.2f}M voxels"
cells = " / ".join(f"{l['voxels_synthesized'] / 1e6:.2f}M, {l['corrections'] / 1e6:.2f}M, {l['seconds']:.1f} s" for l in levels[1:])
print(f"| {run} | {float(timing[0]):.1f} s | {int(timing[1]) / 1024:.0f} MiB | {coarsest['seconds']:.1f} s, {where} | {cells} |")
PY
done
echo
echo "Renders and stats: $out"
