// Writes the C++ file that proves every block shared between C++ and GLSL has one layout: for each
// struct declared in a shared header (a .h under shaders/, see shaders/common/interop.h) and each
// shader whose SPIR-V uses it, a static_assert per member on its offset and size, on the struct's
// size, and on the stride of every array of it. The shaders' own reflection is the truth, so the
// checks cannot drift: edit either side alone and the build stops, naming the shader and the member.
//
// Usage: vitrine_block_layouts OUT.cpp HEADER... [--spirv NAME=FILE.spv ...], run from the repository
// root with headers named from it ("shaders/kifs/march_push.h"), as the generated file includes them.
// Without --spirv it checks every shader built into the binary (gpu::embeddedShaders()).
#include "gpu/embedded_shaders.h"
#include "gpu/shader_reflection.h"

#include <fmt/format.h>

#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>


namespace {

using vitrine::gpu::ReflectedStruct;

std::vector<uint32_t> readWords(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  return words;
}

// The struct names a shared header declares.
std::vector<std::string> declaredStructs(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string source = text.str();
  static const std::regex declaration(R"(\bstruct\s+([A-Za-z_]\w*)\s*\{)");
  std::vector<std::string> names;
  for (auto it = std::sregex_iterator(source.begin(), source.end(), declaration); it != std::sregex_iterator(); ++it)
    names.push_back((*it)[1]);
  return names;
}

std::string layoutKey(const ReflectedStruct& s) {
  std::string key = fmt::format("{}:{}", s.name, s.size);
  for (const auto& m : s.members) key += fmt::format("|{}@{}+{}/{}", m.name, m.offset, m.size, m.arrayStride);
  return key;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: vitrine_block_layouts OUT.cpp HEADER... [--spirv NAME=FILE.spv ...]\n";
    return 2;
  }
  const std::string outPath = argv[1];
  std::vector<std::string> headers;
  std::vector<std::pair<std::string, std::vector<uint32_t>>> shaders;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--spirv" && i + 1 < argc) {
      const std::string spec = argv[++i];
      const auto eq = spec.find('=');
      shaders.emplace_back(spec.substr(0, eq), readWords(spec.substr(eq + 1)));
    } else {
      headers.push_back(arg);
    }
  }
  if (shaders.empty())
    for (const auto& [name, code] : vitrine::gpu::embeddedShaders())
      shaders.emplace_back(std::string(name), std::vector<uint32_t>(code.begin(), code.end()));

  std::map<std::string, std::string> sharedIn;  // struct name -> its header
  for (const auto& header : headers)
    for (const auto& name : declaredStructs(header)) {
      if (auto [it, fresh] = sharedIn.emplace(name, header); !fresh) {
        std::cerr << fmt::format("{}: struct {} is declared in {} too: shared structs share one namespace\n",
                                 header, name, it->second);
        return 1;
      }
    }

  std::string checks;
  std::set<std::string> emitted, used;
  try {
    for (const auto& [shader, code] : shaders) {
      const auto interface = vitrine::gpu::reflectShader(code, shader);
      for (const ReflectedStruct& s : interface.structs) {
        // An array of a shared struct inside any block (shared or not: `buffer Heads { HeadState h[]; }`)
        // must step as a C++ array of it does.
        for (const auto& m : s.members) {
          if (!m.arrayStride || !sharedIn.contains(m.structName)) continue;
          if (!emitted.insert(fmt::format("{}[]{}", m.structName, m.arrayStride)).second) continue;
          checks += fmt::format("static_assert(sizeof({0}) == {1}, \"{2}: {3}::{4} steps {1} bytes per {0} in the shader\");\n",
                                m.structName, m.arrayStride, shader, s.name, m.name);
        }
        if (!sharedIn.contains(s.name) || !emitted.insert(layoutKey(s)).second) continue;
        used.insert(s.name);
        checks += fmt::format("// {} as {} lays it out\n", s.name, shader);
        for (const auto& m : s.members) {
          checks += fmt::format(
              "static_assert(offsetof({0}, {1}) == {2}, \"{3}: {0}::{1} is at byte {2} in the shader\");\n", s.name,
              m.name, m.offset, shader);
          if (m.size)
            checks += fmt::format(
                "static_assert(sizeof({0}::{1}) == {2}, \"{3}: {0}::{1} is {2} bytes in the shader\");\n", s.name,
                m.name, m.size, shader);
        }
        checks += fmt::format("static_assert(sizeof({0}) == {1}, \"{2}: {0} is {1} bytes in the shader\");\n\n",
                              s.name, s.size, shader);
      }
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }

  std::string out =
      "// Generated by tools/block_layouts.cpp from the shaders' SPIR-V: every struct a header shares between\n"
      "// C++ and GLSL, checked against each shader's own layout. Do not edit; edit the header or the shader.\n"
      "#include <cstddef>\n";
  for (const auto& header : headers) out += fmt::format("#include \"{}\"\n", header);
  out += "\nnamespace vitrine::shader {\n\n" + checks + "}  // namespace vitrine::shader\n";
  for (const auto& [name, header] : sharedIn)
    if (!used.contains(name)) out += fmt::format("// {} ({}) is used by no shader's buffer or push block.\n", name, header);

  // Rewrite only on a change, so an unchanged result recompiles nothing.
  std::ifstream previous(outPath);
  std::stringstream old;
  old << previous.rdbuf();
  if (old.str() != out) std::ofstream(outPath) << out;
  return 0;
}
