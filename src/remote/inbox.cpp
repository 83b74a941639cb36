#include "remote/inbox.h"

#include <utility>

namespace vitrine::remote {

bool RemoteInbox::push(RemoteCommand command) {
  std::lock_guard lock(mutex_);
  if (queue_.size() >= capacity_) return false;
  queue_.push_back(std::move(command));
  return true;
}

std::vector<RemoteCommand> RemoteInbox::drain() {
  std::vector<RemoteCommand> taken;
  std::lock_guard lock(mutex_);
  taken.swap(queue_);
  return taken;
}

void RemoteInbox::refused(Refusal refusal) {
  std::lock_guard lock(mutex_);
  if (refusals_.size() < kRefusalNotes) refusals_.push_back(std::move(refusal));
}

std::vector<RemoteInbox::Refusal> RemoteInbox::drainRefusals() {
  std::vector<Refusal> taken;
  std::lock_guard lock(mutex_);
  taken.swap(refusals_);
  return taken;
}

}  // namespace vitrine::remote
