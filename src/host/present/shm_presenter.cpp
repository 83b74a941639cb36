#include "host/present/shm_presenter.h"

#include <sys/ipc.h>
#include <sys/shm.h>
#include <xcb/shm.h>
#include <xcb/xcb.h>

#include "gpu/check.h"
#include "gpu/fault_injection.h"
#include "gpu/sync_objects.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string_view>

// GLFW's X11 accessors, declared here rather than through glfw3native.h, which would bring Xlib's
// macros (None, Status, ...) into a unity batch and needs Xrandr's headers besides. Window is an XID.
extern "C" {
void* glfwGetX11Display(void);
unsigned long glfwGetX11Window(GLFWwindow* window);
}

namespace vitrine::host {

// What the thread draws with: its own connection (xcb connections may be used from any thread, and
// this one's events are the presenter's alone), the window, a graphics context and one shared segment,
// reused while it is big enough. The segment is marked for removal as soon as the X server has
// attached it, so it goes away with the process however that ends.
struct ShmPresenter::Connection {
  xcb_connection_t* x = nullptr;
  xcb_window_t window = 0;
  xcb_gcontext_t gc = 0;
  uint8_t completion = 0;  // the event type that says the server has finished reading the segment
  xcb_shm_seg_t segment = 0;
  void* pixels = nullptr;
  size_t size = 0;

  ~Connection() {
    release();
    if (gc) xcb_free_gc(x, gc);
    if (x) xcb_disconnect(x);
  }

  void release() {
    if (!pixels) return;
    xcb_shm_detach(x, segment);
    xcb_flush(x);
    shmdt(pixels);
    pixels = nullptr;
    size = 0;
  }

  // A segment of at least `bytes`, attached read-only by the server; an empty string when it is.
  std::string reserve(size_t bytes) {
    if (size >= bytes) return {};
    release();
    if (const std::optional<uint64_t> limit = gpu::injectedShmLimit(); limit && bytes > *limit)  // as shmmax refuses
      return fmt::format("shmget of {} bytes: {} (VITRINE_INJECT)", bytes, std::strerror(EINVAL));
    const int id = shmget(IPC_PRIVATE, bytes, IPC_CREAT | 0600);
    if (id < 0) return fmt::format("shmget of {} bytes: {}", bytes, std::strerror(errno));
    void* at = shmat(id, nullptr, 0);
    if (at == reinterpret_cast<void*>(-1)) {
      shmctl(id, IPC_RMID, nullptr);
      return fmt::format("shmat: {}", std::strerror(errno));
    }
    segment = xcb_generate_id(x);
    xcb_generic_error_t* error = xcb_request_check(x, xcb_shm_attach_checked(x, segment, uint32_t(id), 1));
    shmctl(id, IPC_RMID, nullptr);  // attached (or refused): removed once both sides have let go
    if (error) {                    // a server on another machine cannot reach this one's memory
      free(error);
      shmdt(at);
      return "the X server cannot attach this process's shared memory";
    }
    pixels = at;
    size = bytes;
    return {};
  }

