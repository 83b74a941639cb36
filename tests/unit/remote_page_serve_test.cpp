// Not a test: a way to look at the page by hand or with a browser without a GPU. Disabled unless run
// with --gtest_also_run_disabled_tests; serves for VITRINE_REMOTE_SERVE_SECONDS (default 30) on
// 127.0.0.1:8731 with the token "test", applying commands to scratch settings the way the host does.
#include "params/schema.h"
#include "remote/remote_control.h"
#include "scenes/scene.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <thread>

namespace vitrine::remote {
namespace {

TEST(RemotePage, DISABLED_Serve) {
  const char* seconds = std::getenv("VITRINE_REMOTE_SERVE_SECONDS");
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(seconds ? std::atoi(seconds) : 30);
  RemoteControl remote({.bind = {"127.0.0.1", 8731}, .token = "test"});
  std::printf("%s\n", remote.pageUrl().c_str());
  std::fflush(stdout);
  std::map<std::string, std::shared_ptr<void>> settings;
  const SceneInfo* current = &sceneRegistry()[0];
  const auto bound = [&](const SceneInfo& info) {
    auto& slot = settings[std::string(info.name)];
    if (!slot) slot = info.schema().makeDefaults();
    return params::Bound{&info.schema(), slot.get()};
  };
  remote.publish(std::string(current->name), params::snapshot(bound(*current)));
  while (std::chrono::steady_clock::now() < until) {
    for (const RemoteCommand& command : remote.drain()) {
      std::printf("%s: kind %d %s %s %s\n", command.client.c_str(), int(command.kind), command.scene.c_str(),
                  command.key.c_str(), command.value.c_str());
      if (command.kind == RemoteCommand::Kind::Scene) current = findScene(command.scene);
      if (command.kind == RemoteCommand::Kind::Set) params::applyValues(bound(*findScene(command.scene)), {{command.key, command.value}});
    }
    std::fflush(stdout);
    remote.publish(std::string(current->name), params::snapshot(bound(*current)));
    std::this_thread::sleep_for(std::chrono::milliseconds(16));
  }
}

}  // namespace
}  // namespace vitrine::remote
