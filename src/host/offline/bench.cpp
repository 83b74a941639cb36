// vitrine bench: every pass timed with GPU timestamps over a fixed number of frames after a warm-up,
// medians and 95th percentiles per pass, written as JSON with the device and each scene's full
// parameter values (from its schema), so a figure can always be traced to what produced it.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string_view>
#include <system_error>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/output_path.h"
#include "core/resident_memory.h"
#include "core/stats.h"
#include "gpu/dmabuf_export.h"
#include "gpu/memory_ledger.h"
#include "host/user_presets.h"
#include "host/modes.h"
#include "host/filters/filter_options.h"
#include "host/offline/offscreen.h"
#include "host/present/readback_output.h"
#include "params/settings_file.h"
#include "rig/dmabuf_pool.h"
#include "rig/pipewire_source.h"

namespace vitrine::host {
namespace {

using Json = nlohmann::ordered_json;

Json summary(const std::vector<double>& samples) {
  return {{"median_ms", percentile(samples, 50)}, {"p95_ms", percentile(samples, 95)}};
}

// The --set values for `scene`: those naming it, and the unqualified ones; benching every scene, an
// unqualified key goes to the scenes that have it (`--set tier=low` for all but the calibration card).
params::KeyValues benchParameters(const Options& options, const std::string& scene, bool everyScene) {
  if (!everyScene) return parametersFor(options, scene, true);
  params::KeyValues values = parametersFor(options, scene, false);
  const params::Schema& schema = findScene(scene)->schema();
  for (const auto& setting : options.parameters)
    if (setting.scene.empty() && schema.find(setting.key)) values.emplace_back(setting.key, setting.value);
  return values;
}

// bench --publish: frames handed over as a published output's are, then let go, as by a consumer that
// takes every frame; what is timed is the GPU's part (the publish passes), with no daemon needed. Where
// the device exports DMA-BUFs, each frame is copied into one of three exported B,G,R,A images (what a
// consumer such as OBS takes), which it gives straight back; else, or with VITRINE_PUBLISH=shm, it is
// read back as for a consumer of shared memory.
class DiscardingSink final : public FrameSink {
 public:
  DiscardingSink(const gpu::Device& device, VkExtent2D size) {
    if (const char* path = std::getenv("VITRINE_PUBLISH"); path && std::string_view(path) == "shm") {
      std::printf("publish    by shm: VITRINE_PUBLISH=shm\n");
      return;
    }
    const rig::DmaBufOffer offer = rig::PipeWireSource::dmaBufOffer(device);
    if (!offer.device || offer.bgraModifiers.empty()) {
      std::printf("publish    by shm: %s\n", offer.why.c_str());
      return;
    }
    pool_ = std::make_shared<rig::DmaBufPool>([this] { giveBack(); });
    std::vector<uint64_t> modifiers;
    for (const auto& entry : offer.bgraModifiers) modifiers.push_back(entry.modifier);
    try {
      for (const int& key : keys_) {
        auto image = std::make_unique<gpu::ExportedImage>(device, offer.bgra, size, VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                                          modifiers, "bench dma-buf");
        modifier_ = image->modifier();
        pool_->add(&key, std::move(image), size, offer.bgra);
        pool_->given(&key);
      }
    } catch (const Error& e) {
      std::printf("publish    by shm: DMA-BUF failed: %s\n", e.what());
      pool_.reset();
      return;
    }
    pool_->setActive(true);
    std::printf("publish    by dma-buf: B,G,R,A, %s\n", gpu::drm::describeModifier(modifier_).c_str());
  }
  void frame(const PublishedFrame&) override { ++frames_; }
  std::shared_ptr<ImageHandOver> images() override { return pool_; }
  Output::Health health() const override { return {.kind = "bench", .line = "discarded", .frames = frames_}; }