  // Draws the segment's first `extent` pixels into the window and waits until the server has read them.
  // False when the connection is gone.
  bool put(VkExtent2D extent) {
    xcb_shm_put_image(x, window, gc, uint16_t(extent.width), uint16_t(extent.height), 0, 0, uint16_t(extent.width),
                      uint16_t(extent.height), 0, 0, 24, XCB_IMAGE_FORMAT_Z_PIXMAP, 1, segment, 0);
    xcb_flush(x);
    while (xcb_generic_event_t* event = xcb_wait_for_event(x)) {
      const uint8_t type = event->response_type & 0x7f;
      free(event);
      if (type == completion) return true;
      if (type == 0) return true;  // an error (the window went away first): nothing is reading the segment
    }
    return false;
  }
};

namespace {

// What `work` threw, or nothing.
template <typename Work>
std::string attempt(Work&& work) {
  try {
    work();
    return {};
  } catch (const std::exception& error) {
    return error.what();
  }
}

constexpr uint32_t kImages = 3;  // one being drawn, one being copied, one on its way to the window

// Whether the window's visual stores a pixel as B, G, R, X bytes (depth 24 in 32 bits, little-endian
// masks): then B8G8R8A8_UNORM texels are its pixels, copied as they are.
bool bgrxVisual(xcb_connection_t* x, xcb_window_t window) {
  xcb_get_window_attributes_reply_t* attributes =
      xcb_get_window_attributes_reply(x, xcb_get_window_attributes(x, window), nullptr);
  if (!attributes) return false;
  const xcb_visualid_t visual = attributes->visual;
  free(attributes);
  const xcb_setup_t* setup = xcb_get_setup(x);
  if (setup->image_byte_order != XCB_IMAGE_ORDER_LSB_FIRST) return false;
  bool wide = false;  // depth 24 is stored in 32 bits
  for (auto f = xcb_setup_pixmap_formats_iterator(setup); f.rem; xcb_format_next(&f))
    if (f.data->depth == 24) wide = f.data->bits_per_pixel == 32;
  if (!wide) return false;
  for (auto screen = xcb_setup_roots_iterator(setup); screen.rem; xcb_screen_next(&screen))
    for (auto depth = xcb_screen_allowed_depths_iterator(screen.data); depth.rem; xcb_depth_next(&depth)) {
      if (depth.data->depth != 24) continue;
      for (auto v = xcb_depth_visuals_iterator(depth.data); v.rem; xcb_visualtype_next(&v))
        if (v.data->visual_id == visual)
          return v.data->red_mask == 0xff0000u && v.data->green_mask == 0xff00u && v.data->blue_mask == 0xffu;
    }
  return false;
}

std::string unavailable(const gpu::Device& device, GLFWwindow* window) {
  if (const char* present = std::getenv("VITRINE_PRESENT"); present && std::string_view(present) == "swapchain")
    return "VITRINE_PRESENT=swapchain";
  if (device.properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU) return "not a software device";
  if (!device.storageWriteWithoutFormat()) return "no storage writes without a format";
  constexpr VkFormatFeatureFlags needed =
      VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
  if ((device.optimalTilingFeatures(ShmPresenter::kFormat) & needed) != needed)
    return "B8G8R8A8_UNORM cannot be written";
  if (!window || !glfwGetX11Display() || !glfwGetX11Window(window)) return "not an X11 window";
  return {};
}

}  // namespace

std::unique_ptr<ShmPresenter> ShmPresenter::create(const gpu::Device& device, GLFWwindow* window, std::string* why) {
  if (std::string reason = unavailable(device, window); !reason.empty()) {
    *why = std::move(reason);
    return nullptr;
  }
  auto connection = std::make_unique<Connection>();
  connection->x = xcb_connect(nullptr, nullptr);  // $DISPLAY, the display GLFW opened
  if (xcb_connection_has_error(connection->x)) {
    *why = "cannot open a second connection to the display";
    return nullptr;
  }
  const xcb_query_extension_reply_t* shm = xcb_get_extension_data(connection->x, &xcb_shm_id);
  if (!shm || !shm->present) {
    *why = "the display has no MIT-SHM";
    return nullptr;
  }
  connection->completion = uint8_t(shm->first_event + XCB_SHM_COMPLETION);
  connection->window = xcb_window_t(glfwGetX11Window(window));
  if (!bgrxVisual(connection->x, connection->window)) {
    *why = "the window's visual is not 24-bit BGRX";
    return nullptr;
  }
  connection->gc = xcb_generate_id(connection->x);
  xcb_create_gc(connection->x, connection->gc, connection->window, 0, nullptr);
  if (std::string reason = connection->reserve(4096); !reason.empty()) {  // can the server attach at all?
    *why = std::move(reason);
    return nullptr;
  }
  return std::unique_ptr<ShmPresenter>(new ShmPresenter(device, std::move(connection)));
}

ShmPresenter::ShmPresenter(const gpu::Device& device, std::unique_ptr<Connection> connection)
    : device_(device), connection_(std::move(connection)), pool_(gpu::createCommandPool(device, 0, "window copies")) {
  jobs_.reserve(kImages);
  thread_ = std::thread([this] { run(); });
}

ShmPresenter::~ShmPresenter() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
  // Copies handed over but not shown may still be running: the images, buffers and the pool holding
  // their command buffers go once the submissions so far have finished.
  device_.retire(std::move(slots_));
  device_.retire(std::move(pool_));
}

