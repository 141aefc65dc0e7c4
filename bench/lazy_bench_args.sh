# Shared by bench/lazy_solid_scaling.sh and bench/lazy_solid_cut.sh (sourced, not run): the
# options both take (--mesh, --exemplar, -- extra lazy flags), their checks, and a warm-up run
# that fills the analysis cache under OUTPUT_DIR so no timed run pays for it.
# Sets: build, out, mesh, exemplar, texsynth, extra (array), rest (the script's own options).
build=${1:-build}
out=${2:-$(mktemp -d)}
shift $(($# < 2 ? $# : 2))
mesh=.data/meshes/bunny00.off
exemplar=/usr/share/gimp/2.0/patterns/Stone/pink_marble.pat
extra=() rest=()
while [ $# -gt 0 ]; do
  case $1 in
    --mesh) mesh=$2; shift 2 ;;
    --exemplar) exemplar=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) rest+=("$1"); shift ;;
  esac
done
texsynth="$build/bin/texsynth"

# After the script parsed `rest`: check the inputs and warm the cache.
lazy_bench_prepare() {
  [ -x "$texsynth" ] || { echo "build first: $texsynth is missing" >&2; exit 1; }
  [ -f "$exemplar" ] || { echo "exemplar $exemplar is missing (scripts/install-deps.sh installs gimp-data)" >&2; exit 1; }
  [ -f "$mesh" ] || { echo "mesh $mesh is missing (scripts/install-deps.sh extracts CGAL's meshes)" >&2; exit 1; }
  mkdir -p "$out"
  export TEXSYNTH_CACHE="$out/cache"
  "$texsynth" solid "$exemplar" --method lazy --slice z=0.5 --resolution 4 -o "$out/warmup.png" --quiet "${extra[@]}"
}
