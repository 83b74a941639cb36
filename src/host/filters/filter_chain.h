#pragma once
// ISF filters after a scene (docs/ISF.md, "Filters and transitions"): files with an inputImage, run in
// order over the scene's HDR frame in place, before the flash guard, the outputs and their warps. Each
// filter is an isf::Runner with its own images (gpu::FrameResources, sized with the frame) and its
// inputs' values as a parameter schema, so --set filter.NAME.KEY, the panel, the settings file and
// films treat them as they treat a scene's. An empty chain records nothing: no pass, no copy.
#include "frame/frame_input.h"
#include "gpu/frame_resources.h"
#include "gpu/pass_timer.h"
#include "gpu/program.h"
#include "gpu/stream.h"
#include "params/schema.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::host {

// One filter as the command line and the settings file name it: its file and its inputs' values.
struct FilterSpec {
  std::filesystem::path file;
  params::KeyValues values;
};

// What --set filter.NAME.KEY and the manifest call a filter: its file's name without the extension.
std::string filterName(const std::filesystem::path& file);

// The chain as the settings file keeps it, [{"file": "...", "values": {"KEY": VALUE}}], and back; an
// entry that is not of that shape is said in `warnings` and skipped.
nlohmann::ordered_json chainJson(const std::vector<FilterSpec>& chain);
std::vector<FilterSpec> chainFromJson(const nlohmann::ordered_json& json, std::vector<std::string>& warnings);

class FilterChain {
 public:
  FilterChain(const gpu::Device& device, gpu::ProgramLibrary& programs);
  ~FilterChain();
  FilterChain(const FilterChain&) = delete;
  FilterChain& operator=(const FilterChain&) = delete;

  // Loads, compiles and appends a filter with its values. Throws isf::IsfError (the file's own line)
  // or vitrine::Error (not a filter; a value refused, naming filter.NAME.KEY).
  void add(const FilterSpec& spec);
  void remove(size_t index);  // retired behind the frames that used it
  void clear();
  bool empty() const { return filters_.empty(); }
  size_t size() const { return filters_.size(); }
  const std::string& name(size_t index) const;
  const std::filesystem::path& file(size_t index) const;
  params::Bound parameters(size_t index);
  // key=value pairs for one filter, judged together; on failure nothing changes and the reason is
  // returned.
  std::string applyParameters(size_t index, const params::KeyValues& values);
  // Every filter, its file and its values now: what the settings file keeps.
  std::vector<FilterSpec> specs();
  // Every filter's values as filter.NAME.KEY=VALUE (a film's manifest), exact.
  params::KeyValues snapshot();
  // "NAME FINGERPRINT" per filter, the fingerprint of its file's bytes: which code made a film.
  std::vector<std::string> fingerprints() const;

  // The filters over `frame` (the scene's HDR target, top row first), in place. `realtime`: DATE is the
  // wall clock's, else the simulation's (films do not depend on the day they were made).
  void record(VkCommandBuffer cmd, uint32_t slot, gpu::PassTimer* timer, gpu::StreamArena& stream, gpu::Image& frame,
              const FrameInput& input, bool drawing, bool realtime);

 private:
  struct Filter;
  const gpu::Device& device_;
  gpu::ProgramLibrary& programs_;
  std::vector<std::unique_ptr<Filter>> filters_;
};

}  // namespace vitrine::host
