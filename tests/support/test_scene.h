#pragma once
// Scenes that exist only in a test: a base with no parameters, and a SceneInfo (not registered)
// whose factory remembers the instance it made, so the test can look inside the scene the host drives.
#include "scenes/scene.h"

#include <memory>

namespace vitrine::test {

class TestScene : public Scene {
 public:
  void update(const FrameInput&) override {}
  params::Bound parameters() override { return {&schema(), &settings_}; }
  static const params::Schema& schema() {
    static const params::Schema table = params::Schema::forStruct<NoSettings>();
    return table;
  }

 private:
  struct NoSettings {
    int unused = 0;
  };
  NoSettings settings_;
};

// The SceneInfo of test scene T; `made` points at the last instance the host created.
template <typename T> const SceneInfo& testSceneInfo(T*& made) {
  static T** target = nullptr;
  target = &made;
  static const SceneInfo info{"test", "Test", 9,
                              [](const SceneContext& context) -> std::unique_ptr<Scene> {
                                auto scene = std::make_unique<T>(context);
                                *target = scene.get();
                                return scene;
                              },
                              &TestScene::schema, "none"};
  return info;
}

}  // namespace vitrine::test
