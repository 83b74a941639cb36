#pragma once
// An ISF file run on the GPU: every pass of it drawn each frame into its buffers, and the last pass's
// picture written into an output image. What owns a runner (an ISF generator as a scene, a filter
// after any scene, a transition between two) tells it the inputs' values and the frames it samples;
// the runner keeps everything else.
//
// Built as a scene's passes are (frame/frame_context.h), so it lives with the scene or host part that
// owns it and uses its GpuContext:
//   - one pipeline per pass target format, from the file's SPIR-V (gpu::ProgramLibrary::provide), the
//     4-vertex strip of the translation's vertex stage (its .vs, or the generated one);
//   - the ISFFrame uniform block filled from isf::frameBlock each frame (frame.stream), RENDERSIZE and
//     PASSINDEX as push constants per pass, descriptors pushed per pass;
//   - every TARGET declared through the runner's own gpu::FrameResources (its images go with it: a
//     reloaded file's runner is retired whole, device.retire(std::move(runner)), never destroyed while
//     frames in flight may use it) at the size its WIDTH/HEIGHT expressions give
//     (re-evaluated each frame from the output's size and the values; redeclared when they change),
//     rgba8 as a GL host's buffers are, rgba32f when FLOAT; PERSISTENT ones as history pairs (the host
//     clears a new pair and flips it each frame);
//   - images stored bottom row first, as ISF (GL) expects: an input frame is flipped on its way in and
//     the output on its way out (shaders/isf/convert.comp), so no shader needs a flip;
//   - ISF computes on display values (sRGB-encoded, as a GL host shows them): the frames handed in are
//     encoded on the way in, and the output decoded to linear light on the way out.
//
// How a filter or a transition uses it:
//   Runner runner(context, isf::loadFile(path));      // in the owner's constructor
//   runner.resize(extent);                             // in resize(): the render size
//   runner.update(values);                             // in update(): buffer sizes, pictures
//   const SourceImage sources[] = {{"inputImage", &frame.target}};   // a filter
//   //  or {{"startImage", &from}, {"endImage", &to}} with values' "progress" set: a transition
//   runner.record(frame, {.values = values, .time = ..., .sources = sources}, output);
// A source is any rgba16f (or other sampled) image in linear light, top row first: a scene's target.
// It is copied (flipped, encoded) into the runner's own image of the output's size before the first
// pass, so `output` may be the very image a source names (a filter drawing over frame.target). The
// output is written as a storage image: frame.target, or any rgba16f image with storage usage.
#include "frame/frame_context.h"
#include "isf/isf_file.h"
#include "isf/isf_values.h"

#include <glm/vec4.hpp>

#include <array>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::isf {

// A frame an image input samples, by the input's NAME ("inputImage", "startImage", "endImage", or any
// other image input the owner feeds with frames rather than pictures).
struct SourceImage {
  std::string_view name;
  gpu::Image* image = nullptr;
};

struct RunInput {
  const Values& values;
  double time = 0.0;        // TIME, seconds
  float timeDelta = 0.0f;   // TIMEDELTA
  uint64_t frameIndex = 0;  // FRAMEINDEX
  // DATE: year, month (1..12), day (1..31), seconds since midnight.
  glm::vec4 date{2000.0f, 1.0f, 1.0f, 0.0f};
  std::span<const SourceImage> sources = {};
  // audio inputs: the newest mono samples, -1..1, oldest first; audioFFT inputs: magnitudes 0..1 from
  // the lowest frequency up. Each is resampled to the MAX the input asks for; empty: silence.
  std::span<const float> wave = {};
  std::span<const float> spectrum = {};
};

// DATE from the wall clock (the gallery) or from simulation seconds after 2000-01-01 00:00 (headless
// runs and films, whose pictures must not depend on the day they were made).
glm::vec4 wallClockDate();
glm::vec4 simulatedDate(double seconds);

class Runner {
 public:
  // Builds the pipelines and declares the buffers and pictures (context.resources is not used: the
  // runner keeps its own set). Throws gpu's Error when a pipeline
  // cannot be made (the file's SPIR-V is checked already: this is the driver refusing it).
  Runner(const GpuContext& context, std::shared_ptr<const LoadedFile> file);
  ~Runner();
  Runner(const Runner&) = delete;
  Runner& operator=(const Runner&) = delete;

  const LoadedFile& file() const { return *file_; }
  const Document& document() const { return file_->document; }

  // The render size ($WIDTH, $HEIGHT; the size of the frames handed in), before the first record().
  // Outside recording, or in a scene's resize() at the start of its frame.
  void resize(VkExtent2D renderSize);
  // Outside recording (a scene's update()): evaluates the passes' sizes with these values (redeclaring the buffers whose size changed) and reads the pictures image inputs
  // name when they changed. Returns why a picture could not be read or a size not evaluated ("" when
  // all is well); such an input samples transparent black, such a buffer keeps its size.
  std::string update(const Values& values);

  // Records every pass, then writes the last one's picture into `output` (linear, top row first),
  // covering it whole. Pass sizes follow output's extent.
  void record(const FrameContext& frame, const RunInput& input, gpu::Image& output);

 private:
  std::string sizeTargets();
  struct State;
  std::unique_ptr<State> state_;
  std::shared_ptr<const LoadedFile> file_;
};

}  // namespace vitrine::isf
