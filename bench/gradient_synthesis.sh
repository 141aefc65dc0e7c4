#!/usr/bin/env bash
# Speed and memory of gradient-solid synthesis (`texsynth solid --method gradient`, gradient-solid
# textures §4) over resolutions: one run per resolution on one exemplar, each writing R.tsgs and
# R.json (--stats). Per run: voxels, control points, check points, exemplar seconds (loading the
# cached analysis), synthesis seconds, the seconds of every level (coarse..fine), wall time, peak
# resident memory, the bucket window actually held against what buckets for every voxel would take,
# and peak RSS per n² (flat when memory grows as n², the bucket window's promise). A first run at 32 fills a fresh exemplar-analysis cache; its
# exemplar_seconds is the one-off preprocessing, cached for every timed run. Prints Markdown.
#
# Wall time and peak RSS come from /usr/bin/time -f '%e %M' (Debian package `time`). texsynth restarts
# its VmHWM between phases (/proc/self/clear_refs, for the per-phase peaks of --stats), so the kernel's
# ru_maxrss that /usr/bin/time reads covers only the last phase; the peak RSS column is the larger of
# that and --stats' peak_rss_mib (the process-wide peak over all phases).
#
# Builds nothing: cmake --build build --target texsynth.
# Usage: bench/gradient_synthesis.sh [RESOLUTION...]        (default 64 128 256 512 1024)
# Environment (relative paths are taken from the current directory):
#   TEXSYNTH=build/bin/texsynth   the binary (default: the repository's build/bin/texsynth)
#   EXEMPLAR=/usr/share/gimp/2.0/patterns/Stone/pink_marble.pat
#   OUT=$(mktemp -d)              work directory (R.tsgs, R.json, R.time, the analysis cache)
#   MAX_SECONDS=1800              skip a resolution whose predicted time (the previous one's wall time
#                                 x 8, the cube of a doubling) is above this
#   ITERATIONS, CHECK_POINTS      passed as --iterations / --check-points when set (N_O, N_C)
#   THREADS                       passed as --threads when set (default: all cores)
# Cheapest check: ITERATIONS=1 bench/gradient_synthesis.sh 32 48
set -euo pipefail
absolute() { case $1 in /*) echo "$1" ;; *) echo "$PWD/$1" ;; esac; }
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
texsynth=$(absolute "${TEXSYNTH:-$root/build/bin/texsynth}")
exemplar=$(absolute "${EXEMPLAR:-/usr/share/gimp/2.0/patterns/Stone/pink_marble.pat}")
out=$(absolute "${OUT:-$(mktemp -d)}")
max_seconds=${MAX_SECONDS:-1800}
cd "$root"
resolutions=("$@")
[ $# -eq 0 ] && resolutions=(64 128 256 512 1024)
[ -x "$texsynth" ] || { echo "build first: $texsynth is missing" >&2; exit 1; }
[ -f "$exemplar" ] || { echo "exemplar $exemplar is missing (scripts/install-deps.sh installs gimp-data)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "/usr/bin/time is missing (scripts/install-deps.sh installs the package 'time')" >&2; exit 1; }
command -v python3 >/dev/null || { echo "python3 is missing" >&2; exit 1; }
for r in "${resolutions[@]}"; do
  [[ $r =~ ^[1-9][0-9]*$ ]] || { echo "not a resolution: $r" >&2; exit 2; }
done
mkdir -p "$out"
export TEXSYNTH_CACHE="$out/cache"
rm -rf "$TEXSYNTH_CACHE"

flags=()
[ -n "${ITERATIONS:-}" ] && flags+=(--iterations "$ITERATIONS")
[ -n "${CHECK_POINTS:-}" ] && flags+=(--check-points "$CHECK_POINTS")
globals=(--quiet)
[ -n "${THREADS:-}" ] && globals+=(--threads "$THREADS")

# One run at resolution $1, named $2: R.tsgs, R.json (--stats) and R.time ("wall_s max_rss_kib").
synthesize() {
  /usr/bin/time -f '%e %M' -o "$out/$2.time" "$texsynth" solid "$exemplar" --method gradient --resolution "$1" \
    -o "$out/$2.tsgs" --stats "$out/$2.json" "${flags[@]}" "${globals[@]}"
}

# The row of resolution $1 from its R.json and R.time (the wall time goes to $out/last_wall).
row() {
  python3 - "$1" "$out/$1.json" "$out/$1.time" "$out/last_wall" <<'PY'
import json, sys
n, stats_file, time_file, wall_file = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
stats = json.load(open(stats_file))
wall, rss_kib = open(time_file).read().split()[-2:]
s = stats["synthesis"]
voxels = s["voxels"]
count = voxels[0] * voxels[1] * voxels[2]
peak_mib = max(float(rss_kib) / 1024, stats.get("peak_rss_mib", -1))
levels = " / ".join(f"{t:.2f}" for t in s["level_seconds"])
open(wall_file, "w").write(wall + "\n")
print(f"| {n}³ | {count / 1e6:.2f}M | {'x'.join(map(str, s['controls']))} | {s['check_points']:,} "
      f"| {stats['exemplar_seconds']:.2f} | {s['seconds']:.2f} | {levels} | {float(wall):.2f} | {peak_mib:.0f} "
      f"| {s['bucket_window_mib']:.1f} | {s['full_buckets_mib']:.1f} | {peak_mib * 1024 / (n * n):.2f} |")
PY
}

synthesize 32 warmup
preprocessing=$(python3 -c "import json, sys; print(f\"{json.load(open(sys.argv[1]))['exemplar_seconds']:.2f}\")" \
  "$out/warmup.json")

echo "# Gradient solid synthesis, $(basename "$exemplar" .pat), $(nproc) cores${flags[*]:+, ${flags[*]}}${THREADS:+, --threads $THREADS}"
echo
echo "Preprocessing (exemplar analysis, first run at 32³, cached for the runs below): $preprocessing s"
echo
echo "| resolution | voxels | controls | check points | exemplar s | synthesis s | level seconds (coarse..fine) | wall s | peak RSS MiB | bucket window MiB | full buckets MiB | RSS/n² KiB |"
echo "|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|"
previous=""
for r in "${resolutions[@]}"; do
  if [ -n "$previous" ]; then
    predicted=$(awk -v t="$previous" 'BEGIN { printf "%.0f", t * 8 }')
    if awk -v p="$predicted" -v m="$max_seconds" 'BEGIN { exit !(p > m) }'; then
      echo "| ${r}³ | skipped (predicted $predicted s) | | | | | | | | | | |"
      previous=$predicted
      continue
    fi
  fi
  synthesize "$r" "$r"
  row "$r"
  previous=$(cat "$out/last_wall")
done
echo
echo "Peak RSS: the larger of /usr/bin/time's %M (last phase only: texsynth restarts its VmHWM per phase) and"
echo "--stats' peak_rss_mib (all phases). Exemplar s: loading the cached analysis. Wall s: the whole command."
echo "Full buckets: what buckets for every voxel would take."
echo "Paper (2 x 2.26 GHz): 128³ in 13 s after 10 s preprocessing; 512³ in 15 min; 1024 in 35 min within 900 MB."
echo "Goals here: 128³ <= 3 s, 512³ <= 2 min, 1024³-equivalent <= 15 min and <= 1 GB peak RSS."
echo
echo "Solids and stats: $out"
