#pragma once
// The images and buffers a scene declares instead of creating. An image: by format, usage, mip count
// and a size relative to its render target (1, 1/2, 1/4 ...) or absolute (a 96^3 lattice, a 1024^2
// atlas), single, as a ping-pong pair or as a history pair (this frame's and last frame's). A buffer:
// by usage and a size in bytes, absolute or per pixel of the target (a visibility buffer), single, a
// ping-pong pair or one per frame in flight (CPU-written or read back), with initial bytes or a
// word to clear it to. The host creates them, recreates relative ones on resize and redeclared ones
// at once (the old ones are retired, never waited for), uploads initial data, flips history pairs
// each frame and clears a history pair after it is (re)created, reporting it invalid for that frame.
#include "gpu/resources.h"
#include "gpu/stream.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace vitrine::gpu {

struct ImageSize {
  float scale = 1.0f;       // relative: the target's extent times this
  VkExtent3D extent{0, 0, 0};  // absolute when width > 0
  static ImageSize relative(float scale) { return {scale, {0, 0, 0}}; }
  static ImageSize absolute(uint32_t w, uint32_t h, uint32_t d = 1) { return {1.0f, {w, h, d}}; }
  bool isRelative() const { return extent.width == 0; }
};

enum class Pairing {
  Single,
  PingPong,  // two the scene flips between (iterative passes: read one, write the other)
  History,   // images: flipped by the host each frame: current() is this frame's, previous() last frame's
  PerFrame,  // buffers: one per frame in flight, current() the one of the frame being recorded
};

struct ImageDecl {
  std::string name;
  VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT;
  VkImageUsageFlags usage = 0;
  ImageSize size;
  uint32_t mips = 1;  // 0: full chain
  Pairing pairing = Pairing::Single;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  std::vector<std::byte> initial;  // level-0 texels uploaded at creation (absolute sizes)
  ImageUse initialUse = use::ComputeSample;  // where an uploaded image is left
  bool state = false;  // simulation state a checkpoint saves and restores (download, restore)
  bool zeroed = false;  // cleared to zero at creation: for images too big to upload from the CPU
  // A second format that storage writes see (Image::storageView): e.g. R32_UINT over a packed unorm
  // format, so a shader writes the texels' bits with a rounding it chooses rather than the driver's.
  VkFormat storageFormat = VK_FORMAT_UNDEFINED;
};

struct ImageHandle {
  uint32_t index = ~0u;
};

struct BufferSize {
  VkDeviceSize bytes = 0;     // absolute
  VkDeviceSize perPixel = 0;  // relative: this many bytes per pixel of the target
  static BufferSize absolute(VkDeviceSize bytes) { return {bytes, 0}; }
  static BufferSize relative(VkDeviceSize bytesPerPixel) { return {0, bytesPerPixel}; }
  bool isRelative() const { return perPixel > 0; }
};

struct BufferDecl {
  std::string name;
  BufferSize size;
  VkBufferUsageFlags usage = 0;
  Pairing pairing = Pairing::Single;
  MemoryUse memory = MemoryUse::Device;
  std::vector<std::byte> initial;  // uploaded at creation (a prefix of the buffer)
  bool clear = false;              // else every 32-bit word set to clearValue at creation
  uint32_t clearValue = 0;
  BufferUse initialUse = use::ComputeReadBuffer;  // where initial contents leave it
  bool state = false;  // simulation state a checkpoint saves and restores (download, restore)
};

struct BufferHandle {
  uint32_t index = ~0u;
};

class FrameResources {
 public:
  // Destroying the set destroys its images at once: its owner retires the whole set (a scene switch)
  // until the frames that used it have finished.
  explicit FrameResources(const Device& device) : device_(device) {}
  FrameResources(const FrameResources&) = delete;
  FrameResources& operator=(const FrameResources&) = delete;

  // Absolute images exist at once; relative ones from the next resize on.
  ImageHandle declare(ImageDecl decl);
  // Replaces a declaration (a lattice size changed): the old images are retired. Declare and
  // redeclare images with initial data, and history pairs, in a scene's constructor or update(): they
  // are uploaded or cleared as the next frame begins, and using one before that is an error.
  void redeclare(ImageHandle handle, ImageDecl decl);

