#!/usr/bin/env bash
# Output encoding before and after: `texsynth image --method tile-deform` of a GIMP pattern at
# 4096^2 and 8192^2 into PNG, EXR and JPEG, run once by each of two texsynth binaries. Prints
# one markdown table: end-to-end wall time of the command, file size, and the synthesis-only
# time the command reports (--json "seconds"), so the rest is reading plus writing.
# Usage: bench/output_encoding.sh BEFORE_BINARY AFTER_BINARY [OUTPUT_DIR]   (env SIZES: default "4096 8192")
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 BEFORE_BINARY AFTER_BINARY [OUTPUT_DIR]" >&2; exit 2; }
before=$1
after=$2
out=${3:-$(mktemp -d)}
for binary in "$before" "$after"; do
  [ -x "$binary" ] || { echo "not an executable: $binary" >&2; exit 1; }
done
exemplar=/usr/share/gimp/2.0/patterns/Stone/pink_marble.pat
[ -f "$exemplar" ] || { echo "gimp-data is not installed (scripts/install-deps.sh)" >&2; exit 1; }
mkdir -p "$out"
read -r -a sizes <<<"${SIZES:-4096 8192}"  # SIZES="512 1024" for a quick try
formats=(png exr jpg)

# Runs one synthesis; prints "wall_seconds cpu_seconds synthesis_seconds bytes". CPU time (user
# + system, all threads) is printed too because it hardly depends on what else the machine runs.
measure() {
  local binary=$1 size=$2 file=$3 times synthesis
  rm -f "$file"
  times=$({ TIMEFORMAT='%R %U %S'; time "$binary" image "$exemplar" --method tile-deform --size "${size}x${size}" \
    -o "$file" --quiet --json >"$out/report.json"; } 2>&1)
  synthesis=$(awk -F': ' '/"seconds"/ { gsub(",", "", $2); print $2 }' "$out/report.json")
  awk -v t="$times" -v s="$synthesis" -v b="$(stat -c %s "$file")" \
    'BEGIN { split(t, f, " "); printf "%.2f %.2f %s %s\n", f[1], f[2] + f[3], s, b }'
  rm -f "$file"  # big files: keep the disk free for the next run
}

echo "# Output encoding: tile-deform of $(basename "$exemplar"), $(nproc) cores, one run each"
echo
echo "Wall and CPU seconds of the whole command; synthesis: the part the command reports as synthesis (wall)."
echo
echo "| format | size | before s | after s | speedup | before CPU s | after CPU s | before MB | after MB | size ratio |" \
  "synthesis s (before / after) |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for size in "${sizes[@]}"; do
  for format in "${formats[@]}"; do
    read -r beforeWall beforeCpu beforeSynth beforeBytes <<<"$(measure "$before" "$size" "$out/before_$size.$format")"
    read -r afterWall afterCpu afterSynth afterBytes <<<"$(measure "$after" "$size" "$out/after_$size.$format")"
    awk -v f="$format" -v s="$size" -v bw="$beforeWall" -v aw="$afterWall" -v bc="$beforeCpu" -v ac="$afterCpu" \
      -v bb="$beforeBytes" -v ab="$afterBytes" -v bs="$beforeSynth" -v as="$afterSynth" 'BEGIN {
        printf "| %s | %d² | %.2f | %.2f | %.1fx | %.2f | %.2f | %.1f | %.1f | %.3f | %.2f / %.2f |\n",
          f, s, bw, aw, bw / aw, bc, ac, bb / 1e6, ab / 1e6, ab / bb, bs, as
      }'
  done
done
echo
echo "Load average while measuring: $(cut -d' ' -f1-3 /proc/loadavg) (other work on the machine inflates wall times)"
