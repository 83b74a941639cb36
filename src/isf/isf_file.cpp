#include "isf/isf_file.h"

#include <fmt/format.h>

namespace vitrine::isf {

std::shared_ptr<const LoadedFile> loadFile(const std::filesystem::path& path) {
  auto file = std::make_shared<LoadedFile>();
  file->path = path;
  file->document = loadDocument(path);
  const Document& doc = file->document;
  file->compiled = compileIsf(doc, loadVertexFile(path));
  if (const size_t images = file->compiled.translation.samplers.size(); images > kMaxImages)
    throw IsfError(doc.file, doc.inputs.empty() ? 1 : doc.inputs.front().line,
                   fmt::format("samples {} images (inputs, imported pictures and buffers); at most {}", images, kMaxImages));
  for (const ImportedImage& imported : doc.imported) {
    // Relative to the file's folder, as the specification asks; an absolute path is taken as written.
    const std::filesystem::path where = imported.path.is_absolute() ? imported.path : path.parent_path() / imported.path;
    try {
      file->imported.push_back(readPicture(where, kMaxPictureSide));
    } catch (const Error& e) {
      throw IsfError(doc.file, imported.line, fmt::format("IMPORTED '{}': {}", imported.name, e.what()));
    }
  }
  return file;
}

}  // namespace vitrine::isf
