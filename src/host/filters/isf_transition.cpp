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
  std::unique_ptr<gpu::FrameResources> resources;  // what a GpuContext holds (the runner keeps its own)
  std::unique_ptr<isf::Runner> runner;
};

IsfTransition::IsfTransition(const gpu::Device& device, gpu::ProgramLibrary& programs,
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
  s.runner->resize(from.extent2d());  // nothing when the size is the one it has
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
