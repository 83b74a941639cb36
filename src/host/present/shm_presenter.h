#pragma once
// Frames to an X11 window through MIT-SHM, for software devices (lavapipe), in place of Vulkan's
// swapchain. Mesa's software swapchain (22.3, Debian 12's) waits in vkQueuePresentKHR for the queue to
// drain and then sends the image through the X socket from the calling thread, so the CPU "GPU" idles
// while the image travels and the X server copies it in (docs/PERFORMANCE.md: 19 % of a 2-core
// machine idle, 15 % in Xvfb). Here each frame ends with a copy of its image into a mapped buffer; a
// thread of its own waits for that copy, puts the pixels into a shared-memory segment and asks the X
// server to draw them, while the next frame renders. The images are ordinary ones of the device,
// written as a swapchain's are (B8G8R8A8_UNORM through compute, the overlay's render pass last). With
// vsync on, the thread shows at most a frame a refresh, which paces the frame loop as FIFO would.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "gpu/device.h"
#include "gpu/resources.h"

struct GLFWwindow;

namespace vitrine::host {

class ShmPresenter {
 public:
  static constexpr VkFormat kFormat = VK_FORMAT_B8G8R8A8_UNORM;  // an X TrueColor pixel of depth 24, in memory order

  // Null, with the reason in `why`, where this cannot work: not a CPU device, no X11 window, no MIT-SHM
  // on the display, a visual that is not 24-bit BGRX, or VITRINE_PRESENT=swapchain.
  static std::unique_ptr<ShmPresenter> create(const gpu::Device& device, GLFWwindow* window, std::string* why);
  ~ShmPresenter();

  // Waits for the frames on their way to the window, retires the images and makes new ones. An empty
  // string, or why the window cannot be drawn through shared memory at this size (the presenter then
  // holds no images until a build at a size that fits).
  std::string build(VkExtent2D extent);
  VkExtent2D extent() const { return extent_; }
  uint32_t imageCount() const { return uint32_t(slots_.size()); }
  VkImage image(uint32_t index) const { return slots_[index].image.handle(); }
  VkImageView view(uint32_t index) const { return slots_[index].image.view(); }

  // The next image whose last frame has reached the window (waiting for it if need be); `acquired`
  // is signalled by an empty submission, as a swapchain's acquire would.
  uint32_t acquire(VkSemaphore acquired);
  // Copies the image to its buffer once `renderFinished` is signalled, and hands it to the thread.
  void present(uint32_t index, VkSemaphore renderFinished);
  // Vsync: the thread shows at most a frame an `interval` (the display's refresh), so the frame loop waits
  // for a free image as it would for a FIFO swapchain's; zero shows each frame as soon as it is ready.
  void pace(std::chrono::nanoseconds interval) { interval_ = interval.count(); }

 private:
  struct Connection;  // the thread's own X connection, window, graphics context and shared segment
  ShmPresenter(const gpu::Device& device, std::unique_ptr<Connection> connection);
  struct Slot {
    gpu::Image image;
    gpu::Buffer pixels;  // the image's texels, row after row, for the thread to read
    VkCommandBuffer copy = VK_NULL_HANDLE;
    bool free = true;  // not on its way to the window
  };
  struct Job {
    uint32_t slot;
    uint64_t copied;  // the device serial of the copy
    VkExtent2D extent;
  };
  void run();                    // the thread
  void copyOut(const Job& job);  // waits for the job's copy and puts its pixels in the shared segment
  void drain();                  // until every job handed over has reached the window
  void waitForTurn();            // vsync's pace (pace())

  const gpu::Device& device_;
  std::unique_ptr<Connection> connection_;
  gpu::Unique<VkCommandPool> pool_;
  std::vector<Slot> slots_;
  uint32_t next_ = 0;
  VkExtent2D extent_{};

  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<Job> jobs_;  // at most one a slot: reserved once, so handing over a frame allocates nothing
  bool busy_ = false;      // the thread is showing a job it took
  bool stopping_ = false;
  std::string failed_;  // what stopped the thread, said by the next acquire
  std::atomic<std::chrono::nanoseconds::rep> interval_{0};
  std::chrono::steady_clock::time_point due_;  // the thread's: when the next frame may be shown
  std::thread thread_;
};

}  // namespace vitrine::host
