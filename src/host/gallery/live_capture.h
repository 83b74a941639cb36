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
  // `shown` (a transfer source) is the window's picture at its size, `rendered` the size the scene drew
  // it at (written into each frame's metadata): copies it while capturing.
  void record(VkCommandBuffer cmd, uint32_t slot, gpu::Image& shown, VkExtent2D rendered, gpu::PassTimer* timer);
  // Once `slot`'s fence has signalled: hands its copy to the writer.
  void collect(uint32_t slot);
  // "capturing … : 120 frames written, 3 dropped" while it runs, then the count still being written
  // and the final summary, counted from what reached the disk. Only for `scene`, the scene the
  // sequence was taken in; empty before any.
  std::string status(std::string_view scene) const;
  // Once, when a stopped sequence's last frame is on disk (or failed): its summary, for the console.
  std::optional<std::string> takeFinished();

 private:
  struct Frame {
    std::vector<uint16_t> halves;
    VkExtent2D extent{};
    VkExtent2D rendered{};
    std::string scene;
    std::filesystem::path path;
  };
  struct Copy {  // one frame in flight's read-back, kept across frames while the size holds
    std::optional<gpu::Buffer> pixels;
    VkExtent2D extent{};
    VkExtent2D rendered{};
    bool pending = false;
    uint64_t frame = 0;
  };
  void writeLoop();
  std::string summary() const;  // with the mutex held

  const gpu::Device& device_;
  std::filesystem::path root_;
  std::vector<Copy> copies_;
  bool active_ = false;
  std::filesystem::path folder_;  // the sequence being written
  std::string scene_;             // the scene it was taken in
  bool finishedSaid_ = true;      // takeFinished() has reported the last sequence

  mutable std::mutex mutex_;
  uint64_t next_ = 0;             // its next frame number: how many frames it has taken

  std::condition_variable wake_;
  std::deque<Frame> queue_;  // at most kMaxQueued
  uint64_t written_ = 0, dropped_ = 0;
  std::string failure_;  // the first write that failed: capture stops
  bool stopping_ = false;
  std::thread writer_;  // last: started once everything it uses exists
};

}  // namespace vitrine::host
