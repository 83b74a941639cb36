// The integrate pass on the device against the CPU reference (src/scenes/noodles/strand.h): a few
// small grids of strands in each field, integrator, tangent and frame mode, read back node by node;
// the flow's bake (bake.comp, integrate_baked.comp) against theirs (bakeField, strandVelocity); and
// the raster's walk over a chunk's strands (raster_push.glsl) against strand_walk.h.
#include "gpu/barriers.h"
#include "host/offline/offscreen.h"
#include "gpu/resources.h"
#include "scenes/noodles/integrate_pass.h"
#include "scenes/noodles/raster_pass.h"
#include "scenes/noodles/strand.h"
#include "scenes/noodles/strand_layout.h"
#include "scenes/noodles/strand_walk.h"
#include "support/gpu_test.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace vitrine::noodles {
namespace {

using maths::FieldKind;  // the flows are shared with neon (src/maths/flow_field.h)

class NoodlesGpu : public test::GpuTest {
 protected:
  gpu::ProgramLibrary programs_{device()};
  const IntegratePass pass_{programs_};

  // Only the integrate pass runs here: the raster pass's workgroups, which count nothing here, are
  // taken as the integrate pass's.
  StrandWorkgroups workgroups() const { return {pass_.workgroupSize(), pass_.workgroupSize()}; }

  // The baked flow's texels as bake.comp left them (RGB10A2), when the settings bake.
  std::vector<uint32_t> bakedTexels_;

  // Every strand's nodes, strand-major (strand s at s * (segments + 1)), as the GPU wrote them.
  std::vector<PackedNode> integrateOnDevice(const StrandSettings& settings, const DeviceBudget& budget) {
    const StrandLayout layout = planStrands(settings.grid, settings.segments, budget, workgroups());
    gpu::Buffer nodes(device(), layout.bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                            gpu::MemoryUse::Device, "test nodes");
    gpu::Buffer readback(device(), layout.bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback,
                               "test node readback");
    const glm::uvec3 texels = settings.bake.baked() ? settings.bake.texels : glm::uvec3(1);
    gpu::Image volume(device(),
                      {.extent = {texels.x, texels.y, texels.z}, .format = kBakedFlowFormat,
                       .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                       .type = VK_IMAGE_TYPE_3D,
                       .storageFormat = kBakedFlowStorageFormat},
                      "test baked flow");
    gpu::Buffer volumeReadback(device(), settings.bake.count() * 4 + 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               gpu::MemoryUse::Readback, "test baked flow readback");
    device().submitNow([&](VkCommandBuffer cmd) {
      BakedFlow baked;
      if (settings.bake.baked()) {
        volume.use(cmd, gpu::use::ComputeWrite);
        pass_.recordBake(cmd, settings, volume.storageView());
        volume.use(cmd, gpu::use::ComputeSample);
        baked = {volume.view(), device().sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp)};
      }
      nodes.use(cmd, gpu::use::ComputeWriteBuffer);
      pass_.record(cmd, layout, nodes.handle(), settings, baked);
      if (settings.bake.baked()) gpu::recordReadback(cmd, volume, volumeReadback);
      nodes.use(cmd, gpu::use::TransferSrcBuffer);
      readback.use(cmd, gpu::use::TransferDstBuffer);
      const VkBufferCopy copy{0, 0, layout.bytes};
      vkCmdCopyBuffer(cmd, nodes.handle(), readback.handle(), 1, &copy);
      readback.use(cmd, gpu::use::HostReadBuffer);
    });
    readback.invalidate();
    if (settings.bake.baked()) {
      volumeReadback.invalidate();
      const auto words = volumeReadback.view<const uint32_t>();
      bakedTexels_.assign(words.begin(), words.begin() + ptrdiff_t(settings.bake.count()));
    }
    const auto raw = readback.view<const PackedNode>();
    const uint32_t perStrand = layout.segments + 1;
    std::vector<PackedNode> strandMajor(size_t(layout.strands) * perStrand);
    for (const StrandChunk& chunk : layout.chunks)
      for (uint32_t local = 0; local < chunk.strandCount; ++local)
        for (uint32_t k = 0; k < perStrand; ++k)
          strandMajor[size_t(chunk.firstStrand + local) * perStrand + k] =
              raw[chunk.offset / kNodeBytes + nodeSlot(chunk.strandCount, perStrand, local, k)];
    return strandMajor;
  }

