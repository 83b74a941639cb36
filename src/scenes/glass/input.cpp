#include "scenes/glass/input.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <filesystem>
#include <string_view>
#include <utility>

namespace vitrine::glass {

KeyRequests readKeys(const FrameInput& input) {
  auto acted = [&](std::string_view name) {
    return std::any_of(input.actions.begin(), input.actions.end(), [&](const ActionCall& c) { return c.name == name; });
  };
  KeyRequests requests;
  requests.shuffle = input.pressed(GLFW_KEY_SPACE) || acted("shuffle");
  requests.nextPhoto = input.pressed(GLFW_KEY_R) || acted("next_photo");
  const std::pair<int, DiamondView> views[] = {{GLFW_KEY_T, DiamondView::Top}, {GLFW_KEY_S, DiamondView::Side},
                                               {GLFW_KEY_B, DiamondView::Bottom}, {GLFW_KEY_F, DiamondView::Free}};
  for (const auto& [key, view] : views)
    if (input.pressed(key)) requests.diamondView = view;
  requests.zHeld = input.held(GLFW_KEY_Z);
  return requests;
}

void applyDiamondView(const KeyRequests& keys, Settings& settings) {
  if (!keys.diamondView) return;
  settings.shape = ShapeKind::Diamond;
  settings.diamondView = *keys.diamondView;
}

void takeDroppedFiles(const FrameInput& input, Settings& settings) {
  for (const std::string& path : input.droppedFiles) {
    const bool exr = std::filesystem::path(path).extension() == ".exr";
    if (exr && settings.environment) settings.panorama = path;
    else settings.background = path;
  }
}

}  // namespace vitrine::glass
