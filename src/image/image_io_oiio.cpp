#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>

#include <algorithm>

#include "core/error.h"
#include "core/atomic_file.h"
#include "image/image_file.h"
#include "image/image_io.h"

namespace vitrine {

bool canWritePng() { return true; }

void writeImage(const std::filesystem::path& path, const ImageRgba& image) {
  namespace OIIO = OIIO;
  const std::string ext = path.extension().string();
  const bool png = ext == ".png" || ext == ".PNG";
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buffer(spec, const_cast<float*>(image.pixels.data()));
  OIIO::ImageBuf encoded;
  if (png) {
    encoded = OIIO::ImageBufAlgo::colorconvert(buffer, "linear", "sRGB");
    encoded = OIIO::ImageBufAlgo::clamp(encoded, 0.0f, 1.0f);
    encoded.set_write_format(OIIO::TypeDesc::UINT8);
  } else {
    encoded.copy(buffer);
    encoded.set_write_format(OIIO::TypeDesc::HALF);
  }
  replaceAtomically(path, [&](const std::filesystem::path& temporary) {
    if (!encoded.write(temporary.string()))
      throw Error(fmt::format("Cannot write {}: {}", path.string(), encoded.geterror()));
  });
}

ImageRgba readImage(const std::filesystem::path& path) {
  checkExrFile(path);
  OIIO::ImageBuf buffer(path.string());
  if (!buffer.read(0, 0, true, OIIO::TypeDesc::FLOAT))
    throw Error(fmt::format("Cannot read {}: {}", path.string(), buffer.geterror()));
  const auto& spec = buffer.spec();
  ImageRgba image{static_cast<uint32_t>(spec.width), static_cast<uint32_t>(spec.height), {}};
  image.pixels.assign(size_t(spec.width) * spec.height * 4, 1.0f);
  const int channels = std::min(spec.nchannels, 4);
  std::vector<float> all(size_t(spec.width) * spec.height * spec.nchannels);
  buffer.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, all.data());
  for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i)
    for (int c = 0; c < channels; ++c) image.pixels[i * 4 + c] = all[i * spec.nchannels + c];
  return image;
}

}  // namespace vitrine
