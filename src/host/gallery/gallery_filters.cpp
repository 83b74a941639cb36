// The gallery's ISF filters and transitions: each scene's filter chain (the run's --filter, else the one
// saved for it), kept in the settings file, and scene switches drawn through --transition.
#include <fmt/format.h>

#include <cstdio>

#include "host/gallery/gallery_app.h"
#include "isf/isf_document.h"
#include "scenes/pieces/piece_catalogue.h"
#include "scenes/pieces/piece_scene.h"

namespace vitrine::host {
namespace {

using Clock = Gallery::Clock;

// A gallery's scene switch through the transition takes as long as the kiosk's cross-fade.
constexpr double kSwitchFadeSeconds = KioskTiming{}.fade;

}  // namespace

// The chain after `info` in `renderer`: the run's (built once, at start, and kept across scenes), or
// the one saved for the scene. A saved filter that no longer loads is said and left out; the scene runs.
void Gallery::startFilters(SceneRenderer& renderer, const SceneInfo& info) {
  if (filtersGiven_) {
    if (renderer.filters().size() == runFilters_.size()) return;
    renderer.filters().clear();
    for (const FilterSpec& filter : runFilters_) renderer.filters().add(filter);
    return;
  }
  const nlohmann::ordered_json* saved = settings_.filtersFor(info.name);
  if (!saved && !renderer.hasFilters()) return;  // no chain, and none made
  renderer.filters().clear();
  if (!saved) return;
  std::vector<std::string> problems;
  std::vector<FilterSpec>& unloaded = unloadedFilters_[std::string(info.name)];
  unloaded.clear();
  for (const FilterSpec& filter : chainFromJson(*saved, problems)) {
    try {
      renderer.filters().add(filter);
    } catch (const Error& e) {
      problems.push_back(e.what());
      unloaded.push_back(filter);
    }
  }
  for (const std::string& problem : problems)
    std::fprintf(stderr, "vitrine: filters of %.*s: %s\n", int(info.name.size()), info.name.data(), problem.c_str());
}

// The chain of the scene showing, with its values, as the settings file keeps it (not the run's).
void Gallery::rememberFilters() {
  if (filtersGiven_ || !renderer_->hasScene()) return;
  std::vector<FilterSpec> chain = renderer_->hasFilters() ? renderer_->filters().specs() : std::vector<FilterSpec>{};
  if (const auto unloaded = unloadedFilters_.find(renderer_->info().name); unloaded != unloadedFilters_.end())
    chain.insert(chain.end(), unloaded->second.begin(), unloaded->second.end());
  settings_.setFilters(renderer_->info().name, chain.empty() ? nlohmann::ordered_json() : chainJson(chain), Clock::now());
}

// A scene switch in the gallery with --transition: the scene comes in as the kiosk's do, through the
// transition, and becomes the one showing when it is over (switchFadeStep).
void Gallery::fadeTo(const SceneInfo& info) {
  if (hasScene_ && remembers()) rememberValues();
  crossfade_.cancel();
  (void)startScene(crossfade_.incoming(), info);  // outside the kiosk a scene that fails throws, as a switch does
  crossfade_.began(input_);
  crossfade_.setWeight(0.0f);
  switchFade_ = 0.0;
  std::fprintf(stderr, "vitrine: %.*s comes in through %s\n", int(info.name.size()), info.name.data(),
               transition_->file().filename().c_str());
}

void Gallery::switchFadeStep(double elapsed) {
  if (!switchFade_) return;
  *switchFade_ += elapsed;
  if (*switchFade_ < kSwitchFadeSeconds) {
    crossfade_.setWeight(float(*switchFade_ / kSwitchFadeSeconds));
    return;
  }
  switchFade_.reset();
  finishFade();
  crossfade_.setWeight(0.0f);
  settings_.showing(renderer_->info().name, Clock::now());
}

// The filters and transitions in the pieces folders, the user's and the settings file's (a generator
// there is a scene).
void Gallery::findFilters() {
  availableFilters_.clear();
  availableTransitions_.clear();
  std::vector<std::filesystem::path> folders = pieces::settingsPieceFolders(settings_.path());
  if (auto folder = pieces::userPiecesFolder(); !folder.empty()) folders.insert(folders.begin(), std::move(folder));
  for (const std::filesystem::path& folder : folders)
    for (const std::filesystem::path& file : pieces::piecesIn(folder)) {
      try {
        const isf::Kind kind = isf::loadDocument(file).kind;
        if (kind == isf::Kind::Filter) availableFilters_.push_back(file);
        if (kind == isf::Kind::Transition) availableTransitions_.push_back(file);
      } catch (const Error&) {  // a file that does not read is the pieces' list's to report
      }
    }
}

void Gallery::drawFilters() {
  std::vector<FilterRow> rows;
  if (renderer_->hasFilters())
    for (size_t i = 0; i < renderer_->filters().size(); ++i)
      rows.push_back({renderer_->filters().name(i), renderer_->filters().parameters(i)});
  TransitionRow transition{transition_ ? transition_->file().filename().string() : std::string(),
                           transition_ ? std::optional(transition_->parameters()) : std::nullopt, availableTransitions_};
  filterChoice_ = filterPanel_.draw(rows, availableFilters_, transition, filterError_);
}

// The transition of scene switches from now on (none: the cross-fade's mix). A file that does not load
// leaves the one there was, and says why where the menu shows refusals.
void Gallery::chooseTransition(const std::optional<std::filesystem::path>& file, const params::KeyValues& values) {
  std::unique_ptr<IsfTransition> made;
  if (file) {
    try {
      made = std::make_unique<IsfTransition>(device_, programs_, *file);
      if (auto why = made->applyParameters(values); !why.empty()) filterError_ = "transition: " + why;
    } catch (const Error& e) {
      filterError_ = e.what();
      std::fprintf(stderr, "vitrine: transition: %s\n", e.what());
      return;
    }
  }
  crossfade_.setTransition(made.get());
  transition_ = std::move(made);  // the one it replaces is retired behind the frames that used it
}

void Gallery::rememberTransition() {
  if (transitionGiven_) return;
  settings_.setTransition(transition_ ? chainJson({{transition_->file(), params::snapshot(transition_->parameters(), false)}})[0]
                                      : nlohmann::ordered_json(),
                          Clock::now());
}

// The menu's filter edits: values through the filter's own checks, a filter taken out or added at the
// end; each kept in the settings file as the scene's chain (not a --filter run's).
void Gallery::applyFilterChoice(const FilterPanelChoice& choice) {
  if (choice.transition) {
    chooseTransition(*choice.transition, {});
    rememberTransition();
  }
  if (choice.transitionEdit && transition_) {
    if (choice.transitionEdit->what == PanelEdit::What::ResetAll) params::resetToDefaults(transition_->parameters());
    else if (choice.transitionEdit->what == PanelEdit::What::Values)
      filterError_ = transition_->applyParameters(choice.transitionEdit->values);
    rememberTransition();
  }
  if (!choice.edit && !choice.remove && !choice.add) return;
  if (choice.edit) {
    const auto& [index, edit] = *choice.edit;
    if (edit.what == PanelEdit::What::ResetAll) {
      params::resetToDefaults(renderer_->filters().parameters(index));
      filterError_.clear();
    } else if (edit.what == PanelEdit::What::Values) {
      filterError_ = renderer_->filters().applyParameters(index, edit.values);
    }
  }
  if (choice.remove) {
    renderer_->filters().remove(*choice.remove);
    filterPanel_.forget();
    filterError_.clear();
  }
  if (choice.add) {
    try {
      renderer_->filters().add({*choice.add, {}});
      filterError_.clear();
    } catch (const Error& e) {
      filterError_ = e.what();
    }
  }
  if (remembers()) rememberValues();
}

}  // namespace vitrine::host
