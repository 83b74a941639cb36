#pragma once
// GPU timestamps per pass, one query range per frame in flight. A Pass opens a debug label and a
// timestamp pair together, so no pass can be timed without being labelled or the other way round.
// Where the device counts invocations (Device::countsInvocations: bench --pipeline-stats), each pass
// also counts the shader invocations it ran: a render pass's fragments are what its time on a GPU's
// graphics part follows.
#include "gpu/unique.h"

#include <optional>
#include <string>
#include <vector>

namespace vitrine::gpu {

class Device;

struct PassInvocations {
  uint64_t vertex = 0, fragment = 0, compute = 0;
};

struct PassTime {
  std::string name;
  double ms;
  std::optional<PassInvocations> invocations;  // counted passes only (a pass inside another is not)
};

class PassTimer {
 public:
  PassTimer(const Device& device, uint32_t slots, uint32_t maxPassesPerFrame = 32);

  void beginFrame(VkCommandBuffer cmd, uint32_t slot);  // resets this slot's queries
  uint32_t begin(VkCommandBuffer cmd, const char* name);
  void end(VkCommandBuffer cmd, uint32_t pass);
  // Once the slot's fence has signalled: its passes in recording order.
  std::vector<PassTime> collect(uint32_t slot) const;

 private:
  const Device& device_;
  Unique<VkQueryPool> pool_;
  Unique<VkQueryPool> invocations_;  // a pipeline-statistics query a pass, where counted
  uint32_t maxPasses_;
  double nsPerTick_;
  uint64_t validMask_;
  bool drainBeforeEnd_ = false;  // a CPU device: see end()
  uint32_t slot_ = 0;
  std::vector<std::vector<std::string>> names_;  // per slot
  std::vector<std::vector<bool>> counted_;       // per slot, per pass: whether its query ran
  bool counting_ = false;                        // a pass's query is open (passes may nest; queries may not)
};

class Pass {
 public:
  Pass(const Device& device, PassTimer* timer, VkCommandBuffer cmd, const char* name);
  ~Pass();
  Pass(const Pass&) = delete;
  Pass& operator=(const Pass&) = delete;

 private:
  const Device& device_;
  PassTimer* timer_;
  VkCommandBuffer cmd_;
  uint32_t index_ = 0;
};

}  // namespace vitrine::gpu
