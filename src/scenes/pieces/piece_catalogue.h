#pragma once
// Pieces found at run time: ISF generators (docs/ISF.md) named with --isf or lying in a pieces folder,
// each a scene after the built-in ones, with a schema made from its INPUTS. This part needs no GPU: it
// reads each file's header when the program starts (a folder of fifty files costs milliseconds; the
// GLSL is compiled when a piece is first shown), keeps every version's schema alive, and says where a
// file changed since. The scene that draws a piece is scenes/pieces/piece_scene.h.
#include "isf/isf_file.h"
#include "isf/isf_values.h"
#include "scenes/catalogue.h"

#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace vitrine::pieces {

// One version of a piece: what its header declared when it was read, and its schema. Versions are
// kept for the run (a running scene or the panel may hold the schema of an older one).
struct Version {
  std::shared_ptr<const isf::LoadedFile> file;  // compiled; null until the piece is first shown
  isf::Document document;
  params::Schema schema;
  std::deque<std::string> events;  // the actions' names (stable storage for their string_views)
  std::vector<SceneAction> actions;
};

struct Piece {
  std::filesystem::path path;
  std::string name;   // the scene's name: the file's stem as a command-line word, made unique
  std::string title;  // the menu's: the file's stem as written
  std::string input;  // the help card's line
  std::deque<Version> versions;  // the newest last; empty when the file never loaded
  std::string error;             // "file:line: words" of the last load that failed; "" after one that worked
  std::filesystem::file_time_type seen{};  // the file's time when last read, loaded or refused
  SceneInfo* info = nullptr;
  // The file's time when the GPU stopped responding while this piece ran (see blame()).
  std::optional<std::filesystem::file_time_type> faultedAt;

  const Version* current() const { return versions.empty() ? nullptr : &versions.back(); }
  // The file as it is now, read and compiled, made the current version (its schema published in the
  // registry). Throws isf::IsfError and leaves everything as it was when the file is refused.
  const Version& adopt(std::shared_ptr<const isf::LoadedFile> file);
  // The file's modification time now; a file that cannot be read gives the time it had.
  std::filesystem::file_time_type modified() const;
  // Blamed for a lost device and not edited since: the piece does not start (its scene throws).
  bool faulted() const { return faultedAt && *faultedAt == modified(); }
};

// The GPU stopped responding (a lost device: a shader the loop guard did not bound, a driver fault)
// while `piece` was showing: its error says so, and it is not started again until its file changes.
// What the kiosk's restart calls before it moves on to the next scene.
void blame(Piece& piece, const std::string& why);

// $XDG_DATA_HOME/vitrine/pieces (else ~/.local/share/vitrine/pieces); empty when neither is known.
std::filesystem::path userPiecesFolder();

// The files of a folder that may be pieces: its *.fs files, sorted by name (not its subfolders).
std::vector<std::filesystem::path> piecesIn(const std::filesystem::path& folder);

// Registers each file as a piece, in order, after the scenes there are. A file that is not an ISF
// generator (a filter, a transition) is left out. A file named on the command line (`required`)
// whose header is refused throws the isf::IsfError; one found in a folder is listed with its error,
// so the menu says why and a save that mends it brings it in. Call while the program starts (the
// registry's rule). Returns the pieces added.
std::vector<Piece*> addPieces(std::span<const std::filesystem::path> files, bool required);

// The piece drawn by the scene named `name`; null for a built-in scene or no scene.
Piece* findPiece(std::string_view name);
// The piece of a file (as given on the command line, or the same file by another path); null if none.
Piece* findPieceByPath(const std::filesystem::path& path);
// Every piece, in the registry's order.
std::span<Piece* const> allPieces();

}  // namespace vitrine::pieces
