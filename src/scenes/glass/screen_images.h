#pragma once
// The images the size of the view that the glass passes hand to one another: the spectral pass writes
// colour and motion (and depth on the raster path), the resolve pass folds them into the history, and
// the compose pass lays the backdrop they all refract. The host resizes them with the view.
#include "gpu/frame_resources.h"

namespace vitrine::glass {

inline constexpr VkFormat kColourFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kMotionFormat = VK_FORMAT_R16G16_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

struct ScreenImages {
  explicit ScreenImages(gpu::FrameResources& resources);

  gpu::ImageHandle colour;    // the glass's light; alpha 1 where glass covers
  gpu::ImageHandle motion;    // where each glass pixel's surface point was last frame
  gpu::ImageHandle depth;     // the raster path's: overlapping instances sort
  gpu::ImageHandle history;   // the running average; a pair, so last frame's is read as this one is written
  gpu::ImageHandle backdrop;  // what the glass refracts, with a full mip chain
};

}  // namespace vitrine::glass
