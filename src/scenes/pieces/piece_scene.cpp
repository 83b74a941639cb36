#include "scenes/pieces/piece_scene.h"

#include "isf/gpu/isf_runner.h"
#include "params/settings_file.h"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <future>
#include <utility>

namespace vitrine::pieces {
namespace {

using Clock = std::chrono::steady_clock;

// A version's result of loading in the background: the file, or why it was refused.
struct Loaded {
  std::shared_ptr<const isf::LoadedFile> file;
  std::string error;
};

Loaded load(const std::filesystem::path& path) {
  try {
    return {isf::loadFile(path), {}};
  } catch (const Error& e) {
    return {nullptr, e.what()};
  }
}

class PieceScene final : public Scene {
 public:
  PieceScene(const SceneContext& context, Piece& piece) : context_(context), piece_(piece) {
    const Version* version = piece_.current();
    // First showing, or the file changed since its header was read: compile it now (a scene switch
    // may take that long; later edits are compiled in the background).
    if (!version || !version->file || piece_.modified() != piece_.seen) {
      piece_.seen = piece_.modified();
      Loaded loaded = load(piece_.path);
      if (loaded.file) {
        try {
          version = &piece_.adopt(loaded.file);
        } catch (const Error& e) {
          loaded.error = e.what();
        }
      }
      if (!loaded.error.empty()) refused(loaded.error, context.realtime);
    }
    if (version && version->file) start(*version, nullptr);
    // A run that is not the gallery cannot wait for a mended file: a piece that never loaded ends it.
    if (!runner_ && !context_.realtime) throw Error(piece_.error);
    polled_ = Clock::now();
  }

  ~PieceScene() override {
    // A background compile still running finishes on its own thread; its result is dropped.
    if (pending_.valid()) pending_.wait();
  }

  void resize(VkExtent2D target) override {
    target_ = target;
    if (runner_) runner_->resize(target);
  }

  void update(const FrameInput& input) override {
    if (context_.realtime) watchFile();
    for (const ActionCall& call : input.actions)
      for (size_t i = 0; version_ && i < version_->document.inputs.size(); ++i)
        if (version_->document.inputs[i].type == isf::InputType::Event && version_->document.inputs[i].name == call.name) {
          fired_.push_back(i);
          context_.events.emit(input.time, {"event", {{"input", call.name}}});
        }
    if (drag_ >= 0 && input.cursor.dragging) {
      const isf::Input& point = version_->document.inputs[size_t(drag_)];
      // The cursor's 0..1 from the top-left, as ISF's bottom-left 0..1, into the input's range.
      const glm::vec2 at{input.cursor.normalized.x, 1.0f - input.cursor.normalized.y};
      auto& value = values_.inputs[size_t(drag_)].number;
      value[0] = mapped(point, 0, at.x);
      value[1] = mapped(point, 1, at.y);
    }
    shown_ = input;
    if (runner_) {
      const std::string problem = runner_->update(values_);
      if (problem != problem_) {
        problem_ = problem;
        if (!problem.empty()) std::fprintf(stderr, "vitrine: %s\n", problem.c_str());
      }
    }
  }

  void record(const FrameContext& frame) override {
    if (!runner_) {
      // Never ran: a black frame under the panel's message.
      const auto pass = frame.pass("piece refused");
      const auto rendering = frame.rendering({{gpu::ColorAttachment{&frame.target, VkClearColorValue{{0, 0, 0, 1}}}}, {}});
      return;
    }
    // An event is true in the shader for the one frame drawn after it fired.
    for (const size_t event : fired_) values_.inputs[event].number[0] = 1.0f;
    const isf::RunInput run{.values = values_,
                            .time = shown_.time,
                            .timeDelta = shown_.dt,
                            .frameIndex = shown_.frame,
                            .date = context_.realtime ? isf::wallClockDate() : isf::simulatedDate(shown_.time),
                            .wave = shown_.soundWave,
                            .spectrum = shown_.soundSpectrum};
    runner_->record(frame, run, frame.target);
    for (const size_t event : fired_) values_.inputs[event].number[0] = 0.0f;
    fired_.clear();
  }

