#pragma once
// Where the glass instances stand, in world units (world_view.h: the view's centre at 0, y up): their
// opening places, a seeded shuffle, and the drag that carries the one under the cursor. Each keeps
// last frame's centre as well, from which the resolve pass reprojects the history.
#include "scenes/glass/scene_shape.h"
#include "scenes/glass/shapes.h"
#include "scenes/scene.h"

#include <array>

namespace vitrine::glass {

struct Instance {
  glm::vec2 centre{0.0f}, previous{0.0f};
};

class Instances {
 public:
  // The opening places of `shape` in a view `view` world units wide and high: the diamond in the
  // middle, the other shapes at the corners of a square.
  void layOut(ShapeKind shape, glm::vec2 view);
  ShapeKind laidOut() const { return laidOut_; }
  // Random places inside the view, kept apart where the view has room; the same for the same seed.
  void shuffle(ShapeKind shape, const ShapeDims& dims, glm::vec2 view, uint32_t seed);
  // Grabs the instance under the cursor as a drag begins and moves it with the cursor until it ends.
  void drag(const CursorInput& cursor, ShapeKind shape, const ShapeDims& dims, glm::vec2 view);

  // A new frame: where each stands now is where it stood last frame.
  void beginFrame();
  bool moved() const;  // since beginFrame()
  const std::array<Instance, kMaxInstances>& all() const { return instances_; }

 private:
  std::array<Instance, kMaxInstances> instances_{};
  ShapeKind laidOut_ = ShapeKind::Cube;
  int dragged_ = -1;
  bool wasDragging_ = false;
  uint32_t shuffles_ = 0;
};

}  // namespace vitrine::glass
