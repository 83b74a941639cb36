#pragma once
// "vitrine --list-params SCENE": every parameter of a scene as a readable table, from its schema alone.
#include "params/schema.h"

#include <string>
#include <string_view>

namespace vitrine::params {

// One aligned line per parameter — key, type with range or choices, default, flags worth knowing
// ("rebuilds", "not saved"), help — grouped as the panel groups them, then the presets with their
// values. Ends with a newline.
std::string describeSchema(std::string_view sceneName, const Schema& schema);

}  // namespace vitrine::params
