#!/usr/bin/env bash
# The gradient-solid benchmark's 128³ volumes (bench/gradient_table.sh), 8-bit NRRD in DIR:
#   balls.nrrd + balls_mask.nrrd, caustics.nrrd   synthetic stand-ins for the paper's (make_test_volumes)
#   EXEMPLAR_METHOD.nrrd                          texsynth solids from two GIMP patterns (tile-deform; lazy for one)
#   choc_swirl_tile-deform_mask.nrrd              that solid's luminance thresholded at its median
# Builds nothing: run `cmake --build build --target make_test_volumes texsynth` first (BUILD=dir to
# use another build). Volumes that exist are kept.
# Usage: scripts/make-test-volumes.sh [DIR]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${BUILD:-build}
dir=${1:-$build/test-volumes}
texsynth="$build/bin/texsynth"
tool="$build/bench/make_test_volumes"
patterns=/usr/share/gimp/2.0/patterns
for program in "$texsynth" "$tool"; do
  [ -x "$program" ] || { echo "build first: $program is missing" >&2; exit 1; }
done
[ -d "$patterns" ] || { echo "gimp-data is not installed (scripts/install-deps.sh)" >&2; exit 1; }
mkdir -p "$dir"

"$tool" "$dir" 128
# Pink marble (veined, soft) and chocolate swirl (smooth bands): solids worth vectorizing. Only the marble
# is also made by lazy synthesis, at one exemplar pixel per voxel (--tiles 1: about 100 s on 2 cores).
for solid in Stone/pink_marble:tile-deform Stone/pink_marble:lazy Food/choc_swirl:tile-deform; do
  exemplar=${solid%%:*} method=${solid##*:}
  volume="$dir/$(basename "$exemplar")_$method.nrrd"
  if [ -e "$volume" ]; then
    echo "$volume exists, kept"
  else
    tiles=2
    [ "$method" = lazy ] && tiles=1
    "$texsynth" solid "$patterns/$exemplar.pat" --method "$method" --volume "$volume" --resolution 128 --seed 1 \
      --tiles "$tiles" --quiet
    echo "wrote $volume"
  fi
done
"$tool" --mask-from "$dir/choc_swirl_tile-deform.nrrd" "$dir/choc_swirl_tile-deform_mask.nrrd"
