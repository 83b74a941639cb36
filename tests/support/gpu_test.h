#pragma once
// One validated Vulkan device for the whole test binary (instance creation with the validation layer
// costs more than most tests). Every GPU test fails if the validation layer spoke while it ran.
#include "gpu/device.h"

#include <gtest/gtest.h>

#include <memory>

namespace vitrine::test {

struct SharedGpu {
  std::unique_ptr<gpu::Instance> instance;
  std::unique_ptr<gpu::Device> device;
  ~SharedGpu() {
    device.reset();  // before the instance it came from
    instance.reset();
  }
};

inline SharedGpu& sharedGpu() {
  static SharedGpu gpu;
  if (!gpu.device) {
    gpu.instance = std::make_unique<gpu::Instance>(gpu::InstanceOptions{true, {}});
    gpu.device = std::make_unique<gpu::Device>(*gpu.instance, gpu::DeviceOptions{});
  }
  return gpu;
}

class GpuTest : public ::testing::Test {
 protected:
  static const gpu::Device& device() { return *sharedGpu().device; }
  void SetUp() override { before_ = sharedGpu().instance->validationMessages(); }
  void TearDown() override {
    EXPECT_EQ(sharedGpu().instance->validationMessages(), before_) << "the validation layer reported problems";
  }

 private:
  int before_ = 0;
};

}  // namespace vitrine::test
