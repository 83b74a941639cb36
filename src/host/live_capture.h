#pragma once
// F9 in the gallery: every frame the scene draws, written as a numbered EXR sequence while it runs
// (a performance, a drag, a phone playing it), beside the screenshots. The copy is recorded in the
// frame's own command buffer like a screenshot's; the files are written by a worker thread so the
// frame loop never waits on a disk. When the disk cannot keep up, frames are dropped and counted
// rather than queued without bound: for a film at a fixed rate, `vitrine record` is the tool.
#include "gpu/pass_timer.h"
#include "gpu/resources.h"

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace vitrine::host {

class LiveCapture {
 public:
  LiveCapture(const gpu::Device& device, uint32_t framesInFlight, std::filesystem::path folder);
  ~LiveCapture();  // writes what is queued
  LiveCapture(const LiveCapture&) = delete;
  LiveCapture& operator=(const LiveCapture&) = delete;

  // Starts a new sequence in FOLDER/vitrine-<scene>-<time>/, or stops the one running; says what happened.
  std::string toggle(std::string_view scene);
  bool active() const { return active_; }
  // After the scene renderer, which leaves `target` a transfer source: copies it while capturing.
  void record(VkCommandBuffer cmd, uint32_t slot, gpu::Image& target, gpu::PassTimer* timer);
  // Once `slot`'s fence has signalled: hands its copy to the writer.
  void collect(uint32_t slot);
  // "capturing … : 120 frames written, 3 dropped", or the last sequence's summary; empty before any.
  std::string status() const;

 private:
  struct Frame {
    std::vector<uint16_t> halves;
    VkExtent2D extent{};
    std::filesystem::path path;
  };
  struct Copy {  // one frame in flight's read-back, kept across frames while the size holds
    std::optional<gpu::Buffer> pixels;
    VkExtent2D extent{};
    bool pending = false;
    uint64_t frame = 0;
  };
  void writeLoop();

  const gpu::Device& device_;
  std::filesystem::path root_;
  std::vector<Copy> copies_;
  bool active_ = false;
  std::filesystem::path folder_;  // the sequence being written
  uint64_t next_ = 0;             // its next frame number

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Frame> queue_;  // at most kMaxQueued
  uint64_t written_ = 0, dropped_ = 0;
  std::string failure_;  // the first write that failed: capture stops
  bool stopping_ = false;
  std::thread writer_;  // last: started once everything it uses exists
};

}  // namespace vitrine::host
