// The device-memory ledger the soak reads: every allocation counted with its size while it lives, and
// gone from the count once freed, so "flat" means what it says on any driver.
#include "gpu/memory_ledger.h"
#include "gpu/resources.h"
#include "support/gpu_test.h"

#include <optional>

namespace vitrine::test {
namespace {

class MemoryLedger : public GpuTest {};

TEST_F(MemoryLedger, CountsABufferWhileItLivesAndNotAfter) {
  const gpu::MemoryTally before = gpu::liveDeviceMemory();
  std::optional<gpu::Buffer> buffer;
  buffer.emplace(device(), 3u << 20, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Device, "ledger test");
  const gpu::MemoryTally during = gpu::liveDeviceMemory();
  EXPECT_EQ(during.allocations, before.allocations + 1);
  EXPECT_GE(during.bytes, before.bytes + (3u << 20)) << "its size, rounded up by the driver's requirements";
  buffer.reset();
  device().drainRetired();  // freeing is deferred to the end of the frames that may use it
  const gpu::MemoryTally after = gpu::liveDeviceMemory();
  EXPECT_EQ(after.allocations, before.allocations);
  EXPECT_EQ(after.bytes, before.bytes);
}

}  // namespace
}  // namespace vitrine::test