std::string ShmPresenter::build(VkExtent2D extent) {
  drain();
  if (!slots_.empty()) {  // the old size's, which a refused size leaves none of
    std::vector<VkCommandBuffer> copies;
    for (const Slot& slot : slots_) copies.push_back(slot.copy);
    vkFreeCommandBuffers(device_, pool_, uint32_t(copies.size()), copies.data());  // every copy has finished
    device_.retire(std::move(slots_));  // frames in flight may still draw into the images
    slots_.clear();
  }
  // The segment for this size now, while the thread is idle: where the system will not grant one
  // (a kernel.shmmax under the window's bytes), the caller still has Vulkan's swapchain to turn to.
  const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
  if (std::string why = connection_->reserve(bytes); !why.empty()) return why;
  extent_ = extent;
  next_ = 0;
  std::vector<VkCommandBuffer> copies(kImages);
  const VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr, pool_,
                                             VK_COMMAND_BUFFER_LEVEL_PRIMARY, kImages};
  VK_CHECK(vkAllocateCommandBuffers(device_, &allocate, copies.data()));
  slots_.resize(kImages);
  for (uint32_t i = 0; i < kImages; ++i) {
    Slot& slot = slots_[i];
    gpu::ImageDesc desc;
    desc.extent = {extent.width, extent.height, 1};
    desc.format = kFormat;
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    slot.image = gpu::Image(device_, desc, fmt::format("window image {}", i));
    slot.pixels = gpu::Buffer(device_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback,
                              fmt::format("window pixels {}", i));
    slot.copy = copies[i];
    // Recorded once: from where every frame leaves a window image (as a swapchain's, ready to present,
    // the copy's submission waiting for that frame at the copy stage) to its pixels in the buffer,
    // visible to the thread that reads them.
    const VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(slot.copy, &begin));
    slot.image.assumeUse({VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR});
    slot.image.use(slot.copy, gpu::use::TransferSrc);
    slot.pixels.use(slot.copy, gpu::use::TransferDstBuffer);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(slot.copy, slot.image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, slot.pixels.handle(),
                           1, &region);
    slot.pixels.use(slot.copy, gpu::use::HostReadBuffer);
    VK_CHECK(vkEndCommandBuffer(slot.copy));
  }
  return {};
}

uint32_t ShmPresenter::acquire(VkSemaphore acquired) {
  const uint32_t index = next_;
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return slots_[index].free || !failed_.empty(); });
    if (!failed_.empty()) throw Error(fmt::format("Showing frames in the window failed: {}", failed_));
    slots_[index].free = false;
  }
  next_ = (index + 1) % imageCount();
  const VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO, nullptr, acquired, 0,
                                     VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,    0};
  device_.submit({VK_NULL_HANDLE, {}, std::span(&signal, 1)});
  return index;
}

void ShmPresenter::present(uint32_t index, VkSemaphore renderFinished) {
  const VkSemaphoreSubmitInfo wait{
      VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO, nullptr, renderFinished, 0, VK_PIPELINE_STAGE_2_COPY_BIT, 0};
  const uint64_t copied = device_.submit({slots_[index].copy, std::span(&wait, 1), {}});
  {
    std::lock_guard lock(mutex_);
    jobs_.push_back({index, copied, extent_});
  }
  changed_.notify_all();
}

void ShmPresenter::drain() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return (jobs_.empty() && !busy_) || !failed_.empty(); });
  if (!failed_.empty()) throw Error(fmt::format("Showing frames in the window failed: {}", failed_));
}

// Each job: wait for its copy, move the pixels into the segment (the slot may be drawn again from
// then on), and have the server draw them, waiting until it has read the segment.
void ShmPresenter::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
      if (stopping_) return;
      job = jobs_.front();
      jobs_.erase(jobs_.begin());
      busy_ = true;
    }
    std::string failure = attempt([&] { copyOut(job); });
    {
      std::lock_guard lock(mutex_);
      slots_[job.slot].free = true;
    }
    changed_.notify_all();
    if (failure.empty()) {
      waitForTurn();
      failure = attempt([&] {
        if (!connection_->put(job.extent)) throw Error("the connection to the X server closed");
      });
    }
    {
      std::lock_guard lock(mutex_);
      busy_ = false;
      failed_ = failure;
    }
    changed_.notify_all();
    if (!failure.empty()) return;
  }
}

// A frame an interval, on a steady beat; a late frame is shown at once and the beat starts again from it.
void ShmPresenter::waitForTurn() {
  const std::chrono::nanoseconds interval(interval_.load());
  if (interval.count() <= 0) return;
  due_ = std::max(due_ + interval, std::chrono::steady_clock::now());
  std::this_thread::sleep_until(due_);
}

void ShmPresenter::copyOut(const Job& job) {
  device_.wait(job.copied);
  const Slot& slot = slots_[job.slot];
  const size_t bytes = size_t(job.extent.width) * job.extent.height * 4;  // build() reserved the segment
  slot.pixels.invalidate();
  std::memcpy(connection_->pixels, slot.pixels.mapped(), bytes);
}

}  // namespace vitrine::host
