#!/usr/bin/env bash
# The fast test suites (core, io, geometry, field, render, gradient, surface, animation, studio; eval takes minutes at
# -O0) built with the `debug` preset: address and
# undefined-behaviour sanitizers, warnings as errors. Any sanitizer report fails the run.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash scripts/install-deps.sh
cmake --preset debug -DTEXSYNTH_WERROR=ON -DTEXSYNTH_BUILD_BENCH=OFF >/dev/null
suites=(core io geometry field render gradient surface animation studio)
cmake --build build-debug -j "$(nproc)" --target "${suites[@]/#/test_}"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
label_regex="^($(IFS='|'; echo "${suites[*]}"))\$"
# The studio tests that synthesize lazy solids take minutes at -O0 (the solid suite is not here either);
# the browser test runs in the main suite.
ctest --test-dir build-debug --output-on-failure --timeout 900 -j "$(nproc)" -L "$label_regex" \
  -E '^(StudioApi\.(Lazy|ANewerJob)|studio_browser)'
