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

}  // namespace vitrine::remote
