#include <ImfArray.h>
#include <ImfHeader.h>
#include <ImfRgbaFile.h>
#include <ImfStringAttribute.h>
#include <fmt/format.h>

#include "core/error.h"
#include "core/atomic_file.h"
#include "image/image_file.h"
#include "image/image_io.h"

namespace vitrine {

bool canWritePng() { return false; }

bool canReadPictures() { return false; }

Picture readPicture(const std::filesystem::path& path, uint32_t) {
  throw Error(fmt::format("Cannot read {}: this build reads EXR only (built with VITRINE_WITH_OIIO=OFF).",
                          path.string()));
}

void writeImage(const std::filesystem::path& path, const ImageRgba& image, const ImageNotes& notes) {
  if (path.extension() != ".exr" && path.extension() != ".EXR")
    throw Error(
        fmt::format("Cannot write {}: this build has no OpenImageIO and writes EXR only "
                    "(configure with -DVITRINE_WITH_OIIO=ON for PNG).",
                    path.string()));
  replaceAtomically(path, [&](const std::filesystem::path& temporary) {
    try {
      std::vector<Imf::Rgba> half(size_t(image.width) * image.height);
      for (size_t i = 0; i < half.size(); ++i)
        half[i] =
            Imf::Rgba(image.pixels[i * 4], image.pixels[i * 4 + 1], image.pixels[i * 4 + 2], image.pixels[i * 4 + 3]);
      Imf::Header header(int(image.width), int(image.height));
      for (const auto& [name, value] : notes) header.insert(name, Imf::StringAttribute(value));
      Imf::RgbaOutputFile file(temporary.c_str(), header, Imf::WRITE_RGBA);
      file.setFrameBuffer(half.data(), 1, image.width);
      file.writePixels(int(image.height));
    } catch (const std::exception& e) {
      throw Error(fmt::format("Cannot write {}: {}", path.string(), e.what()));
    }
  });
}

ImageRgba readImage(const std::filesystem::path& path) {
  checkExrFile(path);
  try {
    Imf::RgbaInputFile file(path.c_str());
    const auto window = file.dataWindow();
    const int width = window.max.x - window.min.x + 1;
    const int height = window.max.y - window.min.y + 1;
    Imf::Array2D<Imf::Rgba> half(height, width);
    file.setFrameBuffer(&half[0][0] - window.min.x - size_t(window.min.y) * width, 1, width);
    file.readPixels(window.min.y, window.max.y);
    ImageRgba image{uint32_t(width), uint32_t(height), std::vector<float>(size_t(width) * height * 4)};
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const Imf::Rgba& p = half[y][x];
        float* out = image.at(x, y);
        out[0] = p.r, out[1] = p.g, out[2] = p.b, out[3] = p.a;
      }
    return image;
  } catch (const std::exception& e) {
    throw Error(fmt::format("Cannot read {}: {}", path.string(), e.what()));
  }
}

}  // namespace vitrine
