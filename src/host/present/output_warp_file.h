#pragma once
// An output's warp (maths/output_warp.h) as JSON, the way the settings file keeps it per output and
// --output-warp FILE gives it as numbers:
//   {"turn": 180, "mirror": false, "region": [0.5, 0, 1, 1],
//    "corners": [[0.02, 0.0], [1.0, 0.04], [0.97, 1.0], [0.0, 0.96]],
//    "blend": {"left": 0.12, "right": 0, "top": 0, "bottom": 0, "curve": 2, "gamma": 2.2}}
// Every key is optional (the identity's value); an unknown key, a wrong type or a warp checkWarp refuses
// is an Error naming `where` and the key.
#include "maths/output_warp.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string_view>

namespace vitrine::host {

maths::OutputWarp outputWarpFromJson(const nlohmann::json& json, std::string_view where);
nlohmann::json outputWarpToJson(const maths::OutputWarp& warp);
// Reads FILE: throws vitrine::Error naming it and what is wrong.
maths::OutputWarp readOutputWarp(const std::filesystem::path& file);

}  // namespace vitrine::host
