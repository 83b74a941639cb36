#include "gpu/program.h"

#include "gpu/check.h"
#include "gpu/shader_compiler.h"

#include <algorithm>
#include <fmt/format.h>
#include <set>
#include <utility>

namespace vitrine::gpu {

// ------------------------------------------------------------------------------------------ library

ProgramLibrary::ProgramLibrary(const Device& device, std::filesystem::path sourceRoot, bool preferNewerSources)
    : device_(device), root_(std::move(sourceRoot)) {
  if (!hotReloadAvailable()) return;
  seen_ = baseline_ = newestSource();
  if (preferNewerSources) {
    std::error_code ec;
    if (const auto built = std::filesystem::last_write_time("/proc/self/exe", ec); !ec && seen_ > built) {
      baseline_ = built;
      sourcesEdited_ = true;
    }
  }
}

bool ProgramLibrary::hotReloadAvailable() const {
  std::error_code ec;
  return std::filesystem::is_directory(root_, ec);
}

std::span<const uint32_t> ProgramLibrary::builtIn(const std::string& name) const {
  for (const auto& [shader, code] : embeddedShaders())
    if (shader == name) return code;
  throw Error(fmt::format("No shader named '{}' was built into this binary", name));
}

std::span<const uint32_t> ProgramLibrary::spirv(const std::string& name) {
  if (auto it = provided_.find(name); it != provided_.end()) return it->second;
  if (sourcesEdited_ && !current_.contains(name) && compileFromSource(name)) reloadedNames_.push_back(name);
  if (auto it = reloaded_.find(name); it != reloaded_.end()) return it->second;
  return builtIn(name);
}

// Compiles `name` as its sources are now and keeps the result when it differs from what is in use.
// The build's SPIR-V carries debug information a run-time compile does not, so against the built-in
// code "differs" means a source of the shader (it or an include) was written after the baseline. A
// compile error keeps what is in use and adds the log to error().
bool ProgramLibrary::compileFromSource(const std::string& name) {
  current_.insert(name);
  CompiledShader compiled = compileGlsl(root_, name);
  if (compiled.spirv.empty()) {
    error_ += compiled.log;
    return false;
  }
  if (const auto it = reloaded_.find(name); it != reloaded_.end()) {
    if (it->second == compiled.spirv) return false;
  } else {
    std::error_code ec;
    const bool edited = std::any_of(compiled.sources.begin(), compiled.sources.end(), [&](const auto& source) {
      return std::filesystem::last_write_time(source, ec) > baseline_;
    });
    if (!edited) return false;
  }
  reloaded_[name] = std::move(compiled.spirv);
  return true;
}

std::filesystem::file_time_type ProgramLibrary::newestSource() const {
  // file_clock times can be negative (libstdc++ puts its epoch in 2174): start from min(), not zero.
  auto newest = std::filesystem::file_time_type::min();
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(root_, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
    if (it->is_regular_file(ec)) newest = std::max(newest, it->last_write_time(ec));
  return newest;
}

int ProgramLibrary::reloadChanged() {
  if (!hotReloadAvailable()) return 0;
  const auto newest = newestSource();
  if (newest <= seen_) return 0;
  seen_ = newest;
  sourcesEdited_ = true;
  current_.clear();  // every shader is stale until compiled again, in use now or when next used

  std::set<std::string> names;
  for (const Program* program : programs_)
    for (const auto& shader : program->shaders())
      if (!provided_.contains(shader)) names.insert(shader);
  std::set<std::string> changed;
  error_.clear();
  for (const auto& name : names)
    if (compileFromSource(name)) changed.insert(name);
  if (changed.empty()) return 0;
  reloadedNames_.insert(reloadedNames_.end(), changed.begin(), changed.end());
  int rebuilt = 0;
  for (Program* program : programs_) {
    const auto& used = program->shaders();
    if (std::none_of(used.begin(), used.end(), [&](const std::string& s) { return changed.count(s) > 0; })) continue;
    try {
      program->rebuild();
      ++rebuilt;
    } catch (const Error& e) {  // e.g. an interface mismatch the compiler could not see
      error_ += e.what();
    }
  }
  return rebuilt;
}

void ProgramLibrary::provide(const std::string& name, std::vector<uint32_t> code) {
  if (code.empty()) throw Error(fmt::format("Shader '{}' was provided with no code", name));
  provided_[name] = std::move(code);
}

void ProgramLibrary::remove(Program* program) { std::erase(programs_, program); }

std::vector<std::pair<std::string, std::vector<std::string>>> ProgramLibrary::pipelineStatistics() const {
  std::vector<std::pair<std::string, std::vector<std::string>>> all;
  for (const Program* program : programs_) all.emplace_back(program->label(), device_.pipelineStatistics(program->pipeline()));
  return all;
}

// ------------------------------------------------------------------------------------------ bindings

Bindings::Slot& Bindings::next(std::string_view name, VkDescriptorType type) {
  if (count_ == kMax) throw Error("Too many descriptor bindings for one program");
  if (name.empty() || name.size() >= kMaxName) throw Error(fmt::format("Binding name '{}' is empty or too long", name));
  for (uint32_t i = 0; i < count_; ++i)
    if (slots_[i].nameView() == name) throw Error(fmt::format("Binding '{}' is given twice", name));
  Slot& slot = slots_[count_++];
  slot = {{}, type, {}, {}};
  name.copy(slot.name.data(), name.size());
  return slot;
}

Bindings& Bindings::storageImage(std::string_view name, VkImageView view, VkImageLayout layout) {
  next(name, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE).image = {VK_NULL_HANDLE, view, layout};
  return *this;
}

Bindings& Bindings::sampledImage(std::string_view name, VkImageView view, VkSampler sampler, VkImageLayout layout) {
  next(name, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER).image = {sampler, view, layout};
  return *this;
}

Bindings& Bindings::storageBuffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
  next(name, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).buffer = {buffer, offset, range};
  return *this;
}

Bindings& Bindings::uniformBuffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
  next(name, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER).buffer = {buffer, offset, range};
  return *this;
}

