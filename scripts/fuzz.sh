#!/usr/bin/env bash
# Fuzzes the file loaders with libFuzzer (docs/fuzzing.md).
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]     targets: image mesh volume sketch field gradient_solid
# Installs clang and libFuzzer, builds build-fuzz/ (clang, address + undefined sanitizers),
# seeds each corpus from Debian's test files and the project's own writers, runs each target
# for SECONDS_PER_TARGET (default 60), JOBS at a time (default 1), and prints per target the
# executions, the corpus size and the crashes found. Corpora grow in fuzz/corpus/TARGET/,
# crashing inputs land in fuzz/crashes/TARGET/, logs in build-fuzz/logs/TARGET.log.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(image mesh volume sketch field gradient_solid)
jobs=${JOBS:-1}

bash scripts/install-deps.sh clang libclang-rt-14-dev

build="build-fuzz"
if [ ! -f "$build/build.ninja" ]; then
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTEXSYNTH_FUZZ=ON \
    -DTEXSYNTH_BUILD_TESTS=OFF -DTEXSYNTH_BUILD_BENCH=OFF "${launcher[@]}"
fi
cmake --build "$build" --target make_seeds "${targets[@]/#/fuzz_}"

# Seeds: files the readers accept (our writers, examples) and real-world ones, valid or not.
seeds=$build/seeds
rm -rf "$seeds"
"$build/bin/make_seeds" "$seeds"
mkdir -p "$seeds/sketch"
cp examples/sketches/*.json "$seeds/sketch/"
copy_small() {  # copy_small DEST DIR PATTERN...: files under 256 KiB whose names match
  local dest=$1 dir=$2
  shift 2
  [ -d "$dir" ] || return 0
  local expr=() p
  for p in "$@"; do expr+=(-o -iname "$p"); done
  find "$dir" -type f -size -256k \( "${expr[@]:1}" \) -print0 |
    while IFS= read -r -d '' f; do cp "$f" "$dest/$(echo "$f" | md5sum | cut -c1-12)-$(basename "$f")"; done
}
copy_small "$seeds/image" /usr/share/gimp/2.0/patterns '*.pat'
copy_small "$seeds/image" /usr/share/assimp/models '*.png' '*.jpg' '*.jpeg' '*.bmp' '*.tga' '*.exr'
copy_small "$seeds/mesh" /usr/share/assimp/models '*.obj' '*.ply' '*.off' '*.stl'

max_len() {
  case $1 in
    image | mesh) echo 65536 ;;
    volume) echo 16384 ;;
    *) echo 8192 ;;
  esac
}

run_target() {
  local target=$1
  local corpus=fuzz/corpus/$target crashes=fuzz/crashes/$target log=$build/logs/$target.log
  mkdir -p "$corpus" "$crashes" "$build/logs"
  local dict=()
  [ -f "fuzz/$target.dict" ] && dict=(-dict="fuzz/$target.dict")
  local before
  before=$(find "$crashes" -type f | wc -l)
  # A crash stops libFuzzer; its exit status is not this script's failure.
  "$build/bin/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len="$(max_len "$target")" \
    -print_final_stats=1 -artifact_prefix="$crashes/" "${dict[@]}" "$corpus" "$seeds/$target" >"$log" 2>&1 || true
  local executions after
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  after=$(find "$crashes" -type f | wc -l)
  printf '%-7s %4ss  executions %-10s corpus %-6s new crashes %s (log %s)\n' "$target" "$seconds" \
    "${executions:-?}" "$(find "$corpus" -type f | wc -l)" "$((after - before))" "$log"
}

running=0
for target in "${targets[@]}"; do
  [ -x "$build/bin/fuzz_$target" ] || { echo "fuzz.sh: unknown target '$target'" >&2; exit 2; }
  run_target "$target" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n
    running=$((running - 1))
  fi
done
wait
find fuzz/crashes -type f -printf 'crash: %p\n' 2>/dev/null || true
