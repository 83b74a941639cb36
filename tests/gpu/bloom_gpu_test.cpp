// shaders/bloom/diffuse.comp against its CPU reference (src/scenes/bloom/bloom_math.h) on a small
// lattice: random vapour inside the crystal, an off-centre source, several steps; and the lattice
// vents at the same speed whatever sub-step a lattice size needs (the storage keeps every step).
#include "gpu/program.h"
#include "gpu/stream.h"
#include "scenes/bloom/bloom_math.h"
#include "shaders/bloom/diffuse_push.h"
#include "support/gpu_test.h"

#include <cmath>
#include <random>

namespace vitrine::bloom {
namespace {

// One 3D r32f lattice pair on the GPU, run through diffuse.comp and read back.
class BloomGpu : public test::GpuTest {
 protected:
  std::vector<float> run(uint32_t n, const std::vector<float>& texels, const DiffusionParams& p, int steps) {
    gpu::ImageDesc desc;
    desc.extent = {n, n, n};
    desc.type = VK_IMAGE_TYPE_3D;
    desc.format = VK_FORMAT_R32_SFLOAT;
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    gpu::Image images[2] = {gpu::Image(device(), desc, "lattice a"), gpu::Image(device(), desc, "lattice b")};
    gpu::ProgramLibrary programs(device());
    gpu::ComputeProgram diffuse(programs, "bloom/diffuse.comp");
    gpu::StreamArena arena(device());
    gpu::Buffer readback(device(), texels.size() * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         gpu::MemoryUse::Readback, "lattice readback");
    const shader::BloomDiffusePush push{.source = p.source,
                                        .diffusion = p.diffusion,
                                        .decay = p.decay,
                                        .dt = p.dt,
                                        .sigma = p.sigma,
                                        .sourceRate = p.sourceOn ? p.sourceRate : 0.0f};
    device().submitNow([&](VkCommandBuffer cmd) {
      // Both images: the step never writes outside the crystal, which must hold zero in each.
      for (gpu::Image& image : images)
        gpu::uploadImage(cmd, arena, image, std::as_bytes(std::span(texels)), gpu::use::ComputeRead);
      diffuse.bind(cmd);
      diffuse.constants(cmd, push);
      for (int step = 0; step < steps; ++step) {
        gpu::Image& in = images[step % 2];
        gpu::Image& out = images[(step + 1) % 2];
        in.use(cmd, gpu::use::ComputeRead);
        out.use(cmd, gpu::use::ComputeWrite);
        diffuse.push(cmd, gpu::Bindings().storageImage("current", in.view()).storageImage("next", out.view()));
        diffuse.dispatchOver(cmd, VkExtent3D{n, n, (n + shader::kBloomDiffuseColumn - 1) / shader::kBloomDiffuseColumn});
      }
      gpu::Image& result = images[steps % 2];
      result.use(cmd, gpu::use::TransferSrc);
      readback.use(cmd, gpu::use::TransferDstBuffer);
      VkBufferImageCopy region{};
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.imageExtent = {n, n, n};
      vkCmdCopyImageToBuffer(cmd, result.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 1, &region);
      readback.use(cmd, gpu::use::HostReadBuffer);
    });
    readback.invalidate();
    const auto view = readback.view<const float>();
    return {view.begin(), view.end()};
  }
};

// On a lattice of one run a column, and on odd ones of several runs (whose crystal's tips touch the
// lattice's faces, where a neighbour is clamped).
TEST_F(BloomGpu, TheDiffusionStepMatchesTheCpuReference) {
  constexpr int kSteps = 5;
  for (const uint32_t n : {12u, 37u, 71u}) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<float> cpu(size_t(n) * n * n, 0.0f), next;
    for (uint32_t z = 0; z < n; ++z)
      for (uint32_t y = 0; y < n; ++y)
        for (uint32_t x = 0; x < n; ++x)
          if (insideCrystal(voxelCentre({x, y, z}, n))) cpu[(size_t(z) * n + y) * n + x] = uniform(random);
    const DiffusionParams p{6.0f, 0.3f, 0.02f, true, glm::vec3(7.5f, 11.0f, 9.0f), 3.0f, 1.5f};
    const std::vector<float> gpu = run(n, cpu, p, kSteps);
    for (int step = 0; step < kSteps; ++step) diffuseLattice(cpu, next, n, p), std::swap(cpu, next);
    float worst = 0.0f;
    for (size_t i = 0; i < cpu.size(); ++i) worst = std::max(worst, std::abs(gpu[i] - cpu[i]));
    const std::string what = std::to_string(n) + "^3";
    EXPECT_LT(worst, 1e-5f) << what << ": floats: only the GPU's own rounding of a sum differs";
    EXPECT_GT(*std::max_element(cpu.begin(), cpu.end()), 0.5f) << what << ": the comparison saw real vapour";
  }
}

// A full crystal venting from the climax (1.05) with the default rates, at the sub-step each lattice
// size runs at 60 Hz (48^3: 1, 96^3: 2, 256^3: 12): its interior must fall past the climax threshold
// (0.82) at the same moment, the physics' ln(1.05 / 0.82) / 0.40 = 0.62 s. A half-float lattice
// did not: each 256^3 sub-step's decay was under half a half-float step, and the vent time followed
// the lattice size and the driver's rounding (0.45 s at 48^3, 0.27 s at 256^3 on lavapipe). The
// lattice here is small (the interior does not feel the surface within the vent); only dt differs.
TEST_F(BloomGpu, TheCrystalVentsInTheSameTimeAtEveryLatticeSize) {
  constexpr uint32_t n = 24;
  constexpr float kFrame = 1.0f / 60.0f, kFrom = 1.05f, kClimax = 0.82f, kDecay = 0.40f;
  constexpr int kFrames = 45;
  std::vector<float> full(size_t(n) * n * n, 0.0f);
  for (uint32_t z = 0; z < n; ++z)
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x)
        if (insideCrystal(voxelCentre({x, y, z}, n))) full[(size_t(z) * n + y) * n + x] = kFrom;
  const size_t centre = (size_t(n / 2) * n + n / 2) * n + n / 2;
  const float expected = std::log(kFrom / kClimax) / kDecay;
  for (uint32_t lattice : {48u, 96u, 256u}) {
    const uint32_t substeps = substepsFor(scaledDiffusion(15.0f, lattice), kFrame);
    DiffusionParams p;
    p.diffusion = 0.0f;  // the interior of a uniform crystal: its Laplacian is zero
    p.decay = kDecay;
    p.dt = kFrame / float(substeps);
    const std::vector<float> after = run(n, full, p, int(substeps) * kFrames);
    // The decay rate the lattice showed, and so when it passes 0.82.
    const float shownDecay = std::log(kFrom / after[centre]) / (kFrames * kFrame);
    const float vented = std::log(kFrom / kClimax) / shownDecay;
    EXPECT_NEAR(after[centre], kFrom * std::pow(1.0f - kDecay * p.dt, float(substeps * kFrames)), 2e-4f) << lattice;
    EXPECT_NEAR(vented, expected, 0.01f) << lattice << "^3, " << substeps << " sub-steps a frame";
  }
}

}  // namespace
}  // namespace vitrine::bloom