// ------------------------------------------------------------------------------------------- program

Program::Program(ProgramLibrary& library, std::string label, std::vector<std::string> shaders,
                 const ProgramOptions& options, VkPipelineBindPoint bindPoint)
    : library_(library), label_(std::move(label)), shaders_(std::move(shaders)), bindPoint_(bindPoint),
      specializationValues_(options.specialization) {
  for (uint32_t i = 0; i < specializationValues_.size(); ++i)
    specializationEntries_.push_back({i, uint32_t(i * sizeof(int32_t)), sizeof(int32_t)});
  specializationInfo_ = {uint32_t(specializationEntries_.size()), specializationEntries_.data(),
                         specializationValues_.size() * sizeof(int32_t), specializationValues_.data()};
  stages_ = bindPoint == VK_PIPELINE_BIND_POINT_COMPUTE ? VK_SHADER_STAGE_COMPUTE_BIT : VK_SHADER_STAGE_ALL_GRAPHICS;
  interface_ = reflect();
  createLayouts();
  library_.add(this);
}

Program::~Program() { library_.remove(this); }

// The stages' interfaces as one: a binding number two stages share must be the same resource, and
// the push block is as large as the largest stage's (each stage declares the part it reads).
ShaderInterface Program::reflect() const {
  ShaderInterface merged;
  for (const auto& shader : shaders_) {
    ShaderInterface stage = reflectShader(library_.spirv(shader), shader);
    for (auto& binding : stage.bindings) {
      const auto same = std::find_if(merged.bindings.begin(), merged.bindings.end(),
                                     [&](const auto& b) { return b.binding == binding.binding; });
      if (same == merged.bindings.end()) {
        merged.bindings.push_back(std::move(binding));
      } else if (same->type != binding.type || same->name != binding.name) {
        throw Error(fmt::format("{}: binding {} is {} '{}' in one stage and {} '{}' in {}", label_, binding.binding,
                                describe(same->type), same->name, describe(binding.type), binding.name, shader));
      }
    }
    merged.pushConstantBytes = std::max(merged.pushConstantBytes, stage.pushConstantBytes);
    if (bindPoint_ == VK_PIPELINE_BIND_POINT_COMPUTE) merged.localSize = stage.localSize;
  }
  std::sort(merged.bindings.begin(), merged.bindings.end(),
            [](const auto& a, const auto& b) { return a.binding < b.binding; });
  return merged;
}

void Program::createLayouts() {
  const Device& dev = device();
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const auto& binding : interface_.bindings)
    bindings.push_back({binding.binding, binding.type, 1, stages_, nullptr});
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  setInfo.bindingCount = static_cast<uint32_t>(bindings.size());
  setInfo.pBindings = bindings.data();
  VkDescriptorSetLayout setLayout;
  VK_CHECK(vkCreateDescriptorSetLayout(dev, &setInfo, nullptr, &setLayout));
  if (setLayout_) dev.retire(std::move(setLayout_));
  setLayout_ = Unique<VkDescriptorSetLayout>(dev, setLayout);

  const VkPushConstantRange range{stages_, 0, interface_.pushConstantBytes};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout;
  layoutInfo.pushConstantRangeCount = interface_.pushConstantBytes ? 1 : 0;
  layoutInfo.pPushConstantRanges = &range;
  VkPipelineLayout pipelineLayout;
  VK_CHECK(vkCreatePipelineLayout(dev, &layoutInfo, nullptr, &pipelineLayout));
  if (layout_) dev.retire(std::move(layout_));
  layout_ = Unique<VkPipelineLayout>(dev, pipelineLayout);
  dev.name(pipelineLayout, VK_OBJECT_TYPE_PIPELINE_LAYOUT, label_ + " layout");
}

