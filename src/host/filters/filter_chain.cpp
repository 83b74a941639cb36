#include "host/filters/filter_chain.h"

#include <fmt/format.h>

#include <optional>
#include <utility>

#include "core/bounded_file.h"
#include "core/error.h"
#include "core/printable.h"
#include "frame/frame_context.h"
#include "host/offline/record_manifest.h"
#include "isf/gpu/isf_runner.h"
#include "isf/isf_values.h"
#include "params/settings_file.h"

namespace vitrine::host {

struct FilterChain::Filter {
  std::string name;
  std::string fingerprint;
  std::shared_ptr<const isf::LoadedFile> file;
  std::optional<params::Schema> schema;
  isf::Values values;
  // What a GpuContext holds: the runner keeps its images in a set of its own. Before the runner.
  std::unique_ptr<gpu::FrameResources> resources;
  std::unique_ptr<isf::Runner> runner;
  params::Bound bound() { return params::bindSettings(*schema, values); }
};

std::string filterName(const std::filesystem::path& file) { return file.stem().string(); }

nlohmann::ordered_json chainJson(const std::vector<FilterSpec>& chain) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const FilterSpec& spec : chain) {
    nlohmann::ordered_json values = nlohmann::ordered_json::object();
    for (const auto& [key, text] : spec.values) values[key] = text;
    out.push_back({{"file", spec.file.string()}, {"values", std::move(values)}});
  }
  return out;
}

std::vector<FilterSpec> chainFromJson(const nlohmann::ordered_json& json, std::vector<std::string>& warnings) {
  std::vector<FilterSpec> chain;
  if (!json.is_array()) return chain;
  for (const auto& entry : json) {
    if (!entry.is_object() || !entry.contains("file") || !entry.at("file").is_string()) {
      warnings.push_back(fmt::format("a filter without a \"file\" ({}) is skipped", printable(entry.dump().substr(0, 80))));
      continue;
    }
    FilterSpec spec{entry.at("file").get<std::string>(), {}};
    if (const auto values = entry.find("values"); values != entry.end() && values->is_object())
      for (const auto& [key, value] : values->items())
        spec.values.emplace_back(key, value.is_string() ? value.get<std::string>() : value.dump());
    chain.push_back(std::move(spec));
  }
  return chain;
}

FilterChain::FilterChain(const gpu::Device& device, gpu::ProgramLibrary& programs)
    : device_(device), programs_(programs) {}

FilterChain::~FilterChain() { clear(); }

void FilterChain::add(const FilterSpec& spec) {
  auto filter = std::make_unique<Filter>();
  filter->file = isf::loadFile(spec.file);
  const isf::Document& document = filter->file->document;
  if (document.kind != isf::Kind::Filter)
    throw Error(fmt::format("{} is an ISF {}, not a filter: a filter has an image input named inputImage",
                            spec.file.string(), isf::kindName(document.kind)));
  filter->name = filterName(spec.file);
  filter->fingerprint = fingerprint(readBoundedFile(spec.file, isf::kMaxFileBytes));
  filter->schema.emplace(isf::makeSchema(document));
  filter->values = isf::defaultValues(document);
  if (auto why = params::applyValues(filter->bound(), spec.values); !why.empty())
    throw Error(fmt::format("filter {} ({}) rejects {}", filter->name, spec.file.string(), why));
  filter->resources = std::make_unique<gpu::FrameResources>(device_);
  filter->runner = std::make_unique<isf::Runner>(GpuContext{device_, programs_, *filter->resources}, filter->file);
  if (auto why = filter->runner->update(filter->values); !why.empty())
    std::fprintf(stderr, "vitrine: filter %s: %s\n", filter->name.c_str(), why.c_str());
  filters_.push_back(std::move(filter));
}

void FilterChain::remove(size_t index) {
  if (index >= filters_.size()) return;
  // Frames in flight may still use its pipelines and images: retired, not waited for.
  device_.retire(std::move(filters_[index]));
  filters_.erase(filters_.begin() + std::ptrdiff_t(index));
}

void FilterChain::clear() {
  while (!filters_.empty()) remove(filters_.size() - 1);
}

const std::string& FilterChain::name(size_t index) const { return filters_.at(index)->name; }
const std::filesystem::path& FilterChain::file(size_t index) const { return filters_.at(index)->file->path; }
params::Bound FilterChain::parameters(size_t index) { return filters_.at(index)->bound(); }

std::string FilterChain::applyParameters(size_t index, const params::KeyValues& values) {
  Filter& filter = *filters_.at(index);
  std::string why = params::applyValues(filter.bound(), values);
  if (why.empty())
    if (auto unread = filter.runner->update(filter.values); !unread.empty())
      std::fprintf(stderr, "vitrine: filter %s: %s\n", filter.name.c_str(), unread.c_str());
  return why;
}

std::vector<FilterSpec> FilterChain::specs() {
  std::vector<FilterSpec> out;
  for (const auto& filter : filters_) out.push_back({filter->file->path, params::snapshot(filter->bound(), false)});
  return out;
}

params::KeyValues FilterChain::snapshot() {
  params::KeyValues out;
  for (const auto& filter : filters_)
    for (auto& [key, text] : params::snapshot(filter->bound(), true))
      out.emplace_back(fmt::format("filter.{}.{}", filter->name, key), std::move(text));
  return out;
}

std::vector<std::string> FilterChain::fingerprints() const {
  std::vector<std::string> out;
  for (const auto& filter : filters_) out.push_back(filter->name + " " + filter->fingerprint);
  return out;
}

void FilterChain::record(VkCommandBuffer cmd, uint32_t slot, gpu::PassTimer* timer, gpu::StreamArena& stream,
                         gpu::Image& frame, const FrameInput& input, bool drawing, bool realtime) {
  const VkExtent2D extent = frame.extent2d();
  for (const auto& filter : filters_) {
    filter->runner->resize(extent);  // nothing when the size is the one it has
    const FrameContext context{device_, cmd, timer, frame, *filter->resources, stream, input, slot, drawing};
    const isf::SourceImage sources[] = {{"inputImage", &frame}};
    isf::RunInput run{.values = filter->values,
                      .time = input.time,
                      .timeDelta = input.dt,
                      .frameIndex = input.frame,
                      .date = realtime ? isf::wallClockDate() : isf::simulatedDate(input.time),
                      .sources = sources,
                      .wave = input.soundWave,
                      .spectrum = input.soundSpectrum};
    filter->runner->record(context, run, frame);
  }
}

}  // namespace vitrine::host
