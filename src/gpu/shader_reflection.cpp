#include "gpu/shader_reflection.h"

#include "core/error.h"

#include <fmt/format.h>
#include <spirv_cross/spirv_cross_c.h>

#include <algorithm>
#include <memory>
#include <set>

namespace vitrine::gpu {
namespace {

using Context = std::unique_ptr<std::remove_pointer_t<spvc_context>, decltype(&spvc_context_destroy)>;

// The struct layouts reachable from one buffer or push block, each struct type once.
class StructWalker {
 public:
  StructWalker(spvc_compiler compiler, std::vector<ReflectedStruct>& out) : compiler_(compiler), out_(out) {}

  void visit(spvc_type_id typeId) {
    const spvc_type type = spvc_compiler_get_type_handle(compiler_, typeId);
    if (spvc_type_get_basetype(type) != SPVC_BASETYPE_STRUCT) return;
    // An array of structs is a type of its own whose base is the struct: its members live there.
    const spvc_type_id structId = spvc_type_get_base_type_id(type);
    if (!seen_.insert(structId).second) return;
    const spvc_type structType = spvc_compiler_get_type_handle(compiler_, structId);
    ReflectedStruct layout;
    layout.name = spvc_compiler_get_name(compiler_, structId);
    size_t size = 0;
    spvc_compiler_get_declared_struct_size(compiler_, structType, &size);
    layout.size = uint32_t(size);
    const unsigned count = spvc_type_get_num_member_types(structType);
    for (unsigned i = 0; i < count; ++i) {
      const spvc_type_id memberId = spvc_type_get_member_type(structType, i);
      const spvc_type member = spvc_compiler_get_type_handle(compiler_, memberId);
      ReflectedMember m;
      m.name = spvc_compiler_get_member_name(compiler_, structId, i);
      spvc_compiler_type_struct_member_offset(compiler_, structType, i, &m.offset);
      const unsigned dims = spvc_type_get_num_array_dimensions(member);
      const bool runtimeArray = dims > 0 && spvc_type_array_dimension_is_literal(member, dims - 1) &&
                                spvc_type_get_array_dimension(member, dims - 1) == 0;
      if (dims > 0) spvc_compiler_type_struct_member_array_stride(compiler_, structType, i, &m.arrayStride);
      if (spvc_type_get_basetype(member) == SPVC_BASETYPE_STRUCT)
        m.structName = spvc_compiler_get_name(compiler_, spvc_type_get_base_type_id(member));
      if (!runtimeArray) {
        size_t memberSize = 0;
        spvc_compiler_get_declared_struct_member_size(compiler_, structType, i, &memberSize);
        m.size = uint32_t(memberSize);
      }
      layout.members.push_back(std::move(m));
      visit(memberId);
    }
    if (!layout.name.empty()) out_.push_back(std::move(layout));
  }

 private:
  spvc_compiler compiler_;
  std::vector<ReflectedStruct>& out_;
  std::set<spvc_type_id> seen_;
};

}  // namespace

const char* describe(VkDescriptorType type) {
  switch (type) {
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: return "storage image";
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: return "sampled image";
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: return "storage buffer";
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: return "uniform buffer";
    default: return "unsupported descriptor";
  }
}

ShaderInterface reflectShader(std::span<const uint32_t> spirv, const std::string& shader) {
  spvc_context raw = nullptr;
  if (spvc_context_create(&raw) != SPVC_SUCCESS) throw Error("SPIRV-Cross could not start");
  const Context context(raw, &spvc_context_destroy);
  const auto fail = [&](const std::string& what) {
    return Error(fmt::format("{}: {}{}", shader, what,
                             *spvc_context_get_last_error_string(raw) ? std::string(" (") +
                                 spvc_context_get_last_error_string(raw) + ")" : std::string()));
  };
  spvc_parsed_ir ir = nullptr;
  spvc_compiler compiler = nullptr;
  spvc_resources resources = nullptr;
  if (spvc_context_parse_spirv(raw, spirv.data(), spirv.size(), &ir) != SPVC_SUCCESS ||
      spvc_context_create_compiler(raw, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler) !=
          SPVC_SUCCESS ||
      spvc_compiler_create_shader_resources(compiler, &resources) != SPVC_SUCCESS)
    throw fail("not readable SPIR-V");

  ShaderInterface result;
  StructWalker walker(compiler, result.structs);
  const auto each = [&](spvc_resource_type kind, auto&& body) {
    const spvc_reflected_resource* list = nullptr;
    size_t count = 0;
    spvc_resources_get_resource_list_for_type(resources, kind, &list, &count);
    for (size_t i = 0; i < count; ++i) body(list[i]);
  };
  const auto addBinding = [&](const spvc_reflected_resource& resource, VkDescriptorType type) {
    if (spvc_compiler_get_decoration(compiler, resource.id, SpvDecorationDescriptorSet) != 0)
      throw fail(fmt::format("'{}' is in a descriptor set other than 0", resource.name));
    if (spvc_type_get_num_array_dimensions(spvc_compiler_get_type_handle(compiler, resource.type_id)) != 0)
      throw fail(fmt::format("'{}' is an array of descriptors, which the hosts do not bind", resource.name));
    result.bindings.push_back(
        {spvc_compiler_get_decoration(compiler, resource.id, SpvDecorationBinding), type, resource.name});
  };
  each(SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, [&](const spvc_reflected_resource& r) {
    addBinding(r, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    walker.visit(r.base_type_id);
  });
  each(SPVC_RESOURCE_TYPE_STORAGE_BUFFER, [&](const spvc_reflected_resource& r) {
    addBinding(r, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    walker.visit(r.base_type_id);
  });
  each(SPVC_RESOURCE_TYPE_STORAGE_IMAGE,
       [&](const spvc_reflected_resource& r) { addBinding(r, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE); });
  each(SPVC_RESOURCE_TYPE_SAMPLED_IMAGE,
       [&](const spvc_reflected_resource& r) { addBinding(r, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER); });
  each(SPVC_RESOURCE_TYPE_SEPARATE_IMAGE,
       [&](const spvc_reflected_resource& r) { throw fail(fmt::format("'{}' is a separate image", r.name)); });
  each(SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS,
       [&](const spvc_reflected_resource& r) { throw fail(fmt::format("'{}' is a separate sampler", r.name)); });
  each(SPVC_RESOURCE_TYPE_PUSH_CONSTANT, [&](const spvc_reflected_resource& r) {
    size_t size = 0;
    spvc_compiler_get_declared_struct_size(compiler, spvc_compiler_get_type_handle(compiler, r.base_type_id), &size);
    result.pushConstantBytes = uint32_t(size);
    walker.visit(r.base_type_id);
  });
  std::sort(result.bindings.begin(), result.bindings.end(),
            [](const auto& a, const auto& b) { return a.binding < b.binding; });
  for (size_t i = 1; i < result.bindings.size(); ++i)
    if (result.bindings[i].binding == result.bindings[i - 1].binding)
      throw fail(fmt::format("'{}' and '{}' share binding {}", result.bindings[i - 1].name, result.bindings[i].name,
                             result.bindings[i].binding));
  if (spvc_compiler_get_execution_model(compiler) == SpvExecutionModelGLCompute)
    for (unsigned axis = 0; axis < 3; ++axis)
      result.localSize[axis] =
          std::max(1u, spvc_compiler_get_execution_mode_argument_by_index(compiler, SpvExecutionModeLocalSize, axis));
  return result;
}

}  // namespace vitrine::gpu
