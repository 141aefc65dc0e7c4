#!/usr/bin/env bash
# Runs every benchmark executable in build/bench and prints one results table (markdown).
# Usage: bench/run_benchmarks.sh [BUILD_DIR] [-- extra Google Benchmark flags, e.g. --benchmark_filter=Ann]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=build
if [ $# -gt 0 ] && [ "$1" != "--" ]; then build=$1; shift; fi
[ "${1:-}" = "--" ] && shift
shopt -s nullglob
benches=("$build"/bench/bench_*)
if [ ${#benches[@]} -eq 0 ]; then
  echo "no benchmarks in $build/bench: build first (scripts/build.sh)" >&2
  exit 1
fi
echo "# texsynth benchmarks — $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo
echo "| benchmark | time/iter | CPU/iter | iterations | counters |"
echo "|---|---:|---:|---:|---|"
for bench in "${benches[@]}"; do
  "$bench" --benchmark_format=csv "$@" 2>/dev/null | awk -F, '
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    {
      name = $col["name"]; gsub(/"/, "", name)
      unit = $col["time_unit"]
      counters = ""
      for (key in col) {
        if (key ~ /^(name|iterations|real_time|cpu_time|time_unit|bytes_per_second|items_per_second|label|error_occurred|error_message)$/) continue
        if ($col[key] != "") counters = counters sprintf("%s=%.4g ", key, $col[key])
      }
      if ($col["items_per_second"] != "") counters = counters sprintf("items/s=%.4g ", $col["items_per_second"])
      printf "| %s | %.3f %s | %.3f %s | %s | %s|\n", name, $col["real_time"], unit, $col["cpu_time"], unit, $col["iterations"], counters
    }'
done
