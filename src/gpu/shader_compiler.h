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

}  // namespace vitrine::gpu
