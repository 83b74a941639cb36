#pragma once
// The shape the settings choose, at a moment of the scene's clock: its dimensions (the plate's waves
// move), its rotation and how many instances of it stand in the view.
#include "scenes/glass/settings.h"
#include "scenes/glass/shapes.h"
#include "shaders/glass/frame_block.h"

#include <glm/mat3x3.hpp>

namespace vitrine::glass {

// The most instances shown at once: the frame block holds each one's place.
inline constexpr int kMaxInstances = GLASS_MAX_INSTANCES;

ShapeDims shapeDims(const Settings& settings, double time);
// World -> object; the pill and the prism do not turn.
glm::mat3 shapeRotation(const Settings& settings, double time);
// The diamond stands alone; the other shapes come kMaxInstances at a time.
int instanceCount(ShapeKind shape);

}  // namespace vitrine::glass
