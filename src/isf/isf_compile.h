#pragma once
// An ISF file's translation compiled to SPIR-V with glslang, at load time, with no GPU: what fails is
// reported in the author's terms, "file.fs:12: error: 'colr' : undeclared identifier".
#include "isf/isf_translate.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vitrine::isf {

struct CompiledIsf {
  Translation translation;
  std::vector<uint32_t> fragment;  // SPIR-V
  std::vector<uint32_t> vertex;
};

// Throws IsfError at the first error's file and line; its `why` holds that error and, on the lines
// after, every other one, each as "file:line: error: words".
CompiledIsf compileIsf(const Document& document, const std::optional<VertexFile>& vertex = std::nullopt);

// glslang's log with each "ERROR: 1:12: words" written as "names[1]:12: error: words"; its noise (the
// "compilation terminated" and error-count lines) left out.
std::vector<std::string> mappedLog(const std::string& log, const std::vector<std::string>& names);

// The .vs file beside an .fs file (same name, extension .vs), if there is one; read through the same
// size bound. Throws IsfError when it exists but cannot be read or is not UTF-8 text.
std::optional<VertexFile> loadVertexFile(const std::filesystem::path& fragmentPath);

}  // namespace vitrine::isf
