#include "gpu/check.h"
#include "host/modes.h"
#include "host/offscreen.h"
#include "core/atomic_file.h"
#include "core/output_path.h"
#include "core/stats.h"

#include <cerrno>
#include <cstdio>
#include <fmt/format.h>
#include <fstream>
#include <map>

namespace vitrine::host {
namespace {

struct Series {
  std::vector<double> samples;
  std::string json(const char* indent) const {
    return fmt::format("{{\"median_ms\": {:.4f}, \"p95_ms\": {:.4f}}}", percentile(samples, 50), percentile(samples, 95))
        .insert(0, indent);
  }
};

struct SceneResult {
  std::string scene;
  std::vector<std::string> order;  // passes in recording order
  std::map<std::string, Series> passes;
  Series gpu, cpu;
};

SceneResult benchScene(const gpu::Device& device, const Options& options, const std::string& scene) {
  OffscreenConfig config{scene, options.size.value_or(VkExtent2D{1920, 1080}), options.time, options.seed,
                         options.reducedMotion, parametersFor(options, scene)};
  Offscreen offscreen(device, config);
  // Warm-up: pipeline compilation, clocks ramping, caches; not counted.
  for (uint32_t i = 0; i < options.warmup; ++i) offscreen.renderFrame();
  SceneResult result{scene, {}, {}, {}, {}};
  for (uint32_t i = 0; i < options.frames; ++i) {
    const FrameTimes times = offscreen.renderFrame();
    result.gpu.samples.push_back(times.gpuMs);
    result.cpu.samples.push_back(times.cpuMs);
    for (const auto& pass : times.passes) {
      if (!result.passes.count(pass.name)) result.order.push_back(pass.name);
      result.passes[pass.name].samples.push_back(pass.ms);
    }
  }
  return result;
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
    if (!findScene(scene)) throw Error(fmt::format("Unknown scene '{}'; vitrine --list-scenes shows them.", scene));
  gpu::Instance instance({options.validation, {}});
  gpu::Device device(instance, {options.device});

  const VkExtent2D size = options.size.value_or(VkExtent2D{1920, 1080});
  std::string json = fmt::format(
      "{{\n  \"device\": \"{}\",\n  \"driver_version\": {},\n  \"vulkan\": \"{}.{}.{}\",\n  \"size\": [{}, {}],\n"
      "  \"frames\": {},\n  \"warmup\": {},\n  \"parameters\": {{",
      device.properties().deviceName, device.properties().driverVersion,
      VK_API_VERSION_MAJOR(device.properties().apiVersion), VK_API_VERSION_MINOR(device.properties().apiVersion),
      VK_API_VERSION_PATCH(device.properties().apiVersion), size.width, size.height, options.frames, options.warmup);
  for (size_t i = 0; i < options.parameters.size(); ++i) {
    const SceneSetting& set = options.parameters[i];
    json += fmt::format("{}\"{}{}{}\": \"{}\"", i ? ", " : "", set.scene, set.scene.empty() ? "" : ".", set.key,
                        set.value);
  }
  json += "},\n  \"scenes\": [\n";

  std::printf("%s, %ux%u, %u frames after %u warm-up\n", device.describe().c_str(), size.width, size.height,
              options.frames, options.warmup);
  for (size_t s = 0; s < scenes.size(); ++s) {
    const SceneResult r = benchScene(device, options, scenes[s]);
    std::printf("%-10s gpu median %8.3f ms  p95 %8.3f ms   cpu median %6.3f ms\n", r.scene.c_str(),
                percentile(r.gpu.samples, 50), percentile(r.gpu.samples, 95), percentile(r.cpu.samples, 50));
    json += fmt::format("    {{\n      \"scene\": \"{}\",\n      \"gpu\": {},\n      \"cpu\": {},\n      \"passes\": [\n",
                        r.scene, r.gpu.json(""), r.cpu.json(""));
    for (size_t p = 0; p < r.order.size(); ++p) {
      const Series& series = r.passes.at(r.order[p]);
      std::printf("  %-24s median %8.3f ms  p95 %8.3f ms\n", r.order[p].c_str(), percentile(series.samples, 50),
                  percentile(series.samples, 95));
      json += fmt::format("        {{\"name\": \"{}\", \"median_ms\": {:.4f}, \"p95_ms\": {:.4f}}}{}\n", r.order[p],
                          percentile(series.samples, 50), percentile(series.samples, 95),
                          p + 1 < r.order.size() ? "," : "");
    }
    json += fmt::format("      ]\n    }}{}\n", s + 1 < scenes.size() ? "," : "");
  }
  json += "  ]\n}\n";
  replaceAtomically(options.out, [&](const std::filesystem::path& temporary) {
    errno = 0;
    std::ofstream file(temporary, std::ios::binary);
    file << json;
    file.close();  // flushes: a full disk shows here
    if (!file)
      throw Error(fmt::format("Cannot write {}: {}.", options.out,
                              errno ? std::generic_category().message(errno) : "the write failed"));
  });
  if (instance.validationMessages() > 0) {
    std::fprintf(stderr, "%d validation messages: failing.\n", instance.validationMessages());
    return 3;
  }
  return 0;
}

}  // namespace vitrine::host
