#include "scenes/glass/instances.h"

#include "maths/hash.h"
#include "scenes/glass/scene_shape.h"

#include <algorithm>
#include <cmath>

namespace vitrine::glass {
namespace {

// How far `offset` from an instance's centre lies within its grab area (1 at the rim): its silhouette's
// rough extent, a circle for the shapes that tumble (cube, plate, diamond).
float hitRadius(ShapeKind shape, const ShapeDims& dims, glm::vec2 offset) {
  const glm::vec3 half = shapeHalfExtent(dims);
  if (shape == ShapeKind::Cube || shape == ShapeKind::Diamond || shape == ShapeKind::Plate)
    return glm::length(offset) / std::max(half.x, half.y);
  return std::max(std::abs(offset.x) / half.x, std::abs(offset.y) / half.y);
}

}  // namespace

void Instances::layOut(ShapeKind shape, glm::vec2 view) {
  laidOut_ = shape;
  if (instanceCount(shape) == 1) {
    instances_[0] = {{0.0f, 0.0f}, {0.0f, 0.0f}};
    return;
  }
  const glm::vec2 spread{std::min(0.22f * view.x, 300.0f), 0.2f * view.y};
  const glm::vec2 at[kMaxInstances] = {{-1, 1}, {1, 1}, {-1, -1}, {1, -1}};
  for (int i = 0; i < kMaxInstances; ++i) instances_[i].centre = instances_[i].previous = at[i] * spread;
}

void Instances::shuffle(ShapeKind shape, const ShapeDims& dims, glm::vec2 view, uint32_t seed) {
  // A turning shape reaches as far as its box's half diagonal; pill and prism keep their box.
  const glm::vec3 half = shapeHalfExtent(dims);
  const bool turns = shape != ShapeKind::Pill && shape != ShapeKind::Prism;
  const glm::vec2 reach = turns ? glm::vec2(glm::length(half)) : glm::vec2(half);
  const glm::vec2 room = glm::max(view * 0.5f - reach, glm::vec2(0.0f));
  ++shuffles_;
  for (int i = 0; i < instanceCount(shape); ++i) {
    glm::vec2 best{0.0f};
    for (uint32_t attempt = 0; attempt < 64; ++attempt) {
      const glm::uvec3 key{seed, shuffles_ * 97u + uint32_t(i), attempt};
      best = (glm::vec2(maths::hash01(key), maths::hash01(key + glm::uvec3(0, 0, 7919u))) * 2.0f - 1.0f) * room;
      bool apart = true;
      for (int j = 0; j < i; ++j)
        apart = apart && glm::length(best - instances_[j].centre) > 2.0f * std::max(reach.x, reach.y);
      if (apart) break;
    }
    instances_[i].centre = best;
  }
}

void Instances::drag(const CursorInput& cursor, ShapeKind shape, const ShapeDims& dims, glm::vec2 view) {
  const glm::vec2 at = (cursor.normalized - 0.5f) * glm::vec2(1.0f, -1.0f) * view;
  if (cursor.dragging && !wasDragging_) {
    dragged_ = -1;
    float nearest = 1.0f;
    for (int i = 0; i < instanceCount(shape); ++i) {
      const float r = hitRadius(shape, dims, at - instances_[i].centre);
      if (r <= nearest) nearest = r, dragged_ = i;
    }
  }
  if (!cursor.dragging) dragged_ = -1;
  wasDragging_ = cursor.dragging;
  if (dragged_ >= 0) instances_[size_t(dragged_)].centre += cursor.dragDelta * glm::vec2(1.0f, -1.0f) * view;
}

void Instances::beginFrame() {
  for (Instance& instance : instances_) instance.previous = instance.centre;
}

bool Instances::moved() const {
  return std::any_of(instances_.begin(), instances_.end(),
                     [](const Instance& instance) { return instance.centre != instance.previous; });
}

}  // namespace vitrine::glass
