// Vitrine: parses the command line and hands over to one mode. Every failure a user can cause ends
// here as one sentence on stderr and a non-zero exit.
#include "app/help.h"
#include "app/options.h"
#include "core/version.h"
#include "gpu/check.h"
#include "gpu/device.h"
#include "host/modes.h"
#include "host/user_presets.h"
#include "host/present/window.h"
#include "scenes/catalogue.h"
#include "scenes/pieces/piece_scene.h"

#include <algorithm>
#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  using namespace vitrine;
  try {
    // Pieces become scenes before the command line is read: its --scene and --set may name them.
    pieces::addStartupPieces(argc, argv);
    const Options options = parseOptions(argc, argv);
    switch (options.mode) {
      case Mode::Help: std::fputs(help::usage().c_str(), stdout); return 0;
      case Mode::HelpMan: std::fputs(help::manPage().c_str(), stdout); return 0;
      case Mode::HelpCompletion: std::fputs(help::bashCompletion().c_str(), stdout); return 0;
      case Mode::Version:
        std::printf("vitrine %.*s (commit %.*s)\n", int(versionNumber().size()), versionNumber().data(),
                    int(buildCommit().size()), buildCommit().data());
        return 0;
      case Mode::ListScenes: {
        int width = 0;  // the longest name: the titles line up after it
        for (const auto& info : sceneRegistry()) width = std::max(width, int(info.name.size()));
        for (const auto& info : sceneRegistry())
          std::printf("%s  %-*.*s  %.*s\n", info.key > 0 ? std::to_string(info.key).c_str() : "-", width,
                      int(info.name.size()), info.name.data(), int(info.title.size()), info.title.data());
        return 0;
      }
      case Mode::ListParams:  // for now a list of names only: host/list_params.cpp is to be replaced
        return host::runListParams(options);
      case Mode::ListKeys: return host::runListKeys(options);
      case Mode::ListPresets: return host::runListPresets(options);
      case Mode::ListMonitors: std::fputs(host::Window::listMonitors().c_str(), stdout); return 0;
      case Mode::ListDevices: {
        gpu::Instance instance({options.validation, {}});
        std::fputs(gpu::listDevices(instance).c_str(), stdout);
        return 0;
      }
      case Mode::ExportPreset: return host::runExportPreset(options);
      case Mode::Headless: return host::runHeadless(options);
      case Mode::Bench: return host::runBench(options);
      case Mode::Record: return host::runRecord(options);
      case Mode::Encode: return host::runEncode(options);
      case Mode::Compare: return host::runCompare(options);
      case Mode::Gallery: return host::runGallery(options);
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "vitrine: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vitrine: unexpected error: %s\n", e.what());
    return 1;
  }
  return 0;
}
