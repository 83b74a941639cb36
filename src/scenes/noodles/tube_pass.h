#pragma once
// The render pass that draws every segment as an instanced 8-sided tube: reverse-Z depth, optional
// 4x MSAA resolved into the scene's target. Owns its depth and multisampled colour images, sized to
// the target and rebuilt only when the size or the sample count changes.
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
  TubePass(const gpu::Device& device, gpu::ProgramLibrary& programs);
  void record(VkCommandBuffer cmd, const RenderTarget& target, const StrandLayout& layout, VkBuffer nodes,
              const TubeView& view);

 private:
  void ensureAttachments(VkExtent2D extent, VkSampleCountFlagBits samples);

  const gpu::Device& device_;
  gpu::GraphicsProgram single_;
  gpu::GraphicsProgram multisampled_;
  gpu::Image depth_;
  gpu::Image colour_;  // multisampled; empty without MSAA
};

}  // namespace vitrine::noodles