  void drawPanel() override {
    if (version_ && !version_->document.description.empty()) ImGui::TextWrapped("%s", version_->document.description.c_str());
    if (version_ && !version_->document.credit.empty()) ImGui::TextDisabled("by %s", version_->document.credit.c_str());
    ImGui::TextDisabled("%s", piece_.path.string().c_str());
    for (const std::string* message : {&piece_.error, &problem_})
      if (!message->empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", message->c_str());
    if (!piece_.error.empty() && runner_) ImGui::TextDisabled("The last version that loaded keeps running.");
  }

  params::Bound parameters() override {
    return version_ ? params::bindSettings(version_->schema, values_) : params::bindSettings(empty_, values_);
  }

  // A frame depends on its time and values alone, unless a buffer carries the picture from frame to
  // frame: those are not saved, so such a piece runs from its first frame.
  bool checkpoints() const override {
    if (!version_) return true;
    return std::none_of(version_->document.passes.begin(), version_->document.passes.end(),
                        [](const isf::Pass& pass) { return pass.persistent; });
  }

 private:
  static float mapped(const isf::Input& point, int component, float at) {
    const auto c = size_t(component);
    const float lo = point.hasMin ? float(point.minValue[c]) : 0.0f, hi = point.hasMax ? float(point.maxValue[c]) : 1.0f;
    return std::clamp(lo + std::clamp(at, 0.0f, 1.0f) * (hi - lo), std::min(lo, hi), std::max(lo, hi));
  }

  // Makes `version` the one drawn, keeping the values the old one shares with it.
  void start(const Version& version, const params::Bound* old) {
    auto runner = std::make_unique<isf::Runner>(context_, version.file);
    params::KeyValues kept;
    if (old) kept = params::snapshot(*old);
    isf::Values values = isf::defaultValues(version.document);
    const params::Bound bound = params::bindSettings(version.schema, values);
    for (const auto& pair : kept)
      if (version.schema.find(pair.first)) params::applyValues(bound, {pair});  // one by one: a refusal drops one
    if (runner_) context_.device.retire(std::move(runner_));  // frames in flight may still use it
    runner_ = std::move(runner);
    values_ = std::move(values);
    version_ = &version;
    drag_ = isf::dragPoint(version.document);
    fired_.clear();
    if (target_.width > 0) runner_->resize(target_);
  }

  void refused(const std::string& error, bool say = true) {
    piece_.error = error;
    if (say) std::fprintf(stderr, "vitrine: %s\n", error.c_str());
    context_.events.emit(shown_.time, {"refused", {{"error", error}}});
  }

  // Polls the file's time now and then; compiles an edit on another thread; adopts it when ready.
  void watchFile() {
    if (pending_.valid()) {
      if (pending_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
      Loaded loaded = pending_.get();
      if (loaded.file) {
        try {
          const params::Bound old = parameters();
          const Version& version = piece_.adopt(loaded.file);
          start(version, &old);
          problem_.clear();
          std::fprintf(stderr, "vitrine: %s reloaded\n", piece_.path.string().c_str());
          context_.events.emit(shown_.time, {"reloaded", {{"file", piece_.path.string()}}});
        } catch (const Error& e) {
          loaded.error = e.what();
        }
      }
      if (!loaded.error.empty()) refused(loaded.error);
      return;
    }
    const auto now = Clock::now();
    if (now - polled_ < kPollInterval) return;
    polled_ = now;
    const auto modified = piece_.modified();
    if (modified == piece_.seen) return;
    piece_.seen = modified;
    pending_ = std::async(std::launch::async, load, piece_.path);
  }

  SceneContext context_;
  Piece& piece_;
  const Version* version_ = nullptr;
  std::unique_ptr<isf::Runner> runner_;
  isf::Values values_;
  params::Schema empty_ = params::Schema::forStruct<isf::Values>(isf::Values{});
  VkExtent2D target_{0, 0};
  FrameInput shown_;
  std::vector<size_t> fired_;
  int drag_ = -1;
  std::string problem_;
  Clock::time_point polled_;
  std::future<Loaded> pending_;
};

}  // namespace

std::unique_ptr<Scene> createPieceScene(const SceneContext& context, Piece& piece) {
  if (piece.faulted()) throw Error(piece.error);
  return std::make_unique<PieceScene>(context, piece);
}

void addPieceFactories(std::span<Piece* const> pieces) {
  for (Piece* piece : pieces)
    addSceneFactory(piece->name, [piece](const SceneContext& context) { return createPieceScene(context, *piece); });
}

std::vector<std::filesystem::path> settingsPieceFolders(const std::filesystem::path& settings) {
  std::error_code ec;
  if (settings.empty() || !std::filesystem::is_regular_file(settings, ec)) return {};
  // Read only, never moved aside or rewritten here: the gallery reads the file again and owns it.
  const params::LoadResult loaded = params::loadSettings(settings, nullptr, params::LoadMode::LeaveAlone);
  std::vector<std::filesystem::path> folders;
  const auto& unknown = loaded.settings.unknown;
  if (unknown.is_object() && unknown.contains("pieces") && unknown["pieces"].is_array())
    for (const auto& folder : unknown["pieces"])
      if (folder.is_string()) folders.emplace_back(folder.get<std::string>());
  return folders;
}

void addStartupPieces(int argc, const char* const* argv) {
  std::vector<std::filesystem::path> named;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::string_view(argv[i]) == "--isf") named.emplace_back(argv[++i]);
  addPieceFactories(addPieces(named, true));
  std::vector<std::filesystem::path> folders;
  if (const auto folder = userPiecesFolder(); !folder.empty()) folders.push_back(folder);
  for (auto& folder : settingsPieceFolders(params::defaultSettingsPath())) folders.push_back(std::move(folder));
  for (const auto& folder : folders) addPieceFactories(addPieces(piecesIn(folder), false));
}

}  // namespace vitrine::pieces
