#include "gpu/pass_timer.h"

#include "gpu/check.h"
#include "gpu/device.h"

namespace vitrine::gpu {
namespace {

// Results come back in the order of these bits: vertex, fragment, compute.
constexpr VkQueryPipelineStatisticFlags kCountedStages = VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT |
                                                         VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT |
                                                         VK_QUERY_PIPELINE_STATISTIC_COMPUTE_SHADER_INVOCATIONS_BIT;

}  // namespace

PassTimer::PassTimer(const Device& device, uint32_t slots, uint32_t maxPassesPerFrame)
    : device_(device), maxPasses_(maxPassesPerFrame), names_(slots), counted_(slots) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = slots * maxPasses_ * 2;
  VkQueryPool pool;
  VK_CHECK(vkCreateQueryPool(device, &info, nullptr, &pool));
  pool_ = Unique<VkQueryPool>(device, pool);
  device.name(pool, VK_OBJECT_TYPE_QUERY_POOL, "pass timestamps");
  nsPerTick_ = device.limits().timestampPeriod;
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device.physical(), &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device.physical(), &count, families.data());
  const uint32_t bits = families[device.queueFamily()].timestampValidBits;
  validMask_ = bits >= 64 ? ~0ull : (1ull << bits) - 1;
  drainBeforeEnd_ = device.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  if (device.countsInvocations()) {
    VkQueryPoolCreateInfo counts{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    counts.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    counts.queryCount = slots * maxPasses_;
    counts.pipelineStatistics = kCountedStages;
    VK_CHECK(vkCreateQueryPool(device, &counts, nullptr, &pool));
    invocations_ = Unique<VkQueryPool>(device, pool);
    device.name(pool, VK_OBJECT_TYPE_QUERY_POOL, "pass invocations");
  }
}

void PassTimer::beginFrame(VkCommandBuffer cmd, uint32_t slot) {
  slot_ = slot;
  names_[slot].clear();
  counted_[slot].clear();
  counting_ = false;  // a new command buffer: nothing of the last one's is open in it
  vkCmdResetQueryPool(cmd, pool_, slot * maxPasses_ * 2, maxPasses_ * 2);
  if (invocations_) vkCmdResetQueryPool(cmd, invocations_, slot * maxPasses_, maxPasses_);
}

uint32_t PassTimer::begin(VkCommandBuffer cmd, const char* name) {
  auto& names = names_[slot_];
  if (names.size() >= maxPasses_) throw Error("More GPU passes in one frame than the pass timer holds");
  const auto index = static_cast<uint32_t>(names.size());
  names.emplace_back(name);
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, (slot_ * maxPasses_ + index) * 2);
  const bool count = invocations_ && !counting_;
  counted_[slot_].push_back(count);
  if (count) {
    vkCmdBeginQuery(cmd, invocations_, slot_ * maxPasses_ + index, 0);
    counting_ = true;
  }
  return index;
}

void PassTimer::end(VkCommandBuffer cmd, uint32_t pass) {
  if (drainBeforeEnd_) {
    // A CPU device (lavapipe) stamps the time when it reaches the command, while draws it has queued
    // may still be rasterising on its threads; the next pass's first barrier would then absorb them.
    // A full barrier is where lavapipe waits, so the pass ends with its own work done.
    const VkMemoryBarrier2 all{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2, nullptr, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                               VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_NONE};
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &all;
    vkCmdPipelineBarrier2(cmd, &dependency);
  }
  if (counted_[slot_][pass]) {
    vkCmdEndQuery(cmd, invocations_, slot_ * maxPasses_ + pass);
    counting_ = false;
  }
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, (slot_ * maxPasses_ + pass) * 2 + 1);
}

std::vector<PassTime> PassTimer::collect(uint32_t slot) const {
  const auto& names = names_[slot];
  std::vector<PassTime> result;
  if (names.empty()) return result;
  std::vector<uint64_t> ticks(names.size() * 2);
  VK_CHECK(vkGetQueryPoolResults(device_, pool_, slot * maxPasses_ * 2, static_cast<uint32_t>(ticks.size()),
                                 ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  for (size_t i = 0; i < names.size(); ++i) {
    const uint64_t elapsed = ((ticks[2 * i + 1] & validMask_) - (ticks[2 * i] & validMask_)) & validMask_;
    result.push_back({names[i], static_cast<double>(elapsed) * nsPerTick_ * 1e-6, std::nullopt});
    if (!counted_[slot][i]) continue;  // never begun: waiting on it would never end
    uint64_t counts[3];
    VK_CHECK(vkGetQueryPoolResults(device_, invocations_, uint32_t(slot * maxPasses_ + i), 1, sizeof(counts), counts,
                                   sizeof(counts), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    result.back().invocations = PassInvocations{counts[0], counts[1], counts[2]};
  }
  return result;
}

Pass::Pass(const Device& device, PassTimer* timer, VkCommandBuffer cmd, const char* name)
    : device_(device), timer_(timer), cmd_(cmd) {
  device_.beginLabel(cmd_, name);
  if (timer_) index_ = timer_->begin(cmd_, name);
}

Pass::~Pass() {
  if (timer_) timer_->end(cmd_, index_);
  device_.endLabel(cmd_);
}

}  // namespace vitrine::gpu
