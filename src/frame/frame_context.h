#pragma once
// What GPU work drawn for a scene sees: GpuContext when it is made (the device, the program library,
// the images it declares) and FrameContext each frame (the command buffer, the target, the frame's
// input). Scenes get these through scenes/scene.h; passes that any scene may own (text/) include this
// header instead, so the dependencies point one way: gpu <- frame <- text, scenes <- host. Nothing
// here knows of a scene, a host mode or a window.
#include "frame/frame_input.h"
#include "gpu/device.h"
#include "gpu/frame_resources.h"
#include "gpu/pass_timer.h"
#include "gpu/program.h"
#include "gpu/rendering.h"
#include "gpu/stream.h"

#include <cstdint>
#include <span>

namespace vitrine {

// What a pass needs to build its programs and declare its images. A scene's SceneContext is one, so
// a scene hands its own context to the passes it owns (text::TextPass).
struct GpuContext {
  const gpu::Device& device;
  gpu::ProgramLibrary& programs;
  gpu::FrameResources& resources;  // declare images here; the host owns and resizes them
};

struct FrameContext {
  const gpu::Device& device;
  VkCommandBuffer cmd;
  gpu::PassTimer* timer;
  // The HDR image the scene draws into: rgba16f, linear, contents undefined at the start of the
  // frame. Usable as storage image, colour attachment (or resolve target) and sampled image.
  gpu::Image& target;
  gpu::FrameResources& resources;  // the images the scene declared
  gpu::StreamArena& stream;        // per-frame CPU-written memory (uniform blocks, uploads)
  const FrameInput& input;
  uint32_t slot;  // frame-in-flight index, for per-frame resources
  // False for a frame nobody will see (record's frames before its --range): a scene may record only
  // what later frames depend on (its simulation) and skip its drawing. A scene whose picture carries
  // history from frame to frame (glass' accumulation) draws all the same.
  bool draws = true;

  // A labelled, timestamped GPU pass for the scope of the returned object.
  gpu::Pass pass(const char* name) const { return gpu::Pass(device, timer, cmd, name); }
  // The barrier from the resource's last use to `use` is derived; nothing else to write.
  void transition(gpu::Image& image, const gpu::ImageUse& use) const { image.use(cmd, use); }
  void transition(gpu::Buffer& buffer, const gpu::BufferUse& use) const { buffer.use(cmd, use); }
  gpu::Image& image(gpu::ImageHandle handle) const { return resources.current(handle); }
  gpu::Buffer& buffer(gpu::BufferHandle handle) const { return resources.current(handle); }
  // Colour/depth attachments transitioned, rendering begun, viewport and scissor set; ends with scope.
  gpu::Rendering rendering(const gpu::RenderingDesc& desc) const { return gpu::Rendering(cmd, desc); }
  // A uniform or parameter block for this frame.
  template <typename T> gpu::StreamSlice uniform(const T& value) const { return stream.writeValue(value); }
  void upload(gpu::Buffer& buffer, VkDeviceSize offset, std::span<const std::byte> data,
              const gpu::BufferUse& after) const {
    gpu::uploadBuffer(cmd, stream, buffer, offset, data, after);
  }
};

}  // namespace vitrine
