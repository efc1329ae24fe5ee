#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, AddressSanitizer and UndefinedBehaviorSanitizer
# into build-fuzz/ and runs each for RUNS executions (default 1,000,000) from its seed
# corpus in fuzz/corpus/<target> (the corpus grows in build-fuzz/corpus/<target>).
# The random seed is FUZZ_SEED (default 1, so a run from a fresh clone, as in CI, is
# repeatable; long runs that continue a grown corpus take another seed), and a run stops
# after FUZZ_SECONDS (default: no limit) if RUNS are not done by then. An input taking
# over FUZZ_TIMEOUT seconds (default 10) is reported as a hang: a run beside builds or
# benches takes a longer one, since such a load slows an input tenfold and more.
# TARGETs default to all four: fuzz_boundary, fuzz_domain, fuzz_brep, fuzz_step.
#
#   [FUZZ_SEED=N] [FUZZ_SECONDS=S] [FUZZ_TIMEOUT=T] scripts/fuzz.sh [RUNS [TARGET...]]
set -euo pipefail
repo_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
runs=${1:-1000000}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_boundary fuzz_domain fuzz_brep fuzz_step)
build="$repo_dir/build-fuzz"
cmake -S "$repo_dir" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DTQUAD_FUZZ=ON -DTQUAD_BUILD_TESTS=OFF > /dev/null
cmake --build "$build" --target "${targets[@]}"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$repo_dir/scripts/lsan_suppressions.txt:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
mkdir -p "$build/artifacts"
for target in "${targets[@]}"; do
  mkdir -p "$build/corpus/$target"
  "$build/bin/$target" -runs="$runs" -seed="${FUZZ_SEED:-1}" -max_total_time="${FUZZ_SECONDS:-0}" -timeout="${FUZZ_TIMEOUT:-10}" -rss_limit_mb=4096 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$build/artifacts/$target-" \
    "$build/corpus/$target" "$repo_dir/fuzz/corpus/$target"
done
