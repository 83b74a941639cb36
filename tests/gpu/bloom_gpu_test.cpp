// shaders/bloom/diffuse.comp against its CPU reference (src/scenes/bloom/bloom_math.h) on a small
// lattice: random vapour inside the crystal, an off-centre source, several steps; and the lattice
// vents at the same speed whatever sub-step a lattice size needs (the storage keeps every step).
#include "gpu/program_variants.h"
#include "gpu/stream.h"
#include "scenes/bloom/bloom_math.h"
#include "shaders/bloom/diffuse_push.h"
#include "support/gpu_test.h"

#include <cmath>
#include <random>

namespace vitrine::bloom {
namespace {

// Three r32f lattice buffers on the GPU (slot 0 the state, as in the scene) and the crystal's view,
// run through diffuse.comp for frames of a plan and read back: the lattice, and the view, which the
// last stage must leave equal to it.
class BloomGpu : public test::GpuTest {
 protected:
  std::vector<float> run(uint32_t n, const std::vector<float>& texels, DiffusionParams p, const DiffusionPlan& plan,
                         int frames) {
    const VkDeviceSize bytes = texels.size() * sizeof(float);
    const VkBufferUsageFlags usage =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    gpu::Buffer lattices[3] = {gpu::Buffer(device(), bytes, usage, gpu::MemoryUse::Device, "lattice a"),
                               gpu::Buffer(device(), bytes, usage, gpu::MemoryUse::Device, "lattice b"),
                               gpu::Buffer(device(), bytes, usage, gpu::MemoryUse::Device, "lattice stage")};
    gpu::ImageDesc desc;
    desc.extent = {n, n, n};
    desc.type = VK_IMAGE_TYPE_3D;
    desc.format = VK_FORMAT_R32_SFLOAT;
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    gpu::Image view(device(), desc, "view");
    gpu::ProgramLibrary programs(device());
    gpu::ComputeVariants diffuse(programs, "bloom/diffuse.comp");
    gpu::StreamArena arena(device());
    gpu::Buffer readback(device(), 2 * bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback,
                         "lattice readback");
    shader::BloomDiffusePush push{.source = p.source,
                                  .diffusion = p.diffusion,
                                  .decay = p.decay,
                                  .sigma = p.sigma,
                                  .sourceRate = p.sourceOn ? p.sourceRate : 0.0f,
                                  .side = n};
    uint32_t state = 0;  // the pair's current lattice, 0 or 1
    device().submitNow([&](VkCommandBuffer cmd) {
      // Every lattice: a stage never writes outside the crystal, which must hold zero in each.
      for (gpu::Buffer& lattice : lattices)
        gpu::uploadBuffer(cmd, arena, lattice, 0, std::as_bytes(std::span(texels)), gpu::use::ComputeReadBuffer);
      const std::vector<float> zeros(texels.size(), 0.0f);
      gpu::uploadImage(cmd, arena, view, std::as_bytes(std::span(zeros)), gpu::use::ComputeWrite);
      const uint32_t steps = uint32_t(frames) * plan.superSteps;
      for (uint32_t step = 0; step < steps; ++step) {
        gpu::Buffer* slots[3] = {&lattices[state], &lattices[1 - state], &lattices[2]};
        uint32_t older = 0, here = 0;
        for (uint32_t j = 1; j <= plan.stages; ++j) {
          const uint32_t next = stageSlot(j, plan.stages, here, older);
          const StageWeights w = rklStage(j, plan.stages);
          push.dt = w.step * plan.dt, push.keep = w.keep, push.older = w.older;
          push.last = j == plan.stages ? 1u : 0u;
          const gpu::ComputeProgram& stage = diffuse({w.older != 0.0f, push.last && step + 1 == steps});
          stage.bind(cmd);
          slots[here]->use(cmd, gpu::use::ComputeReadBuffer);
          slots[older]->use(cmd, gpu::use::ComputeReadBuffer);
          slots[next]->use(cmd, gpu::use::ComputeWriteBuffer);
          view.use(cmd, gpu::use::ComputeWrite);
          stage.push(cmd, gpu::Bindings()
                              .storageBuffer("Current", slots[here]->handle())
                              .storageBuffer("Older", slots[older]->handle())
                              .storageBuffer("Next", slots[next]->handle())
                              .storageImage("view", view.view()));
          stage.constants(cmd, push);
          stage.dispatchOver(cmd,
                             VkExtent3D{n, n, (n + shader::kBloomDiffuseColumn - 1) / shader::kBloomDiffuseColumn});
          older = here, here = next;
        }
        EXPECT_LT(here, 2u) << "a super step ends in the pair";
        if (here == 1) state = 1 - state;
      }
      gpu::Buffer& result = lattices[state];
      result.use(cmd, gpu::use::TransferSrcBuffer);
      readback.use(cmd, gpu::use::TransferDstBuffer);
      const VkBufferCopy copy{0, 0, bytes};
      vkCmdCopyBuffer(cmd, result.handle(), readback.handle(), 1, &copy);
      view.use(cmd, gpu::use::TransferSrc);
      VkBufferImageCopy region{};
      region.bufferOffset = bytes;
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.imageExtent = {n, n, n};
      vkCmdCopyImageToBuffer(cmd, view.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 1, &region);
      readback.use(cmd, gpu::use::HostReadBuffer);
    });
    readback.invalidate();
    const auto both = readback.view<const float>();
    const std::vector<float> lattice(both.begin(), both.begin() + ptrdiff_t(texels.size()));
    size_t differ = 0;
    for (size_t i = 0; i < texels.size(); ++i) differ += both[texels.size() + i] != lattice[i] ? 1 : 0;
    EXPECT_EQ(differ, 0u) << n << "^3: the view shows the lattice as the last stage left it";
    return lattice;
  }
};

std::vector<float> randomCrystal(uint32_t n) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<float> lattice(size_t(n) * n * n, 0.0f);
  for (uint32_t z = 0; z < n; ++z)
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x)
        if (insideCrystal(voxelCentre({x, y, z}, n))) lattice[(size_t(z) * n + y) * n + x] = uniform(random);
  return lattice;
}

