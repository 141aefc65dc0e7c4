#!/usr/bin/env bash
# Configures and builds texsynth (Release, portable) into build/. Extra arguments go to cmake's configure step,
# e.g. scripts/build.sh -DTEXSYNTH_NATIVE=ON.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j "$(nproc)"
