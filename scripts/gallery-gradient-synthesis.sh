#!/usr/bin/env bash
# The gallery's pictures of gradient solids synthesized from exemplars (gradient-solid-textures §4, Figs. 6-9):
# a solid on CGAL's bunny with a cut, wood without and with a sketched field, brick without and with its
# joints as a mask, and a 512 solid with a close-up. Called by scripts/gallery.sh; about ten minutes on
# 2 cores (the 512 solid runs one check point per cube and one iteration per level to stay within that).
# Usage: scripts/gallery-gradient-synthesis.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
out=${2:-docs/gallery}
mkdir -p "$out"
t="$build/bin/texsynth"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
patterns=/usr/share/gimp/2.0/patterns
bunny=.data/meshes/bunny00.off
source scripts/gallery-join.sh
exemplar() { "$t" image "$1" --lambda 0 --size "$2" -o "$3" --quiet; } # the exemplar tiled, as it is

# (a) Figs. 7-8: leopard spots synthesized over the bunny's box at 128, rendered and cut open.
"$t" solid "$patterns/Animal/leopard.pat" --method gradient --mesh "$bunny" --resolution 128 \
  --render "$tmp/a.png" --views 1 --cut z=0.5 --render-size 384 --quiet
exemplar "$patterns/Animal/leopard.pat" 128 "$tmp/a0.png"
join "$tmp/a_all.png" "$tmp/a0.png" "$tmp/a.png"
gmic -v - "$tmp/a_all.png" -o "$out/gradient_synthesis_leopard_bunny_cut.jpg,85"

# (b) Fig. 7: bark's furrows without and with the field of the bunny's example sketch (two slices matched, as
# for anisotropic exemplars).
for field in none sketch; do
  flags=()
  [ "$field" = sketch ] && flags=(--sketch examples/sketches/bunny.json)
  "$t" solid "$patterns/Wood/bark.pat" --method gradient --slices 2 --mesh "$bunny" --resolution 128 \
    "${flags[@]}" --render "$tmp/b_$field.png" --views 1 --render-size 384 --quiet
done
join "$tmp/b.png" "$tmp/b_none.png" "$tmp/b_sketch.png"
gmic -v - "$tmp/b.png" -o "$out/gradient_synthesis_bark_field_off_on.jpg,85"

# (c) Fig. 6: brick without a mask and with its joints (the darkest 15%) as one: region separation keeps the
# joints' edges sharp. Central z slices of 128³ solids, sampled at 256, without residual grain so the edges show.
"$build/bench/make_test_volumes" --dark-mask-from "$patterns/Stone/brick.pat" "$tmp/joints.png" 0.15 >/dev/null
"$t" solid "$patterns/Stone/brick.pat" --method gradient --resolution 128 --detail off -o "$tmp/brick.tsgs" --quiet
"$t" solid "$patterns/Stone/brick.pat" --method gradient --mask "$tmp/joints.png" --resolution 128 --detail off \
  -o "$tmp/brick_mask.tsgs" --quiet
exemplar "$patterns/Stone/brick.pat" 256 "$tmp/c0.png"
"$t" solid "$tmp/brick.tsgs" --slice z=0.5 --resolution 256 -o "$tmp/c1.png" --quiet
"$t" solid "$tmp/brick_mask.tsgs" --slice z=0.5 --resolution 256 -o "$tmp/c2.png" --quiet
join "$tmp/c.png" "$tmp"/c{0,1,2}.png
gmic -v - "$tmp/c.png" -o "$out/gradient_synthesis_brick_exemplar_nomask_mask.jpg,85"

# (d) Figs. 8-9: a 512 solid (one check point per cube, one iteration per level), its central slice and a
# close-up of its corner magnified 4x by the solid itself (sampled at 2048 across).
"$t" solid "$patterns/Food/choc_swirl.pat" --method gradient --resolution 512 --check-points 1 --iterations 1 \
  -o "$tmp/big.tsgs" --slice z=0.5 -o "$tmp/d0.png" --quiet
"$t" solid "$tmp/big.tsgs" --slice z=0.5 --resolution 2048 -o "$tmp/d_full.png" --quiet
gmic -v - "$tmp/d_full.png" crop 0,0,511,511 -o "$tmp/d1.png"
join "$tmp/d.png" "$tmp/d0.png" "$tmp/d1.png"
gmic -v - "$tmp/d.png" -o "$out/gradient_synthesis_512_closeup.jpg,85"
ls -la "$out"/gradient_synthesis_*
