// The gallery's keys and menu: the parameter panel's edits and presets, screenshots and captures,
// projector setup's start.
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>

#include "core/user_dirs.h"
#include "host/gallery/gallery_app.h"

namespace vitrine::host {
namespace {

using Clock = Gallery::Clock;

constexpr auto kToastSeconds = std::chrono::seconds(4);  // how long a note shows with the UI hidden

const SceneInfo* sceneForKey(int key) {
  for (const auto& info : sceneRegistry())
    if (info.key > 0 && key == GLFW_KEY_0 + info.key) return &info;
  return nullptr;
}

// The gallery keys an installation's visitors may use: the scene keys (and the scenes' own keys).
// Esc stays for whoever runs it; everything that would change the installation is ignored.
bool kioskAllows(int key) { return key == GLFW_KEY_ESCAPE || sceneForKey(key) != nullptr; }

}  // namespace

// After the menu has seen this frame's clicks and keys: a field that a click activated in this very
// frame (at 1 fps, a click and the digits typed after it arrive together) already has the keyboard.
void Gallery::handleKeys() {
  const std::vector<int> keys = window_.takeKeys();
  if (overlay_.wantsKeyboard()) return;  // typed into a field, not commands
  const auto& held = window_.keysHeld();
  const bool shift = std::find(held.begin(), held.end(), GLFW_KEY_LEFT_SHIFT) != held.end() ||
                     std::find(held.begin(), held.end(), GLFW_KEY_RIGHT_SHIFT) != held.end();
  for (int key : keys) {
    if (kiosk_ && !kioskAllows(key)) continue;
    // During projector setup its keys are setup's: Esc undoes the pin rather than closing the gallery.
    if (const GalleryOutputs::SetupKey setup = outputs_.setupKey(key, shift, swapchain_.extent()); setup.used) {
      if (!setup.note.empty()) note_ = setup.note, noted_ = Clock::now();
      if (setup.ended && beforeSetup_) nextScene_ = std::exchange(beforeSetup_, nullptr);
      continue;
    }
    switch (key) {
      case GLFW_KEY_ESCAPE:
        window_.close();
        break;
      case GLFW_KEY_TAB:
        uiHidden_ = !uiHidden_;
        break;
      case GLFW_KEY_M:
        audio_.setMuted(!audio_.muted());
        break;
      case GLFW_KEY_V:
        vsync_ = !vsync_;
        break;
      case GLFW_KEY_F11:
        window_.toggleFullscreen();
        break;
      case GLFW_KEY_F12:
        screenshots_.request();
        break;
      case GLFW_KEY_F9:
        toggleCapture();
        break;
      case GLFW_KEY_P:
        time_.paused = !time_.paused;
        break;
      case GLFW_KEY_F1:
      case GLFW_KEY_SLASH:  // '?' on most layouts
        helpShown_ = !helpShown_;
        if (helpShown_) uiHidden_ = false;  // the card is part of the UI
        break;
      case GLFW_KEY_PERIOD:
        if (time_.paused) time_.stepRequested = true;
        break;
      case GLFW_KEY_LEFT_BRACKET:
        time_.slower();
        break;
      case GLFW_KEY_RIGHT_BRACKET:
        time_.faster();
        break;
      case GLFW_KEY_BACKSLASH:
        time_.normal();
        break;
      case GLFW_KEY_F7:
        startSetup();
        break;
      case GLFW_KEY_L:  // the lights' blackout (--lights)
        if (lights_) note_ = lights_->toggleBlackout(), noted_ = Clock::now();
        break;
      case GLFW_KEY_F5:  // the scene from its first frame, its parameters kept
        nextScene_ = &renderer_->info();
        break;
      default:
        if (const SceneInfo* info = sceneForKey(key)) {
          nextScene_ = info;
        } else if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) {  // the footer's range says which exist
          note_ = fmt::format("no scene on key {}: the scenes are on {}", key - GLFW_KEY_0, sceneKeyRange());
          noted_ = Clock::now();
        }
    }
  }
  keys_.insert(keys_.end(), keys.begin(), keys.end());
  for (std::string& path : window_.takeDrops()) drops_.push_back(std::move(path));
}

// Projector setup shows the calibration card, when this build has one, and the UI it needs.
void Gallery::startSetup() {
  if (outputs_.setupActive()) return;
  outputs_.startSetup();
  if (const SceneInfo* card = findScene("calibrate"); card && card != &renderer_->info())
    beforeSetup_ = &renderer_->info(), nextScene_ = card;
  note_ = "projector setup";
  noted_ = Clock::now();
}

