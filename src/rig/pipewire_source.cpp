#include "rig/pipewire_source.h"

#include <fmt/format.h>
#include <pipewire/pipewire.h>
#include <spa/param/video/format-utils.h>
#include <spa/pod/builder.h>
#include <spa/utils/result.h>

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <mutex>
#include <vector>

#include "core/error.h"
#include "gpu/device.h"
#include "gpu/dmabuf_export.h"
#include "rig/dmabuf_pool.h"

namespace vitrine::rig {
namespace {

// The largest side offered (8K): a larger frame is no video a consumer takes live, and each size costs
// four frames of memory; the device's own limits and memory are checked when a consumer asks.
constexpr uint32_t kLargest = 8192;

// The formats offered, the consumer's choice first among equals: 8-bit, 4 bytes a pixel, so a frame is
// copied row by row, swapping red and blue for the BGR ones.
constexpr std::array<spa_video_format, 4> kFormats{SPA_VIDEO_FORMAT_BGRx, SPA_VIDEO_FORMAT_RGBx, SPA_VIDEO_FORMAT_BGRA,
                                                   SPA_VIDEO_FORMAT_RGBA};

const char* formatName(uint32_t format) {
  switch (format) {
    case SPA_VIDEO_FORMAT_BGRx: return "BGRx";
    case SPA_VIDEO_FORMAT_RGBx: return "RGBx";
    case SPA_VIDEO_FORMAT_BGRA: return "BGRA";
    case SPA_VIDEO_FORMAT_RGBA: return "RGBA";
    default: return "?";
  }
}

// B,G,R order in memory (BGRx, BGRA) against R,G,B (RGBx, RGBA).
bool blueFirst(uint32_t format) { return format == SPA_VIDEO_FORMAT_BGRx || format == SPA_VIDEO_FORMAT_BGRA; }

// A frame's shared memory, made by this node (the stream lets the producer allocate, for DMA-BUFs).
struct SharedFrame {
  SharedFrame(size_t bytes) : size(bytes) {
    fd = memfd_create("vitrine-frame", MFD_CLOEXEC | MFD_ALLOW_SEALING);
    if (fd < 0 || ftruncate(fd, off_t(size)) < 0) return;
    fcntl(fd, F_ADD_SEALS, F_SEAL_GROW | F_SEAL_SHRINK | F_SEAL_SEAL);
    void* mapped = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    data = mapped == MAP_FAILED ? nullptr : mapped;
  }
  ~SharedFrame() {
    if (data) munmap(data, size);
    if (fd >= 0) close(fd);
  }
  SharedFrame(const SharedFrame&) = delete;
  SharedFrame& operator=(const SharedFrame&) = delete;
  size_t size;
  int fd = -1;
  void* data = nullptr;
};

// Said once a process, whatever the number of nodes: there is no daemon.
std::atomic<bool> saidNoDaemon{false};

// PipeWire is initialised once a process and never deinitialised: a later source starts it again.
void initPipeWire() {
  static std::once_flag once;
  std::call_once(once, [] { pw_init(nullptr, nullptr); });
}

}  // namespace

struct PipeWireSource::Impl {
  // One frame held between the frame thread and the loop.
  struct Held {
    std::vector<std::byte> bytes;  // RGBA, rows `width * 4` apart
    uint32_t width = 0, height = 0;
    uint64_t index = 0;
    double time = 0.0;
  };

  Impl(std::string nodeName, VkExtent2D extent, uint32_t fps, DmaBufOffer dmaBufOffer)
      : node(std::move(nodeName)), offered(extent), rate(fps), offer(std::move(dmaBufOffer)) {}

  const std::string node;
  const VkExtent2D offered;
  const uint32_t rate;
  const DmaBufOffer offer;
  std::shared_ptr<DmaBufPool> pool;  // the DMA-BUF images, when the device exports them

  pw_thread_loop* loop = nullptr;
  pw_context* context = nullptr;
  pw_core* core = nullptr;
  pw_stream* stream = nullptr;
  spa_hook coreListener{};
  spa_hook streamListener{};
  spa_source* wake = nullptr;   // signalled by the frame thread: a new frame is in the mailbox
  spa_source* retry = nullptr;  // the timer that reaches the daemon again
  spa_source* toShared = nullptr;  // offers shared memory only, after DMA-BUF buffers could not be made
  bool saidMissing = false;     // the console has heard there is no daemon

  // The mailbox: the frame thread fills `back` and swaps it with `newest`; the loop swaps `newest` with
  // `front` and copies from there. The lock is held for the swaps only.
  std::mutex mailbox;
  Held back, newest, front;
  bool fresh = false;  // `newest` holds a frame the loop has not taken

