#include "isf/gpu/isf_runner.h"

#include "core/error.h"
#include "gpu/stream.h"
#include "shaders/isf/convert_push.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <map>
#include <optional>

namespace vitrine::isf {
namespace {

// An image a pass samples, in either stage: a .vs may sample too.
constexpr gpu::ImageUse kSampled{VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};

// A GL host's buffers are 8 bits a channel unless FLOAT asks for floats; ISF files are written (and
// their feedback loops tuned) for that clamping and precision. The output keeps half floats: it is
// the last pass's picture, converted to linear light after.
constexpr VkFormat kBufferFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kFloatFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat kOutputFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkImageUsageFlags kDrawn = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
// Samples an audio texture holds when its input gives no MAX.
constexpr int kDefaultAudioSamples = 256;

std::vector<std::byte> bottomRowFirst(const Picture& picture) {
  std::vector<std::byte> texels(picture.rgba.size());
  const size_t row = size_t(picture.width) * 4;
  for (uint32_t y = 0; y < picture.height; ++y)
    std::memcpy(texels.data() + size_t(y) * row, picture.rgba.data() + size_t(picture.height - 1 - y) * row, row);
  return texels;
}

gpu::ImageDecl pictureDecl(std::string name, const Picture& picture) {
  gpu::ImageDecl decl;
  decl.name = std::move(name);
  decl.format = VK_FORMAT_R8G8B8A8_UNORM;  // the file's values as they are, as GL samples them
  decl.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  decl.size = gpu::ImageSize::absolute(std::max(picture.width, 1u), std::max(picture.height, 1u));
  decl.initial = picture.rgba.empty() ? std::vector<std::byte>(4, std::byte{0}) : bottomRowFirst(picture);
  decl.initialUse = kSampled;
  return decl;
}

// `samples` spread over `wanted` texels, each `offset + scale * value`: a waveform takes the sample at
// each texel (as a line drawn at another width would), a spectrum the loudest bin a texel covers (so
// a tone between two texels' bins still shows); `offset` throughout when there are none.
std::vector<float> resampled(std::span<const float> samples, size_t wanted, float offset, float scale, bool peak) {
  std::vector<float> texels(wanted, offset);
  if (samples.empty()) return texels;
  const auto finite = [&](size_t i) { return std::isfinite(samples[i]) ? samples[i] : 0.0f; };
  for (size_t i = 0; i < wanted; ++i) {
    const size_t from = std::min(samples.size() - 1, i * samples.size() / wanted);
    const size_t to = std::max(from + 1, std::min(samples.size(), (i + 1) * samples.size() / wanted));
    float value = finite(from);
    if (peak)
      for (size_t k = from + 1; k < to; ++k) value = std::max(value, finite(k));
    texels[i] = offset + scale * value;
  }
  return texels;
}

std::atomic<uint64_t> nextSerial{0};

}  // namespace

glm::vec4 wallClockDate() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t t = std::chrono::system_clock::to_time_t(now);
  std::tm local{};
  localtime_r(&t, &local);
  const double fraction =
      std::chrono::duration<double>(now.time_since_epoch()).count() - std::floor(std::chrono::duration<double>(now.time_since_epoch()).count());
  return {float(local.tm_year + 1900), float(local.tm_mon + 1), float(local.tm_mday),
          float(local.tm_hour * 3600 + local.tm_min * 60 + local.tm_sec) + float(fraction)};
}

glm::vec4 simulatedDate(double seconds) {
  const double clamped = std::clamp(seconds, 0.0, 86400.0 * 365.0 * 50.0);
  const auto days = int64_t(clamped / 86400.0);
  // Civil date from days since 2000-01-01 (Howard Hinnant's algorithm, shifted to that epoch).
  const int64_t z = days + 10957 + 719468;
  const int64_t era = z / 146097, doe = z - era * 146097;
  const int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100), mp = (5 * doy + 2) / 153;
  const int64_t day = doy - (153 * mp + 2) / 5 + 1, month = mp < 10 ? mp + 3 : mp - 9;
  const int64_t year = yoe + era * 400 + (month <= 2 ? 1 : 0);
  return {float(year), float(month), float(day), float(clamped - double(days) * 86400.0)};
}

