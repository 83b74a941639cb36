#pragma once
// The images a scene declares instead of creating: by format, usage, mip count and a size relative to
// its render target (1, 1/2, 1/4 ...) or absolute (a 96^3 lattice, a 1024^2 atlas), single, as a
// ping-pong pair or as a history pair (this frame's and last frame's). The host creates them,
// recreates relative ones on resize (the old ones are retired, never waited for), uploads initial
// data, flips history pairs each frame and clears a history pair after it is (re)created, reporting
// it invalid for that one frame.
#include "gpu/resources.h"
#include "gpu/stream.h"

#include <cstddef>
#include <string>
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
  PingPong,  // two images the scene flips between (iterative passes: read one, write the other)
  History,   // flipped by the host each frame: current() is this frame's, previous() last frame's
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
};

struct ImageHandle {
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

  // Host: the scene's target has this extent; recreates relative images whose size changed.
  void resize(VkExtent2D target);
  // Host, first thing in a frame: initial uploads, history flips and clears.
  void beginFrame(VkCommandBuffer cmd, StreamArena& stream);

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
  };
  void create(Entry& entry, VkExtent2D target);
  Entry& ready(ImageHandle handle);
  const Device& device_;
  std::vector<Entry> entries_;
  VkExtent2D target_{0, 0};
};

}  // namespace vitrine::gpu