  // What the loop negotiated, for the frame thread and the menu.
  mutable std::mutex stateLock;
  bool connected = false;  // to a daemon
  bool streaming = false;  // a consumer is linked and the stream runs
  spa_video_info_raw format{};
  bool negotiated = false;
  bool dmaBuf = false;      // the negotiated buffers are DMA-BUFs
  uint64_t modifier = 0;    // their layout
  bool refused = false;     // DMA-BUF failed once: shared memory from then on
  std::string sharedWhy;    // why frames go through shared memory
  std::string problemDmaBuf;  // why a DMA-BUF buffer could not be made (add_buffer), for toShared
  std::string problem;  // why there is no node now
  std::atomic<uint64_t> handed{0}, dropped{0};

  // Loop-thread side (the loop's lock held).
  void connect();
  void disconnect();
  void process();
  void processDmaBuf();
  void negotiate(const spa_pod* param);
  // The formats offered: DMA-BUF ones first (unless refused), then shared memory; `fixed` gives only
  // the DMA-BUF one of that format and modifier (the fixation, offered ahead of the others).
  std::vector<const spa_pod*> formats(spa_pod_builder& builder, std::optional<std::pair<uint32_t, uint64_t>> fixed);
  void offerShared(std::string why);  // gives DMA-BUF up, says why once, renegotiates
  void addBuffer(pw_buffer* buffer);
  void removeBuffer(pw_buffer* buffer);
  VkFormat vulkanFormat(uint32_t spaFormat) const { return blueFirst(spaFormat) ? offer.bgra : offer.rgba; }
  const std::vector<gpu::drm::DriverModifier>& driverModifiers(uint32_t spaFormat) const {
    return blueFirst(spaFormat) ? offer.bgraModifiers : offer.rgbaModifiers;
  }
  void setProblem(std::string why) {
    std::lock_guard lock(stateLock);
    problem = std::move(why);
    connected = streaming = negotiated = false;
  }
};

namespace {

const pw_stream_events kStreamEvents = [] {
  pw_stream_events events{};
  events.version = PW_VERSION_STREAM_EVENTS;
  events.state_changed = [](void* data, pw_stream_state, pw_stream_state state, const char* error) {
    auto* impl = static_cast<PipeWireSource::Impl*>(data);
    std::lock_guard lock(impl->stateLock);
    impl->streaming = state == PW_STREAM_STATE_STREAMING;
    if (state == PW_STREAM_STATE_ERROR) impl->problem = fmt::format("the stream failed: {}", error ? error : "?");
  };
  events.param_changed = [](void* data, uint32_t id, const spa_pod* param) {
    if (id == SPA_PARAM_Format) static_cast<PipeWireSource::Impl*>(data)->negotiate(param);
  };
  events.process = [](void* data) { static_cast<PipeWireSource::Impl*>(data)->process(); };
  events.add_buffer = [](void* data, pw_buffer* buffer) { static_cast<PipeWireSource::Impl*>(data)->addBuffer(buffer); };
  events.remove_buffer = [](void* data, pw_buffer* buffer) {
    static_cast<PipeWireSource::Impl*>(data)->removeBuffer(buffer);
  };
  return events;
}();

const pw_core_events kCoreEvents = [] {
  pw_core_events events{};
  events.version = PW_VERSION_CORE_EVENTS;
  events.error = [](void* data, uint32_t id, int, int res, const char* message) {
    auto* impl = static_cast<PipeWireSource::Impl*>(data);
    if (id != PW_ID_CORE) return;
    // The daemon went away (or refused us): tear down from the timer, outside the core's own callback.
    impl->setProblem(fmt::format("PipeWire: {} ({})", message ? message : "error", spa_strerror(res)));
    timespec soon{0, 1}, every{PipeWireSource::kRetry.count(), 0};
    pw_loop_update_timer(pw_thread_loop_get_loop(impl->loop), impl->retry, &soon, &every, false);
  };
  return events;
}();

}  // namespace

void PipeWireSource::Impl::connect() {
  if (core) return;
  core = pw_context_connect(context, nullptr, 0);
  if (!core) {
    const std::string why = fmt::format("no PipeWire daemon ({})", std::strerror(errno));
    if (!saidMissing && !saidNoDaemon.exchange(true))
      std::fprintf(stderr, "vitrine: pipewire: %s: node %s not published; trying again every %lld s\n", why.c_str(),
                   node.c_str(), (long long)kRetry.count());
    saidMissing = true;
    setProblem(why + fmt::format(", trying again every {} s", kRetry.count()));
    return;
  }
  pw_core_add_listener(core, &coreListener, &kCoreEvents, this);
  pw_properties* props = pw_properties_new(PW_KEY_MEDIA_TYPE, "Video", PW_KEY_MEDIA_CATEGORY, "Source", PW_KEY_MEDIA_CLASS,
                                           "Video/Source", PW_KEY_NODE_NAME, node.c_str(), nullptr);
  pw_properties_setf(props, PW_KEY_NODE_DESCRIPTION, "Vitrine: %s", node.c_str());
  stream = pw_stream_new(core, node.c_str(), props);
  if (!stream) {
    setProblem(fmt::format("cannot make a stream: {}", std::strerror(errno)));
    disconnect();
    return;
  }
  pw_stream_add_listener(stream, &streamListener, &kStreamEvents, this);

  std::vector<uint8_t> storage(16384);
  spa_pod_builder builder = SPA_POD_BUILDER_INIT(storage.data(), uint32_t(storage.size()));
  std::vector<const spa_pod*> params = formats(builder, std::nullopt);
  // The node allocates its buffers (DMA-BUFs it exports, or shared memory it makes) in add_buffer.
  const int result = pw_stream_connect(
      stream, PW_DIRECTION_OUTPUT, PW_ID_ANY,
      pw_stream_flags(PW_STREAM_FLAG_DRIVER | PW_STREAM_FLAG_MAP_BUFFERS | PW_STREAM_FLAG_ALLOC_BUFFERS), params.data(),
      uint32_t(params.size()));
  if (result < 0) {
    setProblem(fmt::format("cannot publish the node: {}", spa_strerror(result)));
    disconnect();
    return;
  }
  if (saidMissing) std::fprintf(stderr, "vitrine: pipewire: daemon found: publishing node %s\n", node.c_str());
  saidMissing = false;
  saidNoDaemon = false;
  std::lock_guard lock(stateLock);
  problem.clear();
  connected = true;
}

void PipeWireSource::Impl::disconnect() {
  if (stream) {
    spa_hook_remove(&streamListener);
    pw_stream_destroy(stream);
    stream = nullptr;
  }
  if (core) {
    spa_hook_remove(&coreListener);
    pw_core_disconnect(core);
    core = nullptr;
  }
  std::lock_guard lock(stateLock);
  connected = streaming = negotiated = false;
}

std::vector<const spa_pod*> PipeWireSource::Impl::formats(spa_pod_builder& builder,
                                                         std::optional<std::pair<uint32_t, uint64_t>> fixed) {
  std::vector<const spa_pod*> params;
  const spa_rectangle size{offered.width, offered.height}, smallest{1, 1},
                      largest{std::max(kLargest, offered.width), std::max(kLargest, offered.height)};
  const spa_fraction rateOffered{rate, 1}, slowest{0, 1}, fastest{1000, 1};
  // The common part of every format: video, raw, any size and rate (the output's first).
  const auto begin = [&](spa_pod_frame& object) {
    spa_pod_builder_push_object(&builder, &object, SPA_TYPE_OBJECT_Format, SPA_PARAM_EnumFormat);
    spa_pod_builder_add(&builder, SPA_FORMAT_mediaType, SPA_POD_Id(SPA_MEDIA_TYPE_video), SPA_FORMAT_mediaSubtype,
                        SPA_POD_Id(SPA_MEDIA_SUBTYPE_raw), 0);
  };
  const auto end = [&](spa_pod_frame& object) {
    spa_pod_builder_add(&builder, SPA_FORMAT_VIDEO_size, SPA_POD_CHOICE_RANGE_Rectangle(&size, &smallest, &largest), 0);
    spa_pod_builder_add(&builder, SPA_FORMAT_VIDEO_framerate,
                        SPA_POD_CHOICE_RANGE_Fraction(&rateOffered, &slowest, &fastest), 0);
    params.push_back(static_cast<const spa_pod*>(spa_pod_builder_pop(&builder, &object)));
  };
  // DMA-BUF first, one format at a time (each with its driver's modifiers), so a consumer that takes
  // them is given them; the modifier is mandatory there, so a consumer without it matches the last.
  bool dmaBufOffered = false;
  {
    std::lock_guard lock(stateLock);
    dmaBufOffered = !refused;
  }
  for (const spa_video_format spaFormat : kFormats) {
    if (!dmaBufOffered || !offer.device) break;
    if (fixed && fixed->first != uint32_t(spaFormat)) continue;
    const auto& modifiers = driverModifiers(spaFormat);
    if (modifiers.empty()) continue;
    spa_pod_frame object, choice;
    begin(object);
    spa_pod_builder_add(&builder, SPA_FORMAT_VIDEO_format, SPA_POD_Id(spaFormat), 0);
    // Mandatory; left open (DONT_FIXATE) until this node, which allocates, has picked one.
    spa_pod_builder_prop(&builder, SPA_FORMAT_VIDEO_modifier,
                         SPA_POD_PROP_FLAG_MANDATORY | (fixed ? 0u : uint32_t(SPA_POD_PROP_FLAG_DONT_FIXATE)));
    spa_pod_builder_push_choice(&builder, &choice, SPA_CHOICE_Enum, 0);
    if (fixed) {
      spa_pod_builder_long(&builder, int64_t(fixed->second));  // the default, then the one choice
      spa_pod_builder_long(&builder, int64_t(fixed->second));
    } else {
      spa_pod_builder_long(&builder, int64_t(modifiers.front().modifier));
      for (const auto& entry : modifiers) spa_pod_builder_long(&builder, int64_t(entry.modifier));
    }
    spa_pod_builder_pop(&builder, &choice);
    end(object);
  }
  if (fixed) return params;  // the fixation goes ahead of the formats offered before, shared memory last
  spa_pod_frame object;
  begin(object);
  spa_pod_builder_add(&builder, SPA_FORMAT_VIDEO_format,
                      SPA_POD_CHOICE_ENUM_Id(5, kFormats[0], kFormats[0], kFormats[1], kFormats[2], kFormats[3]), 0);
  end(object);
  return params;
}

void PipeWireSource::Impl::offerShared(std::string why) {
  {
    std::lock_guard lock(stateLock);
    if (refused) return;
    refused = true;
    sharedWhy = "DMA-BUF failed: " + why;
  }
  if (pool) pool->setActive(false);
  std::fprintf(stderr, "vitrine: pipewire: node %s: DMA-BUF failed (%s): frames go through shared memory\n",
               node.c_str(), why.c_str());
  if (!stream) return;
  std::vector<uint8_t> storage(16384);
  spa_pod_builder builder = SPA_POD_BUILDER_INIT(storage.data(), uint32_t(storage.size()));
  std::vector<const spa_pod*> params = formats(builder, std::nullopt);
  pw_stream_update_params(stream, params.data(), uint32_t(params.size()));
}

namespace {

// The modifiers a format's modifier property lists (one, or a choice's values), without the default.
std::vector<uint64_t> modifiersOf(const spa_pod_prop& prop) {
  uint32_t count = 0, choice = 0;
  const spa_pod* values = spa_pod_get_values(&prop.value, &count, &choice);
  std::vector<uint64_t> list;
  if (!values || values->type != SPA_TYPE_Long || count == 0) return list;
  const auto* longs = static_cast<const int64_t*>(SPA_POD_BODY_CONST(values));
  for (uint32_t i = choice == SPA_CHOICE_None ? 0 : 1; i < count; ++i) list.push_back(uint64_t(longs[i]));
  if (list.empty()) list.push_back(uint64_t(longs[0]));
  return list;
}

}  // namespace

void PipeWireSource::Impl::negotiate(const spa_pod* param) {
  if (!param) {  // the format was cleared: no consumer
    if (pool) pool->setActive(false);
    std::lock_guard lock(stateLock);
    negotiated = false;
    return;
  }
  spa_video_info_raw info{};
  if (spa_format_video_raw_parse(param, &info) < 0 || info.size.width == 0 || info.size.height == 0) return;
  const spa_pod_prop* modifierProp = spa_pod_find_prop(param, nullptr, SPA_FORMAT_VIDEO_modifier);
  const bool wantsDmaBuf = modifierProp && offer.device && !driverModifiers(info.format).empty();
  if (wantsDmaBuf && (modifierProp->flags & SPA_POD_PROP_FLAG_DONT_FIXATE)) {
    // The consumer's and the driver's modifiers meet here; the driver picks among them for a test image
    // of the negotiated size, and the formats are offered again with that one alone.
    const auto candidates = gpu::drm::acceptable(driverModifiers(info.format), modifiersOf(*modifierProp));
    if (candidates.empty()) return offerShared("no modifier both the driver and the consumer take");
    uint64_t chosen = candidates.front();
    try {
      const gpu::ExportedImage probe(*offer.device, vulkanFormat(info.format), {info.size.width, info.size.height},
                                     VK_IMAGE_USAGE_TRANSFER_DST_BIT, candidates, node + " test image");
      chosen = probe.modifier();
    } catch (const Error& e) {
      return offerShared(e.what());
    }
    std::vector<uint8_t> storage(16384);
    spa_pod_builder builder = SPA_POD_BUILDER_INIT(storage.data(), uint32_t(storage.size()));
    std::vector<const spa_pod*> params = formats(builder, std::make_pair(info.format, chosen));
    const auto rest = formats(builder, std::nullopt);
    params.insert(params.end(), rest.begin(), rest.end());
    pw_stream_update_params(stream, params.data(), uint32_t(params.size()));
    return;
  }
  uint32_t planes = 0;
  if (wantsDmaBuf) {
    const auto fixedModifiers = modifiersOf(*modifierProp);
    info.modifier = fixedModifiers.empty() ? gpu::drm::kInvalid : fixedModifiers.front();
    planes = gpu::drm::planesOf(driverModifiers(info.format), info.modifier);
    if (planes == 0) return offerShared(fmt::format("the consumer fixed modifier {:#x}, which the driver lacks", info.modifier));
  }
  {
    std::lock_guard lock(stateLock);
    format = info;
    negotiated = true;
    dmaBuf = planes > 0;
    modifier = info.modifier;
    if (!dmaBuf && !refused)
      sharedWhy = offer.device ? (modifierProp ? "the driver has no modifier for the format" : "the consumer takes no DMA-BUF")
                               : offer.why;
  }
  if (pool) pool->setActive(planes > 0);
  const uint32_t stride = info.size.width * 4;
  std::array<uint8_t, 1024> storage;
  spa_pod_builder builder = SPA_POD_BUILDER_INIT(storage.data(), uint32_t(storage.size()));
  const spa_pod* params[2];
  // DMA-BUFs: one block a memory plane; their layout is the driver's (the size and stride here only
  // describe the frame). Shared memory: one block, rows of 4 bytes a pixel.
  params[0] = static_cast<const spa_pod*>(spa_pod_builder_add_object(
      &builder, SPA_TYPE_OBJECT_ParamBuffers, SPA_PARAM_Buffers, SPA_PARAM_BUFFERS_buffers, SPA_POD_CHOICE_RANGE_Int(4, 2, 8),
      SPA_PARAM_BUFFERS_blocks, SPA_POD_Int(int32_t(std::max(planes, 1u))), SPA_PARAM_BUFFERS_size,
      SPA_POD_Int(int32_t(stride * info.size.height)), SPA_PARAM_BUFFERS_stride, SPA_POD_Int(int32_t(stride)),
      SPA_PARAM_BUFFERS_dataType,
      SPA_POD_CHOICE_FLAGS_Int(planes > 0 ? (1 << SPA_DATA_DmaBuf) : (1 << SPA_DATA_MemFd))));
  params[1] = static_cast<const spa_pod*>(spa_pod_builder_add_object(
      &builder, SPA_TYPE_OBJECT_ParamMeta, SPA_PARAM_Meta, SPA_PARAM_META_type, SPA_POD_Id(SPA_META_Header),
      SPA_PARAM_META_size, SPA_POD_Int(int32_t(sizeof(spa_meta_header)))));
  pw_stream_update_params(stream, params, 2);
}

// A buffer the stream asks for: DMA-BUF images exported by the device, one block a memory plane, or a
// frame of shared memory. An image that cannot be made gives DMA-BUF up (from PipeWire's loop, outside
// this callback).
void PipeWireSource::Impl::addBuffer(pw_buffer* buffer) {
  spa_buffer* spaBuffer = buffer->buffer;
  if (spaBuffer->n_datas == 0) return;
  spa_data* datas = spaBuffer->datas;
  spa_video_info_raw info;
  bool asDmaBuf;
  uint64_t layout;
  {
    std::lock_guard lock(stateLock);
    info = format;
    asDmaBuf = dmaBuf && !refused;
    layout = modifier;
  }
  if (asDmaBuf && (datas[0].type & (1u << SPA_DATA_DmaBuf)) && pool) {
    try {
      const std::array<uint64_t, 1> modifiers{layout};
      auto image = std::make_unique<gpu::ExportedImage>(*offer.device, vulkanFormat(info.format),
                                                        VkExtent2D{info.size.width, info.size.height},
                                                        VK_IMAGE_USAGE_TRANSFER_DST_BIT, modifiers,
                                                        fmt::format("{} buffer", node));
      if (image->planes().size() != spaBuffer->n_datas)
        throw Error(fmt::format("{} memory planes for {} blocks", image->planes().size(), spaBuffer->n_datas));
      for (uint32_t i = 0; i < spaBuffer->n_datas; ++i) {
        const auto& plane = image->planes()[i];
        datas[i].type = SPA_DATA_DmaBuf;
        datas[i].flags = SPA_DATA_FLAG_READABLE;
        datas[i].fd = plane.fd.get();
        datas[i].mapoffset = 0;
        datas[i].maxsize = uint32_t(std::min<VkDeviceSize>(image->memorySize(), UINT32_MAX));
        datas[i].data = nullptr;
        datas[i].chunk->offset = uint32_t(plane.layout.offset);
        datas[i].chunk->stride = int32_t(plane.layout.rowPitch);
        datas[i].chunk->size = uint32_t(plane.layout.size);
        datas[i].chunk->flags = SPA_CHUNK_FLAG_NONE;
      }
      pool->add(buffer, std::move(image), {info.size.width, info.size.height}, vulkanFormat(info.format));
      return;
    } catch (const Error& e) {
      {
        std::lock_guard lock(stateLock);
        if (problemDmaBuf.empty()) problemDmaBuf = e.what();
      }
      pw_loop_signal_event(pw_thread_loop_get_loop(loop), toShared);
      return;  // this buffer has no memory: no frame is ever written to it
    }
  }
  if (!(datas[0].type & (1u << SPA_DATA_MemFd))) return;
  const size_t bytes = size_t(info.size.width) * 4 * info.size.height;
  auto* frame = new SharedFrame(bytes);
  if (!frame->data) {
    delete frame;
    return;
  }
  buffer->user_data = frame;
  datas[0].type = SPA_DATA_MemFd;
  datas[0].flags = SPA_DATA_FLAG_READWRITE;
  datas[0].fd = frame->fd;
  datas[0].mapoffset = 0;
  datas[0].maxsize = uint32_t(bytes);
  datas[0].data = frame->data;
}

void PipeWireSource::Impl::removeBuffer(pw_buffer* buffer) {
  if (pool) pool->remove(buffer);
  delete static_cast<SharedFrame*>(std::exchange(buffer->user_data, nullptr));
  for (uint32_t i = 0; i < buffer->buffer->n_datas; ++i) {
    buffer->buffer->datas[i].fd = -1;
    buffer->buffer->datas[i].data = nullptr;
  }
}

// A finished DMA-BUF copy to the consumer. Buffers it gave back are free for the frame thread's copies;
// of the copies finished since the last cycle, the newest goes and the others are dropped and counted.
void PipeWireSource::Impl::processDmaBuf() {
  while (pw_buffer* returned = pw_stream_dequeue_buffer(stream)) pool->given(returned);
  uint64_t superseded = 0;
  const auto done = pool->takeDone(superseded);
  dropped += superseded;
  if (!done) return;
  auto* buffer = static_cast<pw_buffer*>(const_cast<void*>(done->key));
  if (auto* header = static_cast<spa_meta_header*>(
          spa_buffer_find_meta_data(buffer->buffer, SPA_META_Header, sizeof(spa_meta_header)))) {
    header->flags = 0;
    header->offset = 0;
    header->pts = int64_t(done->time * 1e9);
    header->dts_offset = 0;
    header->seq = done->index;
  }
  pw_stream_queue_buffer(stream, buffer);
  ++handed;
}

// The newest frame into a buffer the consumer gave back, converted to the negotiated format.
void PipeWireSource::Impl::process() {
  bool asDmaBuf;
  {
    std::lock_guard lock(stateLock);
    asDmaBuf = dmaBuf && !refused;
  }
  if (asDmaBuf && pool) return processDmaBuf();
  {
    std::lock_guard lock(mailbox);
    if (!fresh) return;
    std::swap(front, newest);
    fresh = false;
  }
  spa_video_info_raw info;
  {
    std::lock_guard lock(stateLock);
    info = format;
  }
  // A frame of the size before the consumer's (the output follows it a frame or two later).
  if (front.width != info.size.width || front.height != info.size.height) {
    ++dropped;
    return;
  }
  pw_buffer* buffer = pw_stream_dequeue_buffer(stream);
  if (!buffer) {  // the consumer still holds every buffer: this frame is dropped, not waited for
    ++dropped;
    return;
  }
  spa_data& data = buffer->buffer->datas[0];
  auto* out = static_cast<uint8_t*>(data.data);
  const uint32_t stride = data.chunk->stride > 0 ? uint32_t(data.chunk->stride) : front.width * 4;
  const uint32_t rowBytes = front.width * 4;
  if (!out || data.maxsize < stride * (front.height - 1) + rowBytes) {
    data.chunk->size = 0;
    pw_stream_queue_buffer(stream, buffer);
    ++dropped;
    return;
  }
  const bool swapRedBlue = blueFirst(info.format);
  const auto* in = reinterpret_cast<const uint8_t*>(front.bytes.data());
  for (uint32_t y = 0; y < front.height; ++y) {
    const uint8_t* from = in + size_t(y) * rowBytes;
    uint8_t* to = out + size_t(y) * stride;
    if (!swapRedBlue) {
      std::memcpy(to, from, rowBytes);
      continue;
    }
    // Whole pixels at a time, red and blue swapped (a loop the compiler vectorises).
    for (uint32_t x = 0; x < rowBytes; x += 4) {
      uint32_t pixel;
      std::memcpy(&pixel, from + x, 4);
      pixel = (pixel & 0xff00ff00u) | ((pixel & 0xffu) << 16) | ((pixel >> 16) & 0xffu);
      std::memcpy(to + x, &pixel, 4);
    }
  }
  data.chunk->offset = 0;
  data.chunk->stride = int32_t(stride);
  data.chunk->size = stride * front.height;
  if (auto* header = static_cast<spa_meta_header*>(spa_buffer_find_meta_data(buffer->buffer, SPA_META_Header, sizeof(spa_meta_header)))) {
    header->flags = 0;
    header->offset = 0;
    header->pts = int64_t(front.time * 1e9);
    header->dts_offset = 0;
    header->seq = front.index;
  }
  pw_stream_queue_buffer(stream, buffer);
  ++handed;
}

DmaBufOffer PipeWireSource::dmaBufOffer(const gpu::Device& device) {
  DmaBufOffer offer;
  if (!device.exportsDmaBuf()) {
    offer.why = fmt::format("{} exports no DMA-BUF", device.properties().deviceName);
    return offer;
  }
  // The frame's own byte order is copied (transfer destination); the other is blitted (blit destination).
  const VkFormat frame = host::ReadbackOutput::frameFormat(device);
  const bool srgb = frame == VK_FORMAT_R8G8B8A8_SRGB;
  offer.rgba = frame;
  offer.bgra = srgb ? VK_FORMAT_B8G8R8A8_SRGB : VK_FORMAT_B8G8R8A8_UNORM;
  offer.rgbaModifiers = gpu::exportableModifiers(device, offer.rgba, VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                                 VK_FORMAT_FEATURE_TRANSFER_DST_BIT);
  offer.bgraModifiers = gpu::exportableModifiers(device, offer.bgra, VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                                 VK_FORMAT_FEATURE_TRANSFER_DST_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT);
  if (offer.rgbaModifiers.empty() && offer.bgraModifiers.empty()) {
    offer.why = fmt::format("{} exports no DMA-BUF of 8-bit RGBA", device.properties().deviceName);
    return offer;
  }
  offer.device = &device;
  return offer;
}

PipeWireSource::PipeWireSource(std::string node, VkExtent2D extent, uint32_t fps, DmaBufOffer offer)
    : impl_(std::make_unique<Impl>(std::move(node), extent, fps, std::move(offer))) {
  initPipeWire();
  Impl& state = *impl_;
  if (!state.offer.device) state.sharedWhy = state.offer.why;
  state.loop = pw_thread_loop_new("vitrine-pipewire", nullptr);
  if (!state.loop) {
    state.setProblem("cannot start PipeWire's thread");
    std::fprintf(stderr, "vitrine: pipewire: cannot start PipeWire's thread: node %s not published\n", state.node.c_str());
    return;
  }
  pw_loop* loop = pw_thread_loop_get_loop(state.loop);
  state.context = pw_context_new(loop, nullptr, 0);
  state.wake = pw_loop_add_event(
      loop,
      [](void* data, uint64_t) {
        auto* impl = static_cast<Impl*>(data);
        if (impl->stream && pw_stream_get_state(impl->stream, nullptr) == PW_STREAM_STATE_STREAMING)
          pw_stream_trigger_process(impl->stream);
      },
      &state);
  state.toShared = pw_loop_add_event(
      loop,
      [](void* data, uint64_t) {
        auto* impl = static_cast<Impl*>(data);
        std::string why;
        {
          std::lock_guard lock(impl->stateLock);
          why = impl->problemDmaBuf;
        }
        impl->offerShared(why);
      },
      &state);
  if (state.offer.device)
    state.pool = std::make_shared<DmaBufPool>([loop, wake = state.wake] { pw_loop_signal_event(loop, wake); });
  state.retry = pw_loop_add_timer(
      loop,
      [](void* data, uint64_t) {
        auto* impl = static_cast<Impl*>(data);
        bool lost;
        {
          std::lock_guard lock(impl->stateLock);
          lost = !impl->connected;
        }
        if (lost) impl->disconnect(), impl->connect();
      },
      &state);
  pw_thread_loop_lock(state.loop);  // before the thread runs: the first try says at once if there is no daemon
  if (state.context) state.connect();
  else state.setProblem("cannot make a PipeWire context");
  timespec every{kRetry.count(), 0};
  pw_loop_update_timer(loop, state.retry, &every, &every, false);
  pw_thread_loop_unlock(state.loop);
  pw_thread_loop_start(state.loop);
}

PipeWireSource::~PipeWireSource() {
  Impl& state = *impl_;
  if (!state.loop) return;
  pw_thread_loop_stop(state.loop);  // the thread has ended: its objects are this thread's now
  state.disconnect();
  pw_loop* loop = pw_thread_loop_get_loop(state.loop);
  if (state.wake) pw_loop_destroy_source(loop, state.wake);
  if (state.retry) pw_loop_destroy_source(loop, state.retry);
  if (state.toShared) pw_loop_destroy_source(loop, state.toShared);
  if (state.context) pw_context_destroy(state.context);
  pw_thread_loop_destroy(state.loop);
}

void PipeWireSource::frame(const host::PublishedFrame& frame) {
  Impl& impl = *impl_;
  if (!impl.loop || !taking()) return;
  // Copied outside the lock, into the frame thread's own buffer; then handed over by a swap.
  Impl::Held& back = impl.back;
  back.bytes.resize(size_t(frame.width) * frame.height * 4);
  for (uint32_t y = 0; y < frame.height; ++y)
    std::memcpy(back.bytes.data() + size_t(y) * frame.width * 4, frame.bytes.data() + size_t(y) * frame.stride,
                size_t(frame.width) * 4);
  back.width = frame.width;
  back.height = frame.height;
  back.index = frame.index;
  back.time = frame.time;
  bool replaced;
  {
    std::lock_guard lock(impl.mailbox);
    std::swap(impl.back, impl.newest);
    replaced = std::exchange(impl.fresh, true);
  }
  if (replaced) ++impl.dropped;  // the loop never took the one before
  pw_loop_signal_event(pw_thread_loop_get_loop(impl.loop), impl.wake);
}

std::optional<VkExtent2D> PipeWireSource::wantedExtent() const {
  std::lock_guard lock(impl_->stateLock);
  if (!impl_->negotiated) return std::nullopt;
  return VkExtent2D{impl_->format.size.width, impl_->format.size.height};
}

bool PipeWireSource::taking() const {
  std::lock_guard lock(impl_->stateLock);
  return impl_->streaming && impl_->negotiated;
}

host::Output::Health PipeWireSource::health() const {
  const Impl& impl = *impl_;
  host::Output::Health health;
  health.kind = "pipewire";
  health.frames = impl.handed.load();
  health.dropped = impl.dropped.load();
  std::lock_guard lock(impl.stateLock);
  health.connected = impl.streaming && impl.negotiated;
  if (!impl.problem.empty())
    health.line = fmt::format("node {}: {}", impl.node, impl.problem);
  else if (!impl.connected)
    health.line = fmt::format("node {}: connecting", impl.node);
  else if (!health.connected)
    health.line = fmt::format("node {}: published, waiting for a consumer", impl.node);
  else if (impl.dmaBuf && !impl.refused)
    health.line = fmt::format("node {}: {}x{} {} to a consumer by dma-buf ({})", impl.node, impl.format.size.width,
                              impl.format.size.height, formatName(impl.format.format),
                              gpu::drm::describeModifier(impl.modifier));
  else
    health.line = fmt::format("node {}: {}x{} {} to a consumer by shm ({})", impl.node, impl.format.size.width,
                              impl.format.size.height, formatName(impl.format.format), impl.sharedWhy);
  return health;
}

std::shared_ptr<host::ImageHandOver> PipeWireSource::images() { return impl_->pool; }

std::unique_ptr<host::Output> makePipeWireOutput(const gpu::Device& device, std::string name, std::string node,
                                                 const maths::OutputWarp& warp, VkExtent2D extent) {
  auto source = std::make_unique<PipeWireSource>(std::move(node), extent, 60, PipeWireSource::dmaBufOffer(device));
  return std::make_unique<host::ReadbackOutput>(device, std::move(name), warp, extent, std::move(source));
}

}  // namespace vitrine::rig
