#pragma once
// Pipelines built from named shaders ("kifs/kifs.comp"), with push descriptors instead of descriptor
// pools. The library hands out SPIR-V (embedded at build time, or recompiled by hot reload) and
// rebuilds every program whose code changed; a compile error keeps the old pipeline and is reported.
//
// A program's interface is the shader's own, read from its SPIR-V (gpu/shader_reflection.h): the
// descriptor types and binding numbers, the push block's size and the workgroup size are never
// retyped in C++. A scene binds by name; push() and constants() check what they are given against the
// shader and throw an Error naming the shader, the binding and what it expected, before any GPU work.
#include "gpu/device.h"
#include "gpu/embedded_shaders.h"
#include "gpu/shader_reflection.h"

#include <array>
#include <filesystem>
#include <map>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vitrine::gpu {

class Program;

struct ProgramOptions {
  // Specialization constant i (layout(constant_id = i) in every stage) takes specialization[i]: one
  // shader source compiled into variants whose unused paths the driver removes (glass' shapes).
  std::vector<int32_t> specialization;
};

class ProgramLibrary {
 public:
  // `preferNewerSources` (the gallery, run from its source tree): when the sources were edited after
  // the binary was built, a shader is compiled from its source when first used instead of taking the
  // built-in SPIR-V. Headless runs and tests leave it off: their pictures depend on the binary alone.
  explicit ProgramLibrary(const Device& device, std::filesystem::path sourceRoot = VITRINE_SHADER_SOURCE_DIR,
                          bool preferNewerSources = false);
  const Device& device() const { return device_; }

  // The shader's SPIR-V: provided, else reloaded, else compiled from an edited source on first use,
  // else built in.
  std::span<const uint32_t> spirv(const std::string& name);
  // SPIR-V made at run time (an ISF file compiled as it loads) under a name no shader source has
  // ("isf:3/frag"): programs built from the name take it, and hot reload of the shader sources leaves
  // it alone. Providing a name again replaces its code for the programs built or rebuilt after;
  // withdraw() forgets it once no program uses it.
  void provide(const std::string& name, std::vector<uint32_t> code);
  void withdraw(const std::string& name) { provided_.erase(name); }

  // Polls the shader sources; when any changed, recompiles the shaders in use and rebuilds the
  // programs whose SPIR-V changed (old pipelines are retired: frames in flight may still use them).
  // Shaders not in use are compiled when a program first uses them (a scene not showing picks up
  // its edits when it opens). Returns how many programs were rebuilt.
  int reloadChanged();
  const std::string& error() const { return error_; }  // the last compile log; empty when all compile
  // The shaders that took new SPIR-V from their sources since the last call (reloads, and edited
  // sources compiled on first use), for the gallery to say so.
  std::vector<std::string> takeReloaded() { return std::exchange(reloadedNames_, {}); }
  bool hotReloadAvailable() const;

  void add(Program* program) { programs_.push_back(program); }
  // Each program's label and its pipeline's compiler statistics (Device::pipelineStatistics), in the
  // order they were made; empty unless the device captures them.
  std::vector<std::pair<std::string, std::vector<std::string>>> pipelineStatistics() const;
  void remove(Program* program);

 private:
  std::filesystem::file_time_type newestSource() const;
  std::span<const uint32_t> builtIn(const std::string& name) const;
  bool compileFromSource(const std::string& name);  // true when the SPIR-V changed
  const Device& device_;
  std::filesystem::path root_;
  std::filesystem::file_time_type seen_ = std::filesystem::file_time_type::min();  // the newest source polled
  // When the built-in SPIR-V was made, as far as the sources can tell: the binary's time when the
  // sources are newer and preferred, else the newest source when the library started.
  std::filesystem::file_time_type baseline_ = std::filesystem::file_time_type::min();
  bool sourcesEdited_ = false;  // since the build (preferNewerSources) or since the library started
  std::set<std::string, std::less<>> current_;  // compiled from the sources as they are now
  std::map<std::string, std::vector<uint32_t>, std::less<>> reloaded_;
  std::map<std::string, std::vector<uint32_t>, std::less<>> provided_;
  std::vector<std::string> reloadedNames_;
  std::vector<Program*> programs_;
  std::string error_;
};

// Descriptors for one dispatch or draw, each named as the shader names it: an image by its variable
// name, a buffer by its block's name (`buffer Heads { ... }` is "Heads"). Holds only values (names are
// copied), so a copy is as good as the original; the Vulkan writes are built and checked at push.
class Bindings {
 public:
  Bindings& storageImage(std::string_view name, VkImageView view, VkImageLayout layout = VK_IMAGE_LAYOUT_GENERAL);
  Bindings& sampledImage(std::string_view name, VkImageView view, VkSampler sampler, VkImageLayout layout);
  Bindings& storageBuffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset = 0,
                          VkDeviceSize range = VK_WHOLE_SIZE);
  Bindings& uniformBuffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset = 0,
                          VkDeviceSize range = VK_WHOLE_SIZE);
  uint32_t count() const { return count_; }

 private:
  friend class Program;
  static constexpr size_t kMax = 8, kMaxName = 32;
  struct Slot {
    std::array<char, kMaxName> name;
    VkDescriptorType type;
    VkDescriptorImageInfo image;
    VkDescriptorBufferInfo buffer;
    std::string_view nameView() const { return name.data(); }
  };
  std::array<Slot, kMax> slots_{};
  uint32_t count_ = 0;
  Slot& next(std::string_view name, VkDescriptorType type);
};

