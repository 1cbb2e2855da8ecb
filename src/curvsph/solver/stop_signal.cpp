#include "curvsph/solver/stop_signal.hpp"

#include <atomic>
#include <csignal>
#include <mutex>

namespace curvsph {
namespace {

// A signal handler may only store to a volatile sig_atomic_t (or a lock-free atomic).
volatile std::sig_atomic_t g_signal = 0;
extern "C" void on_stop_signal(int sig) {
  g_signal = sig;
}

std::atomic<bool> g_ends_program{false};
std::mutex g_mutex;  // guards the count and the saved handlers
int g_active = 0;
void (*g_old_int)(int) = SIG_DFL;
void (*g_old_term)(int) = SIG_DFL;

}  // namespace

StopOnSignal::StopOnSignal() {
  const std::lock_guard<std::mutex> lock(g_mutex);
  if (g_active++ > 0) return;
  if (!g_ends_program) g_signal = 0;
  g_old_int = std::signal(SIGINT, on_stop_signal);
  g_old_term = std::signal(SIGTERM, on_stop_signal);
}

StopOnSignal::~StopOnSignal() {
  const std::lock_guard<std::mutex> lock(g_mutex);
  if (--g_active > 0) return;
  std::signal(SIGINT, g_old_int);
  std::signal(SIGTERM, g_old_term);
}

int stop_signal() {
  return g_signal;
}

void stop_ends_program(bool on) {
  g_ends_program = on;
}

bool stop_ends_program() {
  return g_ends_program;
}

}  // namespace curvsph
