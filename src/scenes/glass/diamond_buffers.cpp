#include "scenes/glass/diamond_buffers.h"

#include "scenes/glass/diamond.h"

#include <span>
#include <vector>

namespace vitrine::glass {

void DiamondBuffers::update(const FrameContext& frame, float size) {
  if (planes_ && size == builtSize_) return;
  const DiamondGeometry diamond = makeDiamond(size);
  const std::vector<glm::vec4> planes = diamondBufferWords(diamond);
  std::vector<glm::vec4> hull;
  for (const glm::vec3& v : diamondHullTriangles(diamond)) hull.emplace_back(v, 1.0f);
  if (!planes_) {
    // Sized on the first frame: the cut is the same at every size, only scaled, so the counts never change.
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    planes_.emplace(frame.device, planes.size() * sizeof(glm::vec4), usage, gpu::MemoryUse::Device,
                    "glass diamond planes");
    hull_.emplace(frame.device, hull.size() * sizeof(glm::vec4), usage, gpu::MemoryUse::Device, "glass diamond hull");
  }
  frame.upload(*planes_, 0, std::as_bytes(std::span(planes)), gpu::use::FragmentReadBuffer);
  frame.upload(*hull_, 0, std::as_bytes(std::span(hull)), gpu::use::VertexReadBuffer);
  hullVertices_ = uint32_t(hull.size());
  builtSize_ = size;
}

}  // namespace vitrine::glass
