// Elapsed wall time, the one formula behind every stage and face timing.
#pragma once

#include <chrono>

namespace tquad {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace tquad