struct Runner::State {
  struct Target {
    std::string name;
    bool persistent = false;
    VkFormat format = kBufferFormat;
    gpu::ImageHandle image;
    VkExtent2D size{0, 0};
  };
  struct Sampled {
    SamplerBinding binding;
    enum class Kind { Picture, Source, Audio, Imported, Target } kind = Kind::Picture;
    int input = -1;       // Document::inputs index (Picture, Source, Audio)
    gpu::ImageHandle image;  // Picture, Source, Audio, Imported
    size_t target = 0;       // Target: index in targets
    std::string file;        // Picture: the file loaded
    int audioSamples = 0;    // Audio: texels
  };

  explicit State(const GpuContext& context) : device(context.device), programs(context.programs), resources(context.device) {}

  const gpu::Device& device;
  gpu::ProgramLibrary& programs;
  // The runner's own set, not its owner's: a reloaded file's buffers go with the runner it replaces.
  gpu::FrameResources resources;
  std::string vertexName, fragmentName;
  std::map<VkFormat, std::unique_ptr<gpu::GraphicsProgram>> pipelines;
  std::optional<gpu::ComputeProgram> convert;
  std::vector<Target> targets;
  std::vector<Sampled> sampled;
  std::vector<int> passTarget;  // per pass: index in targets, -1 for the output
  gpu::ImageHandle output, cleared;
  VkExtent2D outputSize{0, 0};
  Values values;  // the latest update()'s: what sizes are evaluated with
  BlockLayout block;

  gpu::GraphicsProgram& pipeline(VkFormat format) { return *pipelines.at(format); }
};

Runner::Runner(const GpuContext& context, std::shared_ptr<const LoadedFile> file)
    : state_(std::make_unique<State>(context)), file_(std::move(file)) {
  State& s = *state_;
  const Document& doc = file_->document;
  const uint64_t serial = nextSerial++;
  s.vertexName = fmt::format("isf:{}:{}.vert", serial, file_->path.filename().string());
  s.fragmentName = fmt::format("isf:{}:{}.frag", serial, file_->path.filename().string());
  s.programs.provide(s.vertexName, file_->compiled.vertex);
  s.programs.provide(s.fragmentName, file_->compiled.fragment);
  s.block = file_->compiled.translation.frame;
  s.values = defaultValues(doc);

  for (const Pass* pass : doc.targets())
    s.targets.push_back({pass->target, pass->persistent, pass->floatTarget ? kFloatFormat : kBufferFormat, {}, {}});
  for (const Pass& pass : doc.passes) {
    int index = -1;
    for (size_t t = 0; t < s.targets.size(); ++t)
      if (!pass.target.empty() && s.targets[t].name == pass.target) index = int(t);
    s.passTarget.push_back(index);
  }
  const auto makePipeline = [&](VkFormat format) {
    if (s.pipelines.contains(format)) return;
    gpu::GraphicsState state;
    state.vertex = s.vertexName;
    state.fragment = s.fragmentName;
    state.colorFormats = {format};
    state.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    s.pipelines[format] = std::make_unique<gpu::GraphicsProgram>(s.programs, state);
  };
  for (size_t p = 0; p < doc.passes.size(); ++p)
    makePipeline(s.passTarget[p] < 0 ? kOutputFormat : s.targets[size_t(s.passTarget[p])].format);
  s.convert.emplace(s.programs, "isf/convert.comp");

  s.cleared = s.resources.declare(pictureDecl("isf cleared", Picture{}));
  for (const SamplerBinding& binding : file_->compiled.translation.samplers) {
    State::Sampled entry{binding};
    if (binding.source == SamplerBinding::Source::Imported) {
      entry.kind = State::Sampled::Kind::Imported;
      for (size_t i = 0; i < doc.imported.size(); ++i)
        if (doc.imported[i].name == binding.name)
          entry.image = s.resources.declare(pictureDecl("isf " + binding.name, file_->imported[i]));
    } else if (binding.source == SamplerBinding::Source::Target) {
      entry.kind = State::Sampled::Kind::Target;
      for (size_t t = 0; t < s.targets.size(); ++t)
        if (s.targets[t].name == binding.name) entry.target = t;
    } else {
      for (size_t i = 0; i < doc.inputs.size(); ++i)
        if (doc.inputs[i].name == binding.name) entry.input = int(i);
      const Input& input = doc.inputs.at(size_t(entry.input));
      if (input.type == InputType::Image) {
        // A filter's or transition's own images are frames handed in; any other is a picture file.
        const bool frame = input.name == "inputImage" || input.name == "startImage" || input.name == "endImage";
        entry.kind = frame ? State::Sampled::Kind::Source : State::Sampled::Kind::Picture;
        entry.image = s.resources.declare(pictureDecl("isf " + binding.name, Picture{}));
      } else {
        entry.kind = State::Sampled::Kind::Audio;
        entry.audioSamples = input.audioSamples > 0 ? input.audioSamples : kDefaultAudioSamples;
        gpu::ImageDecl decl;
        decl.name = "isf " + binding.name;
        decl.format = VK_FORMAT_R32_SFLOAT;
        decl.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        decl.size = gpu::ImageSize::absolute(uint32_t(entry.audioSamples), 1);
        decl.initial.assign(size_t(entry.audioSamples) * sizeof(float), std::byte{0});
        decl.initialUse = kSampled;
        entry.image = s.resources.declare(std::move(decl));
      }
    }
    s.sampled.push_back(std::move(entry));
  }
}

