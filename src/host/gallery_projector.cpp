// The gallery's projector setup (F7): the corner pin dragged on the picture, and the pins it keeps.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstdio>

#include "core/atomic_file.h"
#include "host/gallery_app.h"
#include "host/output_warp_file.h"

namespace vitrine::host {

// Projector setup shows the calibration card, when this build has one, and the UI it needs.
void Gallery::startSetup() {
  if (setup_.active()) return;
  setupOutput_ = 0;
  setup_.start(warpOf(0));
  if (const SceneInfo* card = findScene("calibrate"); card && card != &renderer_->info())
    beforeSetup_ = &renderer_->info(), nextScene_ = card;
  note_ = "projector setup";
  noted_ = Clock::now();
}

void Gallery::endSetup(ProjectorSetup::Key how) {
  if (how != ProjectorSetup::Key::Undone) keepWarp(setupOutput_);
  else note_ = fmt::format("projector setup of {} undone", outputName(setupOutput_)), noted_ = Clock::now();
  if (how == ProjectorSetup::Key::Next) {  // F7 again: the next output's pin, the card still showing
    setupOutput_ = (setupOutput_ + 1) % (outputs_.size() + 1);
    setup_.start(warpOf(setupOutput_));
    return;
  }
  if (beforeSetup_) nextScene_ = std::exchange(beforeSetup_, nullptr);
}

maths::OutputWarp& Gallery::warpOf(size_t output) {
  if (output > 0) return outputs_[output - 1]->warp();
  if (!warp_) warp_.emplace();
  return *warp_;
}

// An output's warp as the settings file keeps it (projector setup's last kept pin); one the file holds
// but this build refuses, or whose frame at the output's `extent` is past the device, is a warning,
// and the output shows the whole frame.
std::optional<maths::OutputWarp> Gallery::savedWarp(std::string_view output, VkExtent2D extent) {
  const nlohmann::ordered_json* saved = settings_.warpFor(output);
  if (!saved) return std::nullopt;
  try {
    const std::string where = fmt::format("{}: outputs.{}", settings_.path().string(), output);
    maths::OutputWarp warp = outputWarpFromJson(nlohmann::json::parse(saved->dump()), where);
    checkWarpedFrame(device_, extent, warp, where);
    return warp;
  } catch (const Error& e) {
    std::fprintf(stderr, "vitrine: settings: %s; showing the whole frame there\n", e.what());
    return std::nullopt;
  }
}

// A kept pin goes to the settings file under the output's name, and for the main window also to
// --output-warp's file when one was given (which wins over the settings at the next start).
void Gallery::keepWarp(size_t output) {
  const maths::OutputWarp& warp = warpOf(output);
  settings_.setWarp(outputName(output), warp.isIdentity() ? nlohmann::ordered_json() : nlohmann::ordered_json(outputWarpToJson(warp)),
                    Clock::now());
  note_ = fmt::format("projector setup of {} kept in the settings", outputName(output));
  if (output == 0 && !warpFile_.empty()) {
    const std::string text = outputWarpToJson(warp).dump(2) + "\n";
    writeFileAtomically(warpFile_, std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
    note_ = fmt::format("projector setup of {} kept in {} and the settings", outputName(output), warpFile_);
  }
  noted_ = Clock::now();
}

}  // namespace vitrine::host
