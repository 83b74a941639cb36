// vitrine_dmabuf_consumer NODE COUNT [SECONDS]: takes COUNT frames of the PipeWire node NODE as
// DMA-BUFs only (BGRx, the LINEAR modifier: a layout the CPU can read through mmap), checks each is
// a frame (a plane of the negotiated size, not all black) and exits 0; exits 1 saying why when no
// DMA-BUF format is agreed within SECONDS (10) or a frame is wrong. A consumer for trying the
// hand-over where the driver exports DMA-BUFs and a PipeWire daemon runs; nothing in the suite needs it.
#include <linux/dma-buf.h>
#include <pipewire/pipewire.h>
#include <spa/param/video/format-utils.h>
#include <spa/pod/builder.h>
#include <sys/ioctl.h>
#include <sys/mman.h>

#include <array>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

constexpr uint64_t kLinear = 0;

struct Consumer {
  pw_main_loop* loop = nullptr;
  pw_stream* stream = nullptr;
  spa_video_info_raw format{};
  int wanted = 0, taken = 0;
  int status = 1;
  std::string why = "no DMA-BUF format was agreed";
};

void finish(Consumer& consumer, int status, std::string why) {
  consumer.status = status;
  consumer.why = std::move(why);
  pw_main_loop_quit(consumer.loop);
}

void onParamChanged(void* data, uint32_t id, const spa_pod* param) {
  auto& consumer = *static_cast<Consumer*>(data);
  if (id != SPA_PARAM_Format || !param) return;
  spa_format_video_raw_parse(param, &consumer.format);
  std::printf("agreed: %ux%u, modifier %#llx\n", consumer.format.size.width, consumer.format.size.height,
              (unsigned long long)consumer.format.modifier);
  std::array<uint8_t, 512> storage;
  spa_pod_builder builder = SPA_POD_BUILDER_INIT(storage.data(), uint32_t(storage.size()));
  const spa_pod* buffers = static_cast<const spa_pod*>(spa_pod_builder_add_object(
      &builder, SPA_TYPE_OBJECT_ParamBuffers, SPA_PARAM_Buffers, SPA_PARAM_BUFFERS_dataType,
      SPA_POD_CHOICE_FLAGS_Int(1 << SPA_DATA_DmaBuf)));
  pw_stream_update_params(consumer.stream, &buffers, 1);
}

