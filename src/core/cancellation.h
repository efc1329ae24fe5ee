// Cooperative cancellation of long loops: a user's Cancel must act within about a
// second even inside one face of millions of quads.
//
// A CancellationScope names, for the calling thread, the flag that cancels and a
// heartbeat (the progress report through which a front end may raise that flag).
// Long loops call poll_cancellation(work) with the work done since their last call
// (quads, nodes, a row's length); once enough has accumulated it checks the flag,
// throwing OperationCancelled when raised, and calls the heartbeat at most every
// kHeartbeatSeconds. Outside any scope a poll is one thread-local test.
//
// OperationCancelled is not a std::exception, so the routes' `catch (const
// std::exception&)` (a failed candidate) lets it through; the pipeline turns it into
// its own cancellation error at the stage boundary.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>

namespace tquad {

struct OperationCancelled {};

// Work between two looks at the flag and the clock: tens of milliseconds of the
// cheapest loops (a quad's corners), far less for the costly ones (which pass a larger
// weight per item).
constexpr std::size_t kPollWork = 1 << 16;
constexpr double kHeartbeatSeconds = 0.2;

namespace detail {

struct CancellationState {
  const std::atomic<bool>* flag = nullptr;
  const std::function<void()>* heartbeat = nullptr;
  std::size_t work = 0;
  std::chrono::steady_clock::time_point last_beat{};
};

CancellationState& cancellation_state();
void look_at_cancellation(CancellationState& state);

}  // namespace detail

// Polls as above; `work`: the items processed since the last call, weighted by cost.
inline void poll_cancellation(std::size_t work = 1) {
  detail::CancellationState& state = detail::cancellation_state();
  if (!state.flag) return;
  state.work += work;
  if (state.work >= kPollWork) detail::look_at_cancellation(state);
}

// For the calling thread while it lives: `flag` (may be null: nothing cancels) and
// `heartbeat` (may be empty). The scope before it is restored at its end.
class CancellationScope {
 public:
  CancellationScope(const std::atomic<bool>* flag, std::function<void()> heartbeat);
  ~CancellationScope();
  CancellationScope(const CancellationScope&) = delete;
  CancellationScope& operator=(const CancellationScope&) = delete;

 private:
  std::function<void()> heartbeat_;
  detail::CancellationState saved_;
};

}  // namespace tquad
