#pragma once
// What a shader's SPIR-V says about its interface, read through SPIRV-Cross: its descriptor bindings
// (number, type, name), its push-constant block's size, its workgroup size, and the layout of every
// named struct it uses in a buffer or push block. The host builds layouts from this and checks what a
// scene gives against it, so a binding or a block is declared in one place, the shader, never retyped.
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace vitrine::gpu {

struct ReflectedBinding {
  uint32_t binding = 0;  // in set 0, the only set Vitrine's shaders use
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
  std::string name;  // the variable's name, or its block's type name for an unnamed block
};

// One member of a struct as laid out in the shader (std140, std430 or push-constant offsets).
struct ReflectedMember {
  std::string name;
  uint32_t offset = 0;
  uint32_t size = 0;         // declared size: for an array, element stride x count (0 for a runtime array)
  uint32_t arrayStride = 0;  // arrays only
  std::string structName;    // the struct it is (or is an array of), if any
};

struct ReflectedStruct {
  std::string name;  // the GLSL struct or block type name
  uint32_t size = 0;  // declared size, without a trailing runtime array
  std::vector<ReflectedMember> members;
};

struct ShaderInterface {
  std::vector<ReflectedBinding> bindings;  // sorted by binding number
  uint32_t pushConstantBytes = 0;
  std::array<uint32_t, 3> localSize{1, 1, 1};  // compute shaders
  std::vector<ReflectedStruct> structs;        // every named struct reachable from a buffer or push block
};

// Throws vitrine::Error naming `shader` when the SPIR-V cannot be read or uses what Vitrine's hosts
// do not bind (a descriptor set other than 0, separate samplers, arrays of descriptors).
ShaderInterface reflectShader(std::span<const uint32_t> spirv, const std::string& shader);

const char* describe(VkDescriptorType type);  // "storage image", for messages

}  // namespace vitrine::gpu