  // Buffers, likewise: absolute ones exist at once, relative ones from the next resize on; a
  // redeclared buffer (a size that follows a parameter) is recreated at once, the old one retired.
  BufferHandle declare(BufferDecl decl);
  void redeclare(BufferHandle handle, BufferDecl decl);
  Buffer& current(BufferHandle handle);   // Single: the buffer. PingPong: the one to read. PerFrame: this frame's
  Buffer& previous(BufferHandle handle);  // PingPong: the one to write
  void flip(BufferHandle handle);         // PingPong: swaps current and previous

  // Checkpoints (frame/state_archive.h), for images and buffers declared with `state`: download reads
  // the current() one's level-0 contents back, waiting for the device (between frames, never while
  // recording); restore replaces them as the next frame begins, after any initial upload, and its
  // size must be the whole image's or buffer's.
  std::vector<std::byte> download(ImageHandle handle);
  std::vector<std::byte> download(BufferHandle handle);
  void restore(ImageHandle handle, std::vector<std::byte> contents);
  void restore(BufferHandle handle, std::vector<std::byte> contents);

  // Host: how many frames may be in flight (PerFrame buffers), before any buffer is declared.
  void setFramesInFlight(uint32_t frames) { framesInFlight_ = frames; }
  // Host: the scene's target has this extent; recreates relative images and buffers whose size changed.
  void resize(VkExtent2D target);
  // Host, first thing in a frame: initial uploads, history flips and clears.
  void beginFrame(VkCommandBuffer cmd, StreamArena& stream, uint32_t slot = 0);

  Image& current(ImageHandle handle);   // Single: the image. PingPong: the one to read. History: this frame's
  Image& previous(ImageHandle handle);  // PingPong: the one to write. History: last frame's
  void flip(ImageHandle handle);        // PingPong: swaps current and previous
  // History: false in the frame after (re)creation, when previous() holds zeros rather than last frame.
  bool historyValid(ImageHandle handle) const;
  VkExtent3D extent(ImageHandle handle) const;

 private:
  struct Entry {
    ImageDecl decl;
    Image images[2];
    uint32_t front = 0;        // index of current()
    bool fresh = true;         // created since the last beginFrame: upload / clear pending
    bool historyValid = false;
    std::vector<std::byte> restored;  // contents for current(), uploaded as the next frame begins
  };
  struct BufferEntry {
    BufferDecl decl;
    std::vector<Buffer> buffers;
    uint32_t front = 0;
    bool fresh = true;
    std::vector<std::byte> restored;  // contents for current(), uploaded as the next frame begins
  };
  void create(Entry& entry, VkExtent2D target);
  void create(BufferEntry& entry, VkExtent2D target);
  // Images and buffers alike: an absolute size is known at once, a relative one once the target's is.
  template <typename E> void createWhenSized(E& entry) {
    if (!entry.decl.size.isRelative() || target_.width > 0) create(entry, target_);
  }
  // declare and redeclare, for images and buffers alike: the new entry's index; the entry redeclared.
  template <typename E> uint32_t declareIn(std::vector<E>& entries, decltype(E::decl) decl) {
    entries.push_back(E{std::move(decl)});
    createWhenSized(entries.back());
    return uint32_t(entries.size() - 1);
  }
  template <typename E> void redeclareIn(std::vector<E>& entries, uint32_t index, decltype(E::decl) decl) {
    E& entry = entries.at(index);
    entry.decl = std::move(decl);
    createWhenSized(entry);
  }
  void beginBuffers(VkCommandBuffer cmd, StreamArena& stream);
  void writeFirstContents(VkCommandBuffer cmd, StreamArena& stream, Entry& entry);
  Entry& ready(ImageHandle handle);
  BufferEntry& ready(BufferHandle handle);
  const Device& device_;
  std::vector<Entry> entries_;
  std::vector<BufferEntry> buffers_;
  VkExtent2D target_{0, 0};
  uint32_t framesInFlight_ = 1, slot_ = 0;
};

}  // namespace vitrine::gpu
