#include "host/gallery/gallery_lights.h"

#include "host/scene_renderer.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace vitrine::host {
namespace {

class LightsSink final : public FrameSink {
 public:
  LightsSink(lights::Lights& lights, GalleryLights::SceneSignals sceneSignals)
      : lights_(lights), sceneSignals_(std::move(sceneSignals)) {}
  void frame(const PublishedFrame& frame) override {
    ++frames_;
    // A copy of the rows (147 KiB) and nothing more on the frame thread: the lights thread decodes them.
    std::vector<uint8_t> rgba(size_t(frame.width) * frame.height * 4);
    const auto* bytes = reinterpret_cast<const uint8_t*>(frame.bytes.data());
    for (uint32_t y = 0; y < frame.height; ++y)
      std::copy_n(bytes + size_t(y) * frame.stride, size_t(frame.width) * 4, rgba.data() + size_t(y) * frame.width * 4);
    lights_.publishSrgb8(std::move(rgba), frame.width, frame.height, sceneSignals_());
  }
  Output::Health health() const override {
    const lights::Lights::Counts counts = lights_.counts();
    return {.kind = "lights", .line = lights_.status(), .frames = frames_, .dropped = 0, .connected = counts.connected};
  }

 private:
  lights::Lights& lights_;
  GalleryLights::SceneSignals sceneSignals_;
  uint64_t frames_ = 0;
};

}  // namespace

GalleryLights::GalleryLights(const gpu::Device& device, const std::string& patchFile, SceneSignals sceneSignals)
    : lights_(std::make_unique<lights::Lights>(lights::loadPatch(patchFile))) {
  output_ = std::make_unique<ReadbackOutput>(device, "lights", maths::OutputWarp{}, VkExtent2D{lights::kRegionWidth, lights::kRegionHeight},
                                             std::make_unique<LightsSink>(*lights_, std::move(sceneSignals)));
}

GalleryLights::~GalleryLights() {
  output_.reset();  // the sink refers to the lights
  lights_.reset();
}

void GalleryLights::record(VkCommandBuffer cmd, uint32_t slot, SceneRenderer& renderer, const Crossfade& fade,
                           VkPipelineStageFlags2 stage, const FrameInput& shown) {
  if (!output_->acquire(slot, false)) return;
  renderer.recordOutput(cmd, output_->destination(stage), fade);
  output_->drawn(cmd, &renderer.timer(), shown);
}

std::string GalleryLights::toggleBlackout() {
  lights_->setBlackout(!lights_->blackout());
  return lights_->blackout() ? "lights: blackout" : "lights: on";
}

}  // namespace vitrine::host
