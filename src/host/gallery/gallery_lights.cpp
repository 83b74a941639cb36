#include "host/gallery/gallery_lights.h"

#include "host/scene_renderer.h"

#include <utility>

namespace vitrine::host {
namespace {

class LightsSink final : public FrameSink {
 public:
  LightsSink(lights::Lights& lights, GalleryLights::SceneSignals sceneSignals)
      : lights_(lights), sceneSignals_(std::move(sceneSignals)) {}
  void frame(const PublishedFrame& frame) override {
    ++frames_;
    lights_.publish(lights::reduceSrgb8(reinterpret_cast<const uint8_t*>(frame.bytes.data()), frame.width, frame.height, frame.stride),
                    sceneSignals_());
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
  output_ = std::make_unique<ReadbackOutput>(device, "lights", maths::OutputWarp{}, VkExtent2D{lights::kSmallWidth, lights::kSmallHeight},
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
