#include "core/stop_signal.h"

#include "core/error.h"

#include <fmt/format.h>

#include <csignal>

namespace vitrine {
namespace {

volatile std::sig_atomic_t caught = 0;  // the signal's number, 0 until one comes

}  // namespace

StopOnSignal::StopOnSignal() {
  caught = 0;
  previousInt_ = std::signal(SIGINT, [](int signal) { caught = signal; });
  previousTerm_ = std::signal(SIGTERM, [](int signal) { caught = signal; });
}

StopOnSignal::~StopOnSignal() {
  std::signal(SIGINT, previousInt_ == SIG_ERR ? SIG_DFL : previousInt_);
  std::signal(SIGTERM, previousTerm_ == SIG_ERR ? SIG_DFL : previousTerm_);
}

bool StopOnSignal::requested() { return caught != 0; }

void StopOnSignal::check(std::string_view what) {
  if (caught != 0) throw Error(fmt::format("Interrupted by {}: {}", caught == SIGINT ? "SIGINT" : "SIGTERM", what));
}

}  // namespace vitrine
