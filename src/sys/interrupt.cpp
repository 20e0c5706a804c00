#include "sys/interrupt.hpp"

#include <atomic>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <ctime>

namespace tumble::sys {
namespace {

std::atomic<int> received{0};
std::atomic<std::int64_t> received_at{0};  // ns on the monotonic clock
static_assert(std::atomic<int>::is_always_lock_free, "read from a signal handler");
static_assert(std::atomic<std::int64_t>::is_always_lock_free, "read from a signal handler");

// A second signal within this time repeats the first request: `timeout` sends its signal to the
// child and then to the whole process group, so one stop arrives twice at once.
constexpr std::int64_t kRepeatNanoseconds = 2'000'000'000;

extern "C" void on_interrupt(int signal) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  const std::int64_t ns = std::int64_t{now.tv_sec} * 1'000'000'000 + now.tv_nsec;
  if (received.load() == 0) {
    received_at.store(ns);
    received.store(signal);
  } else if (ns - received_at.load() > kRepeatNanoseconds) {
    std::signal(signal, SIG_DFL);  // asked again, later: stop at once, as without tumble's handler
    std::raise(signal);
  }
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() {
  return received.load();
}

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "a signal";
  }
}

}  // namespace tumble::sys
