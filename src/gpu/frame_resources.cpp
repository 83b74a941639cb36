#include "gpu/frame_resources.h"

#include <fmt/format.h>

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vitrine::gpu {
namespace {

// Bytes a texel of the formats simulation state is kept in (FrameResources::download).
VkDeviceSize formatBytes(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R16_SFLOAT: return 2;
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R16G16_SFLOAT: return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT: return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
    default: throw Error(fmt::format("format {} is not one simulation state is saved in", int(format)));
  }
}

VkImageAspectFlags aspectOf(VkFormat format) {
  switch (format) {
    case VK_FORMAT_D16_UNORM:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_X8_D24_UNORM_PACK32:
      return VK_IMAGE_ASPECT_DEPTH_BIT;
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_D32_SFLOAT_S8_UINT:
      return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    default:
      return VK_IMAGE_ASPECT_COLOR_BIT;
  }
}

VkExtent3D sizeFor(const ImageSize& size, VkExtent2D target) {
  if (!size.isRelative()) return size.extent;
  return {std::max(1u, uint32_t(std::lround(target.width * size.scale))),
          std::max(1u, uint32_t(std::lround(target.height * size.scale))), 1};
}

}  // namespace

ImageHandle FrameResources::declare(ImageDecl decl) { return {declareIn(entries_, std::move(decl))}; }

void FrameResources::redeclare(ImageHandle handle, ImageDecl decl) {
  redeclareIn(entries_, handle.index, std::move(decl));
}

void FrameResources::create(Entry& entry, VkExtent2D target) {
  ImageDesc desc;
  desc.extent = sizeFor(entry.decl.size, target);
  desc.type = desc.extent.depth > 1 ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
  desc.format = entry.decl.format;
  desc.storageFormat = entry.decl.storageFormat;
  desc.usage = entry.decl.usage;
  if (entry.decl.pairing == Pairing::History || entry.decl.zeroed) desc.usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;  // cleared
  if (!entry.decl.initial.empty()) desc.usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (entry.decl.state) desc.usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (entry.decl.mips != 1) desc.usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  desc.samples = entry.decl.samples;
  desc.aspect = aspectOf(entry.decl.format);
  desc.mips = entry.decl.mips;
  const int count = entry.decl.pairing == Pairing::Single ? 1 : 2;
  for (int i = 0; i < 2; ++i) {
    if (entry.images[i]) device_.retire(std::move(entry.images[i]));
    entry.images[i] = {};
    if (i < count)
      entry.images[i] = Image(device_, desc, count == 1 ? entry.decl.name : fmt::format("{} {}", entry.decl.name, i));
  }
  entry.front = 0;
  entry.fresh = true;
  entry.historyValid = false;
  entry.restored.clear();  // meant for the images just retired
}

void FrameResources::resize(VkExtent2D target) {
  if (target.width == target_.width && target.height == target_.height) return;
  target_ = target;
  for (Entry& entry : entries_)
    if (entry.decl.size.isRelative()) create(entry, target);
  for (BufferEntry& entry : buffers_)
    if (entry.decl.size.isRelative()) create(entry, target);
}

void FrameResources::beginFrame(VkCommandBuffer cmd, StreamArena& stream, uint32_t slot) {
  slot_ = slot % framesInFlight_;
  beginBuffers(cmd, stream);
  for (Entry& entry : entries_) {
    if (!entry.images[0]) continue;  // relative, before the first resize
    const bool history = entry.decl.pairing == Pairing::History;
    if (history && !entry.fresh) {
      entry.front ^= 1u;  // last frame's current is this frame's previous
      entry.historyValid = true;
    }
    if (entry.fresh) writeFirstContents(cmd, stream, entry);
    if (!entry.restored.empty())  // a checkpoint's contents, over the initial ones
      uploadImage(cmd, stream, entry.images[entry.front], std::exchange(entry.restored, {}), entry.decl.initialUse);
  }
}

// A new image's initial texels, or zeros: a history pair's (whose scene is told not to trust them this
// frame) or a zeroed image's.
void FrameResources::writeFirstContents(VkCommandBuffer cmd, StreamArena& stream, Entry& entry) {
  entry.fresh = false;
  if (!entry.decl.initial.empty())
    for (Image& image : entry.images)
      if (image) uploadImage(cmd, stream, image, entry.decl.initial, entry.decl.initialUse);
  if (entry.decl.pairing != Pairing::History && !entry.decl.zeroed) return;
  const VkClearColorValue zero{};
  for (Image& image : entry.images) {
    if (!image) continue;
    image.discard();
    image.use(cmd, use::TransferDst);
    const VkImageSubresourceRange range{image.desc().aspect, 0, VK_REMAINING_MIP_LEVELS, 0, 1};
    vkCmdClearColorImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
  }
  entry.historyValid = false;
}

// An image whose initial texels or clear are still pending holds garbage: a scene that redeclared it
// while recording would read that; say so instead of rendering noise.
FrameResources::Entry& FrameResources::ready(ImageHandle handle) {
  Entry& entry = entries_.at(handle.index);
  if ((entry.fresh && (!entry.decl.initial.empty() || entry.decl.pairing == Pairing::History || entry.decl.zeroed)) ||
      !entry.restored.empty())
    throw Error(fmt::format("{} is used before its initial contents were written: (re)declare it in the scene's "
                            "constructor or update(), not while recording",
                            entry.decl.name));
  return entry;
}

Image& FrameResources::current(ImageHandle handle) {
  Entry& entry = ready(handle);
  return entry.images[entry.front];
}

Image& FrameResources::previous(ImageHandle handle) {
  Entry& entry = ready(handle);
  if (entry.decl.pairing == Pairing::Single) throw Error(fmt::format("{} is not a pair", entry.decl.name));
  return entry.images[entry.front ^ 1u];
}

std::vector<std::byte> FrameResources::download(ImageHandle handle) {
  Image& image = current(handle);
  if (!entries_.at(handle.index).decl.state)
    throw Error(fmt::format("{} is not declared as simulation state: it cannot be saved", image.name()));
  const VkExtent3D e = image.extent();
  const VkDeviceSize bytes = VkDeviceSize(e.width) * e.height * e.depth * formatBytes(image.format());
  Buffer staging(device_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback, image.name() + " checkpoint");
  device_.submitNow([&](VkCommandBuffer cmd) { recordReadback(cmd, image, staging); });
  staging.invalidate();
  const auto view = staging.view<const std::byte>();
  return {view.begin(), view.end()};
}

void FrameResources::restore(ImageHandle handle, std::vector<std::byte> contents) {
  Entry& entry = entries_.at(handle.index);
  const Image& image = entry.images[entry.front];
  const VkExtent3D e = image.extent();
  if (!entry.decl.state || contents.size() != size_t(e.width) * e.height * e.depth * formatBytes(image.format()))
    throw Error(fmt::format("{}: {} bytes of saved state do not fill it", entry.decl.name, contents.size()));
  entry.restored = std::move(contents);
}

void FrameResources::flip(ImageHandle handle) { entries_.at(handle.index).front ^= 1u; }

bool FrameResources::historyValid(ImageHandle handle) const { return entries_.at(handle.index).historyValid; }

VkExtent3D FrameResources::extent(ImageHandle handle) const { return entries_.at(handle.index).images[0].extent(); }

}  // namespace vitrine::gpu
