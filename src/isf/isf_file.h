#pragma once
// An ISF file ready to run: read, checked, translated, compiled to SPIR-V, its IMPORTED pictures read
// and their sizes bounded. All of it CPU work with no GPU, so the gallery makes one off the frame
// thread (hot reload) and hands it to the GPU runner (isf/gpu/isf_runner.h) when it is done.
#include "image/image_io.h"
#include "isf/isf_compile.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace vitrine::isf {

// The largest side an IMPORTED picture or an image input's picture is read at (larger ones are
// scaled down, keeping their aspect).
inline constexpr uint32_t kMaxPictureSide = 4096;
// Images one file may sample (inputs, imported pictures, pass targets): the frame block and these
// must fit the 32 push descriptors every Vulkan device offers.
inline constexpr size_t kMaxImages = 31;

struct LoadedFile {
  std::filesystem::path path;
  Document document;
  CompiledIsf compiled;
  std::vector<Picture> imported;  // per Document::imported: RGBA8, top row first as read
};

// Throws IsfError naming the file and line: what loadDocument, loadVertexFile and compileIsf refuse,
// an IMPORTED picture that cannot be read (at its line), more than kMaxImages images.
std::shared_ptr<const LoadedFile> loadFile(const std::filesystem::path& path);

}  // namespace vitrine::isf
