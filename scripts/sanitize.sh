#!/usr/bin/env bash
# The C++ test suites (core, CAD, command line) built with AddressSanitizer and
# UndefinedBehaviorSanitizer into build-sanitize/ and run; any report fails the run.
# The Python and FreeCAD tests are left out: their interpreters are not instrumented.
set -euo pipefail
repo_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="$repo_dir/build-sanitize"
# Line tables only (-g1): the sanitizers' stack traces keep their files and lines, and
# a translation unit compiles in about three quarters of the time it takes with -g.
cmake -S "$repo_dir" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DTQUAD_SANITIZE=ON > /dev/null
cmake --build "$build" --target tquad core_tests occ_tests cli_tests
# Leaks are reported, except OpenCASCADE's own (its allocations live until exit by
# design): scripts/lsan_suppressions.txt names them.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$repo_dir/scripts/lsan_suppressions.txt:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Every fourth generated case of the property suites (tests/case_stride.h): the same
# code paths, at a quarter of their cost; the plain build runs them all.
export TQUAD_CASE_STRIDE=4
ctest --test-dir "$build" --output-on-failure --timeout 1200 -j "$(nproc)" -E "python_module|freecad_workbench|debian_package"
