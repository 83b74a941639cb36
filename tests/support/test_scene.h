#pragma once
// Scenes that exist only in a test: a base with no parameters, and an entry (not registered) whose
// factory remembers the instance it made, so the test can look inside the scene the host drives.
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

// A scene that exists only in a test: its SceneInfo and the factory the renderer makes it with
// (renderer.setScene(entry.info, entry.create)).
struct TestSceneEntry {
  SceneInfo info;
  SceneFactory create;
};

// Test scene T's entry; `made` points at the last instance the host created.
template <typename T> const TestSceneEntry& testScene(T*& made) {
  static T** target = nullptr;
  target = &made;
  static const TestSceneEntry entry{{"test", "Test", 9, &TestScene::schema, "none"},
                                    [](const SceneContext& context) -> std::unique_ptr<Scene> {
                                      auto scene = std::make_unique<T>(context);
                                      *target = scene.get();
                                      return scene;
                                    }};
  return entry;
}

}  // namespace vitrine::test
