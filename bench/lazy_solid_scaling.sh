#!/usr/bin/env bash
# Lazy solid synthesis at scale: full volumes (the unit cube at RES³, one exemplar tile per 128
# voxels) and whole mesh surfaces (every voxel the surface passes through, `--surface R`), each
# with wall time, voxels/s, peak memory and the per-level voxels, corrections, neighbourhood
# comparisons and seconds of `--stats`.
# Usage: bench/lazy_solid_scaling.sh [BUILD_DIR] [OUTPUT_DIR] [--volume RES]... [--surface RES]...
#        [--mesh MESH] [--exemplar PAT] [-- extra lazy flags]
# Defaults: --volume 128 --surface 256, the bunny, pink_marble, texsynth's lazy defaults.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source bench/lazy_bench_args.sh
volumes=() surfaces=()
set -- "${rest[@]}"
while [ $# -gt 0 ]; do
  case $1 in
    --volume) volumes+=("$2"); shift 2 ;;
    --surface) surfaces+=("$2"); shift 2 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done
[ ${#volumes[@]} -eq 0 ] && [ ${#surfaces[@]} -eq 0 ] && volumes=(128) surfaces=(256)
lazy_bench_prepare

# Runs one request; prints a table row (peak memory: the process's, from --stats) and the per-level rows.
run() {  # label voxels stats -- texsynth args
  local label=$1 voxels=$2 stats=$3
  shift 4
  local start end seconds rss
  start=$(date +%s.%N)
  "$texsynth" "$@" --stats "$stats" --quiet "${extra[@]}"
  end=$(date +%s.%N)
  seconds=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }')
  [ "$voxels" = surface ] && voxels=$(python3 -c "import json; print(json.load(open('$stats'))['surface']['voxels'])")
  rss=$(python3 -c "import json; print(round(json.load(open('$stats'))['peak_rss_mib']))")
  printf "| %s | %s | %s s | %.0f | %s MiB |" "$label" "$voxels" "$seconds" "$(awk -v v="$voxels" -v s="$seconds" 'BEGIN { print v / s }')" "$rss"
  python3 - "$stats" <<'PY'
import json, sys
levels = json.load(open(sys.argv[1]))["lazy"][0]["levels"]
print(" " + " / ".join(f"{l['voxels_synthesized'] / 1e6:.1f}M, {l['corrections'] / 1e6:.1f}M, "
                       f"{l.get('comparisons', 0) / 1e6:.0f}M, {l['seconds']:.0f} s" for l in levels) + " |")
PY
}

echo "# Lazy solid synthesis at scale, $(nproc) cores, $(basename "$exemplar" .pat) ${extra[*]:+(flags: ${extra[*]})}"
echo
echo "| request | requested voxels | time | voxels/s | peak memory | per level, coarsest first: voxels synthesized, corrections, neighbourhood comparisons, time |"
echo "|---|---:|---:|---:|---:|---|"
for r in "${volumes[@]}"; do
  run "volume ${r}³" $((r * r * r)) "$out/volume_$r.json" -- solid "$exemplar" --method lazy --tiles "$(awk -v r="$r" 'BEGIN { print r / 128 }')" \
    --volume "$out/volume_$r.nrrd" --resolution "$r"
done
for r in "${surfaces[@]}"; do
  run "$(basename "$mesh" .off) surface at $r" surface "$out/surface_$r.json" -- solid "$exemplar" --method lazy --mesh "$mesh" \
    --tiles "$(awk -v r="$r" 'BEGIN { print r / 128 }')" --surface "$r"
done
echo
echo "Stats and volumes: $out"
