#pragma once
// GPU timestamps per pass, one query range per frame in flight. A Pass opens a debug label and a
// timestamp pair together, so no pass can be timed without being labelled or the other way round.
#include "gpu/unique.h"

#include <string>
#include <vector>

namespace vitrine::gpu {

class Device;

struct PassTime {
  std::string name;
  double ms;
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
  uint32_t maxPasses_;
  double nsPerTick_;
  uint64_t validMask_;
  bool drainBeforeEnd_ = false;  // a CPU device: see end()
  uint32_t slot_ = 0;
  std::vector<std::vector<std::string>> names_;  // per slot
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