void Program::rebuild() {
  if (pipeline_) {  // a reload: the edited shader may declare other bindings or another push block
    ShaderInterface fresh = reflect();
    const bool sameLayout = fresh.pushConstantBytes == interface_.pushConstantBytes &&
                            std::equal(fresh.bindings.begin(), fresh.bindings.end(), interface_.bindings.begin(),
                                       interface_.bindings.end(), [](const auto& a, const auto& b) {
                                         return a.binding == b.binding && a.type == b.type;
                                       });
    interface_ = std::move(fresh);
    if (!sameLayout) createLayouts();
  }
  Unique<VkPipeline> fresh(device(), build());
  if (pipeline_) device().retire(std::move(pipeline_));  // frames in flight may still run the old one
  pipeline_ = std::move(fresh);
  ++builds_;
  device().name(pipeline_.get(), VK_OBJECT_TYPE_PIPELINE, label_);
}

Unique<VkShaderModule> Program::module(const std::string& shader) const {
  const auto code = library_.spirv(shader);
  const VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO, nullptr, 0,
                                      code.size() * sizeof(uint32_t), code.data()};
  VkShaderModule module;
  VK_CHECK(vkCreateShaderModule(device(), &info, nullptr, &module));
  device().name(module, VK_OBJECT_TYPE_SHADER_MODULE, shader);
  return Unique<VkShaderModule>(device(), module);
}

void Program::bind(VkCommandBuffer cmd) const { vkCmdBindPipeline(cmd, bindPoint_, pipeline_); }

// Every binding the shader declares must be given once, by its name and of its type, and nothing
// else: the writes are made in the shader's binding order, whatever order the scene gave them in.
void Program::push(VkCommandBuffer cmd, const Bindings& bindings) const {
  std::array<VkWriteDescriptorSet, Bindings::kMax> writes{};
  if (interface_.bindings.size() > Bindings::kMax)
    throw Error(fmt::format("{}: declares {} bindings, more than {}", label_, interface_.bindings.size(), Bindings::kMax));
  uint32_t used = 0;
  for (size_t i = 0; i < interface_.bindings.size(); ++i) {
    const ReflectedBinding& expected = interface_.bindings[i];
    const Bindings::Slot* given = nullptr;
    for (uint32_t s = 0; s < bindings.count_; ++s)
      if (bindings.slots_[s].nameView() == expected.name) given = &bindings.slots_[s];
    if (!given)
      throw Error(fmt::format("{}: binding {} '{}' ({}) was not given", label_, expected.binding, expected.name,
                              describe(expected.type)));
    if (given->type != expected.type)
      throw Error(fmt::format("{}: binding {} '{}' is a {} in the shader, given a {}", label_, expected.binding,
                              expected.name, describe(expected.type), describe(given->type)));
    const bool image = given->type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE ||
                       given->type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstBinding = expected.binding;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = given->type;
    writes[i].pImageInfo = image ? &given->image : nullptr;
    writes[i].pBufferInfo = image ? nullptr : &given->buffer;
    ++used;
  }
  if (used != bindings.count_) {
    std::string names;
    for (const auto& b : interface_.bindings) names += fmt::format("{}{}", names.empty() ? "" : ", ", b.name);
    for (uint32_t s = 0; s < bindings.count_; ++s)
      if (std::none_of(interface_.bindings.begin(), interface_.bindings.end(),
                       [&](const auto& b) { return b.name == bindings.slots_[s].nameView(); }))
        throw Error(fmt::format("{}: the shader has no binding '{}' (it has: {})", label_,
                                bindings.slots_[s].nameView(), names.empty() ? "none" : names));
  }
  if (used) device().cmdPushDescriptorSet(cmd, bindPoint_, layout_, 0, used, writes.data());
}

void Program::pushConstants(VkCommandBuffer cmd, const void* data, uint32_t size) const {
  if (size != interface_.pushConstantBytes)
    throw Error(fmt::format("{}: the push block is {} bytes in the shader, {} given", label_,
                            interface_.pushConstantBytes, size));
  vkCmdPushConstants(cmd, layout_, stages_, 0, size, data);
}