  // Tolerances. The hash is integer arithmetic and the lattice gradients are exact, so both sides
  // start from identical numbers; they part only through float rounding - the GPU may fuse
  // multiply-adds and its sqrt and division are allowed a few ulp - which is ~1e-6 relative per
  // field evaluation. A streamline amplifies a perturbation by at most exp(|grad v| * length);
  // over these strands (|grad v| ~ 2 per noise unit, length under 3 units at noise scale 0.5) that
  // is a factor of ~20, so positions agree to ~1e-4 of a unit; 2e-3 leaves room without hiding a
  // real difference, which moves a strand by a whole step (0.05) within a segment or two.
  // Frames go through a 10-bit quaternion (< 0.2 degrees); one quantum either way plus the position
  // differences stays under 0.01 in each axis vector. (Lavapipe, which neither fuses nor
  // approximates here, matches the CPU bit for bit; the margin is for GPUs that do.)
  static constexpr float kPositionTolerance = 2e-3f;
  static constexpr float kAxisTolerance = 1e-2f;
  // A baked flow is held to the same bounds: the shader weighs the eight texels in float as the CPU
  // does. A sampler's linear filter would weigh them with the device's sub-texel precision (8 bits
  // on NVIDIA, 4 allowed): up to 1/32 of a texel's difference from its neighbour, ~1e-2 over these
  // 16-step strands.

  void expectMatchesReference(const StrandSettings& settings, const DeviceBudget& budget) {
    const std::vector<PackedNode> gpu = integrateOnDevice(settings, budget);
    const uint32_t strands = settings.grid.x * settings.grid.y * settings.grid.z;
    const uint32_t perStrand = settings.segments + 1;
    const bool baked = settings.bake.baked();
    const std::vector<glm::vec3> texels = baked ? bakeField(settings.bake, settings.field) : std::vector<glm::vec3>{};
    std::vector<PackedNode> cpu(perStrand);
    float worstPosition = 0.0f, worstAxis = 0.0f;
    for (uint32_t s = 0; s < strands; ++s) {
      integrateStrand(settings, s, cpu, texels);
      for (uint32_t k = 0; k < perStrand; ++k) {
        const PackedNode& g = gpu[size_t(s) * perStrand + k];
        worstPosition = std::max(worstPosition, glm::length(nodePosition(g) - nodePosition(cpu[k])));
        const Frame a = nodeFrame(g), b = nodeFrame(cpu[k]);
        worstAxis = std::max({worstAxis, glm::length(a.normal - b.normal), glm::length(a.binormal - b.binormal),
                              glm::length(a.tangent - b.tangent)});
        ASSERT_LT(worstPosition, kPositionTolerance) << fmt::format("strand {} node {}", s, k);
        ASSERT_LT(worstAxis, kAxisTolerance) << fmt::format("strand {} node {}", s, k);
      }
    }
    // The strands went somewhere: a pass that wrote nothing (zeros) must not pass as "close".
    EXPECT_GT(glm::length(nodePosition(gpu[perStrand - 1]) - nodePosition(gpu[0])), 0.1f);
    RecordProperty("worst_position_difference", fmt::format("{:.3g}", worstPosition));
    RecordProperty("worst_axis_difference", fmt::format("{:.3g}", worstAxis));
  }
};

StrandSettings smallGrid() {
  StrandSettings s;
  s.grid = {4, 3, 2};
  s.segments = 48;
  s.field = fieldAtTime(FieldKind::Curl, 0.5f, 0.0f, 2.5);
  return s;
}

TEST_F(NoodlesGpu, CurlEulerRawRotationMinimisingMatchesTheCpu) {
  expectMatchesReference(smallGrid(), deviceBudget(device()));
}

TEST_F(NoodlesGpu, BitangentRk4NormalizedUpVectorMatchesTheCpu) {
  StrandSettings s = smallGrid();
  s.field = fieldAtTime(FieldKind::Bitangent, 0.7f, 0.0f, 11.0);
  s.integrator = Integrator::Rk4;
  s.tangent = TangentMode::Normalized;
  s.frames = FrameMethod::Up;
  expectMatchesReference(s, deviceBudget(device()));
}

