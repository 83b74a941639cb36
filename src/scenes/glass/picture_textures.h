#pragma once
// The pictures the glass refracts, as the scene's photo and panorama textures: they follow the
// `background` and `panorama` settings (backgrounds.h reads the files), R steps through a folder of
// photos, and what cannot be shown is said: an error in headless runs and tests, where the picture
// would silently be another, a line on stderr and the panel's warning in the gallery.
#include "scenes/glass/backgrounds.h"
#include "scenes/glass/settings.h"
#include "scenes/scene.h"

#include <glm/vec2.hpp>

#include <string>
#include <utility>

namespace vitrine::glass {

class PictureTextures {
 public:
  // Declares both textures with a placeholder texel until the first update() loads them.
  explicit PictureTextures(const SceneContext& context);

  struct Loaded {
    bool photo = false;     // the backdrop must be composed again
    bool panorama = false;  // the history no longer matches the light
  };
  // Reads what the settings name, here and not while recording: the texels upload as the next frame begins.
  Loaded update(const Settings& settings);
  void nextPhoto();
  // Why the background or panorama the settings name cannot serve, "" when both can. The last answers
  // are kept, so a slider's drag does not read the named file again at every step.
  std::string problem(const Settings& settings) const;

  gpu::ImageHandle photo() const { return photo_; }
  gpu::ImageHandle panorama() const { return panorama_; }
  BackdropKind backdropKind() const { return source_.kind; }
  glm::vec2 photoSize() const { return photoSize_; }  // texels; 0 when no photo could be read
  std::string photoName() const { return pictures_.currentName(); }
  const std::string& backgroundProblem() const { return backgroundProblem_; }
  const std::string& panoramaProblem() const { return panoramaProblem_; }

 private:
  void loadPhoto(const Settings& settings);
  void loadPanorama(const Settings& settings);
  void warn(const std::string& why) const;

  gpu::FrameResources& resources_;
  const Assets& assets_;
  bool realtime_;  // the gallery: a file that fails to load is a panel warning; headless, an error
  gpu::ImageHandle photo_, panorama_;

  std::string appliedBackground_, appliedPanorama_;
  BackdropSource source_;
  PictureCycle pictures_;
  bool photoLoaded_ = false;
  bool panoramaLoaded_ = false;
  glm::vec2 photoSize_{1.0f};
  std::string backgroundProblem_, panoramaProblem_;
  mutable std::pair<std::string, std::string> checkedBackground_, checkedPanorama_;  // value, problem
};

}  // namespace vitrine::glass