ComputeProgram::ComputeProgram(ProgramLibrary& library, const std::string& shader, const ProgramOptions& options)
    : Program(library, shader, {shader}, options, VK_PIPELINE_BIND_POINT_COMPUTE) {
  rebuild();
}

VkPipelineCreateFlags Program::createFlags() const {
  return device().capturesPipelineStatistics() ? VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR : 0;
}

VkPipeline ComputeProgram::build() const {
  const auto shaderModule = module(shaders()[0]);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.flags = createFlags();
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_COMPUTE_BIT,
                shaderModule, "main", specialization()};
  info.layout = layout();
  VkPipeline pipeline;
  VK_CHECK(vkCreateComputePipelines(device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  return pipeline;
}

void ComputeProgram::dispatchOver(VkCommandBuffer cmd, VkExtent3D invocations) const {
  const auto& local = localSize();
  dispatchGroups(cmd, {(invocations.width + local[0] - 1) / local[0], (invocations.height + local[1] - 1) / local[1],
                       (invocations.depth + local[2] - 1) / local[2]});
}

void ComputeProgram::dispatchOver(VkCommandBuffer cmd, VkExtent2D invocations) const {
  dispatchOver(cmd, VkExtent3D{invocations.width, invocations.height, 1});
}

void ComputeProgram::dispatchGroups(VkCommandBuffer cmd, VkExtent3D groups) const {
  vkCmdDispatch(cmd, groups.width, groups.height, groups.depth);
}

GraphicsProgram::GraphicsProgram(ProgramLibrary& library, const GraphicsState& state, const ProgramOptions& options)
    : Program(library, state.vertex + "+" + state.fragment, {state.vertex, state.fragment}, options,
              VK_PIPELINE_BIND_POINT_GRAPHICS),
      state_(state) {
  rebuild();
}

VkPipeline GraphicsProgram::build() const {
  const auto vertex = module(state_.vertex);
  const auto fragment = module(state_.fragment);
  const VkPipelineShaderStageCreateInfo stages[] = {
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_VERTEX_BIT, vertex, "main",
       specialization()},
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_FRAGMENT_BIT, fragment,
       "main", specialization()}};
  // Geometry comes from storage buffers indexed by gl_VertexIndex / gl_InstanceIndex: no vertex input.
  const VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  const VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
                                                        nullptr, 0, state_.topology, VK_FALSE};
  const VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO, nullptr, 0,
                                                   1, nullptr, 1, nullptr};
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = state_.cull;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = state_.samples;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = state_.depthFormat != VK_FORMAT_UNDEFINED;
  depth.depthWriteEnable = depth.depthTestEnable && state_.depthWrite;
  depth.depthCompareOp = state_.depthCompare;
  VkPipelineColorBlendAttachmentState blend{};
  blend.colorWriteMask = 0xF;
  if (state_.blend != GraphicsState::Blend::None) {
    const bool additive = state_.blend == GraphicsState::Blend::Additive ||
                          state_.blend == GraphicsState::Blend::AdditiveMaxAlpha;
    const bool premultiplied = state_.blend == GraphicsState::Blend::Premultiplied;
    blend.blendEnable = VK_TRUE;
    blend.srcColorBlendFactor = additive || premultiplied ? VK_BLEND_FACTOR_ONE : VK_BLEND_FACTOR_SRC_ALPHA;
    blend.dstColorBlendFactor = additive ? VK_BLEND_FACTOR_ONE : VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend.colorBlendOp = VK_BLEND_OP_ADD;
    blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend.alphaBlendOp = state_.blend == GraphicsState::Blend::AdditiveMaxAlpha ? VK_BLEND_OP_MAX : VK_BLEND_OP_ADD;
  }
  const std::vector<VkPipelineColorBlendAttachmentState> blends(state_.colorFormats.size(), blend);
  VkPipelineColorBlendStateCreateInfo colorBlend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  colorBlend.attachmentCount = static_cast<uint32_t>(blends.size());
  colorBlend.pAttachments = blends.data();
  const VkDynamicState dynamics[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  const VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO, nullptr, 0, 2,
                                                 dynamics};
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = static_cast<uint32_t>(state_.colorFormats.size());
  rendering.pColorAttachmentFormats = state_.colorFormats.data();
  rendering.depthAttachmentFormat = state_.depthFormat;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &colorBlend;
  info.pDynamicState = &dynamic;
  info.layout = layout();
  info.flags = createFlags();
  VkPipeline pipeline;
  VK_CHECK(vkCreateGraphicsPipelines(device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  return pipeline;
}

}  // namespace vitrine::gpu