TEST_F(NoodlesGpu, LiftedCurlRk4MatchesTheCpu) {
  StrandSettings s = smallGrid();
  s.field = fieldAtTime(FieldKind::Curl, 0.5f, 2.0f, 0.0);
  s.integrator = Integrator::Rk4;
  s.tangent = TangentMode::Normalized;
  expectMatchesReference(s, deviceBudget(device()));
}

TEST_F(NoodlesGpu, ChunkedBindingsMatchTheCpu) {
  // Shrink the binding range to five strands' worth (kept aligned) so the 24 strands take several
  // dispatches with offsets, as ten million segments do on a 128 MiB-range device.
  DeviceBudget budget = deviceBudget(device());
  const StrandSettings s = smallGrid();
  budget.maxStorageBufferRange = 5ull * (s.segments + 1) * kNodeBytes;
  const StrandLayout layout = planStrands(s.grid, s.segments, budget, workgroups());
  ASSERT_GT(layout.chunks.size(), 2u);
  expectMatchesReference(s, budget);
}

// bake.comp writes what bakeField computes, packed as bakedTexel packs it, in the order the volume is
// addressed: a level a step away only where the device's arithmetic lands across a rounding boundary
// (a few in ten thousand). A driver's own float-to-unorm conversion may truncate, which Vulkan allows:
// about half the levels would then be a step low.
void expectTheBakedFlowHoldsTheCpuBake(const StrandSettings& s, const std::vector<uint32_t>& texels) {
  ASSERT_TRUE(s.bake.baked());
  const std::vector<glm::vec3> cpu = bakeField(s.bake, s.field);
  ASSERT_EQ(texels.size(), cpu.size());
  size_t stepAway = 0;
  for (size_t i = 0; i < cpu.size(); ++i)
    for (int axis = 0; axis < 3; ++axis) {
      const uint32_t level = (texels[i] >> (10 * axis)) & 1023u, expected = bakedLevel(cpu[i][axis]);
      ASSERT_LE(std::max(level, expected) - std::min(level, expected), 1u) << fmt::format("texel {} axis {}", i, axis);
      stepAway += level != expected;
    }
  const double share = double(stepAway) / double(3 * cpu.size());
  EXPECT_LT(share, 1e-3) << stepAway << " of " << 3 * cpu.size() << " levels a step from the CPU's";
  testing::Test::RecordProperty("levels_a_step_away", fmt::format("{:.3g}", share));
}

TEST_F(NoodlesGpu, TheBakedFlowHoldsTheCpuBake) {
  StrandSettings s = smallGrid();
  s.segments = 16;
  s.bake = planFieldBake(s, FieldSource::Baked);
  integrateOnDevice(s, deviceBudget(device()));
  expectTheBakedFlowHoldsTheCpuBake(s, bakedTexels_);
}

// The bitangent flow takes two potentials, not three, from the workgroup's shared lattice gradients.
TEST_F(NoodlesGpu, TheBakedBitangentFlowHoldsTheCpuBake) {
  StrandSettings s = smallGrid();
  s.segments = 16;
  s.field = fieldAtTime(FieldKind::Bitangent, 0.7f, 1.5f, 4.0);
  s.bake = planFieldBake(s, FieldSource::Baked);
  integrateOnDevice(s, deviceBudget(device()));
  expectTheBakedFlowHoldsTheCpuBake(s, bakedTexels_);
}

// A coarsened bake: at 1.5 times the spacing a workgroup's texels span up to four lattice points along
// an axis (what its table holds), at 3 times more than that, where the workgroup evaluates texel by texel.
TEST_F(NoodlesGpu, CoarseBakesHoldTheCpuBake) {
  for (const float coarser : {1.5f, 3.0f}) {
    SCOPED_TRACE(fmt::format("spacing x{}", coarser));
    StrandSettings s = smallGrid();
    s.segments = 16;
    s.bake = planFieldBake(s, FieldSource::Baked);
    s.bake.spacing *= coarser;
    integrateOnDevice(s, deviceBudget(device()));
    expectTheBakedFlowHoldsTheCpuBake(s, bakedTexels_);
  }
}

TEST_F(NoodlesGpu, CurlInTheBakedFlowMatchesTheCpu) {
  StrandSettings s = smallGrid();
  s.segments = 16;
  s.bake = planFieldBake(s, FieldSource::Baked);
  expectMatchesReference(s, deviceBudget(device()));
}

