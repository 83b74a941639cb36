#include "scenes/glass/diamond_buffers.h"

#include "scenes/glass/diamond.h"
#include "shaders/glass/diamond_blocks.h"

#include <span>
#include <utility>
#include <vector>

namespace vitrine::glass {
namespace {

template <typename T> std::vector<std::byte> bytesOf(std::span<const T> values) {
  const auto bytes = std::as_bytes(values);
  return {bytes.begin(), bytes.end()};
}

// The cut is the same at every size, only scaled: a new size changes the contents, never the counts.
struct DiamondDecls {
  gpu::BufferDecl planes, hull;
  uint32_t hullVertices = 0;
};

DiamondDecls diamondDecls(float size) {
  const DiamondGeometry stone = makeDiamond(size);
  const shader::GlassDiamond block = diamondBlock(stone);
  std::vector<shader::GlassHullVertex> hull;
  for (const glm::vec3& corner : diamondHullTriangles(stone)) hull.push_back({corner, 0.0f});
  DiamondDecls decls;
  decls.planes = {.name = "glass diamond planes",
                  .size = gpu::BufferSize::absolute(sizeof(block)),
                  .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                  .initial = bytesOf(std::span(&block, 1)),
                  .initialUse = gpu::use::FragmentReadBuffer};
  decls.hull = {.name = "glass diamond hull",
                .size = gpu::BufferSize::absolute(hull.size() * sizeof(shader::GlassHullVertex)),
                .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                .initial = bytesOf(std::span<const shader::GlassHullVertex>(hull)),
                .initialUse = gpu::use::VertexReadBuffer};
  decls.hullVertices = uint32_t(hull.size());
  return decls;
}

}  // namespace

DiamondBuffers::DiamondBuffers(gpu::FrameResources& resources, float size) : resources_(resources), size_(size) {
  DiamondDecls decls = diamondDecls(size);
  planes_ = resources_.declare(std::move(decls.planes));
  hull_ = resources_.declare(std::move(decls.hull));
  hullVertices_ = decls.hullVertices;
}

void DiamondBuffers::resize(float size) {
  if (size == size_) return;
  DiamondDecls decls = diamondDecls(size);
  resources_.redeclare(planes_, std::move(decls.planes));
  resources_.redeclare(hull_, std::move(decls.hull));
  hullVertices_ = decls.hullVertices;
  size_ = size;
}

}  // namespace vitrine::glass
