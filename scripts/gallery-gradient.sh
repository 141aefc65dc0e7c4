#!/usr/bin/env bash
# The gallery's gradient-solid pictures (gradient-solid-textures Figs. 6, 10, 11, 14), from the test
# volumes of bench/make_test_volumes and a GIMP stone. Called by scripts/gallery.sh; about a minute.
# Usage: scripts/gallery-gradient.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-docs/gallery}
mkdir -p "$out"
t="$build/bin/texsynth"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/bench/make_test_volumes" "$tmp" 128 >/dev/null

# Plane 64 of a 128³ raster magnified 4x. The voxels themselves come from scripts/nrrd-slice.py
# (nearest neighbour, no texsynth evaluation); a .tsgs is sampled by `solid --slice` at the same
# plane's centre, 4x the voxel rate.
z=0.50390625 # (64 + 0.5) / 128
voxels() { python3 scripts/nrrd-slice.py "$1" 64 4 "$tmp/v.ppm" && gmic -v - "$tmp/v.ppm" -o "$2"; }
slice() { "$t" solid "$1" --slice "z=$z" --resolution 512 -o "$2" --quiet "${@:3}"; }
source scripts/gallery-join.sh

# (a) Fig. 6/11: 'balls' without and with the mask; with it the balls' edges stay sharp, while
# the background keeps its C1 colour ramps.
v=$tmp/balls.nrrd
"$t" vectorize "$v" -o "$tmp/nomask.tsgs" --quiet
"$t" vectorize "$v" --mask "$tmp/balls_mask.nrrd" -o "$tmp/mask.tsgs" --quiet
voxels "$v" "$tmp/a0.png"
slice "$tmp/nomask.tsgs" "$tmp/a1.png"
slice "$tmp/mask.tsgs" "$tmp/a2.png"
join "$tmp/a.png" "$tmp"/a{0,1,2}.png
gmic -v - "$tmp/a.png" -o "$out/gradient_balls_voxels_nomask_mask.jpg,90"

# (b) Fig. 10: 'caustics', first order against --optimize.
v=$tmp/caustics.nrrd
"$t" vectorize "$v" -o "$tmp/first.tsgs" --quiet
"$t" vectorize "$v" --optimize -o "$tmp/opt.tsgs" --quiet
voxels "$v" "$tmp/b0.png"
slice "$tmp/first.tsgs" "$tmp/b1.png"
slice "$tmp/opt.tsgs" "$tmp/b2.png"
join "$tmp/b.png" "$tmp"/b{0,1,2}.png
gmic -v - "$tmp/b.png" -o "$out/gradient_caustics_voxels_first_optimized.jpg,85"

# (c) §4.4: an instant edit of the masked 'balls' on the bunny: a stroke across the big red ball
# asks for gold, one on the background protects it; the other red balls follow by colour.
cat >"$tmp/strokes.json" <<'JSON'
{"version": 1, "color": [0.95, 0.75, 0.1],
 "strokes": [{"points": [[34, 89, 64], [50, 89, 64]], "strength": 1},
             {"points": [[10, 20, 64], [30, 20, 64]], "strength": 0}]}
JSON
"$t" edit "$tmp/mask.tsgs" --strokes "$tmp/strokes.json" -o "$tmp/edited.tsgs" --quiet
for s in mask edited; do
  "$t" solid "$tmp/$s.tsgs" --mesh .data/meshes/bunny00.off --render "$tmp/c_$s.png" --render-size 384 --views 1 --quiet
done
join "$tmp/c.png" "$tmp/c_mask.png" "$tmp/c_edited.png"
gmic -v - "$tmp/c.png" -o "$out/gradient_edit_bunny_before_after.jpg,85"

# (d) Fig. 14: residual detail on a grainy stone (GIMP terra), off and on, next to the voxels (the central
# quarter of the slice, so the grain is visible).
"$t" solid /usr/share/gimp/2.0/patterns/Stone/terra.pat --method tile-deform --tiles 1 --resolution 128 \
  -o "$tmp/stone.nrrd" --quiet
"$t" vectorize "$tmp/stone.nrrd" --detail -o "$tmp/stone.tsgs" --quiet
voxels "$tmp/stone.nrrd" "$tmp/d0.png"
slice "$tmp/stone.tsgs" "$tmp/d1.png" --detail off
slice "$tmp/stone.tsgs" "$tmp/d2.png" --detail on
for i in 0 1 2; do gmic -v - "$tmp/d$i.png" crop 128,128,383,383 -o "$tmp/d$i.png"; done
join "$tmp/d.png" "$tmp"/d{0,1,2}.png
gmic -v - "$tmp/d.png" -o "$out/gradient_stone_voxels_detail_off_on.jpg,85"
ls -la "$out"/gradient_*
