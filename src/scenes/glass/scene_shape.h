#pragma once
// The shape the settings choose, at a moment of the scene's clock: its dimensions (the plate's waves
// move), its rotation and how many instances of it stand in the view.
#include "scenes/glass/settings.h"
#include "scenes/glass/shapes.h"

#include <glm/mat3x3.hpp>

namespace vitrine::glass {

ShapeDims shapeDims(const Settings& settings, double time);
// World -> object; the pill and the prism do not turn.
glm::mat3 shapeRotation(const Settings& settings, double time);
// The diamond stands alone; the other shapes come four at a time (frame_block.h's kMaxInstances).
int instanceCount(ShapeKind shape);

}  // namespace vitrine::glass
