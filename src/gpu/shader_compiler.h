#pragma once
// GLSL to SPIR-V at run time through the glslang library, for hot reload. The build compiles the same
// files with glslangValidator; both resolve #include against the shaders/ root.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vitrine::gpu {

struct CompiledShader {
  std::vector<uint32_t> spirv;                 // empty on failure
  std::string log;                             // compiler messages with file and line
  std::vector<std::filesystem::path> sources;  // the file and everything it included
};

CompiledShader compileGlsl(const std::filesystem::path& root, const std::string& name);

// GLSL text with no #include, for a shader made at run time (an ISF file's translation). The log is
// glslang's, its lines as the text's #line directives number them.
enum class ShaderStage { Vertex, Fragment, Compute };
CompiledShader compileGlslText(const std::string& source, ShaderStage stage);

}  // namespace vitrine::gpu
