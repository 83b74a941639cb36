#pragma once
// Test-only native twins of ISF files, for the runner's speed checks: each does the file's fragment
// work as a native scene does it, in passes labelled "native twin" and "native filter twin".
#include "gpu/device.h"
#include "gpu/frame_resources.h"
#include "gpu/program.h"
#include "host/offline/offscreen.h"
#include "image/image.h"
#include "shaders/test/invert_twin_push.h"
#include "shaders/test/speed_twin_push.h"
#include "support/test_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <vector>

namespace vitrine::test {

// tests/isf/speed_field.fs (shaders/test/speed_twin.*): the field drawn straight into the frame.
class SpeedTwin : public TestScene {
 public:
  explicit SpeedTwin(const SceneContext& context) : field_(context.programs, fieldState()) {}
  void update(const FrameInput& input) override { time_ = float(input.time); }
  void record(const FrameContext& frame) override {
    const auto pass = frame.pass("native twin");
    drawField(frame, frame.target);
  }

 protected:
  void drawField(const FrameContext& frame, gpu::Image& into) {
    const auto rendering = frame.rendering({{{&into, std::nullopt}}, std::nullopt});
    const VkExtent2D size = into.extent2d();
    field_.bind(frame.cmd);
    field_.constants(frame.cmd, shader::TestSpeedTwinPush{.renderSize = glm::vec2(size.width, size.height),
                                                          .time = time_,
                                                          .zoom = 3.0f});
    vkCmdDraw(frame.cmd, 4, 1, 0, 0);
  }
  static gpu::GraphicsState twinState(const char* fragment) {
    gpu::GraphicsState s;
    s.vertex = "test/speed_twin.vert";
    s.fragment = fragment;
    s.colorFormats = {VK_FORMAT_R16G16B16A16_SFLOAT};
    s.depthWrite = false;
    s.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    return s;
  }

 private:
  static gpu::GraphicsState fieldState() { return twinState("test/speed_twin.frag"); }
  gpu::GraphicsProgram field_;
  float time_ = 0.0f;
};

// tests/isf/filter_invert.fs at amount 1 (shaders/test/invert_twin.frag) after the speed field: the
// field drawn into a picture of the frame's size, then turned over into the frame.
class InvertTwin final : public SpeedTwin {
 public:
  explicit InvertTwin(const SceneContext& context)
      : SpeedTwin(context), device_(context.device), invert_(context.programs, twinState("test/invert_twin.frag")) {
    picture_ = context.resources.declare({"twin picture", VK_FORMAT_R16G16B16A16_SFLOAT,
                                          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                          gpu::ImageSize::relative(1.0f), 1});
  }
  void record(const FrameContext& frame) override {
    gpu::Image& picture = frame.image(picture_);
    {
      const auto pass = frame.pass("twin picture");
      drawField(frame, picture);
    }
    const auto pass = frame.pass("native filter twin");
    frame.transition(picture, gpu::use::FragmentSample);
    const auto rendering = frame.rendering({{{&frame.target, std::nullopt}}, std::nullopt});
    invert_.bind(frame.cmd);
    invert_.push(frame.cmd, gpu::Bindings().sampledImage(
                                "source", picture.view(),
                                device_.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp),
                                gpu::use::FragmentSample.layout));
    invert_.constants(frame.cmd, shader::TestInvertTwinPush{.amount = 1.0f});
    vkCmdDraw(frame.cmd, 4, 1, 0, 0);
  }

 private:
  const gpu::Device& device_;
  gpu::GraphicsProgram invert_;
  gpu::ImageHandle picture_;
};

// A twin's run: two frames at 96x54 in the suite; with VITRINE_ISF_SPEED=WxH (the GPU machine,
// 1920x1080) 300 frames at that size, the first 60 not counted.
struct TwinRun {
  VkExtent2D size{96, 54};
  int frames = 2, warmup = 1;
  bool valid = true;  // false: VITRINE_ISF_SPEED is not WxH
};
inline TwinRun twinRun() {
  TwinRun run;
  if (const char* speed = std::getenv("VITRINE_ISF_SPEED")) {
    run.valid = std::sscanf(speed, "%ux%u", &run.size.width, &run.size.height) == 2;
    run.frames = 300, run.warmup = 60;
  }
  return run;
}

inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

// The runner's parts and the twin's pass, each the median of its GPU time a frame.
struct TwinTimes {
  double source = 0.0;  // "isf source": the frame a filter takes, copied in
  double pass = 0.0;    // "isf pass N ...": the file's passes
  double output = 0.0;  // "isf output": the runner's picture, copied out
  double twin = 0.0;    // the native twin's pass
};

// A native Offscreen of `size` drawing the test scene `entry` (the calibrate scene it starts with is
// replaced before the first frame).
inline host::OffscreenConfig twinConfig(VkExtent2D size) {
  host::OffscreenConfig config;
  config.scene = "calibrate";
  config.size = size;
  return config;
}

// run.frames frames of each, in turn; the medians of those after run.warmup: the ISF side's parts and
// the native side's pass labelled `twinLabel`.
inline TwinTimes timeTwins(host::Offscreen& isf, host::Offscreen& native, const TwinRun& run,
                           std::string_view twinLabel) {
  std::vector<double> source, pass, output, twin;
  for (int frame = 0; frame < run.frames; ++frame) {
    const host::FrameTimes a = isf.renderFrame(), b = native.renderFrame();
    if (frame < run.warmup) continue;
    TwinTimes t;
    for (const gpu::PassTime& p : a.passes) {
      if (p.name == "isf source") t.source += p.ms;
      if (p.name.rfind("isf pass ", 0) == 0) t.pass += p.ms;
      if (p.name == "isf output") t.output += p.ms;
    }
    for (const gpu::PassTime& p : b.passes)
      if (p.name == twinLabel) t.twin += p.ms;
    source.push_back(t.source), pass.push_back(t.pass), output.push_back(t.output), twin.push_back(t.twin);
  }
  return {median(source), median(pass), median(output), median(twin)};
}

// How far two frames' display values lie apart, in 8-bit steps, over every pixel and colour channel.
struct TwinDifference {
  double mean = 0.0, worst = 0.0;
};
inline TwinDifference displayDifference(const ImageRgba& a, const ImageRgba& b) {
  TwinDifference d;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double step = std::abs(linearToSrgb(a.at(x, y)[c]) - linearToSrgb(b.at(x, y)[c])) * 255.0;
        d.worst = std::max(d.worst, step), d.mean += step;
      }
  d.mean /= 3.0 * a.width * a.height;
  return d;
}

}  // namespace vitrine::test
