#include "isf/isf_compile.h"

#include "core/bounded_file.h"
#include "gpu/shader_compiler.h"

#include <fmt/format.h>

#include <regex>
#include <sstream>
#include <system_error>

namespace vitrine::isf {

std::vector<std::string> mappedLog(const std::string& log, const std::vector<std::string>& names) {
  static const std::regex entry(R"(^(ERROR|WARNING): (\d+):(\d+): (.*)$)");
  std::vector<std::string> out;
  std::istringstream lines(log);
  std::string line;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::smatch m;
    if (std::regex_match(line, m, entry)) {
      if (m[4].str().find("compilation terminated") != std::string::npos) continue;
      const size_t source = std::stoul(m[2].str().substr(0, 3));
      const std::string name = source < names.size() ? names[source] : fmt::format("<source {}>", m[2].str());
      out.push_back(fmt::format("{}:{}: {}: {}", name, m[3].str(), m[1] == "ERROR" ? "error" : "warning", m[4].str()));
    } else if (line.find("compilation errors.") != std::string::npos || line.find("No code generated") != std::string::npos ||
               line.empty()) {
      continue;
    } else {
      out.push_back(line);  // a link error and the like: no line to map
    }
  }
  return out;
}

namespace {

// The first mapped error's file and line, for the IsfError.
[[noreturn]] void refuse(const std::vector<std::string>& errors, const std::string& fallbackFile, const char* stage) {
  static const std::regex place(R"(^(.*):(\d+): error: (.*)$)");
  std::string rest;
  for (size_t i = 1; i < errors.size(); ++i) rest += "\n" + errors[i];
  std::smatch m;
  for (const std::string& e : errors)
    if (std::regex_match(e, m, place))
      throw IsfError(m[1].str(), std::stoi(m[2].str().substr(0, 9)), fmt::format("error: {}{}", m[3].str(), rest));
  throw IsfError(fallbackFile, 1, fmt::format("the {} shader does not compile: {}{}", stage,
                                              errors.empty() ? "glslang gave no reason" : errors.front(), rest));
}

}  // namespace

CompiledIsf compileIsf(const Document& document, const std::optional<VertexFile>& vertex) {
  CompiledIsf out;
  out.translation = translate(document, vertex);
  const auto& names = out.translation.sourceNames;
  auto fragment = gpu::compileGlslText(out.translation.fragment, gpu::ShaderStage::Fragment);
  if (fragment.spirv.empty()) refuse(mappedLog(fragment.log, names), document.file, "fragment");
  auto vs = gpu::compileGlslText(out.translation.vertex, gpu::ShaderStage::Vertex);
  if (vs.spirv.empty()) refuse(mappedLog(vs.log, names), vertex ? vertex->file : document.file, "vertex");
  out.fragment = std::move(fragment.spirv);
  out.vertex = std::move(vs.spirv);
  return out;
}

std::optional<VertexFile> loadVertexFile(const std::filesystem::path& fragmentPath) {
  auto path = fragmentPath;
  path.replace_extension(".vs");
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return std::nullopt;
  VertexFile file;
  file.file = path.string();
  try {
    file.text = readBoundedFile(path, kMaxFileBytes);
  } catch (const FileRefused& refused) {
    throw IsfError(file.file, 1, fmt::format("cannot be read: {}", refused.why));
  }
  checkText(file.text, file.file);
  return file;
}

}  // namespace vitrine::isf
