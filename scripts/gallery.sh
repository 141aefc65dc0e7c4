#!/usr/bin/env bash
# Renders the pictures in docs/gallery/ from real data: GIMP exemplars on CGAL meshes.
# Usage: scripts/gallery.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-docs/gallery}
mkdir -p "$out"
t="$build/bin/texsynth"
p=/usr/share/gimp/2.0/patterns
m=.data/meshes
common=(--render-size 384 --views 2 --quiet)

# Paper Fig. 8: one-axis stacking smears features on faces parallel to the stacking axis;
# three-axis stacking blended by the normal (eq. 3) shows them everywhere; tile-blend for comparison.
"$t" solid $p/Wood/wood1.pat --mesh $m/bunny00.off --stack z --render "$out/bunny_wood_stack_z.png" "${common[@]}"
"$t" solid $p/Wood/wood1.pat --mesh $m/bunny00.off --stack xyz --render "$out/bunny_wood_stack_xyz.png" "${common[@]}"
"$t" solid $p/Wood/wood1.pat --mesh $m/bunny00.off --method tile-blend --render "$out/bunny_wood_tile_blend.png" "${common[@]}"
# Method 2 on other meshes and exemplars.
"$t" solid $p/Stone/pink_marble.pat --mesh $m/elephant.off --render "$out/elephant_marble_stack_xyz.png" "${common[@]}"
"$t" solid $p/Stone/granite1.pat --mesh $m/cow.off --method tile-blend --render "$out/cow_granite_tile_blend.png" "${common[@]}"
# Method 1: a 3D exemplar. Any volume works; here a 64^3 block synthesized from a 2D exemplar.
"$t" solid $p/Stone/stone33.pat --method tile-blend -o "$out/stone_exemplar_64.nrrd" --resolution 64 --quiet
"$t" solid "$out/stone_exemplar_64.nrrd" --mesh $m/bunny00.off --render "$out/bunny_stone_volume_exemplar.png" "${common[@]}"
"$t" solid "$out/stone_exemplar_64.nrrd" --mesh $m/elephant.off --render "$out/elephant_stone_volume_exemplar.png" "${common[@]}"
rm "$out/stone_exemplar_64.nrrd"
# 2D: exemplar, plain tiling, tile-deform, tile-blend side by side in separate files.
for name in Stone/pink_marble Wood/bark; do
  stem=$(basename $name)
  "$t" image $p/$name.pat --method tile-deform --lambda 0 --size 256 -o "$out/${stem}_tiling.png" --quiet --tileable never
  "$t" image $p/$name.pat --method tile-deform --size 256 -o "$out/${stem}_tile_deform.png" --quiet --tileable never
  "$t" image $p/$name.pat --method tile-blend --size 256 -o "$out/${stem}_tile_blend.png" --quiet --tileable never
done
# Automatic tileable conversion: a crop of a GIMP pattern (a window of its plain tiling) is not
# tileable; tiled 2x2 before and after conversion.
"$t" image $p/Stone/stone33.pat --method tile-deform --lambda 0 --window 20,30,100,100 -o "$out/crop.png" --quiet --tileable never
"$t" image "$out/crop.png" --method tile-deform --lambda 0 --size 200 -o "$out/crop_tiled_before.png" --quiet --tileable never
"$t" image "$out/crop.png" --method tile-deform --lambda 0 --size 200 -o "$out/crop_tiled_after.png" --quiet --tileable always
rm "$out/crop.png"
# Gradient solids: vectorization with and without a mask, --optimize, an edit, residual detail.
bash scripts/gallery-gradient.sh "$build" "$out"
bash scripts/gallery-gradient-synthesis.sh "$build" "$out"
# Lazy solid synthesis of the burlap weave on the bunny at 256 voxels across (one exemplar pixel per
# voxel), identity field and sketched field, each with the bunny cut open (about 5 and 10 s on 2 cores).
lazy=(solid $p/Fabric/burlap.pat --method lazy --mesh $m/bunny00.off --tiles 2.6667 --cut z=0.55 --render-size 500
  --views 2 --quiet)
"$t" "${lazy[@]}" --render "$out/lazy_bunny_burlap_identity.jpg"
"$t" "${lazy[@]}" --sketch examples/sketches/bunny.json --render "$out/lazy_bunny_burlap_sketch.jpg"
# The standard scheme next to dual-grid correction (about 6.5 and 2 minutes).
for scheme in --no-dual-grid --dual-grid; do
  "$t" solid $p/Fabric/burlap.pat --method lazy --mesh $m/bunny00.off --tiles 1 --cut z=0.55 --render-size 400 --views 1 \
    --quiet $scheme --render "$out/lazy_scheme$scheme.png"
done
gmic -v - "$out/lazy_scheme--no-dual-grid.png" "$out/lazy_scheme--dual-grid.png" append x \
  -o "$out/lazy_bunny_burlap_standard_vs_dual.jpg,85"
rm "$out/lazy_scheme--no-dual-grid.png" "$out/lazy_scheme--dual-grid.png"
# The cow, identity field then its sketch (about 1 and 6 minutes).
for v in identity sketch; do
  extra=(); [ $v = sketch ] && extra=(--sketch examples/sketches/cow.json)
  "$t" solid $p/Fabric/burlap.pat --method lazy --mesh $m/cow.off --tiles 1.5 --cut x=0.5 --render-size 400 --views 1 \
    --quiet "${extra[@]}" --render "$out/lazy_cow_$v.png"
done
gmic -v - "$out/lazy_cow_identity.png" "$out/lazy_cow_sketch.png" append x -o "$out/lazy_cow_burlap_identity_vs_sketch.jpg,85"
rm "$out/lazy_cow_identity.png" "$out/lazy_cow_sketch.png"
ls -la "$out"