TEST_F(NoodlesGpu, LiftedBitangentRk4InTheBakedFlowMatchesTheCpu) {
  StrandSettings s = smallGrid();
  s.segments = 16;
  s.field = fieldAtTime(FieldKind::Bitangent, 0.7f, 1.5f, 4.0);
  s.integrator = Integrator::Rk4;
  s.bake = planFieldBake(s, FieldSource::Baked);
  expectMatchesReference(s, deviceBudget(device()));
}

// The segment each raster invocation takes, as the GLSL computes it (walk_probe.comp runs
// raster_push.glsl's phaseSegment): invocations run strand-major, strands in strand_walk.h's order
// (walkedStrand, nearest first), the occluders every NOODLES_OCCLUDER_STRIDE-th strand walked and the
// rest the others in walk order, so the two phases take every segment exactly once. For a grid seen
// along each axis both ways and askew, and for a chunk of a split nest (walked as a row).
TEST_F(NoodlesGpu, TheShaderWalksTheStrandsAsTheCppDoes) {
  const glm::uvec3 grid{5, 4, 3};
  const uint32_t segments = 3;
  gpu::ComputeProgram probe(programs_, "noodles/walk_probe.comp");
  struct Walked {
    uint32_t strands;
    glm::vec3 forward;
  };
  const std::vector<Walked> walks = {{60, {1, 0.2f, 0.1f}},    {60, {-1, 0.2f, 0.1f}}, {60, {0.1f, 1, -0.2f}},
                                     {60, {0.1f, -1, 0.2f}},   {60, {0.2f, 0.1f, 1}},  {60, {-0.3f, 0.4f, -1}},
                                     {60, {0.6f, -0.5f, 0.6f}}, {25, {0.1f, 0.2f, 1}}, {25, {0.1f, 0.2f, -1}}};
  for (const Walked& w : walks) {
    const StrandWalk walk = chunkWalk(grid, w.strands, glm::normalize(w.forward));
    const uint32_t occluders = (w.strands + shader::NOODLES_OCCLUDER_STRIDE - 1) / shader::NOODLES_OCCLUDER_STRIDE;
    std::vector<uint32_t> taken(size_t(w.strands) * segments, 0);  // times each segment is taken by the two phases
    for (uint32_t phase : {shader::NOODLES_RASTER_ALL, shader::NOODLES_RASTER_OCCLUDERS, shader::NOODLES_RASTER_REST}) {
      shader::NoodlesRasterPush push{};
      push.segmentsPerStrand = segments;
      push.chunkStrands = w.strands;
      push.phase = phase;
      push.phaseStrands = phase == shader::NOODLES_RASTER_ALL         ? w.strands
                          : phase == shader::NOODLES_RASTER_OCCLUDERS ? occluders
                                                                      : w.strands - occluders;
      push.walkX = walk.dims.x;
      push.walkY = walk.dims.y;
      push.walk = walk.code;
      const uint32_t count = push.phaseStrands * segments;
      gpu::Buffer out(device(), count * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Readback,
                      "walk probe");
      device().submitNow([&](VkCommandBuffer cmd) {
        probe.bind(cmd);
        probe.push(cmd, gpu::Bindings().storageBuffer("Segments", out.handle()));
        probe.constants(cmd, push);
        out.use(cmd, gpu::use::ComputeWriteBuffer);
        probe.dispatchOver(cmd, count);
        out.use(cmd, gpu::use::HostReadBuffer);
      });
      out.invalidate();
      const auto gpu = out.view<const uint32_t>();
      uint32_t lastWalked = 0;
      for (uint32_t i = 0; i < count; ++i) {
        const std::string where = fmt::format("{} strands, forward ({}, {}, {}), phase {}, invocation {}", w.strands,
                                              w.forward.x, w.forward.y, w.forward.z, phase, i);
        ASSERT_LT(gpu[i], w.strands * segments) << where;
        const uint32_t segment = gpu[i] / w.strands, strand = gpu[i] % w.strands;
        ASSERT_EQ(segment, i % segments) << where << ": neighbours take consecutive segments of one strand";
        // The walk position of the strand this invocation's strand-major group takes.
        uint32_t walked = 0;
        while (walked < w.strands && walkedStrand(walked, walk.dims, walk.code) != strand) ++walked;
        ASSERT_LT(walked, w.strands) << where;
        const uint32_t group = i / segments;
        if (phase == shader::NOODLES_RASTER_ALL) {
          ASSERT_EQ(walked, group) << where << ": strands in the walk's order";
          continue;
        }
        if (phase == shader::NOODLES_RASTER_OCCLUDERS)
          ASSERT_EQ(walked, group * shader::NOODLES_OCCLUDER_STRIDE) << where << ": every stride-th strand walked";
        else
          ASSERT_NE(walked % shader::NOODLES_OCCLUDER_STRIDE, 0u) << where << ": the rest are not occluders";
        if (segment == 0) {
          if (group > 0) {
            ASSERT_GT(walked, lastWalked) << where << ": in walk order";
          }
          lastWalked = walked;
        }
        ++taken[gpu[i]];
      }
    }
    EXPECT_TRUE(std::all_of(taken.begin(), taken.end(), [](uint32_t n) { return n == 1; }))
        << w.strands << " strands: the occluders and the rest take every segment once";
  }
}