Runner::~Runner() {
  if (!state_) return;
  state_->pipelines.clear();  // the programs retire their pipelines; the SPIR-V is no longer needed
  state_->programs.withdraw(state_->vertexName);
  state_->programs.withdraw(state_->fragmentName);
}

void Runner::resize(VkExtent2D renderSize) {
  State& s = *state_;
  if (renderSize.width == s.outputSize.width && renderSize.height == s.outputSize.height) return;
  s.outputSize = renderSize;
  gpu::ImageDecl decl;
  decl.name = "isf output";
  decl.format = kOutputFormat;
  decl.usage = kDrawn | VK_IMAGE_USAGE_STORAGE_BIT;
  decl.size = gpu::ImageSize::absolute(renderSize.width, renderSize.height);
  if (s.output.index == ~0u) s.output = s.resources.declare(decl);
  else s.resources.redeclare(s.output, decl);
  for (State::Sampled& entry : s.sampled) {
    if (entry.kind != State::Sampled::Kind::Source) continue;
    gpu::ImageDecl copy;
    copy.name = "isf " + entry.binding.name;
    copy.format = kOutputFormat;
    copy.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
    copy.size = gpu::ImageSize::absolute(renderSize.width, renderSize.height);
    s.resources.redeclare(entry.image, copy);
  }
  sizeTargets();
}

std::string Runner::update(const Values& values) {
  State& s = *state_;
  std::string problems;
  for (State::Sampled& entry : s.sampled) {
    if (entry.kind != State::Sampled::Kind::Picture) continue;
    const std::string& file = values.inputs.at(size_t(entry.input)).file;
    if (file == entry.file) continue;
    entry.file = file;
    Picture picture;
    if (!file.empty() && file != "none") {
      try {
        picture = readPicture(file, kMaxPictureSide);
      } catch (const Error& e) {
        problems += fmt::format("{}{}: {}", problems.empty() ? "" : "\n", entry.binding.name, e.what());
      }
    }
    s.resources.redeclare(entry.image, pictureDecl("isf " + entry.binding.name, picture));
  }
  s.values = values;
  const std::string sizes = sizeTargets();
  return problems.empty() ? sizes : sizes.empty() ? problems : problems + "\n" + sizes;
}

// Every target at the size its expressions give for the render size and the latest values; a target
// whose size changed is declared again (a new persistent pair starts cleared).
std::string Runner::sizeTargets() {
  State& s = *state_;
  const Document& doc = file_->document;
  if (s.outputSize.width == 0) return {};
  const auto value = [&](std::string_view name) -> std::optional<double> {
    for (size_t i = 0; i < doc.inputs.size() && i < s.values.inputs.size(); ++i)
      if (doc.inputs[i].name == name) return double(s.values.inputs[i].number[0]);
    return std::nullopt;
  };
  std::vector<PassSize> sizes;
  try {
    sizes = passSizes(doc, int(s.outputSize.width), int(s.outputSize.height), value);
  } catch (const IsfError& e) {  // values that ask for too much keep the sizes there are
    if (std::all_of(s.targets.begin(), s.targets.end(), [](const auto& t) { return t.image.index != ~0u; })) return e.what();
    sizes = passSizes(doc, int(s.outputSize.width), int(s.outputSize.height));  // the defaults' sizes, checked on load
  }
  for (size_t p = 0; p < doc.passes.size(); ++p) {
    if (s.passTarget[p] < 0) continue;
    State::Target& target = s.targets[size_t(s.passTarget[p])];
    const VkExtent2D size{uint32_t(sizes[p].width), uint32_t(sizes[p].height)};
    if (target.image.index != ~0u && size.width == target.size.width && size.height == target.size.height) continue;
    target.size = size;
    gpu::ImageDecl decl;
    decl.name = "isf " + target.name;
    decl.format = target.format;
    decl.usage = kDrawn | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    decl.size = gpu::ImageSize::absolute(size.width, size.height);
    decl.pairing = target.persistent ? gpu::Pairing::History : gpu::Pairing::Single;
    if (target.image.index == ~0u) target.image = s.resources.declare(decl);
    else s.resources.redeclare(target.image, decl);
  }
  return {};
}

