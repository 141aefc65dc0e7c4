#!/usr/bin/env bash
# One command on a fresh Debian machine: install dependencies, build, run the whole test suite (ctest).
# Extra arguments go to cmake's configure step, e.g. scripts/test.sh -DTEXSYNTH_WERROR=ON.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh
bash scripts/build.sh "$@"
ctest --test-dir build --output-on-failure --timeout 600 -j "$(nproc)"
