#include "scenes/pieces/piece_catalogue.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <system_error>

namespace vitrine::pieces {
namespace fs = std::filesystem;
namespace {

// Pieces live as long as the program: the registry's SceneInfo entries point into them.
std::deque<Piece>& store() {
  static std::deque<Piece> pieces;
  return pieces;
}
std::vector<Piece*>& ordered() {
  static std::vector<Piece*> pieces;
  return pieces;
}

// The schema of a piece whose file never loaded: no parameters.
const params::Schema& emptySchema() {
  static const params::Schema schema = params::Schema::forStruct<isf::Values>(isf::Values{});
  return schema;
}

// A scene name from a file's stem: lower case letters, digits, '_' and '-' (what --scene, --set
// SCENE.KEY and the settings file carry), made unique against every scene there is.
std::string sceneName(const fs::path& path) {
  std::string name;
  for (const char c : path.stem().string()) {
    const char lower = (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
    const bool plain = (lower >= 'a' && lower <= 'z') || (lower >= '0' && lower <= '9') || lower == '_' || lower == '-';
    name += plain ? lower : '-';
  }
  if (name.empty() || name.size() > 48) name = name.empty() ? "piece" : name.substr(0, 48);
  const std::string base = name;
  for (int n = 2; findScene(name); ++n) name = fmt::format("{}-{}", base, n);
  return name;
}

std::string inputLine(const isf::Document& document) {
  std::string line = document.description.empty() ? "An ISF piece." : document.description;
  if (const int drag = isf::dragPoint(document); drag >= 0)
    line += fmt::format(" Drag: moves {}.", document.inputs[size_t(drag)].label.empty()
                                                  ? document.inputs[size_t(drag)].name
                                                  : document.inputs[size_t(drag)].label);
  if (!document.credit.empty()) line += " By " + document.credit + ".";
  return line;
}

Version makeVersion(isf::Document document, std::shared_ptr<const isf::LoadedFile> file) {
  params::Schema schema = isf::makeSchema(document);
  Version version{std::move(file), std::move(document), std::move(schema), {}, {}};
  for (const std::string& event : isf::eventNames(version.document)) version.events.push_back(event);
  for (const std::string& event : version.events) version.actions.push_back({event, {}, "fires the file's event input"});
  return version;
}

// The registry's entry follows the piece's current version.
void publish(Piece& piece) {
  if (!piece.info) return;
  const Version* version = piece.current();
  piece.info->runtimeSchema = version ? &version->schema : &emptySchema();
  piece.info->actions = version ? std::span<const SceneAction>(version->actions) : std::span<const SceneAction>();
  piece.info->input = piece.input;
}

}  // namespace

fs::file_time_type Piece::modified() const {
  std::error_code ec;
  const auto time = fs::last_write_time(path, ec);
  return ec ? seen : time;
}

const Version& Piece::adopt(std::shared_ptr<const isf::LoadedFile> file) {
  if (file->document.kind != isf::Kind::Generator)
    throw isf::IsfError(file->document.file, 1,
                        fmt::format("is a {}, not a generator: it cannot be shown on its own", isf::kindName(file->document.kind)));
  Version version = makeVersion(file->document, file);
  input = inputLine(version.document);
  versions.push_back(std::move(version));
  error.clear();
  publish(*this);
  return versions.back();
}

void blame(Piece& piece, const std::string& why) {
  piece.faultedAt = piece.modified();
  piece.error = fmt::format("{}: the GPU stopped responding while it ran; it starts again once the file is saved ({})",
                            piece.path.string(), why);
}

fs::path userPiecesFolder() {
  const char* data = std::getenv("XDG_DATA_HOME");
  if (data && *data && fs::path(data).is_absolute()) return fs::path(data) / "vitrine" / "pieces";
  const char* home = std::getenv("HOME");
  if (home && *home) return fs::path(home) / ".local" / "share" / "vitrine" / "pieces";
  return {};
}

std::vector<fs::path> piecesIn(const fs::path& folder) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
    if (it->path().extension() == ".fs" && it->is_regular_file(ec)) files.push_back(it->path());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<Piece*> addPieces(std::span<const fs::path> files, bool required) {
  std::vector<Piece*> added;
  for (const fs::path& path : files) {
    if (findPieceByPath(path)) continue;  // named twice, or on the command line and in a folder
    Piece piece;
    piece.path = path;
    piece.title = path.stem().string();
    piece.seen = piece.modified();
    try {
      isf::Document document = isf::loadDocument(path);
      if (document.kind != isf::Kind::Generator) {
        if (required)
          throw isf::IsfError(document.file, 1, fmt::format("is a {}, not a generator: --isf shows generators",
                                                            isf::kindName(document.kind)));
        continue;  // a filter or transition in a pieces folder is not a scene
      }
      piece.input = inputLine(document);
      piece.versions.push_back(makeVersion(std::move(document), nullptr));
    } catch (const isf::IsfError& e) {
      if (required) throw;
      piece.error = e.what();
      piece.input = "This piece's file was refused: " + piece.error;
    }
    piece.name = sceneName(path);
    Piece& stored = store().emplace_back(std::move(piece));
    const Version* version = stored.current();
    stored.info = &addRuntimeScene(SceneInfo{stored.name, stored.title, 0, nullptr, stored.input, {},
                                             version ? &version->schema : &emptySchema()});
    publish(stored);
    ordered().push_back(&stored);
    added.push_back(&stored);
  }
  return added;
}

Piece* findPiece(std::string_view name) {
  for (Piece* piece : ordered())
    if (piece->name == name) return piece;
  return nullptr;
}

Piece* findPieceByPath(const fs::path& path) {
  std::error_code ec;
  for (Piece* piece : ordered())
    if (piece->path == path || fs::equivalent(piece->path, path, ec)) return piece;
  return nullptr;
}

std::span<Piece* const> allPieces() { return ordered(); }

}  // namespace vitrine::pieces
