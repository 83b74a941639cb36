#pragma once
// The scene that draws a piece found at run time (scenes/pieces/piece_catalogue.h): its ISF file run by
// isf::Runner over the scene's target. The file's inputs are the scene's parameters; its events are
// the scene's actions, each seen by the shader as true for the one frame after it fires; its only
// point2D, if it has one, follows the cursor's drag.
//
// In the gallery (real time) the scene watches its file: an edit is read and compiled off the frame
// thread, and takes over when it is ready, the values it shares with the old version kept. A version
// that fails keeps the old one running, and says why ("file:line: words") on stderr, in the panel and
// in the menu (the piece's error).
#include "scenes/pieces/piece_catalogue.h"
#include "scenes/scene.h"

#include <chrono>
#include <memory>

namespace vitrine::pieces {

// The scene for `piece`; compiles its file when this is its first showing, or when the file changed
// since the version it has. When the file is refused and no version of it ever ran, the scene draws
// black and says why.
std::unique_ptr<Scene> createPieceScene(const SceneContext& context, Piece& piece);

// Registers the scene factory of each piece (scene.h's addSceneFactory).
void addPieceFactories(std::span<Piece* const> pieces);

// What the program does first, before it reads its command line (whose --scene and --set may name a
// piece): every --isf FILE (refused files end the run with their error), then the generators in the
// user's pieces folder and in each folder the settings file's "pieces" array names, as pieces with
// their factories.
void addStartupPieces(int argc, const char* const* argv);
// The folders the settings file at `settings` names in its top-level "pieces" array ("pieces":
// ["~/isf"]); none when it has none or cannot be read.
std::vector<std::filesystem::path> settingsPieceFolders(const std::filesystem::path& settings);

// How often a running piece looks at its file's time (one stat call; never a wait on the frame).
inline constexpr std::chrono::milliseconds kPollInterval{250};

}  // namespace vitrine::pieces
