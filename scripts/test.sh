#!/usr/bin/env bash
# The whole test suite: release build + ctest (validation layers on), the same under
# AddressSanitizer + UndefinedBehaviorSanitizer, and the benchmark tool's quick smoke run.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)

bash "$root/scripts/build.sh" "$root/build"
(cd "$root/build" && ctest --output-on-failure -j "$jobs" --timeout 600)

bash "$root/scripts/build.sh" "$root/build-asan" -DLLL_SANITIZE=ON
# Leaks inside the Vulkan driver and its LLVM JIT are not ours; ours would still be reported.
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
(cd "$root/build-asan" && ctest --output-on-failure -j "$jobs" --timeout 900)
unset LSAN_OPTIONS ASAN_OPTIONS UBSAN_OPTIONS

"$root/build/lll" bench --suite threel --quick --out "$root/build/bench-smoke"
echo "bench smoke: $(wc -l < "$root/build/bench-smoke/results.csv") result rows"