void Gallery::showMenu() {
  if (uiHidden_) return;
  const double fps = frameSeconds_ > 0.0 ? 1.0 / frameSeconds_ : 0.0;
  MenuState state{renderer_->info(), renderer_->scene(), fps, cpuMs_, passes_, vsync_, programs_.error(),
                  note_, missingAssets_, overlay_.titleFont(), &panel_, panelError_, time_,
                  helpShown_, capture_.status(renderer_->info().name), capture_.active(), reloadNote_,
                  remote_.status(), costlyEdit_ ? costlyWhy_ : std::string(),
                  tiers_.describe(renderer_->info().name, params::snapshot(renderer_->parameters())),
                  clockNote(), &menuLayout_};
  state.userPresets = presets_.presetsOf(renderer_->info().name);
  state.livePanel = &live_->panel();
  state.live = live_->panelState();
  state.flashGuard = flashGuard_;
  state.rig = rig_;
  rig::LinkClock* link = live_->link().linkClock();
  if (link) {
    const rig::LinkReading now = link->look();
    state.link = LinkControls{link->enabled(), now.bpm, now.playing};
  }
  filterChoice_ = {};
  state.filters = [this] { drawFilters(); };
  const MenuChoice choice = drawMenu(state);
  applyFilterChoice(filterChoice_);
  if (link && choice.link) {  // what the user changed, the gallery leads
    if (choice.link->joined != state.link->joined) link->setEnabled(choice.link->joined);
    if (choice.link->tempo != state.link->tempo) link->setTempo(choice.link->tempo);
    if (choice.link->playing != state.link->playing) link->setPlaying(choice.link->playing);
  }
  if (live_->apply(choice.live, panel_)) remote_.setMappings(live_->mappingLines());
  vsync_ = choice.vsync;
  if (choice.flashGuard && !flashGuard_) guard_.reset();  // what it held is stale: count from the next frame
  flashGuard_ = choice.flashGuard;
  time_ = choice.time;
  time_.speed = TimeControl::clampSpeed(time_.speed);
  helpShown_ = choice.help;
  if (choice.scene) nextScene_ = choice.scene;
  if (choice.edit) applyEdit(*choice.edit);
  if (choice.capture != capture_.active()) toggleCapture();
  if (choice.costly && costlyEdit_) {
    if (*choice.costly) applyEditNow(*costlyEdit_);
    costlyEdit_.reset();
  }
}

std::vector<rig::RigLine> Gallery::rigLines() const {
  std::vector<rig::RigLine> lines;
  for (const rig::ClockStatus& clock : live_->link().clockStatuses()) lines.push_back(rig::describeClock(clock));
  for (const rig::OutputReport& output : outputs_.reports()) lines.push_back(rig::describeOutput(output));
  return lines;
}

// With the UI hidden (Tab), where a screenshot went and a clock that falls behind still show, briefly
// and small, in a corner. A kiosk shows nothing.
void Gallery::showToast() {
  if (!uiHidden_ || kiosk_) return;
  std::string text;
  if (!note_.empty() && Clock::now() - noted_ < kToastSeconds) text = note_;
  if (const std::string clock = clockNote(); !clock.empty()) text += (text.empty() ? "" : "\n") + clock;
  if (text.empty()) return;
  drawToast(text);
}

// Said while the simulation cannot keep up with the wall clock, and for a few seconds after.
std::string Gallery::clockNote() const {
  if (!steps_.behind() || time_.paused) return {};
  return fmt::format("simulation behind the clock: {:.0f}% of real time ({:.1f} ms a step of {:.1f} ms)",
                     steps_.kept() * 100.0, stepCost_.perStep() * 1e3, steps_.step() * 1e3);
}

// The scene scaled to the window, as the present pass draws it, into an HDR image of the window's size.
void Gallery::recordWindowCopy(VkCommandBuffer cmd) {
  const VkExtent2D size = swapchain_.extent();
  if (!windowCopy_ || windowCopy_->extent2d().width != size.width || windowCopy_->extent2d().height != size.height) {
    if (windowCopy_) device_.retire(std::move(*windowCopy_));  // a frame in flight may still read it
    gpu::ImageDesc desc;
    desc.extent = {size.width, size.height, 1};
    desc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    windowCopy_.emplace(device_, desc, "window copy");
  }
  renderer_->recordScaled(cmd, *windowCopy_);
}