void Runner::record(const FrameContext& frame, const RunInput& input, gpu::Image& output) {
  State& s = *state_;
  const Document& doc = file_->document;
  const bool sized = s.outputSize.width > 0 && std::all_of(s.targets.begin(), s.targets.end(), [](const auto& t) {
    return t.image.index != ~0u;
  });
  if (!sized) throw Error(fmt::format("{}: the ISF runner drew before resize() and update()", doc.file));

  // The frame block, from the one table of its layout.
  std::vector<std::byte> block(s.block.size, std::byte{0});
  const auto put = [&](const BlockMember& member, const void* data, size_t bytes) {
    std::memcpy(block.data() + member.offset, data, std::min<size_t>(bytes, member.size));
  };
  for (const BlockMember& member : s.block.members) {
    switch (member.source) {
      case BlockMember::Source::Time: { const float t = float(input.time); put(member, &t, 4); break; }
      case BlockMember::Source::TimeDelta: put(member, &input.timeDelta, 4); break;
      case BlockMember::Source::Date: put(member, &input.date, 16); break;
      case BlockMember::Source::FrameIndex: { const int32_t f = int32_t(input.frameIndex & 0x7fffffff); put(member, &f, 4); break; }
      case BlockMember::Source::Input: {
        const auto& number = input.values.inputs.at(size_t(member.input)).number;
        if (member.glslType == "int") {
          const int32_t v = int32_t(std::lround(number[0]));
          put(member, &v, 4);
        } else if (member.glslType == "bool") {
          const uint32_t v = number[0] != 0.0f ? 1u : 0u;
          put(member, &v, 4);
        } else {
          put(member, number.data(), member.size);
        }
        break;
      }
    }
  }
  const gpu::StreamSlice frameBlock = frame.stream.write(block);
  s.resources.beginFrame(frame.cmd, frame.stream, frame.slot);  // uploads, history flips and clears

  // Frames handed in: flipped and encoded into the runner's copies, before any pass reads them.
  for (State::Sampled& entry : s.sampled) {
    if (entry.kind != State::Sampled::Kind::Source) continue;
    const auto given = std::find_if(input.sources.begin(), input.sources.end(),
                                    [&](const SourceImage& source) { return source.name == entry.binding.name; });
    // Nothing handed in: the cleared texel stands in (below), the copy is not drawn.
    if (given == input.sources.end() || !given->image) continue;
    gpu::Image& copy = s.resources.current(entry.image);
    const auto pass = frame.pass("isf source");
    frame.transition(*given->image, gpu::use::ComputeSample);
    frame.transition(copy, gpu::use::ComputeWrite);
    s.convert->bind(frame.cmd);
    s.convert->push(frame.cmd, gpu::Bindings()
                                   .sampledImage("source", given->image->view(),
                                                 frame.device.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp),
                                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
                                   .storageImage("target", copy.view()));
    s.convert->constants(frame.cmd, shader::IsfConvertPush{0u});
    s.convert->dispatchOver(frame.cmd, copy.extent2d());
  }
  // Audio and FFT: this frame's samples.
  for (State::Sampled& entry : s.sampled) {
    if (entry.kind != State::Sampled::Kind::Audio) continue;
    const bool fft = doc.inputs.at(size_t(entry.input)).type == InputType::AudioFFT;
    // A waveform as a GL host stores it in an 8-bit texture: 0.5 is silence.
    const std::vector<float> texels = fft ? resampled(input.spectrum, size_t(entry.audioSamples), 0.0f, 1.0f, true)
                                          : resampled(input.wave, size_t(entry.audioSamples), 0.5f, 0.5f, false);
    gpu::uploadImage(frame.cmd, frame.stream, s.resources.current(entry.image), std::as_bytes(std::span(texels)), kSampled);
  }

  const VkSampler sampler = frame.device.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp);
  gpu::Image& outputImage = s.resources.current(s.output);
  gpu::Image* last = &outputImage;
  for (size_t p = 0; p < doc.passes.size(); ++p) {
    const int targetIndex = s.passTarget[p];
    gpu::Image& drawn = targetIndex < 0 ? outputImage : s.resources.current(s.targets[size_t(targetIndex)].image);
    // What each sampler sees in this pass (isf::readOf), transitioned before rendering begins.
    std::vector<std::pair<uint32_t, gpu::Image*>> views;
    for (const State::Sampled& entry : s.sampled) {
      gpu::Image* image = &s.resources.current(s.cleared);
      switch (entry.kind) {
        case State::Sampled::Kind::Target: {
          const State::Target& target = s.targets[entry.target];
          switch (readOf(doc, p, target.name)) {
            case PassRead::EarlierPass: image = &s.resources.current(target.image); break;
            case PassRead::PreviousFrame: image = &s.resources.previous(target.image); break;
            default: break;
          }
          break;
        }
        case State::Sampled::Kind::Source: {
          const bool given = std::any_of(input.sources.begin(), input.sources.end(), [&](const SourceImage& source) {
            return source.name == entry.binding.name && source.image;
          });
          if (given) image = &s.resources.current(entry.image);
          break;
        }
        default: image = &s.resources.current(entry.image); break;
      }
      frame.transition(*image, kSampled);
      views.emplace_back(entry.binding.binding, image);
    }
    const auto timed = frame.pass(targetIndex < 0 ? "isf pass" : "isf buffer pass");
    const auto rendering = frame.rendering({{gpu::ColorAttachment{&drawn, VkClearColorValue{{0, 0, 0, 0}}}}, {}});
    gpu::GraphicsProgram& program = s.pipeline(drawn.format());
    program.bind(frame.cmd);
    // Descriptors straight from the translation's tables: the binding numbers are the file's, and an
    // ISF file may name more images than gpu::Bindings holds.
    std::vector<VkDescriptorImageInfo> images;
    images.reserve(views.size());
    std::vector<VkWriteDescriptorSet> writes;
    const VkDescriptorBufferInfo blockInfo{frameBlock.buffer, frameBlock.offset, s.block.size};
    for (const gpu::ReflectedBinding& binding : program.interface().bindings) {
      VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      write.dstBinding = binding.binding;
      write.descriptorCount = 1;
      write.descriptorType = binding.type;
      if (binding.binding == kFrameBlockBinding) {
        write.pBufferInfo = &blockInfo;
      } else {
        const auto view = std::find_if(views.begin(), views.end(), [&](const auto& v) { return v.first == binding.binding; });
        if (view == views.end()) throw Error(fmt::format("{}: binding {} has no image", doc.file, binding.binding));
        images.push_back({sampler, view->second->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
        write.pImageInfo = &images.back();
      }
      writes.push_back(write);
    }
    if (!writes.empty())
      frame.device.cmdPushDescriptorSet(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, program.layout(), 0,
                                        uint32_t(writes.size()), writes.data());
    if (const uint32_t bytes = program.interface().pushConstantBytes) {
      std::array<std::byte, kPassBlockBytes> push{};
      const float renderSize[2] = {float(drawn.extent2d().width), float(drawn.extent2d().height)};
      const int32_t passIndex = int32_t(p);
      std::memcpy(push.data() + kRenderSizeOffset, renderSize, sizeof(renderSize));
      std::memcpy(push.data() + kPassIndexOffset, &passIndex, sizeof(passIndex));
      vkCmdPushConstants(frame.cmd, program.layout(), VK_SHADER_STAGE_ALL_GRAPHICS, 0, std::min(bytes, kPassBlockBytes),
                         push.data());
    }
    vkCmdDraw(frame.cmd, 4, 1, 0, 0);
    last = &drawn;
  }

  // The last pass's picture, flipped and decoded into the output.
  const auto pass = frame.pass("isf output");
  frame.transition(*last, gpu::use::ComputeSample);
  frame.transition(output, gpu::use::ComputeWrite);
  s.convert->bind(frame.cmd);
  s.convert->push(frame.cmd, gpu::Bindings()
                                 .sampledImage("source", last->view(), sampler, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
                                 .storageImage("target", output.view()));
  s.convert->constants(frame.cmd, shader::IsfConvertPush{1u});
  s.convert->dispatchOver(frame.cmd, output.extent2d());
}

}  // namespace vitrine::isf
