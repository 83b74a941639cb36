#pragma once
// The render pass that draws every segment as an instanced 8-sided tube: reverse-Z depth, optional
// 4x MSAA resolved into the scene's target. Its depth and multisampled colour images are declared
// with the host at the target's size; only a change of sample count redeclares them.
#include "gpu/program.h"
#include "gpu/resources.h"
#include "scenes/noodles/palette.h"
#include "scenes/noodles/strand_layout.h"
#include "scenes/scene.h"

#include <glm/mat4x4.hpp>

namespace vitrine::noodles {

struct TubeView {
  glm::mat4 viewProjection;
  glm::vec3 eye;
  float radius;
  Colouring colouring;
  bool stripe;
  bool msaa;
};

inline constexpr uint32_t kTubeStripVertices = 16;  // 8 sides: two rings of 8, one side left out
inline constexpr glm::vec3 kBackground{0.01f, 0.01f, 0.014f};  // the write-up's clear colour, linear

class TubePass {
 public:
  explicit TubePass(const SceneContext& context);
  void record(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes, const TubeView& view);

 private:
  gpu::FrameResources& resources_;
  gpu::GraphicsProgram single_;
  gpu::GraphicsProgram multisampled_;
  VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_4_BIT;
  gpu::ImageHandle depth_;
  gpu::ImageHandle colour_;  // multisampled; a 1x1 stand-in without MSAA
};

}  // namespace vitrine::noodles
