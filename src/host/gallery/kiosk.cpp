#include "host/gallery/kiosk.h"

#include <algorithm>
#include <utility>

namespace vitrine::host {

KioskSchedule::KioskSchedule(size_t entries, size_t first, KioskTiming timing)
    : KioskSchedule(std::vector<double>(std::max<size_t>(entries, 1), timing.dwell), first, timing) {}

KioskSchedule::KioskSchedule(std::vector<double> dwells, size_t first, KioskTiming timing)
    : timing_(timing), dwells_(dwells.empty() ? std::vector<double>{timing.dwell} : std::move(dwells)),
      failed_(dwells_.size(), false), current_(std::min(first, failed_.size() - 1)) {}

size_t KioskSchedule::nextAfter(size_t index) const {
  for (size_t step = 1; step <= failed_.size(); ++step) {
    const size_t candidate = (index + step) % failed_.size();
    if (!failed_[candidate]) return candidate;
  }
  return index;
}

KioskSchedule::Plan KioskSchedule::advance(double elapsed, bool touched, bool mayBegin) {
  Plan plan;
  sinceTouch_ = touched ? 0.0 : sinceTouch_ + elapsed;
  if (incoming_) {
    fading_ += elapsed;
    if (touched || fading_ >= timing_.fade || cued_) {  // a touch lands on the scene coming in
      current_ = *std::exchange(incoming_, std::nullopt);
      shown_ = 0.0;
      plan.finish = true;
    } else {
      plan.fade = float(fading_ / timing_.fade);
    }
    return plan;
  }
  if (cued_) {
    const size_t next = *std::exchange(cued_, std::nullopt);
    if (next != current_) {
      incoming_ = next;
      fading_ = 0.0;
      plan.begin = next;
      plan.fade = 0.0f;
    }
    return plan;
  }
  if (sinceTouch_ < timing_.idle) {  // held by a person: the clock starts again when they leave
    shown_ = 0.0;
    return plan;
  }
  shown_ += elapsed;
  const size_t next = nextAfter(current_);
  if (shown_ >= dwells_[current_] && next != current_ && mayBegin) {
    incoming_ = next;
    fading_ = 0.0;
    plan.begin = next;
    plan.fade = 0.0f;
  }
  return plan;
}

void KioskSchedule::failed(size_t index) {
  if (index >= failed_.size()) return;
  failed_[index] = true;
  if (std::all_of(failed_.begin(), failed_.end(), [](bool f) { return f; }))
    std::fill(failed_.begin(), failed_.end(), false);  // never stop: try them all again
  if (incoming_ == index) incoming_.reset();
  if (index == current_) {
    current_ = nextAfter(index);
    shown_ = 0.0;
  }
}

void KioskSchedule::jumpTo(size_t index) {
  if (index >= failed_.size()) return;
  incoming_.reset();
  cued_.reset();
  current_ = index;
  shown_ = 0.0;
}

}  // namespace vitrine::host