void Gallery::toggleCapture() {
  std::printf("vitrine: %s\n", capture_.toggle(renderer_->info().name).c_str());
  std::fflush(stdout);
}

// Every panel edit goes through the same validation as --set; a refused one leaves every value as it
// was. One that would freeze the window for seconds is asked about first.
void Gallery::applyEdit(const PanelEdit& edit) {
  if (managePresets(edit)) return;
  if (edit.what == PanelEdit::What::Preset && barWaits() && !onBar_) {  // on the bar, as a scene switch
    barPreset_ = edit;
    note_ = fmt::format("preset '{}' waits for the next bar", edit.preset);
    noted_ = Clock::now();
    return;
  }
  params::KeyValues change = edit.values;
  if (edit.what == PanelEdit::What::Preset)
    if (FoundPreset found = findPreset(renderer_->info().name, edit.preset, &presets_); found.preset)
      change = found.preset->values;
  if (edit.what != PanelEdit::What::ResetAll)
    if (std::string why = freezeWarning(renderer_->costRatio(change), frameMs()); !why.empty()) {
      costlyEdit_ = edit;
      costlyWhy_ = std::move(why);
      return;
    }
  applyEditNow(edit);
}

void Gallery::applyEditNow(const PanelEdit& edit) {
  remote_.userSet(renderer_->info().name, edit);  // what the user sets here is theirs
  switch (edit.what) {
    case PanelEdit::What::Values: panelError_ = renderer_->applyParameters(edit.values); break;
    case PanelEdit::What::Preset: {
      FoundPreset found = findPreset(renderer_->info().name, edit.preset, &presets_);
      panelError_ = found.preset ? renderer_->applyParameters(found.preset->values) : found.why;
      break;
    }
    case PanelEdit::What::ResetAll:
      params::resetToDefaults(renderer_->parameters());
      panelError_.clear();
      break;
    default: break;  // the user's presets: managePresets
  }
  rememberValues();
  remote_.publish(*renderer_, true);
}

// Saving, renaming, deleting or exporting one of the user's presets of the scene showing (true), said in
// the note or, when refused, where the panel shows refusals. The values themselves do not change.
bool Gallery::managePresets(const PanelEdit& edit) {
  const std::string scene(renderer_->info().name);
  std::string why, done;
  switch (edit.what) {
    case PanelEdit::What::SavePreset:
      why = presets_.save({scene, edit.preset, params::snapshot(renderer_->parameters(), /*includeTransient=*/false)});
      done = fmt::format("saved preset '{}'", edit.preset);
      break;
    case PanelEdit::What::RenamePreset:
      why = presets_.rename(scene, edit.preset, edit.newName);
      done = fmt::format("renamed preset '{}' to '{}'", edit.preset, edit.newName);
      break;
    case PanelEdit::What::DeletePreset:
      why = presets_.remove(scene, edit.preset);
      done = fmt::format("deleted preset '{}'", edit.preset);
      break;
    case PanelEdit::What::ExportPreset: {
      // A file to hand on, read back by --preset-file: into the user's documents, under Vitrine/.
      const std::filesystem::path file =
          vitrineUserDir(UserDir::Documents) / "presets" / presets_.fileOf(scene, edit.preset).filename();
      why = presets_.exportTo(scene, edit.preset, file);
      done = fmt::format("wrote preset '{}' to {}", edit.preset, std::filesystem::absolute(file).string());
      break;
    }
    default: return false;
  }
  panelError_ = why;
  if (why.empty()) {
    note_ = done;
    noted_ = Clock::now();
    std::printf("vitrine: %s\n", done.c_str());
    std::fflush(stdout);
    remote_.publish(*renderer_, true);
  }
  return true;
}

// What a client changed is kept out of the settings file (unless --remote-saves): those keys keep
// the values saved before.
void Gallery::rememberValues() {
  const std::string_view scene = renderer_->info().name;
  params::KeyValues values = params::snapshot(renderer_->parameters());
  std::set<std::string> theirs = remote_.notTheUsers(scene);  // keys whose live value is not the user's to save
  if (live_)  // a mapping plays these: the values the user saved stay
    for (std::string& key : live_->drivenKeys()) theirs.insert(std::move(key));
  if (!theirs.empty()) {
    std::erase_if(values, [&](const auto& kv) { return theirs.contains(kv.first); });
    for (auto& kv : settings_.valuesFor(scene))
      if (theirs.contains(kv.first)) values.push_back(std::move(kv));
  }
  settings_.remember(scene, std::move(values), Clock::now());
  rememberFilters();
}

}  // namespace vitrine::host
