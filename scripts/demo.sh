#!/usr/bin/env bash
# One command on a fresh Debian machine: install dependencies, build, run the demo into demo-output/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
build/bin/texsynth demo -o demo-output "$@"
