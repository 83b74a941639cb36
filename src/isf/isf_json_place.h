#pragma once
// Where a value sits in JSON text, so a complaint about INPUTS[3].TYPE names the file's line: the JSON
// library keeps no positions, so the (already parsed, hence valid) text is walked again along a path.
#include <cstddef>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace vitrine::isf {

using JsonPath = std::vector<std::variant<std::string, size_t>>;  // object keys and array indices

// The byte offset of the value at `path` in `json`; where the path cannot be followed (a key written
// with escapes, an index past the end), the offset of the deepest value it reached.
size_t jsonPlace(std::string_view json, const JsonPath& path);

}  // namespace vitrine::isf
