#include "core/cancellation.h"

namespace tquad {

namespace detail {

CancellationState& cancellation_state() {
  thread_local CancellationState state;
  return state;
}

void look_at_cancellation(CancellationState& state) {
  state.work = 0;
  if (state.heartbeat && *state.heartbeat) {
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - state.last_beat).count() >= kHeartbeatSeconds) {
      state.last_beat = now;
      (*state.heartbeat)();
    }
  }
  if (state.flag->load(std::memory_order_relaxed)) throw OperationCancelled{};
}

}  // namespace detail

CancellationScope::CancellationScope(const std::atomic<bool>* flag, std::function<void()> heartbeat)
    : heartbeat_(std::move(heartbeat)), saved_(detail::cancellation_state()) {
  detail::CancellationState& state = detail::cancellation_state();
  state.flag = flag;
  state.heartbeat = &heartbeat_;
  state.work = 0;
  state.last_beat = std::chrono::steady_clock::now();
}

CancellationScope::~CancellationScope() { detail::cancellation_state() = saved_; }

}  // namespace tquad
