#include "host/filters/isf_transition.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "core/error.h"
#include "frame/frame_context.h"
#include "isf/gpu/isf_runner.h"
#include "isf/isf_values.h"

namespace vitrine::host {

struct IsfTransition::State {
  std::shared_ptr<const isf::LoadedFile> file;
  std::optional<params::Schema> schema;
  isf::Values values;
  size_t progress = 0;  // the progress input's index among the values
  std::unique_ptr<gpu::FrameResources> resources;  // before the runner, which declares in them
  std::unique_ptr<isf::Runner> runner;
  VkExtent2D extent{0, 0};
};

IsfTransition::IsfTransition(const gpu::Device& device, gpu::ProgramLibrary& programs, uint32_t framesInFlight,
                             const std::filesystem::path& file)
    : device_(device), state_(std::make_unique<State>()) {
  State& s = *state_;
  s.file = isf::loadFile(file);
  const isf::Document& document = s.file->document;
  if (document.kind != isf::Kind::Transition)
    throw Error(fmt::format("{} is an ISF {}, not a transition: a transition has image inputs startImage and "
                            "endImage and a float input progress",
                            file.string(), isf::kindName(document.kind)));
  s.schema.emplace(isf::makeSchema(document, {"progress"}));
  s.values = isf::defaultValues(document);
  for (size_t i = 0; i < document.inputs.size(); ++i)
    if (document.inputs[i].name == "progress") s.progress = i;
  s.resources = std::make_unique<gpu::FrameResources>(device);
  s.resources->setFramesInFlight(framesInFlight);
  s.runner = std::make_unique<isf::Runner>(GpuContext{device, programs, *s.resources}, s.file);
  if (auto why = s.runner->update(s.values); !why.empty())
    std::fprintf(stderr, "vitrine: transition %s: %s\n", file.string().c_str(), why.c_str());
}

// The runner's pipelines and images may be in use by frames in flight.
IsfTransition::~IsfTransition() { device_.retire(std::move(state_)); }

const std::filesystem::path& IsfTransition::file() const { return state_->file->path; }

params::Bound IsfTransition::parameters() { return params::bindSettings(*state_->schema, state_->values); }

std::string IsfTransition::applyParameters(const params::KeyValues& values) {
  std::string why = params::applyValues(parameters(), values);
  if (why.empty()) state_->runner->update(state_->values);
  return why;
}

void IsfTransition::record(VkCommandBuffer cmd, uint32_t slot, gpu::PassTimer* timer, gpu::StreamArena& stream,
                           gpu::Image& from, gpu::Image& to, float progress, const FrameInput& input, bool realtime) {
  State& s = *state_;
  const VkExtent2D extent = from.extent2d();
  if (s.extent.width != extent.width || s.extent.height != extent.height) {
    s.extent = extent;
    s.resources->resize(extent);
  }
  s.resources->beginFrame(cmd, stream, slot);
  s.values.inputs[s.progress].number[0] = std::clamp(progress, 0.0f, 1.0f);
  const FrameContext context{device_, cmd, timer, from, *s.resources, stream, input, slot, true};
  const isf::SourceImage sources[] = {{"startImage", &from}, {"endImage", &to}};
  const isf::RunInput run{.values = s.values,
                          .time = input.time,
                          .timeDelta = input.dt,
                          .frameIndex = input.frame,
                          .date = realtime ? isf::wallClockDate() : isf::simulatedDate(input.time),
                          .sources = sources};
  s.runner->record(context, run, from);
}

}  // namespace vitrine::host
