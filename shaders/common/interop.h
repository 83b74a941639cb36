// What lets one header declare a block for GLSL and C++ at once: a shared header includes this,
// then declares plain structs between VITRINE_SHARED_BEGIN and VITRINE_SHARED_END with GLSL's type
// names. In GLSL they are what they say; in C++ they are GLM's types in namespace vitrine::shader.
// std140/std430 and C++ can still disagree (a vec3 followed by a vec3, a bool, an array of floats in a
// uniform block): the build checks every shared struct against each shader that uses it, member by
// member (tools/block_layouts.cpp), so a disagreement fails the build naming the shader and member.
#ifndef VITRINE_INTEROP_H
#define VITRINE_INTEROP_H

#ifdef __cplusplus
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>

namespace vitrine::shader {
using uint = uint32_t;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using ivec2 = glm::ivec2;
using ivec4 = glm::ivec4;
using uvec2 = glm::uvec2;
using uvec3 = glm::uvec3;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
}  // namespace vitrine::shader

#define VITRINE_SHARED_BEGIN namespace vitrine::shader {
#define VITRINE_SHARED_END }
#else
#define VITRINE_SHARED_BEGIN
#define VITRINE_SHARED_END
#endif

#endif
