#pragma once
// The menu's "filters and transition" section: the ISF filters after the scene showing, each with its
// inputs' panel (a ParamPanel of its schema) and a button that takes it out, in chain order; a list of
// the filters in the pieces folder to add one at the end; and the transition of scene switches, chosen
// among those in the pieces folder, with its inputs' panel. It only draws and reports what was chosen.
#include "host/ui/param_panel.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace vitrine::host {

struct FilterRow {
  std::string name;
  params::Bound bound;
};

struct FilterPanelChoice {
  std::optional<size_t> remove;                 // the filter to take out
  std::optional<std::filesystem::path> add;     // a file to append
  std::optional<std::pair<size_t, PanelEdit>> edit;  // a filter's values changed
  // The transition chosen: a file, or none (the cross-fade's mix).
  std::optional<std::optional<std::filesystem::path>> transition;
  std::optional<PanelEdit> transitionEdit;  // the transition's values changed
};

struct TransitionRow {
  std::string name;                      // empty: none
  std::optional<params::Bound> bound;    // its inputs, when there is one
  std::span<const std::filesystem::path> available;
};

class FilterPanel {
 public:
  FilterPanelChoice draw(std::span<const FilterRow> chain, std::span<const std::filesystem::path> available,
                         const TransitionRow& transition, std::string_view error);
  void forget() { panels_.clear(); }  // a scene switch, a filter taken out

 private:
  std::vector<ParamPanel> panels_;  // one per filter, for the values being dragged
  ParamPanel transitionPanel_;
};

}  // namespace vitrine::host
