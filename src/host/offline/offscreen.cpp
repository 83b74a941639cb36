#include "host/offline/offscreen.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/printable.h"
#include "gpu/barriers.h"
#include "gpu/check.h"
#include "gpu/sync_objects.h"
#include "host/user_presets.h"

namespace vitrine::host {
Offscreen::Offscreen(const gpu::Device& device, const OffscreenConfig& config)
    : device_(device),
      programs_(device, config.shaderSources.empty() ? VITRINE_SHADER_SOURCE_DIR : config.shaderSources),
      renderer_(device, programs_, assets_, 1), size_(config.size),
      startTime_(config.startTime), step_(config.step), live_(config.live), events_(config.events), warp_(config.warp) {
  if (!(step_ > 0.0) || !std::isfinite(step_)) throw Error("an offscreen run needs a finite, positive time step");
  gpu::checkImageSize(device, size_);
  const SceneInfo* info = findScene(config.scene);
  if (!info) throw Error(unknownScene(config.scene));
  if (config.flashGuard) guard_ = std::make_unique<FlashGuard>(device, programs_);
  renderer_.setFlashGuard(guard_.get());
  renderer_.setEventSink(config.events);
  renderer_.setAudioSink(config.audio);
  renderer_.setScene(*info);
  if (config.input) {
    for (const InputEvent& event : config.input->events)  // a wrong action fails before the first frame
      if (event.kind == InputEvent::Kind::Action)
        if (auto why = checkAction(*info, event.action); !why.empty())
          throw Error(whereInScript(*config.input, event, fmt::format("at t={} s: {}", event.time, why)));
    player_.emplace(*config.input);
  }
  for (const std::string& name : config.presets) {
    const FoundPreset found = findPreset(config.scene, name);
    const std::string why = found.preset ? renderer_.applyParameters(found.preset->values) : found.why;
    if (!why.empty()) throw Error(fmt::format("Scene {} rejects preset {}: {}", config.scene, name, why));
  }
  for (const params::Preset& preset : config.presetFiles)
    if (auto why = renderer_.applyParameters(preset.values); !why.empty())
      throw Error(fmt::format("Scene {} rejects the preset file's '{}': {}", config.scene, preset.name, why));
  if (auto why = renderer_.applyParameters(config.parameters); !why.empty())
    throw Error(fmt::format("Scene {} rejects {}", config.scene, why));
  for (const FilterSpec& filter : config.filters) renderer_.filters().add(filter);
  if (live_) live_->setScene(*info);
  input_.time = config.startTime;
  input_.dt = float(step_);
  input_.seed = config.seed;
  input_.reducedMotion = config.reducedMotion;

  gpu::ImageDesc desc;
  desc.extent = {size_.width, size_.height, 1};
  desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  output_ = gpu::Image(device, desc, "offscreen output");

  pool_ = gpu::createCommandPool(device, VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, "offscreen pool");
  const VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr, pool_,
                                          VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
  VK_CHECK(vkAllocateCommandBuffers(device, &alloc, &cmd_));
  device.name(cmd_, VK_OBJECT_TYPE_COMMAND_BUFFER, "offscreen frame");
}


void Offscreen::addInput(std::vector<ActionCall> actions, std::optional<Pointer> pointer) {
  extraActions_.insert(extraActions_.end(), actions.begin(), actions.end());
  if (pointer) extraPointer_ = pointer;
}

FrameTimes Offscreen::renderFrame(uint32_t steps, bool seen) {
  renderer_.setDrawing(seen);
  const auto start = std::chrono::steady_clock::now();
  for (uint32_t i = 0; i < std::max(steps, 1u); ++i) {
    if (i > 0) ++input_.frame;
    step();
  }
  FrameTimes times = draw(start);
  ++input_.frame;
  return times;
}

void Offscreen::step() {
  gatherInput(events_);
  renderer_.scene().update(input_);
}

void Offscreen::gatherInput(EventSink* events) {
  input_.time = startTime_ + double(input_.frame) * step_;
  input_.actions.clear();  // a step's actions are its own: none carry over to the next
  if (player_) {
    StepInput scripted = player_->step(input_.time, size_);
    input_.cursor = scripted.cursor;
    input_.keysPressed = std::move(scripted.keysPressed);
    input_.keysHeld = std::move(scripted.keysHeld);
    input_.actions = std::move(scripted.actions);
  }
  if (extraPointer_) {
    extraCursor_.observe(*std::exchange(extraPointer_, std::nullopt), false);
    input_.cursor = extraCursor_.take();
  }
  input_.actions.insert(input_.actions.end(), extraActions_.begin(), extraActions_.end());
  extraActions_.clear();
  if (live_) live_->step(renderer_, input_, events);
}

std::vector<std::byte> Offscreen::saveSimulation() {
  if (!renderer_.scene().checkpoints()) throw Error(fmt::format("{} cannot be checkpointed", scene().name));
  StateArchive state = StateArchive::saving();
  params::KeyValues values = params::snapshot(parameters(), true);  // exact: the shortest text of each float
  state(values);
  renderer_.scene().simulationState(state);
  return state.bytes();
}

void Offscreen::restoreSimulation(uint64_t frames, std::span<const std::byte> bytes, const params::KeyValues& film) {
  if (input_.frame != 0 || !renderer_.scene().checkpoints())
    throw Error("a checkpoint is restored before the first frame, into a scene that can be checkpointed");
  // The script's and live input's own state (a held key, a smoothed band) is theirs: replayed, unseen by
  // the scene and unlogged, up to the checkpoint's frame.
  for (; input_.frame < frames; ++input_.frame) gatherInput(nullptr);
  StateArchive state = StateArchive::restoring(bytes);
  params::KeyValues values;
  state(values);
  // Its values are the film's, but for those a mapping moves as it plays: a checkpoint edited to other
  // values (its checksum made again) would draw another film into this one's frames.
  const std::vector<std::string> driven = live_ ? live_->drivenKeys() : std::vector<std::string>{};
  for (const auto& [key, text] : film) {
    if (std::find(driven.begin(), driven.end(), key) != driven.end()) continue;
    const auto held = std::find_if(values.begin(), values.end(), [&name = key](const auto& kv) { return kv.first == name; });
    if (held == values.end())
      throw Error(fmt::format("it holds no {} where the film's record.json has {}={}", key, key, printable(text)));
    if (held->second != text)
      throw Error(fmt::format("it holds {}={} where the film's record.json has {}={}", key, printable(held->second),
                              key, printable(text)));
  }
  if (auto why = renderer_.applyParameters(values); !why.empty())
    throw Error(fmt::format("its parameters are refused: {}", why));
  renderer_.scene().simulationState(state);
  if (!state.finished()) throw Error("it holds more than this build's scene reads");
}

FrameTimes Offscreen::redrawFrame() {
  if (!rendered_) throw Error("No frame has been rendered to draw again");
  --input_.frame;  // the input the last frame was drawn with
  FrameTimes times = draw(std::chrono::steady_clock::now());
  ++input_.frame;
  return times;
}

FrameTimes Offscreen::draw(std::chrono::steady_clock::time_point start) {
  VK_CHECK(vkResetCommandBuffer(cmd_, 0));
  const VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, nullptr,
                                       VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  VK_CHECK(vkBeginCommandBuffer(cmd_, &begin));
  output_.discard();  // every texel is written
  renderer_.record(cmd_, 0, input_,
                   BlitDestination{output_.handle(), size_, output_.lastUse(), gpu::use::TransferSrc, output_.view(),
                                   false, warp_ ? &*warp_ : nullptr});
  output_.assumeUse(gpu::use::TransferSrc);
  for (Output* other : others_)
    if (other->acquire(0, false)) {
      renderer_.recordOutput(cmd_, other->destination(VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT), {});
      other->drawn(cmd_, &renderer_.timer(), input_);
    }
  VK_CHECK(vkEndCommandBuffer(cmd_));
  const uint64_t serial = device_.submit({cmd_, {}, {}});
  for (Output* other : others_) other->present();
  const double cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  device_.wait(serial);
  rendered_ = true;

  FrameTimes times;
  times.cpuMs = cpuMs;
  times.passes = renderer_.timer().collect(0);
  for (const auto& pass : times.passes) times.gpuMs += pass.ms;
  input_.lastGpuMs = times.gpuMs;
  return times;
}

ImageRgba Offscreen::readback() {
  if (!rendered_) throw Error("No frame has been rendered to read back");
  const size_t count = size_t(size_.width) * size_.height;
  gpu::Buffer staging(device_, count * 4 * sizeof(uint16_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback,
                      "readback");
  device_.submitNow([&](VkCommandBuffer cmd) { gpu::recordReadback(cmd, output_, staging); });
  staging.invalidate();
  return imageFromHalves(size_.width, size_.height, staging.view<const uint16_t>());
}

}  // namespace vitrine::host
