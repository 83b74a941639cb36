#include "scenes/glass/scene_shape.h"

namespace vitrine::glass {

ShapeDims shapeDims(const Settings& settings, double time) {
  const Settings& s = settings;
  switch (s.shape) {
    case ShapeKind::Pill:
      return pillDims({s.pillLength, s.pillHeight, s.pillThickness}, s.pillEdge, s.smoothCurvature);
    case ShapeKind::Prism:
      return prismDims({s.prismLength, s.prismWidth, s.prismDepth});
    case ShapeKind::Cube:
      return cubeDims(s.cubeSize, s.cubeEdge, s.smoothCurvature);
    case ShapeKind::Plate:
      return plateDims({s.plateSize, s.plateSize, s.plateThickness}, s.plateEdge, s.waveAmplitude, s.waveLength,
                       plateWavePhase(float(time)), s.smoothCurvature);
    case ShapeKind::Diamond:
      break;
  }
  return diamondDims(s.diamondSize);
}

glm::mat3 shapeRotation(const Settings& settings, double time) {
  switch (settings.shape) {
    case ShapeKind::Cube: return cubeRotation(float(time));
    case ShapeKind::Plate: return plateRotation(float(time));
    case ShapeKind::Diamond: return diamondRotation(settings.diamondView, float(time));
    default: return glm::mat3(1.0f);
  }
}

int instanceCount(ShapeKind shape) { return shape == ShapeKind::Diamond ? 1 : kMaxInstances; }

}  // namespace vitrine::glass
