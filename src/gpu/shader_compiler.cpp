#include "gpu/shader_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <fstream>
#include <mutex>
#include <sstream>

namespace vitrine::gpu {
namespace {

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

EShLanguage stageOf(const std::string& name) {
  const auto ext = std::filesystem::path(name).extension();
  if (ext == ".vert") return EShLangVertex;
  if (ext == ".frag") return EShLangFragment;
  return EShLangCompute;
}

// Resolves "file" includes relative to the includer, then against the shaders/ root; records each.
class Includer : public glslang::TShader::Includer {
 public:
  Includer(std::filesystem::path root, std::vector<std::filesystem::path>& seen) : root_(std::move(root)), seen_(seen) {}

  IncludeResult* includeLocal(const char* header, const char* includer, size_t) override {
    const auto base = std::filesystem::path(includer).parent_path();
    for (const auto& candidate : {base / header, root_ / header}) {
      std::string text = readText(candidate);
      if (text.empty()) continue;
      seen_.push_back(candidate);
      auto* owned = new std::string(std::move(text));
      return new IncludeResult(candidate.string(), owned->data(), owned->size(), owned);
    }
    return nullptr;
  }
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
    return includeLocal(header, includer, depth);
  }
  void releaseInclude(IncludeResult* result) override {
    if (!result) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }

 private:
  std::filesystem::path root_;
  std::vector<std::filesystem::path>& seen_;
};

}  // namespace

namespace {

// Parses and links one stage into `out`; names[0] is the name the log gives the text (null: glslang's
// source-string numbers, as #line directives set them).
void compileInto(CompiledShader& out, const std::string& source, EShLanguage stage, const char* name,
                 glslang::TShader::Includer& includer) {
  static std::once_flag init;
  std::call_once(init, [] { glslang::InitializeProcess(); });
  glslang::TShader shader(stage);
  const char* text = source.c_str();
  if (name) {
    const char* names[] = {name};
    shader.setStringsWithLengthsAndNames(&text, nullptr, names, 1);
  } else {
    shader.setStrings(&text, 1);
  }
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_6);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  if (!shader.parse(GetDefaultResources(), 460, false, messages, includer)) {
    out.log = shader.getInfoLog();
    return;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    out.log = program.getInfoLog();
    return;
  }
  glslang::GlslangToSpv(*program.getIntermediate(stage), out.spirv);
}

// For text with no #include: every include is refused.
class NoIncludes : public glslang::TShader::Includer {
 public:
  IncludeResult* includeLocal(const char*, const char*, size_t) override { return nullptr; }
  IncludeResult* includeSystem(const char*, const char*, size_t) override { return nullptr; }
  void releaseInclude(IncludeResult*) override {}
};

}  // namespace

CompiledShader compileGlsl(const std::filesystem::path& root, const std::string& name) {
  CompiledShader out;
  const auto path = root / name;
  out.sources.push_back(path);
  const std::string source = readText(path);
  if (source.empty()) {
    out.log = path.string() + ": cannot read the shader source";
    return out;
  }
  Includer includer(root, out.sources);
  compileInto(out, source, stageOf(name), path.string().c_str(), includer);
  return out;
}

CompiledShader compileGlslText(const std::string& source, ShaderStage stage) {
  CompiledShader out;
  NoIncludes includer;
  const EShLanguage language = stage == ShaderStage::Vertex     ? EShLangVertex
                               : stage == ShaderStage::Fragment ? EShLangFragment
                                                                : EShLangCompute;
  compileInto(out, source, language, nullptr, includer);
  return out;
}

}  // namespace vitrine::gpu
