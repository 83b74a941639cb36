#pragma once
// An ISF transition (startImage, endImage, progress: docs/ISF.md, "Filters and transitions") drawn in
// place of the cross-fade's mix: the scene going out as startImage, the one coming in as endImage,
// progress the fade's weight. Its other inputs are parameters (--set transition.KEY=VALUE, the
// settings file); progress is the host's and none of them.
#include "frame/frame_input.h"
#include "gpu/frame_resources.h"
#include "gpu/pass_timer.h"
#include "gpu/program.h"
#include "gpu/stream.h"
#include "params/schema.h"

#include <filesystem>
#include <memory>
#include <string>

namespace vitrine::host {

class IsfTransition {
 public:
  // Loads and compiles `file`. Throws isf::IsfError (the file's line) or vitrine::Error (not a
  // transition).
  IsfTransition(const gpu::Device& device, gpu::ProgramLibrary& programs, const std::filesystem::path& file);
  ~IsfTransition();
  IsfTransition(const IsfTransition&) = delete;
  IsfTransition& operator=(const IsfTransition&) = delete;

  const std::filesystem::path& file() const;
  params::Bound parameters();
  std::string applyParameters(const params::KeyValues& values);

  // `from` becoming `to` at `progress` (0..1), written over `from` (a renderer's target, whose size the
  // transition draws at; `to` may have another).
  void record(VkCommandBuffer cmd, uint32_t slot, gpu::PassTimer* timer, gpu::StreamArena& stream, gpu::Image& from,
              gpu::Image& to, float progress, const FrameInput& input, bool realtime);

 private:
  struct State;
  const gpu::Device& device_;
  std::unique_ptr<State> state_;
};

}  // namespace vitrine::host
