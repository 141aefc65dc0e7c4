#!/usr/bin/env bash
# Table 1 of the gradient-solid paper (vectorization error and time, first order and refined) on
# the test volumes of scripts/make-test-volumes.sh, next to box downsampling + tricubic upsampling
# and zfp at the same bytes, then single-point evaluation speeds. Prints Markdown.
# Builds nothing: cmake --build BUILD_DIR --target texsynth make_test_volumes gradient_table.
# Usage: bench/gradient_table.sh [BUILD_DIR] [OUT_DIR] [-- extra gradient_table flags]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-$build/test-volumes}
shift $(($# < 2 ? $# : 2))
[ "${1:-}" = "--" ] && shift
table="$build/bench/gradient_table"
[ -x "$table" ] || { echo "build first: $table is missing" >&2; exit 1; }
BUILD="$build" scripts/make-test-volumes.sh "$out" >&2

v="$out"
echo "# Gradient solids: vectorization (paper Table 1) and baselines at equal bytes, $(nproc) cores"
echo
"$table" "$@" \
  balls="$v/balls.nrrd,$v/balls_mask.nrrd" \
  caustics="$v/caustics.nrrd" \
  pink_marble/tile-deform="$v/pink_marble_tile-deform.nrrd" \
  pink_marble/lazy="$v/pink_marble_lazy.nrrd" \
  choc_swirl/tile-deform="$v/choc_swirl_tile-deform.nrrd" \
  choc_swirl/tile-deform="$v/choc_swirl_tile-deform.nrrd,$v/choc_swirl_tile-deform_mask.nrrd"