 private:
  void giveBack() {  // on the frame thread, once a copy has finished
    uint64_t superseded = 0;
    while (const auto done = pool_->takeDone(superseded)) {
      pool_->given(done->key);
      ++frames_;
    }
  }
  std::shared_ptr<rig::DmaBufPool> pool_;
  std::array<int, 3> keys_{};
  uint64_t modifier_ = 0;
  uint64_t frames_ = 0;
};

Json benchScene(const gpu::Device& device, const Options& options, const std::string& scene, bool everyScene) {
  OffscreenConfig config{scene, options.size.value_or(VkExtent2D{1920, 1080}), options.time, options.seed,
                         options.reducedMotion, presetsFor(options, scene, true), benchParameters(options, scene, everyScene)};
  config.flashGuard = flashGuardOn(options);
  config.filters = filterSpecs(options);
  config.presetFiles = presetFilesFor(options, scene);
  Offscreen offscreen(device, config);
  std::optional<ReadbackOutput> published;
  if (options.publish) {
    published.emplace(device, "publish", maths::OutputWarp{}, config.size,
                      std::make_unique<DiscardingSink>(device, config.size));
    offscreen.addOutput(*published);
  }
  // Warm-up: pipeline compilation, clocks ramping, caches; not counted.
  for (uint32_t i = 0; i < options.warmup; ++i) offscreen.renderFrame();
  std::vector<double> gpu, cpu;
  std::vector<std::string> order;  // passes in recording order
  std::map<std::string, std::vector<double>> passes;
  std::map<std::string, std::array<std::vector<double>, 3>> invocations;  // vertex, fragment, compute
  for (uint32_t i = 0; i < options.frames; ++i) {
    const FrameTimes times = offscreen.renderFrame();
    gpu.push_back(times.gpuMs);
    cpu.push_back(times.cpuMs);
    for (const auto& pass : times.passes) {
      if (!passes.count(pass.name)) order.push_back(pass.name);
      passes[pass.name].push_back(pass.ms);
      if (!pass.invocations) continue;
      auto& counts = invocations[pass.name];
      counts[0].push_back(double(pass.invocations->vertex));
      counts[1].push_back(double(pass.invocations->fragment));
      counts[2].push_back(double(pass.invocations->compute));
    }
  }
  std::printf("%-10s gpu median %8.3f ms  p95 %8.3f ms   cpu median %6.3f ms\n", scene.c_str(), percentile(gpu, 50),
              percentile(gpu, 95), percentile(cpu, 50));
  Json result{{"scene", scene},
              {"parameters", params::valuesJson(offscreen.parameters())},
              {"gpu", summary(gpu)},
              {"cpu", summary(cpu)},
              {"passes", Json::array()}};
  // What the scene holds on the device (every VkDeviceMemory of the process, while it is alive), and
  // the process's resident memory: at 10^8 noodle segments, gigabytes that the check before allocation
  // promised would fit.
  const gpu::MemoryTally held = gpu::liveDeviceMemory();
  result["device_memory"] = {{"allocations", held.allocations}, {"mib", double(held.bytes) / 1048576.0}};
  if (const auto resident = residentBytes()) result["resident_mib"] = double(*resident) / 1048576.0;
  for (const auto& name : order) {
    std::printf("  %-24s median %8.3f ms  p95 %8.3f ms", name.c_str(), percentile(passes[name], 50),
                percentile(passes[name], 95));
    Json pass{{"name", name}};
    pass.update(summary(passes[name]));
    if (const auto counted = invocations.find(name); counted != invocations.end()) {
      // Medians a frame: a render pass's fragments set its floor on a GPU's graphics part.
      const auto& [vertices, fragments, threads] = counted->second;
      const double vertex = percentile(vertices, 50), fragment = percentile(fragments, 50),
                   compute = percentile(threads, 50);
      pass["invocations"] = {{"vertex", vertex}, {"fragment", fragment}, {"compute", compute}};
      std::printf("   vertex %.4g  fragment %.4g  compute %.4g", vertex, fragment, compute);
    }
    std::printf("\n");
    result["passes"].push_back(std::move(pass));
  }
  if (options.pipelineStats) {  // what the driver's compiler made of each pipeline: registers, spills, ...
    result["pipelines"] = Json::array();
    for (const auto& [label, executables] : offscreen.programs().pipelineStatistics()) {
      for (const auto& line : executables) std::printf("  pipeline %s: %s\n", label.c_str(), line.c_str());
      result["pipelines"].push_back({{"pipeline", label}, {"executables", executables}});
    }
  }
  return result;
}

void writeJson(const std::string& path, const Json& json) {
  const std::string text = json.dump(2) + "\n";
  replaceAtomically(path, [&](const std::filesystem::path& temporary) {
    errno = 0;
    std::ofstream file(temporary, std::ios::binary);
    file << text;
    file.close();  // flushes: a full disk shows here
    if (!file)
      throw Error(fmt::format("Cannot write {}: {}.", path,
                              errno ? std::generic_category().message(errno) : "the write failed"));
  });
}

}  // namespace

int runBench(const Options& options) {
  checkWritable(options.out);
  std::vector<std::string> scenes;
  if (options.scene.empty() || options.scene == "all")
    for (const auto& info : sceneRegistry()) scenes.emplace_back(info.name);
  else
    scenes.push_back(options.scene);
  for (const auto& scene : scenes)  // a typo fails before the device is made
    if (!findScene(scene)) throw Error(unknownScene(scene));
  const bool everyScene = scenes.size() > 1;
  if (everyScene)
    for (const auto& setting : options.parameters)
      if (setting.scene.empty() &&
          std::none_of(scenes.begin(), scenes.end(), [&](const auto& s) { return findScene(s)->schema().find(setting.key); }))
        throw Error(fmt::format("No scene has a parameter '{}' (--set {}={}).", setting.key, setting.key, setting.value));
  gpu::Instance instance({options.validation, {}});
  gpu::Device device(instance, {options.device, VK_NULL_HANDLE, options.pipelineStats});
  if (options.pipelineStats && !device.capturesPipelineStatistics())
    std::fprintf(stderr, "vitrine: %s cannot report its pipelines' statistics (VK_KHR_pipeline_executable_properties)\n",
                 device.properties().deviceName);
  if (options.pipelineStats && !device.countsInvocations())
    std::fprintf(stderr, "vitrine: %s cannot count its passes' invocations (pipelineStatisticsQuery)\n",
                 device.properties().deviceName);

  const VkExtent2D size = options.size.value_or(VkExtent2D{1920, 1080});
  const auto& p = device.properties();
  Json json{{"device", p.deviceName},
            {"driver_version", p.driverVersion},
            {"vulkan", fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(p.apiVersion), VK_API_VERSION_MINOR(p.apiVersion),
                                   VK_API_VERSION_PATCH(p.apiVersion))},
            {"size", {size.width, size.height}},
            {"frames", options.frames},
            {"warmup", options.warmup},
            {"scenes", Json::array()}};
  std::printf("%s, %ux%u, %u frames after %u warm-up\n", device.describe().c_str(), size.width, size.height,
              options.frames, options.warmup);
  for (const auto& scene : scenes) json["scenes"].push_back(benchScene(device, options, scene, everyScene));
  writeJson(options.out, json);
  if (instance.validationMessages() > 0) {
    std::fprintf(stderr, "%d validation messages: failing.\n", instance.validationMessages());
    return 3;
  }
  return 0;
}

}  // namespace vitrine::host
