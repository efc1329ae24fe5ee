#!/usr/bin/env bash
# Build TemplateQuad (installing missing Debian packages first) and run every test.
# This is the README's test command; .ci/run calls it.
set -euo pipefail
repo_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$repo_dir/scripts/setup.sh"
ctest --test-dir "$repo_dir/build" --output-on-failure --timeout 600 -j "$(nproc)"
# The property tests record the worst element quality they saw, and the CAD tests a
# table of faces meshed and refused per file; show them.
# In CI (CI=true), or with --sanitize: the C++ suites again under AddressSanitizer and
# UndefinedBehaviorSanitizer, and a short run of each fuzz target (on 2 cores the
# sanitizer build takes about 10 minutes and its suites about 8, with every fourth
# generated case of the property suites; the fuzz build and runs come on top). The shape
# targets fork a reader per input (about 10 runs a second under the sanitizers): 200
# runs each.
if [ "${CI:-}" = true ] || [ "${1:-}" = --sanitize ]; then
  "$repo_dir/scripts/sanitize.sh"
  "$repo_dir/scripts/fuzz.sh" 2000 fuzz_boundary fuzz_domain
  "$repo_dir/scripts/fuzz.sh" 200 fuzz_brep fuzz_step
fi
