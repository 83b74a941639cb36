// shaders/bloom/diffuse.comp against its CPU reference (src/scenes/bloom/bloom_math.h) on a small
// lattice: random vapour inside the crystal, an off-centre source, several steps.
#include "gpu/program.h"
#include "gpu/stream.h"
#include "scenes/bloom/bloom_math.h"
#include "support/gpu_test.h"

#include <Imath/half.h>

#include <cstring>
#include <random>

namespace vitrine::bloom {
namespace {

class BloomGpu : public test::GpuTest {};

TEST_F(BloomGpu, TheDiffusionStepMatchesTheCpuReference) {
  constexpr uint32_t n = 20;
  constexpr int kSteps = 5;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<float> cpu(size_t(n) * n * n, 0.0f), next;
  std::vector<uint16_t> texels(cpu.size(), 0);
  for (uint32_t z = 0; z < n; ++z)
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x) {
        const size_t i = (size_t(z) * n + y) * n + x;
        if (!insideCrystal(voxelCentre({x, y, z}, n))) continue;
        const half h(uniform(random));
        texels[i] = h.bits();
        cpu[i] = float(h);  // the GPU starts from the half-rounded values
      }
  const DiffusionParams p{6.0f, 0.3f, 0.02f, true, glm::vec3(7.5f, 11.0f, 9.0f), 3.0f, 1.5f};

  gpu::ImageDesc desc;
  desc.extent = {n, n, n};
  desc.type = VK_IMAGE_TYPE_3D;
  desc.format = VK_FORMAT_R16_SFLOAT;
  desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  gpu::Image images[2] = {gpu::Image(device(), desc, "lattice a"), gpu::Image(device(), desc, "lattice b")};
  gpu::ProgramLibrary programs(device());
  gpu::ComputeProgram diffuse(programs, "bloom/diffuse.comp",
                              {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, 32});
  gpu::StreamArena arena(device());
  gpu::Buffer readback(device(), texels.size() * sizeof(uint16_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                       gpu::MemoryUse::Readback, "lattice readback");
  struct {
    glm::vec3 source;
    float diffusion, decay, dt, sigma, sourceRate;
  } push{p.source, p.diffusion, p.decay, p.dt, p.sigma, p.sourceRate};
  device().submitNow([&](VkCommandBuffer cmd) {
    gpu::uploadImage(cmd, arena, images[0], std::as_bytes(std::span(texels)), gpu::use::ComputeRead);
    diffuse.bind(cmd);
    diffuse.constants(cmd, push);
    for (int step = 0; step < kSteps; ++step) {
      gpu::Image& in = images[step % 2];
      gpu::Image& out = images[(step + 1) % 2];
      in.use(cmd, gpu::use::ComputeRead);
      out.use(cmd, gpu::use::ComputeWrite);
      diffuse.push(cmd, gpu::Bindings().storageImage(in.view()).storageImage(out.view()));
      diffuse.dispatchOver(cmd, VkExtent3D{n, n, n}, VkExtent3D{8, 8, 4});
    }
    gpu::Image& result = images[kSteps % 2];
    result.use(cmd, gpu::use::TransferSrc);
    readback.use(cmd, gpu::use::TransferDstBuffer);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {n, n, n};
    vkCmdCopyImageToBuffer(cmd, result.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 1, &region);
    readback.use(cmd, gpu::use::HostReadBuffer);
  });
  for (int step = 0; step < kSteps; ++step) {
    diffuseLattice(cpu, next, n, p);
    // Each GPU step stores halves: round the reference the same way, or its error would compound alone.
    for (float& v : next) v = float(half(v));
    std::swap(cpu, next);
  }
  readback.invalidate();
  const auto gpuTexels = readback.view<const uint16_t>();
  float worst = 0.0f;
  for (size_t i = 0; i < cpu.size(); ++i) {
    half h;
    h.setBits(gpuTexels[i]);
    worst = std::max(worst, std::abs(float(h) - cpu[i]));
  }
  // Halves carry 11 bits: one unit in the last place of values up to 1.05 is under 1e-3; the GPU may
  // round a sum differently, so allow two.
  EXPECT_LT(worst, 2e-3f);
  EXPECT_GT(*std::max_element(cpu.begin(), cpu.end()), 0.5f) << "the comparison saw real vapour";
}

}  // namespace
}  // namespace vitrine::bloom
