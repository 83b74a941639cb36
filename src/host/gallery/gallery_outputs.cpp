#include "host/gallery/gallery_outputs.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <span>

#include "core/atomic_file.h"
#include "core/error.h"
#include "gpu/device.h"
#include "gpu/resources.h"
#include "host/present/output_warp_file.h"
#include "host/present/output_window.h"
#include "host/present/window.h"
#include "rig/pipewire_source.h"

namespace vitrine::host {

GalleryOutputs::GalleryOutputs(GallerySettings& settings, FrameCheck check, std::string warpFile,
                               std::optional<maths::OutputWarp> mainWarp, VkExtent2D mainExtent)
    : settings_(settings), check_(std::move(check)), warpFile_(std::move(warpFile)), mainWarp_(std::move(mainWarp)) {
  if (mainWarp_) check_(mainExtent, *mainWarp_, warpFile_);
  else mainWarp_ = savedWarp(kMain, mainExtent);  // a file named on the command line wins
}

void GalleryOutputs::openWindows(const gpu::Instance& instance, const gpu::Device& device, Window& main,
                                 const std::string& file, bool vsync, uint32_t framesInFlight) {
  const std::vector<OutputPlacement> placements = readOutputs(file);
  for (size_t i = 0; i < placements.size(); ++i) {
    const std::string where = fmt::format("{}, output {}", file, i + 1);
    const OutputPlacement& placement = placements[i];
    if (!placement.pipewire.empty()) {
      const VkExtent2D size = placement.size ? VkExtent2D{uint32_t((*placement.size)[0]), uint32_t((*placement.size)[1])}
                                             : main.framebufferSize();
      gpu::checkImageSize(device, size);
      add(rig::makePipeWireOutput(device, placement.name, placement.pipewire, placement.warp.value_or(maths::OutputWarp{}),
                                  size),
          placement.warp.has_value(), where);
      continue;
    }
    if (const auto& window = placements[i].window) {
      const uint32_t limit = device.limits().maxImageDimension2D;
      if (uint32_t((*window)[2]) > limit || uint32_t((*window)[3]) > limit)
        throw Error(fmt::format("{}: a window of {}x{} is outside what {} supports (1 to {} per side).", where,
                                (*window)[2], (*window)[3], device.properties().deviceName, limit));
    }
    auto output = std::make_unique<OutputWindow>(instance, device, placements[i], vsync, framesInFlight, int(i) + 1);
    main.takeKeysOf(output->handle());
    add(std::move(output), placements[i].warp.has_value(), where);
  }
}

void GalleryOutputs::add(std::unique_ptr<Output> output, bool warpGiven, std::string_view where) {
  if (warpGiven) check_(output->extent(), output->warp(), where);
  else output->warp() = savedWarp(output->name(), output->extent()).value_or(maths::OutputWarp{});
  others_.push_back(std::move(output));
}

maths::OutputWarp& GalleryOutputs::warpOf(size_t output) {
  if (output > 0) return others_[output - 1]->warp();
  if (!mainWarp_) mainWarp_.emplace();
  return *mainWarp_;
}

const maths::OutputWarp* GalleryOutputs::shownWarp() {
  if (setup_.active() && setupOutput_ > 0) return &warpOf(setupOutput_);
  return mainWarp_ ? &*mainWarp_ : nullptr;
}

void GalleryOutputs::startSetup() {
  if (setup_.active()) return;
  setupOutput_ = 0;
  setup_.start(warpOf(0));
}

GalleryOutputs::SetupKey GalleryOutputs::setupKey(int key, bool shift, VkExtent2D mainExtent) {
  if (!setup_.active()) return {};
  const ProjectorSetup::Key used = setup_.key(key, shift, extent(setupOutput_, mainExtent), warpOf(setupOutput_));
  if (used == ProjectorSetup::Key::Ignored) return {};
  if (used == ProjectorSetup::Key::Used) return {.used = true};
  SetupKey result{.used = true, .ended = true};
  if (used != ProjectorSetup::Key::Undone) result.note = keep(setupOutput_);
  else result.note = fmt::format("projector setup of {} undone", name(setupOutput_));
  if (used == ProjectorSetup::Key::Next) {  // F7 again: the next output's pin, the card still showing
    setupOutput_ = (setupOutput_ + 1) % count();
    setup_.start(warpOf(setupOutput_));
    result.ended = false;
  }
  return result;
}

void GalleryOutputs::setupPointer(const Pointer& pointer) {
  if (setup_.active()) setup_.pointer(pointer, warpOf(setupOutput_));
}

void GalleryOutputs::drawSetup(VkExtent2D mainExtent) {
  if (setup_.active()) setup_.draw(warpOf(setupOutput_), mainExtent, name(setupOutput_), count());
}

std::optional<std::string_view> GalleryOutputs::setupNewlyShown(bool ready) {
  if (!setup_.active()) {
    setupShown_.reset();
    return std::nullopt;
  }
  if (setupShown_ == setupOutput_ || !ready) return std::nullopt;
  setupShown_ = setupOutput_;
  return name(setupOutput_);
}

std::vector<std::pair<VkSemaphore, VkSemaphore>> GalleryOutputs::record(VkCommandBuffer cmd, uint32_t slot,
                                                                        SceneRenderer& renderer, const Crossfade& fade,
                                                                        bool vsync, VkPipelineStageFlags2 acquireStage,
                                                                        const FrameInput& shown) {
  std::vector<std::pair<VkSemaphore, VkSemaphore>> drawn;
  for (auto& output : others_)
    if (output->acquire(slot, vsync)) {  // one that is hidden or being rebuilt misses this frame
      renderer.recordOutput(cmd, output->destination(acquireStage), fade);
      output->drawn(cmd, &renderer.timer(), shown);
      if (const auto semaphores = output->semaphores(slot); semaphores.first || semaphores.second)
        drawn.push_back(semaphores);
    }
  return drawn;
}

std::vector<Output::Health> GalleryOutputs::health() const {
  std::vector<Output::Health> all;
  for (const auto& output : others_) all.push_back(output->health());
  return all;
}

void GalleryOutputs::present() {
  for (auto& output : others_) output->present();
}

std::optional<maths::OutputWarp> GalleryOutputs::savedWarp(std::string_view output, VkExtent2D extent) {
  const nlohmann::ordered_json* saved = settings_.warpFor(output);
  if (!saved) return std::nullopt;
  try {
    const std::string where = fmt::format("{}: outputs.{}", settings_.path().string(), output);
    maths::OutputWarp warp = outputWarpFromJson(nlohmann::json::parse(saved->dump()), where);
    check_(extent, warp, where);
    return warp;
  } catch (const Error& e) {
    std::fprintf(stderr, "vitrine: settings: %s; showing the whole frame there\n", e.what());
    return std::nullopt;
  }
}

// A kept pin goes to the settings file under the output's name, and for the main window also to
// --output-warp's file when one was given (which wins over the settings at the next start).
std::string GalleryOutputs::keep(size_t output) {
  const maths::OutputWarp& warp = warpOf(output);
  settings_.setWarp(name(output), warp.isIdentity() ? nlohmann::ordered_json() : nlohmann::ordered_json(outputWarpToJson(warp)),
                    GallerySettings::Clock::now());
  if (output != 0 || warpFile_.empty()) return fmt::format("projector setup of {} kept in the settings", name(output));
  const std::string text = outputWarpToJson(warp).dump(2) + "\n";
  writeFileAtomically(warpFile_, std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
  return fmt::format("projector setup of {} kept in {} and the settings", name(output), warpFile_);
}

}  // namespace vitrine::host