// On a lattice of one run a column, and on odd ones of several runs (whose crystal's tips touch the
// lattice's faces, where a neighbour is clamped).
TEST_F(BloomGpu, TheDiffusionStepMatchesTheCpuReference) {
  constexpr int kFrames = 5;
  for (const uint32_t n : {12u, 37u, 71u}) {
    std::vector<float> cpu = randomCrystal(n);
    const DiffusionParams p{6.0f, 0.3f, 0.02f, true, glm::vec3(7.5f, 11.0f, 9.0f), 3.0f, 1.5f};
    const DiffusionPlan plan{1, 1, p.dt};
    const std::vector<float> gpu = run(n, cpu, p, plan, kFrames);
    for (int frame = 0; frame < kFrames; ++frame) diffuseFrame(cpu, n, p, plan);
    float worst = 0.0f;
    for (size_t i = 0; i < cpu.size(); ++i) worst = std::max(worst, std::abs(gpu[i] - cpu[i]));
    const std::string what = std::to_string(n) + "^3";
    EXPECT_LT(worst, 1e-5f) << what << ": floats: only the GPU's own rounding of a sum differs";
    EXPECT_GT(*std::max_element(cpu.begin(), cpu.end()), 0.5f) << what << ": the comparison saw real vapour";
  }
}

// Super steps of every stage count modulo 3 (each ends its rotation in a different slot), with the
// older stage read: the GPU's stages are the CPU reference's.
TEST_F(BloomGpu, TheRungeKuttaLegendreStagesMatchTheCpuReference) {
  constexpr uint32_t n = 37;
  constexpr int kFrames = 2;
  for (const uint32_t stages : {2u, 3u, 4u, 10u}) {
    std::vector<float> cpu = randomCrystal(n);
    const DiffusionParams p{20.0f, 0.3f, 0.0f, true, glm::vec3(17.5f, 21.0f, 19.0f), 3.0f, 1.5f};
    // The longest super step the stages keep stable.
    const DiffusionPlan plan{1, stages, kStabilityLimit * float(stages * stages + stages) * 0.5f / (6.0f * p.diffusion)};
    const std::vector<float> gpu = run(n, cpu, p, plan, kFrames);
    for (int frame = 0; frame < kFrames; ++frame) diffuseFrame(cpu, n, p, plan);
    float worst = 0.0f;
    for (size_t i = 0; i < cpu.size(); ++i) worst = std::max(worst, std::abs(gpu[i] - cpu[i]));
    EXPECT_LT(worst, 1e-4f) << stages << " stages: only the GPU's own rounding differs";
    EXPECT_GT(*std::max_element(cpu.begin(), cpu.end()), 0.3f) << stages << " stages: real vapour";
  }
}

// A full crystal venting from the climax (1.05) with the default rates, with the plan each lattice
// size runs at 60 Hz (48^3: 1 explicit step, 96^3: 2, 256^3: 5 stages, 512^3: 10): its interior must
// fall past the climax threshold (0.82) at the same moment, the physics' ln(1.05 / 0.82) / 0.40 =
// 0.62 s. A half-float lattice did not: each 256^3 sub-step's decay was under half a half-float step,
// and the vent time followed the lattice size and the driver's rounding (0.45 s at 48^3, 0.27 s at
// 256^3 on lavapipe). The lattice here is small (the interior does not feel the surface within the
// vent); only the plan differs.
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
  for (uint32_t lattice : {48u, 96u, 256u, 512u}) {
    const DiffusionPlan plan = diffusionPlan(scaledDiffusion(15.0f, lattice), kFrame);
    DiffusionParams p;
    p.diffusion = 0.0f;  // the interior of a uniform crystal: its Laplacian is zero
    p.decay = kDecay;
    p.dt = plan.dt;
    const std::vector<float> after = run(n, full, p, plan, kFrames);
    // The centre alone, on the CPU: with no Laplacian each voxel is its own equation.
    float cpu = kFrom;
    for (uint32_t step = 0; step < kFrames * plan.superSteps; ++step) {
      float older = cpu, here = cpu;
      for (uint32_t j = 1; j <= plan.stages; ++j) {
        const float next = stageVoxel(here, older, 6.0f * here, glm::vec3(0.0f), true, p, rklStage(j, plan.stages),
                                      j == plan.stages);
        older = here, here = next;
      }
      cpu = here;
    }
    // The decay rate the lattice showed, and so when it passes 0.82.
    const float shownDecay = std::log(kFrom / after[centre]) / (kFrames * kFrame);
    const float vented = std::log(kFrom / kClimax) / shownDecay;
    EXPECT_NEAR(after[centre], cpu, 2e-5f) << lattice;
    EXPECT_NEAR(vented, expected, 0.01f) << lattice << "^3, " << plan.passes() << " passes a frame";
  }
}

}  // namespace
}  // namespace vitrine::bloom
