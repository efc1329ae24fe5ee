// case_stride: the generated-case suites run every case, or every Nth with the
// environment variable TQUAD_CASE_STRIDE=N. scripts/sanitize.sh sets it: under the
// sanitizers the same code paths run at a share of the cost, and the full sets run
// in the plain build.
#pragma once

#include <cstdlib>

namespace tquad::testing {

inline int case_stride() {
  const char* text = std::getenv("TQUAD_CASE_STRIDE");
  const int n = text ? std::atoi(text) : 1;
  return n >= 1 ? n : 1;
}

}  // namespace tquad::testing
