// The remote control's page without a GPU: serves the page and OSC as `vitrine --remote` does, for a
// browser or an OSC sender to try, and applies what clients send to scratch settings of every scene
// (each scene's defaults, checked through its schema as the host checks them), printing each command.
// No scene runs, so nothing is drawn: the page shows the values it would drive. See docs/REMOTE.md.
//
// Usage: vitrine_remote_page [--seconds N] [--bind ADDR:PORT] [--token TOKEN]
//   defaults: 30 seconds, 127.0.0.1:8731 (beside the gallery's 8730), the token "test".
#include "params/schema.h"
#include "remote/bind_address.h"
#include "remote/remote_control.h"
#include "scenes/catalogue.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>

using namespace vitrine;

namespace {

constexpr const char* kUsage = "usage: vitrine_remote_page [--seconds N] [--bind ADDR:PORT] [--token TOKEN]\n";

int serve(double seconds, const remote::BindAddress& address, const std::string& token) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  remote::RemoteControl control({.bind = address, .token = token});
  std::printf("%s\n", control.pageUrl().c_str());
  std::fflush(stdout);
  std::map<std::string, std::shared_ptr<void>> settings;  // each scene's values, made on first use
  const SceneInfo* current = &sceneRegistry()[0];
  const auto bound = [&](const SceneInfo& info) {
    auto& slot = settings[std::string(info.name)];
    if (!slot) slot = info.schema().makeDefaults();
    return params::Bound{&info.schema(), slot.get()};
  };
  control.publish({std::string(current->name), params::snapshot(bound(*current))});
  while (std::chrono::steady_clock::now() < until) {
    for (const remote::RemoteCommand& command : control.drain()) {
      std::printf("%s: kind %d %s %s %s\n", command.client.c_str(), int(command.kind), command.scene.c_str(),
                  command.key.c_str(), command.value.c_str());
      if (command.kind == remote::RemoteCommand::Kind::Scene) current = findScene(command.scene);
      if (command.kind == remote::RemoteCommand::Kind::Set)
        params::applyValues(bound(*findScene(command.scene)), {{command.key, command.value}});
    }
    std::fflush(stdout);
    control.publish({std::string(current->name), params::snapshot(bound(*current))});
    std::this_thread::sleep_for(std::chrono::milliseconds(16));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 30.0;
  remote::BindAddress address{"127.0.0.1", 8731};
  std::string token = "test";
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string_view flag = argv[i];
      if (flag == "--help" || flag == "-h") {
        std::fputs(kUsage, stdout);
        return 0;
      }
      if (flag != "--seconds" && flag != "--bind" && flag != "--token")
        throw std::invalid_argument("unknown option " + std::string(flag));
      if (i + 1 >= argc) throw std::invalid_argument(std::string(flag) + " needs a value");
      const char* value = argv[++i];
      if (flag == "--seconds") {
        char* end = nullptr;
        seconds = std::strtod(value, &end);
        if (*end != '\0' || !(seconds > 0.0) || !std::isfinite(seconds))
          throw std::invalid_argument("--seconds expects a positive number");
      } else if (flag == "--bind") {
        address = remote::parseBind(value);
      } else {
        token = value;
      }
    }
    return serve(seconds, address, token);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vitrine_remote_page: %s\n%s", e.what(), kUsage);
    return 1;
  }
}