class Program {
 public:
  virtual ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  VkPipeline pipeline() const { return pipeline_; }
  // How many pipelines this program has built: 1, then one more at each hot reload. What a scene
  // compares to know its cached output came from the current code (a retired pipeline's handle may be
  // reused by a later one, so handles cannot tell).
  uint32_t builds() const { return builds_; }
  VkPipelineLayout layout() const { return layout_; }
  const std::vector<std::string>& shaders() const { return shaders_; }

  void bind(VkCommandBuffer cmd) const;
  void push(VkCommandBuffer cmd, const Bindings& bindings) const;
  // The push block, whose size must be the shader's (a shared block header makes it so by construction).
  template <typename T> void constants(VkCommandBuffer cmd, const T& value) const {
    static_assert(sizeof(T) <= 128, "push constants are limited to 128 bytes on some devices");
    pushConstants(cmd, &value, sizeof(T));
  }
  // From the library's current SPIR-V; a changed interface (hot reload) gets new layouts.
  void rebuild();
  // What the shaders declare, every stage merged.
  const ShaderInterface& interface() const { return interface_; }
  const std::string& label() const { return label_; }

 protected:
  Program(ProgramLibrary& library, std::string label, std::vector<std::string> shaders, const ProgramOptions& options,
          VkPipelineBindPoint bindPoint);
  virtual VkPipeline build() const = 0;
  Unique<VkShaderModule> module(const std::string& shader) const;
  // The specialization constants of every stage; valid while the program lives.
  const VkSpecializationInfo* specialization() const { return specializationInfo_.mapEntryCount ? &specializationInfo_ : nullptr; }
  const Device& device() const { return library_.device(); }
  // VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR where the device captures them, else none.
  VkPipelineCreateFlags createFlags() const;

 private:
  void pushConstants(VkCommandBuffer cmd, const void* data, uint32_t size) const;
  ShaderInterface reflect() const;  // every stage's interface, merged; throws on a disagreement
  void createLayouts();               // from interface_
  ProgramLibrary& library_;
  std::string label_;
  std::vector<std::string> shaders_;
  VkPipelineBindPoint bindPoint_;
  VkShaderStageFlags stages_;
  std::vector<int32_t> specializationValues_;
  std::vector<VkSpecializationMapEntry> specializationEntries_;
  VkSpecializationInfo specializationInfo_{};
  ShaderInterface interface_;
  Unique<VkDescriptorSetLayout> setLayout_;
  Unique<VkPipelineLayout> layout_;
  Unique<VkPipeline> pipeline_;
  uint32_t builds_ = 0;
};

class ComputeProgram final : public Program {
 public:
  explicit ComputeProgram(ProgramLibrary& library, const std::string& shader, const ProgramOptions& options = {});
  // Enough workgroups of the shader's local size to cover width x height (x depth) invocations.
  void dispatchOver(VkCommandBuffer cmd, VkExtent2D invocations) const;
  void dispatchOver(VkCommandBuffer cmd, VkExtent3D invocations) const;
  // Enough workgroups to cover `count` invocations along x (one per particle, one per segment).
  void dispatchOver(VkCommandBuffer cmd, uint32_t count) const { dispatchOver(cmd, VkExtent3D{count, 1, 1}); }
  // Exactly these workgroup counts (a pass that splits its work into chunks of whole groups).
  void dispatchGroups(VkCommandBuffer cmd, VkExtent3D groups) const;
  const std::array<uint32_t, 3>& localSize() const { return interface().localSize; }

 private:
  VkPipeline build() const override;
};

struct GraphicsState {
  std::string vertex, fragment;
  std::vector<VkFormat> colorFormats;
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  VkCompareOp depthCompare = VK_COMPARE_OP_GREATER;  // reverse-Z by default
  bool depthWrite = true;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkCullModeFlags cull = VK_CULL_MODE_NONE;
  // AdditiveMaxAlpha: colours add, alpha keeps the largest (light that sums, plus the nearest reverse-Z
  // depth of what added it, in one attachment).
  enum class Blend { None, Additive, AdditiveMaxAlpha, Alpha, Premultiplied } blend = Blend::None;
};

class GraphicsProgram final : public Program {
 public:
  explicit GraphicsProgram(ProgramLibrary& library, const GraphicsState& state, const ProgramOptions& options = {});

 private:
  VkPipeline build() const override;
  GraphicsState state_;
};

}  // namespace vitrine::gpu
