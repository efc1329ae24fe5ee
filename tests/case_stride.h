// Which generated cases a property suite runs: every case, every Nth with the
// environment variable TQUAD_CASE_STRIDE=N (scripts/sanitize.sh sets it: under the
// sanitizers the same code paths run at a share of the cost, and the full sets run in
// the plain build), or the one case TQUAD_CASE=I names. A failing case's message
// gives its index (case_trace), so it can be rerun alone:
//   TQUAD_CASE=1234 build/bin/core_tests --gtest_filter=FaceDecomposition.GeneratedDomains*
#pragma once

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace tquad::testing {

inline int case_stride() {
  const char* text = std::getenv("TQUAD_CASE_STRIDE");
  const int n = text ? std::atoi(text) : 1;
  return n >= 1 ? n : 1;
}

// The case TQUAD_CASE names, or -1 for none.
inline int single_case() {
  const char* text = std::getenv("TQUAD_CASE");
  if (!text || !*text) return -1;
  char* end = nullptr;
  const long i = std::strtol(text, &end, 10);
  return *end == '\0' && i >= 0 ? static_cast<int>(i) : -1;
}

// The indices of the cases to run out of `count`; a TQUAD_CASE past them is an error
// (std::out_of_range, which fails the test), not a suite run on nothing.
inline std::vector<int> cases(int count) {
  const int one = single_case();
  if (one >= count) {
    throw std::out_of_range("TQUAD_CASE=" + std::to_string(one) + ": this suite has cases 0.." +
                            std::to_string(count - 1));
  }
  if (one >= 0) return {one};
  std::vector<int> out;
  for (int i = 0; i < count; i += case_stride()) out.push_back(i);
  return out;
}

// Whether the suite runs its whole set (every case, or every Nth): its totals over the
// cases are checked only then.
inline bool whole_set() { return single_case() < 0; }

// A failing case's trace line: its index and how to rerun it alone.
inline std::string case_trace(int i) {
  return "case " + std::to_string(i) + " (rerun it alone with TQUAD_CASE=" + std::to_string(i) + ")";
}

}  // namespace tquad::testing
