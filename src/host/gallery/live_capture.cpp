#include "host/gallery/live_capture.h"

#include <fmt/format.h>

#include <ctime>
#include <utility>

#include "host/plural.h"
#include "host/gallery/screenshot.h"
#include "image/image_io.h"

namespace vitrine::host {
namespace {

// Frames waiting for the disk: about 130 MB at 1080p. Beyond that the frame loop would outrun the
// disk for good, and memory, not the picture, would be what grows.
constexpr size_t kMaxQueued = 8;

std::string stamp() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[32];
  std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &local);
  return text;
}

}  // namespace

LiveCapture::LiveCapture(const gpu::Device& device, uint32_t framesInFlight, std::filesystem::path folder)
    : device_(device), root_(std::move(folder)), copies_(framesInFlight), writer_([this] { writeLoop(); }) {}

LiveCapture::~LiveCapture() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  writer_.join();
}

std::string LiveCapture::toggle(std::string_view scene) {
  if (active_) {
    active_ = false;
    std::lock_guard lock(mutex_);
    return fmt::format("capture stopping: {}", summary());
  }
  std::filesystem::path folder = root_ / fmt::format("vitrine-{}-{}", scene, stamp());
  for (int n = 2; std::filesystem::exists(folder); ++n) folder = root_ / fmt::format("vitrine-{}-{}-{}", scene, stamp(), n);
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) return fmt::format("capture failed: cannot make {}: {}", folder.string(), error.message());
  std::lock_guard lock(mutex_);
  folder_ = std::filesystem::absolute(folder);
  scene_ = std::string(scene);
  finishedSaid_ = false;
  next_ = 0;
  written_ = dropped_ = 0;
  failure_.clear();
  active_ = true;
  return fmt::format("capturing every frame to {}/ (F9 stops)", folder_.string());
}

void LiveCapture::record(VkCommandBuffer cmd, uint32_t slot, gpu::Image& target, VkExtent2D rendered,
                         gpu::PassTimer* timer) {
  if (!active_) return;
  Copy& copy = copies_[slot];
  const VkExtent2D extent = target.extent2d();
  if (!copy.pixels || copy.extent.width != extent.width || copy.extent.height != extent.height) {
    copy.pixels.emplace(device_, VkDeviceSize(extent.width) * extent.height * 4 * sizeof(uint16_t),
                        VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback, "capture readback");
    copy.extent = extent;
  }
  gpu::Pass pass(device_, timer, cmd, "capture copy");
  gpu::recordReadback(cmd, target, *copy.pixels);
  copy.pending = true;
  copy.rendered = rendered;
  std::lock_guard lock(mutex_);
  copy.frame = next_++;
}

void LiveCapture::collect(uint32_t slot) {
  Copy& copy = copies_[slot];
  if (!copy.pending) return;
  copy.pending = false;
  std::unique_lock lock(mutex_);
  if (!failure_.empty()) {
    active_ = false;
    return;
  }
  if (queue_.size() >= kMaxQueued) {
    ++dropped_;
    return;
  }
  copy.pixels->invalidate();
  const auto halves = copy.pixels->view<const uint16_t>();
  queue_.push_back({std::vector<uint16_t>(halves.begin(), halves.end()), copy.extent, copy.rendered, scene_,
                    folder_ / fmt::format("frame_{:06d}.exr", copy.frame)});
  lock.unlock();
  wake_.notify_one();
}

std::string LiveCapture::summary() const {
  const uint64_t done = written_ + dropped_;
  const std::string dropped =
      dropped_ ? fmt::format(", {} dropped (the disk is slower than the frames)", dropped_) : std::string();
  if (!failure_.empty()) return fmt::format("{}/: {} written, then: {}", folder_.string(), counted(written_, "frame"),
                                            failure_);
  if (active_) return fmt::format("capturing to {}/: {} written{}", folder_.string(), counted(written_, "frame"), dropped);
  if (done < next_)
    return fmt::format("{}/: {} of {} written{}, writing the rest", folder_.string(), written_, counted(next_, "frame"),
                       dropped);
  return fmt::format("captured {}/: {} written{}", folder_.string(), counted(written_, "frame"), dropped);
}

std::string LiveCapture::status(std::string_view scene) const {
  std::lock_guard lock(mutex_);
  if (folder_.empty() || (!active_ && scene != scene_)) return {};
  return summary();
}

std::optional<std::string> LiveCapture::takeFinished() {
  std::lock_guard lock(mutex_);
  if (finishedSaid_ || active_) return std::nullopt;
  if (failure_.empty() && written_ + dropped_ < next_) return std::nullopt;
  finishedSaid_ = true;
  return summary();
}

void LiveCapture::writeLoop() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopping, with everything written
    Frame frame = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();
    std::string failed;
    try {
      writeImage(frame.path, imageFromHalves(frame.extent.width, frame.extent.height, frame.halves),
                 Screenshots::notes(frame.scene, frame.extent, frame.rendered));
    } catch (const std::exception& e) {  // a full disk stops the capture, not the gallery
      failed = e.what();
    }
    lock.lock();
    if (failed.empty()) ++written_;
    else if (failure_.empty()) failure_ = std::move(failed);
  }
}

}  // namespace vitrine::host
