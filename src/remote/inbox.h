#pragma once
// The hand-over from the server threads to the main thread: bounded, so a main thread that stops
// draining (a long frame, a minimised window) costs at most `capacity` commands of memory; beyond
// that new commands are dropped and counted.
#include "remote/command.h"

#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

namespace vitrine::remote {

class RemoteInbox {
 public:
  explicit RemoteInbox(size_t capacity = 1024) : capacity_(capacity) {}

  // Any thread. False when full: the command is dropped.
  bool push(RemoteCommand command);
  // The main thread: everything queued, oldest first. Never blocks for longer than a swap.
  std::vector<RemoteCommand> drain();

  // Why a server refused a command of a client with no reply channel (OSC), for the main thread to log:
  // the first kRefusalNotes since the last drain are kept, later ones only counted (RemoteStats).
  struct Refusal {
    std::string client, reason;
  };
  static constexpr size_t kRefusalNotes = 16;
  void refused(Refusal refusal);
  std::vector<Refusal> drainRefusals();

 private:
  const size_t capacity_;
  std::mutex mutex_;
  std::vector<RemoteCommand> queue_;
  std::vector<Refusal> refusals_;
};

}  // namespace vitrine::remote