// A big nest drawn occluders first (every fourth strand walked, a bound a tile, then the rest) is the same
// picture, bit for bit, as one pass over every segment: the rest skip a segment only where every
// sample of every tile its box touches already holds a nearer hit, and keys only fall. The nest is
// just past the threshold, drawn small (lavapipe takes ~3 s a frame), where the occluders cover the
// nest's tiles and most of the rest are skipped.
TEST_F(NoodlesGpu, OccludersFirstDrawTheSamePicture) {
  static_assert(64ull * 64 * 32 * 32 >= kTwoPhasesFrom, "the nest must be drawn in two phases");
  const auto render = [&](const char* occluders) {
    host::OffscreenConfig config;
    config.scene = "noodles";
    config.size = {96, 54};
    config.startTime = 4.0;
    config.parameters = {{"grid", "64x64x32"}, {"segments", "32"}, {"occluders", occluders}};
    host::Offscreen offscreen(device(), config);
    offscreen.renderFrame();
    return offscreen.readback();
  };
  const ImageRgba twoPhases = render("on"), onePass = render("off");
  ASSERT_EQ(twoPhases.pixels.size(), onePass.pixels.size());
  size_t differing = 0, lit = 0;
  for (size_t i = 0; i < onePass.pixels.size(); i += 4) {
    differing += !std::equal(&onePass.pixels[i], &onePass.pixels[i] + 3, &twoPhases.pixels[i]);
    lit += onePass.pixels[i] + onePass.pixels[i + 1] + onePass.pixels[i + 2] > 0.1f;
  }
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(lit, onePass.pixels.size() / 4 / 5) << "the nest covers a fifth of the frame or more";
}

// The seed preset draws grey strands (shade.comp's palette.glsl mirrors palette.h's grey ramp): the lit
// pixels' saturation, their summed (max - min) over their summed max, is 0.07 (the write-up's ambient
// light is a little blue, and so are the tubes' shaded sides), where the default's strands give 0.49.
TEST_F(NoodlesGpu, TheSeedPresetDrawsGreyStrands) {
  const auto saturation = [&](const char* colour) {
    host::OffscreenConfig config;
    config.scene = "noodles";
    config.size = {96, 54};
    config.startTime = 4.0;
    config.presets = {"seed"};
    config.parameters = {{"colour", colour}};
    host::Offscreen offscreen(device(), config);
    offscreen.renderFrame();
    const ImageRgba image = offscreen.readback();
    double spread = 0.0, brightest = 0.0;
    size_t lit = 0;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
      const float r = image.pixels[i], g = image.pixels[i + 1], b = image.pixels[i + 2];
      const float hi = std::max(r, std::max(g, b)), lo = std::min(r, std::min(g, b));
      if (hi < 0.05f) continue;  // the background, and tube edges mostly background
      spread += hi - lo;
      brightest += hi;
      ++lit;
    }
    EXPECT_GT(lit, image.pixels.size() / 4 / 20) << colour << ": the nest covers a twentieth of the frame or more";
    return lit ? spread / brightest : 1.0;
  };
  EXPECT_LT(saturation("grey"), 0.1);
  EXPECT_GT(saturation("gradient"), 0.3);
}

}  // namespace
}  // namespace vitrine::noodles
