#include "scenes/glass/screen_images.h"

#include <string>
#include <utility>

namespace vitrine::glass {
namespace {

gpu::ImageDecl screenImage(std::string name, VkFormat format, VkImageUsageFlags usage) {
  gpu::ImageDecl decl{std::move(name), format, usage, gpu::ImageSize::relative(1.0f)};
  return decl;
}

}  // namespace

ScreenImages::ScreenImages(gpu::FrameResources& resources) {
  colour = resources.declare(
      screenImage("glass colour", kColourFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT));
  motion = resources.declare(
      screenImage("glass motion", kMotionFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT));
  depth = resources.declare(screenImage("glass depth", kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT));
  auto pair = screenImage("glass history", kColourFormat, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  pair.pairing = gpu::Pairing::History;
  history = resources.declare(pair);
  auto chain = screenImage("glass backdrop", kColourFormat, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  chain.mips = 0;  // the original's LOD rule reads a full chain
  backdrop = resources.declare(chain);
}

}  // namespace vitrine::glass
