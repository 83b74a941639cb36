#include "scenes/noodles/raster_pass.h"

#include "core/error.h"
#include "gpu/buffer_commands.h"
#include "scenes/noodles/strand_walk.h"
#include "shaders/noodles/raster_blocks.h"

#include <fmt/format.h>

#include <span>

namespace vitrine::noodles {
namespace {

constexpr VkDeviceSize kKeyBytes = 8;  // one uint64_t key a sample
constexpr uint32_t kMultisampledAxis = 2;  // four samples a pixel, two an axis

gpu::BufferDecl visibilityDecl(uint32_t samplesPerAxis) {
  return {.name = "noodles visibility",
          .size = gpu::BufferSize::relative(kKeyBytes * samplesPerAxis * samplesPerAxis),
          .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT};  // cleared each frame
}

// The keys are 64-bit atomicMin targets: shaderInt64 and shaderBufferInt64Atomics (Vulkan 1.2 core,
// optional; lavapipe and NVIDIA have both), enabled by the device when present. Checked before the
// raster programs are built, which without them would be invalid pipelines, not a clear message.
gpu::ProgramLibrary& programsWithInt64Atomics(const SceneContext& context) {
  if (!context.device.bufferInt64Atomics())
    throw Error(fmt::format("noodles: {} has no 64-bit storage-buffer atomics (shaderInt64, "
                            "shaderBufferInt64Atomics), which its tube rasteriser needs",
                            context.device.properties().deviceName));
  return context.programs;
}

}  // namespace

RasterPass::RasterPass(const SceneContext& context)
    : segments_(programsWithInt64Atomics(context), "noodles/raster.comp"),
      bigSegments_(context.programs, "noodles/raster_big.comp"),
      tileBound_(context.programs, "noodles/tile_bound.comp"),
      visibility_(context.resources.declare(visibilityDecl(kMultisampledAxis))),
      bigList_(context.resources.declare(
          {.name = "noodles big segments",
           .size = gpu::BufferSize::absolute(shader::NOODLES_BIG_LIST_CAPACITY * sizeof(uint32_t)),
           .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT})),
      counters_(context.resources.declare(
          {.name = "noodles big-segment counters",
           .size = gpu::BufferSize::absolute(sizeof(shader::NoodlesBigSegmentCounters)),
           .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                    VK_BUFFER_USAGE_TRANSFER_DST_BIT})),
      tileFar_(context.resources.declare({.name = "noodles tile bounds",
                                          .size = gpu::BufferSize::relative(sizeof(uint32_t)),
                                          .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT})),
      samplesPerAxis_(kMultisampledAxis),
      budget_(deviceBudget(context.device)) {}

void RasterPass::followSamples(const FrameContext& frame, bool multisample) {
  const VkExtent2D extent = frame.target.extent2d();
  const VkDeviceSize pixels = VkDeviceSize(extent.width) * extent.height;
  // Four samples need four keys a pixel; where that is more than one binding may cover (4K on
  // lavapipe's 128 MiB), the picture falls back to one sample rather than failing.
  const bool fits = pixels * kMultisampledAxis * kMultisampledAxis * kKeyBytes <=
                    frame.device.limits().maxStorageBufferRange;
  const uint32_t samplesPerAxis = multisample && fits ? kMultisampledAxis : 1;
  if (samplesPerAxis == samplesPerAxis_) return;
  frame.resources.redeclare(visibility_, visibilityDecl(samplesPerAxis));  // the old one is retired
  samplesPerAxis_ = samplesPerAxis;
}

void RasterPass::record(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes, const TubeView& view) {
  followSamples(frame, view.multisample);
  gpu::Buffer& visibility = frame.buffer(visibility_);
  gpu::fillBuffer(frame.cmd, visibility, 0xffffffffu, gpu::use::ComputeReadWriteBuffer);  // all keys empty

  shader::NoodlesRasterPush push = rasterPush(view, layout);
  const VkExtent2D extent = frame.target.extent2d();
  push.tilesPerRow = (extent.width + shader::NOODLES_BOUND_TILE - 1) / shader::NOODLES_BOUND_TILE;
  if (!view.occluders || layout.segmentCount < kTwoPhasesFrom) return recordPhase(frame, layout, nodes, push, shader::NOODLES_RASTER_ALL);
  recordPhase(frame, layout, nodes, push, shader::NOODLES_RASTER_OCCLUDERS);
  recordTileBound(frame, push.tilesPerRow);
  recordPhase(frame, layout, nodes, push, shader::NOODLES_RASTER_REST);
}

void RasterPass::recordPhase(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes,
                             shader::NoodlesRasterPush push, uint32_t phase) {
  gpu::Buffer& visibility = frame.buffer(visibility_);
  gpu::Buffer& bigList = frame.buffer(bigList_);
  gpu::Buffer& counters = frame.buffer(counters_);
  gpu::Buffer& tileFar = frame.buffer(tileFar_);
  push.phase = phase;
  const size_t chunks = layout.chunks.size();
  for (size_t n = 0; n < chunks; ++n) {  // nearest first, as the strands in each (strand_walk.h)
    const StrandChunk& chunk = layout.chunks[chunksDescending(push.forward) ? chunks - 1 - n : n];
    // Nothing listed yet; the big-segment pass's y and z group counts are 1.
    static constexpr shader::NoodlesBigSegmentCounters kReset{.groupsX = 0, .groupsY = 1, .groupsZ = 1, .listed = 0};
    frame.upload(counters, 0, std::as_bytes(std::span(&kReset, 1)), gpu::use::ComputeReadWriteBuffer);
    frame.transition(bigList, gpu::use::ComputeWriteBuffer);
    frame.transition(visibility, gpu::use::ComputeReadWriteBuffer);
    frame.transition(tileFar, gpu::use::ComputeReadBuffer);
    const gpu::Bindings bindings = gpu::Bindings()
                                       .storageBuffer("Nodes", nodes, chunk.offset, chunk.bytes)
                                       .storageBuffer("Visibility", visibility.handle())
                                       .storageBuffer("BigSegments", bigList.handle())
                                       .storageBuffer("Counters", counters.handle())
                                       .storageBuffer("TileFar", tileFar.handle());
    const uint32_t occluders = (chunk.strandCount + shader::NOODLES_OCCLUDER_STRIDE - 1) / shader::NOODLES_OCCLUDER_STRIDE;
    push.phaseStrands = phase == shader::NOODLES_RASTER_OCCLUDERS ? occluders
                        : phase == shader::NOODLES_RASTER_REST    ? chunk.strandCount - occluders
                                                                  : chunk.strandCount;
    if (push.phaseStrands == 0) continue;
    // This phase's share of the chunk's segments, in rows of workgroups like the whole chunk's
    // (planStrands checked that those fit the dispatch limits, so a share does too).
    const GroupRows groups = phase == shader::NOODLES_RASTER_ALL
                                 ? chunk.rasterGroups
                                 : groupRows(uint64_t(push.phaseStrands) * layout.segments, workgroupSize(), budget_,
                                             "noodles raster");
    push.firstStrand = chunk.firstStrand;
    push.chunkStrands = chunk.strandCount;
    const StrandWalk walk = chunkWalk(layout.grid, chunk.strandCount, push.forward);
    push.walkX = walk.dims.x;
    push.walkY = walk.dims.y;
    push.walk = walk.code;
    push.invocationsPerRow = groups.x * workgroupSize();
    const gpu::ComputeProgram& segmentProgram = segments_({int32_t(samplesPerAxis_)});
    if (segmentProgram.localSize()[0] != kWorkgroupSize) throw Error("noodles: raster.comp's local size changed");
    segmentProgram.bind(frame.cmd);
    segmentProgram.push(frame.cmd, bindings);
    segmentProgram.constants(frame.cmd, push);
    segmentProgram.dispatchGroups(frame.cmd, {groups.x, groups.y, 1});  // one invocation a segment

    frame.transition(bigList, gpu::use::ComputeReadBuffer);
    frame.transition(visibility, gpu::use::ComputeReadWriteBuffer);
    const gpu::ComputeProgram& bigProgram = bigSegments_({int32_t(samplesPerAxis_)});
    bigProgram.bind(frame.cmd);
    bigProgram.push(frame.cmd, bindings);
    bigProgram.constants(frame.cmd, push);
    gpu::dispatchIndirect(frame.cmd, counters);
  }
}

void RasterPass::recordTileBound(const FrameContext& frame, uint32_t tilesPerRow) {
  gpu::Buffer& visibility = frame.buffer(visibility_);
  gpu::Buffer& tileFar = frame.buffer(tileFar_);
  frame.transition(visibility, gpu::use::ComputeReadBuffer);
  frame.transition(tileFar, gpu::use::ComputeWriteBuffer);
  const VkExtent2D extent = frame.target.extent2d();
  tileBound_.bind(frame.cmd);
  tileBound_.push(frame.cmd, gpu::Bindings()
                                 .storageBuffer("Visibility", visibility.handle())
                                 .storageBuffer("TileFar", tileFar.handle()));
  tileBound_.constants(frame.cmd, shader::NoodlesTileBoundPush{.pixels = {extent.width, extent.height},
                                                                .samplesPerPixel = samplesPerAxis_ * samplesPerAxis_,
                                                                .tilesPerRow = tilesPerRow});
  tileBound_.dispatchOver(frame.cmd, extent);  // a workgroup a tile
}

}  // namespace vitrine::noodles
