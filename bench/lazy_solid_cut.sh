#!/usr/bin/env bash
# New cuts through a cached model (sketch-guided solid texturing §5, "a new cut needs only a
# fraction of the voxels"): one `texsynth solid` process synthesizes the coarsest level over the
# mesh's box, then the whole mesh surface at resolution R, then R-voxel slices across the box
# (one exemplar pixel per voxel), each reusing every block the earlier requests cached. Prints per request the time, the process's
# peak memory during it (cached levels included), the voxels, corrections and seconds each level
# added, and per level its peak working memory and final cache size.
# Usage: bench/lazy_solid_cut.sh [BUILD_DIR] [OUTPUT_DIR] [--resolution R] [--cut AXIS=F]...
#        [--mesh MESH] [--exemplar PAT] [-- extra lazy flags]
# Defaults: R 512, cuts z=0.5 and x=0.5, the bunny, pink_marble, texsynth's lazy defaults.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source bench/lazy_bench_args.sh
resolution=512 cuts=()
set -- "${rest[@]}"
while [ $# -gt 0 ]; do
  case $1 in
    --resolution) resolution=$2; shift 2 ;;
    --cut) cuts+=("$2"); shift 2 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done
[ ${#cuts[@]} -eq 0 ] && cuts=(z=0.5 x=0.5)
lazy_bench_prepare

slices=()
for c in "${cuts[@]}"; do slices+=(--slice "$c" -o "$out/cut_${c/=/_}.png"); done
"$texsynth" solid "$exemplar" --method lazy --mesh "$mesh" --tiles "$(awk -v r="$resolution" 'BEGIN { print r / 128 }')" \
  --surface "$resolution" --resolution "$resolution" "${slices[@]}" --stats "$out/stats.json" --quiet "${extra[@]}"

echo "# New cuts through a cached model: $(basename "$mesh" .off) at $resolution, $(nproc) cores," \
  "$(basename "$exemplar" .pat) ${extra[*]:+(flags: ${extra[*]})}"
echo
python3 - "$out/stats.json" "${cuts[@]}" <<'PY'
import json, struct, sys
stats = json.load(open(sys.argv[1]))

def png_size(path):
    with open(path, "rb") as f:
        return struct.unpack(">II", f.read(24)[16:24])

# Per-level counts are totals so far: each request adds the difference to the one before.
coarsest, surface = stats["coarsest_level"], stats["surface"]
requests = [("coarsest level over the mesh box, once", coarsest["seconds"], stats["setup_peak_rss_mib"],
             coarsest["lazy"][0]["levels"]),
            (f"whole surface ({surface['voxels']:,} voxels)", surface["synthesis_seconds"], surface["peak_rss_mib"],
             surface["lazy"][0]["levels"])]
for cut, output in zip(sys.argv[2:], stats["outputs"]):
    w, h = png_size(output["file"])
    requests.append((f"new cut {cut} ({w}x{h})", output["seconds"], output["peak_rss_mib"], output["lazy"][0]["levels"]))
print("| request | time | peak memory during it | per level, coarsest first: voxels synthesized, corrections, seconds |")
print("|---|---:|---:|---|")
before = None
for label, seconds, rss, levels in requests:
    cells = []
    for i, level in enumerate(levels):
        base = before[i] if before else {"voxels_synthesized": 0, "corrections": 0, "seconds": 0}
        cells.append(f"{(level['voxels_synthesized'] - base['voxels_synthesized']) / 1e6:.2f}M, "
                     f"{(level['corrections'] - base['corrections']) / 1e6:.2f}M, {level['seconds'] - base['seconds']:.1f} s")
    print(f"| {label} | {seconds:.1f} s | {rss:.0f} MiB | {' / '.join(cells)} |")
    before = levels
print()
print("| level | peak working memory | cache after all requests |")
print("|---:|---:|---:|")
for level in stats["lazy"][0]["levels"]:
    print(f"| {level['level']} | {level['peak_working_mib']:.0f} MiB | {level['cached_mib']:.0f} MiB |")
PY
echo
echo "Stats and cuts: $out"