void onProcess(void* data) {
  auto& consumer = *static_cast<Consumer*>(data);
  pw_buffer* buffer = pw_stream_dequeue_buffer(consumer.stream);
  if (!buffer) return;
  const spa_data& plane = buffer->buffer->datas[0];
  const uint32_t width = consumer.format.size.width, height = consumer.format.size.height;
  if (plane.type != SPA_DATA_DmaBuf) return finish(consumer, 1, "a buffer that is not a DMA-BUF");
  const uint32_t stride = uint32_t(plane.chunk->stride), offset = plane.chunk->offset;
  if (stride < width * 4) return finish(consumer, 1, "a row pitch narrower than a row");
  const size_t bytes = size_t(offset) + size_t(stride) * height;
  void* mapped = mmap(nullptr, bytes, PROT_READ, MAP_SHARED, int(plane.fd), 0);
  if (mapped == MAP_FAILED) return finish(consumer, 1, "the DMA-BUF cannot be mapped");
  dma_buf_sync sync{DMA_BUF_SYNC_START | DMA_BUF_SYNC_READ};
  ioctl(int(plane.fd), DMA_BUF_IOCTL_SYNC, &sync);
  uint64_t sum = 0;
  for (uint32_t y = 0; y < height; ++y) {
    const auto* row = static_cast<const uint8_t*>(mapped) + offset + size_t(y) * stride;
    for (uint32_t x = 0; x < width * 4; x += 4) sum += row[x] + row[x + 1] + row[x + 2];
  }
  sync.flags = DMA_BUF_SYNC_END | DMA_BUF_SYNC_READ;
  ioctl(int(plane.fd), DMA_BUF_IOCTL_SYNC, &sync);
  munmap(mapped, bytes);
  pw_stream_queue_buffer(consumer.stream, buffer);
  const double mean = double(sum) / (3.0 * width * height);
  std::printf("frame %d: %ux%u, pitch %u, mean %.1f\n", consumer.taken, width, height, stride, mean);
  if (mean < 1.0) return finish(consumer, 1, "a black frame");
  if (++consumer.taken == consumer.wanted) finish(consumer, 0, "");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s NODE COUNT [SECONDS]\n", argv[0]);
    return 2;
  }
  pw_init(&argc, &argv);
  Consumer consumer;
  consumer.wanted = std::max(1, std::atoi(argv[2]));
  const int seconds = argc > 3 ? std::max(1, std::atoi(argv[3])) : 10;
  consumer.loop = pw_main_loop_new(nullptr);
  pw_stream_events events{};
  events.version = PW_VERSION_STREAM_EVENTS;
  events.param_changed = onParamChanged;
  events.process = onProcess;
  consumer.stream = pw_stream_new_simple(
      pw_main_loop_get_loop(consumer.loop), "vitrine-dmabuf-consumer",
      pw_properties_new(PW_KEY_MEDIA_TYPE, "Video", PW_KEY_MEDIA_CATEGORY, "Capture", PW_KEY_MEDIA_ROLE, "Camera",
                        PW_KEY_TARGET_OBJECT, argv[1], nullptr),
      &events, &consumer);
  std::array<uint8_t, 1024> storage;
  spa_pod_builder builder = SPA_POD_BUILDER_INIT(storage.data(), uint32_t(storage.size()));
  spa_pod_frame object, choice;
  spa_pod_builder_push_object(&builder, &object, SPA_TYPE_OBJECT_Format, SPA_PARAM_EnumFormat);
  spa_pod_builder_add(&builder, SPA_FORMAT_mediaType, SPA_POD_Id(SPA_MEDIA_TYPE_video), SPA_FORMAT_mediaSubtype,
                      SPA_POD_Id(SPA_MEDIA_SUBTYPE_raw), SPA_FORMAT_VIDEO_format, SPA_POD_Id(SPA_VIDEO_FORMAT_BGRx), 0);
  spa_pod_builder_prop(&builder, SPA_FORMAT_VIDEO_modifier, SPA_POD_PROP_FLAG_MANDATORY | SPA_POD_PROP_FLAG_DONT_FIXATE);
  spa_pod_builder_push_choice(&builder, &choice, SPA_CHOICE_Enum, 0);
  spa_pod_builder_long(&builder, int64_t(kLinear));
  spa_pod_builder_long(&builder, int64_t(kLinear));
  spa_pod_builder_pop(&builder, &choice);
  const spa_rectangle size{320, 180}, smallest{1, 1}, largest{8192, 8192};
  spa_pod_builder_add(&builder, SPA_FORMAT_VIDEO_size, SPA_POD_CHOICE_RANGE_Rectangle(&size, &smallest, &largest), 0);
  const spa_pod* params[] = {static_cast<const spa_pod*>(spa_pod_builder_pop(&builder, &object))};
  pw_stream_connect(consumer.stream, PW_DIRECTION_INPUT, PW_ID_ANY,
                    pw_stream_flags(PW_STREAM_FLAG_AUTOCONNECT | PW_STREAM_FLAG_MAP_BUFFERS), params, 1);
  spa_source* timeout = pw_loop_add_timer(
      pw_main_loop_get_loop(consumer.loop), [](void* data, uint64_t) { pw_main_loop_quit(static_cast<pw_main_loop*>(data)); },
      consumer.loop);
  timespec after{seconds, 0}, never{0, 0};
  pw_loop_update_timer(pw_main_loop_get_loop(consumer.loop), timeout, &after, &never, false);
  pw_main_loop_run(consumer.loop);
  if (consumer.status != 0)
    std::fprintf(stderr, "vitrine_dmabuf_consumer: %s (%d of %d frames)\n", consumer.why.c_str(), consumer.taken,
                 consumer.wanted);
  else
    std::printf("%d frames taken as DMA-BUFs\n", consumer.taken);
  pw_stream_destroy(consumer.stream);
  pw_main_loop_destroy(consumer.loop);
  pw_deinit();
  return consumer.status;
}
