#include "rig/dmabuf_pool.h"

#include <algorithm>
#include <utility>

#include "gpu/dmabuf_export.h"

namespace vitrine::rig {

DmaBufPool::DmaBufPool(std::function<void()> wake) : wake_(std::move(wake)) {}

DmaBufPool::~DmaBufPool() = default;

DmaBufPool::Slot* DmaBufPool::find(const void* key) {
  for (Slot& slot : slots_)
    if (slot.key == key) return &slot;
  return nullptr;
}

void DmaBufPool::add(const void* key, std::unique_ptr<gpu::ExportedImage> image, VkExtent2D extent, VkFormat format) {
  std::lock_guard guard(lock_);
  const VkImage handle = image ? image->handle() : VK_NULL_HANDLE;
  slots_.push_back({key, nextId_++, std::move(image), handle, extent, format});
}

void DmaBufPool::remove(const void* key) {
  std::lock_guard guard(lock_);
  const auto it = std::find_if(slots_.begin(), slots_.end(), [&](const Slot& slot) { return slot.key == key; });
  if (it == slots_.end()) return;
  if (it->image) removed_.push_back(std::move(it->image));
  slots_.erase(it);
}

void DmaBufPool::given(const void* key) {
  std::lock_guard guard(lock_);
  if (Slot* slot = find(key); slot && slot->state == State::Consumer) slot->state = State::Free;
}

std::optional<DmaBufPool::Done> DmaBufPool::takeDone(uint64_t& superseded) {
  std::lock_guard guard(lock_);
  Slot* newest = nullptr;
  for (Slot& slot : slots_) {
    if (slot.state != State::Done) continue;
    if (newest && newest->index > slot.index) {
      slot.state = State::Free;
      ++superseded;
      continue;
    }
    if (newest) {
      newest->state = State::Free;
      ++superseded;
    }
    newest = &slot;
  }
  if (!newest) return std::nullopt;
  newest->state = State::Consumer;
  return Done{newest->key, newest->index, newest->time};
}

void DmaBufPool::setActive(bool active) {
  std::lock_guard guard(lock_);
  active_ = active;
}

size_t DmaBufPool::size() const {
  std::lock_guard guard(lock_);
  return slots_.size();
}

bool DmaBufPool::active() const {
  std::lock_guard guard(lock_);
  return active_ && !slots_.empty();
}

std::optional<host::ImageHandOver::Target> DmaBufPool::take(VkExtent2D extent) {
  {
    std::lock_guard guard(lock_);
    Slot* chosen = nullptr;
    for (Slot& slot : slots_) {
      if (slot.state == State::Taken) slot.state = State::Free;  // taken by a frame that was not copied
      if (!chosen && slot.state == State::Free && slot.extent.width == extent.width &&
          slot.extent.height == extent.height)
        chosen = &slot;
    }
    if (chosen) {
      chosen->state = State::Taken;
      return Target{chosen->handle, chosen->extent, chosen->format, chosen->id};
    }
  }
  // None free: buffers the consumer gave back are only seen by PipeWire's thread, in a cycle it runs.
  if (wake_) wake_();
  return std::nullopt;
}

void DmaBufPool::submitted(uint64_t id, uint64_t serial, uint64_t index, double time) {
  std::lock_guard guard(lock_);
  for (Slot& slot : slots_)
    if (slot.id == id && slot.state == State::Taken) {
      slot.state = State::Copying;
      slot.serial = serial;
      slot.index = index;
      slot.time = time;
    }
}

bool DmaBufPool::markFinished(uint64_t completed) {
  bool done = false;
  {
    std::lock_guard guard(lock_);
    for (Slot& slot : slots_)
      if (slot.state == State::Copying && slot.serial <= completed) {
        slot.state = State::Done;
        done = true;
      }
  }
  if (done && wake_) wake_();
  return done;
}

void DmaBufPool::finished(uint64_t completed, const gpu::Device& device) {
  markFinished(completed);
  std::vector<std::unique_ptr<gpu::ExportedImage>> retire;
  {
    std::lock_guard guard(lock_);
    retire.swap(removed_);
  }
  for (auto& image : retire) device.retire(std::move(image));
}

}  // namespace vitrine::rig
