#!/usr/bin/env bash
# texsynth studio through its HTTP API on loopback: one user's latencies (a curve to the updated
# field and glyphs, an exemplar to its first textured preview, lazy cuts), then CLIENTS concurrent
# clients adding curves and asking for previews, PHASES times SECONDS (the server's memory after
# each), then bad input; prints the tables.
# Usage: bench/studio.sh [BUILD_DIR] [--clients 50] [--seconds 60] [--phases 2] [--mesh bunny00]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=build
[ $# -gt 0 ] && [[ $1 != --* ]] && { build=$1; shift; }
mesh=bunny00 args=()
while [ $# -gt 0 ]; do
  case $1 in
    --mesh) mesh=$2; shift 2 ;;
    --clients|--seconds|--phases) args+=("$1" "$2"); shift 2 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done
sketch=examples/sketches/${mesh%00}.json
[ -f "$sketch" ] || { echo "no example sketch for $mesh (examples/sketches/)" >&2; exit 2; }
log=$(mktemp)
"$build/bin/texsynth" studio "$mesh" Stone/pink_marble --port 0 --json > "$log" &
server=$!
trap 'kill $server 2>/dev/null; rm -f "$log"' EXIT
for _ in $(seq 100); do grep -q port "$log" && break; sleep 0.1; done
port=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['port'])" "$log")
echo "# texsynth studio on $mesh, $(nproc) cores"
echo
"$build/bench/studio_load" "$port" "$server" "$sketch" "${args[@]}"
