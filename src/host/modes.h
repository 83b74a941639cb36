#pragma once
// The program's modes, each a function of the parsed options returning the process exit code.
#include "app/options.h"

namespace vitrine::host {

int runGallery(const Options& options);   // window, swapchain, overlay (host/gallery/gallery.cpp)
int runHeadless(const Options& options);  // --headless: N frames into an EXR/PNG
int runBench(const Options& options);     // bench: GPU timestamps per pass into JSON
int runRecord(const Options& options);    // record: a numbered frame sequence (and its sound) for a film
int runRecordFilm(const Options& options);  // record --out NAME.mp4|.mov|.mkv: the film itself (host/offline/record_film.cpp)
int runEncode(const Options& options);    // encode FOLDER: a recorded sequence into a film (host/offline/encode.cpp)
int runCompare(const Options& options);   // compare: the golden metric on two files
int runListParams(const Options& options);  // --list-params: each scene's parameters (host/list_params.cpp)
int runListKeys(const Options& options);     // --list-keys: SCENE.KEY, one a line
int runListPresets(const Options& options);  // --list-presets: SCENE.NAME, the scene's own then the user's

}  // namespace vitrine::host
