#!/usr/bin/env bash
# Fuzzes the glTF/GLB loader with libFuzzer under AddressSanitizer + UndefinedBehaviorSanitizer for
# SECONDS (default 60), starting from seeds made of the test scenes (fuzz/make_seeds.cpp). Builds
# into build-fuzz/ with clang-14. Inputs that crash land in build-fuzz/findings/; the corpus grows
# in build-fuzz/corpus/ from run to run. Exits non-zero on a finding.
# Usage: scripts/fuzz.sh [SECONDS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
dir="$root/build-fuzz"
bash "$root/scripts/setup-debian.sh"
cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLLL_FUZZ=ON \
  -DCMAKE_CXX_COMPILER=clang++-14 >/dev/null
cmake --build "$dir" -j "$(nproc)"
rm -rf "$dir/seeds"
"$dir/fuzz/make_seeds" "$root/assets" "$dir/seeds"
mkdir -p "$dir/corpus" "$dir/findings"
# Leak checking stays on here: no Vulkan driver is loaded, so every leak is the loader's.
export ASAN_OPTIONS="abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The loader reads its input's folder only; libFuzzer's own files stay in build-fuzz/.
cd "$dir"
"$dir/fuzz/fuzz_gltf" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$dir/findings/" \
  "$dir/corpus" "$dir/seeds" 2>"$dir/fuzz.log" || { tail -40 "$dir/fuzz.log"; exit 1; }
echo "fuzz: $(grep -o 'stat::number_of_executed_units: *[0-9]*' "$dir/fuzz.log" | grep -o '[0-9]*$') inputs in ${seconds} s, no finding"
