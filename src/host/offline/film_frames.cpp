#include "host/offline/film_frames.h"

#include "core/error.h"
#include "gpu/barriers.h"
#include "gpu/check.h"
#include "gpu/sync_objects.h"
#include "image/image.h"
#include "image/image_io.h"
#include "shaders/host/film_pack_blocks.h"

#include <fmt/format.h>

#include <chrono>
#include <cstring>

namespace vitrine::host {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Every half-float bit pattern's display values, made by image_io's own conversion so the GPU's bytes
// are the CPU's: the 16-bit value in the low half of each word, the 8-bit one above it.
std::vector<uint32_t> displayTable() {
  constexpr size_t kPatterns = 65536;
  std::vector<uint16_t> bits(kPatterns * 4);
  for (size_t i = 0; i < kPatterns; ++i) bits[i * 4] = bits[i * 4 + 1] = bits[i * 4 + 2] = bits[i * 4 + 3] = uint16_t(i);
  const ImageRgba all = imageFromHalves(uint32_t(kPatterns), 1, bits);
  const std::vector<uint8_t> eight = srgb8(all);
  const std::vector<uint16_t> sixteen = srgb16(all);
  std::vector<uint32_t> table(kPatterns);
  for (size_t i = 0; i < kPatterns; ++i) table[i] = uint32_t(sixteen[i * 4]) | (uint32_t(eight[i * 4]) << 16);
  return table;
}

// Pixels one invocation packs (film_pack.comp): four into three words, one into one, two into three.
uint32_t pixelsPerInvocation(film::DisplayLayout layout) {
  switch (layout) {
    case film::DisplayLayout::Rgb24: return 4;
    case film::DisplayLayout::Bgr0:
    case film::DisplayLayout::Rgb0: return 1;
    case film::DisplayLayout::Rgb48: return 2;
  }
  return 1;
}

}  // namespace

FilmFrames::FilmFrames(const gpu::Device& device, VkExtent2D size, film::DisplayLayout layout, uint32_t slots)
    : device_(device), size_(size), layout_(layout),
      groups_(uint32_t((uint64_t(size.width) * size.height + pixelsPerInvocation(layout) - 1) / pixelsPerInvocation(layout))),
      byteCount_(size_t(groups_) * (pixelsPerInvocation(layout) == 1 ? 4 : 12)),
      programs_(device), program_(programs_, "host/film_pack.comp"),
      table_(device, 65536 * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
             gpu::MemoryUse::Device, "film display table"),
      packed_(device, byteCount_, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
              gpu::MemoryUse::Device, "film packed frame"),
      pool_(gpu::createCommandPool(device, VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, "film frames pool")) {
  {
    const std::vector<uint32_t> table = displayTable();
    gpu::Buffer upload(device, table.size() * sizeof(uint32_t), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUse::Upload,
                       "film display table upload");
    std::memcpy(upload.mapped(), table.data(), table.size() * sizeof(uint32_t));
    device.submitNow([&](VkCommandBuffer cmd) {
      upload.use(cmd, gpu::use::TransferSrcBuffer);
      table_.use(cmd, gpu::use::TransferDstBuffer);
      const VkBufferCopy region{0, 0, table.size() * sizeof(uint32_t)};
      vkCmdCopyBuffer(cmd, upload.handle(), table_.handle(), 1, &region);
      table_.use(cmd, gpu::use::ComputeReadBuffer);
    });
  }
  slots_.resize(slots);
  std::vector<VkCommandBuffer> cmds(slots);
  const VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr, pool_,
                                          VK_COMMAND_BUFFER_LEVEL_PRIMARY, slots};
  VK_CHECK(vkAllocateCommandBuffers(device, &alloc, cmds.data()));
  for (uint32_t i = 0; i < slots; ++i) {
    slots_[i].bytes = gpu::Buffer(device, byteCount_, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback,
                                  fmt::format("film frame {}", i));
    slots_[i].cmd = cmds[i];
    device.name(cmds[i], VK_OBJECT_TYPE_COMMAND_BUFFER, fmt::format("film frame {}", i));
  }
}

FilmFrames::~FilmFrames() { vkDeviceWaitIdle(device_); }

uint32_t FilmFrames::pack(gpu::Image& frame) {
  const uint32_t index = uint32_t(next_);
  Slot& slot = slots_[index];
  {
    const auto start = Clock::now();
    std::unique_lock lock(mutex_);
    freed_.wait(lock, [&] { return !slot.busy; });
    slot.busy = true;
    slotWaits_ += since(start);
  }
  next_ = (next_ + 1) % slots_.size();
  VK_CHECK(vkResetCommandBuffer(slot.cmd, 0));
  const VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, nullptr,
                                       VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  VK_CHECK(vkBeginCommandBuffer(slot.cmd, &begin));
  frame.use(slot.cmd, gpu::use::ComputeRead);
  packed_.use(slot.cmd, gpu::use::ComputeWriteBuffer);
  program_.bind(slot.cmd);
  program_.push(slot.cmd, gpu::Bindings()
                              .storageImage("frame", frame.view())
                              .storageBuffer("SrgbTable", table_.handle())
                              .storageBuffer("Packed", packed_.handle()));
  program_.constants(slot.cmd, shader::HostFilmPackPush{size_.width, size_.height, uint32_t(layout_), groups_});
  program_.dispatchOver(slot.cmd, groups_);
  packed_.use(slot.cmd, gpu::use::TransferSrcBuffer);
  slot.bytes.use(slot.cmd, gpu::use::TransferDstBuffer);
  const VkBufferCopy region{0, 0, byteCount_};
  vkCmdCopyBuffer(slot.cmd, packed_.handle(), slot.bytes.handle(), 1, &region);
  slot.bytes.use(slot.cmd, gpu::use::HostReadBuffer);
  VK_CHECK(vkEndCommandBuffer(slot.cmd));
  slot.serial = device_.submit({slot.cmd, {}, {}});
  return index;
}

std::span<const std::byte> FilmFrames::bytes(uint32_t index) {
  Slot& slot = slots_[index];
  const auto start = Clock::now();
  device_.wait(slot.serial);
  copyWaits_ += since(start);
  slot.bytes.invalidate();
  return {static_cast<const std::byte*>(slot.bytes.mapped()), byteCount_};
}

void FilmFrames::release(uint32_t index) {
  {
    std::lock_guard lock(mutex_);
    slots_[index].busy = false;
  }
  freed_.notify_all();
}

}  // namespace vitrine::host
