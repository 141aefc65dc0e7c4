#!/usr/bin/env bash
# Runs every benchmark executable in build/bench and prints their results tables, one per module.
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
echo "# texsynth benchmarks"
echo "$(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
status=0
for bench in "${benches[@]}"; do
  echo
  echo "## $(basename "$bench" | sed 's/^bench_//')"
  echo
  echo '```'
  # Console tables only: the CSV reporter rejects benchmarks with differing user counters.
  "$bench" --benchmark_counters_tabular=true "$@" 2>/dev/null | sed -n '/^---/,$p' || status=1
  echo '```'
done
exit $status
