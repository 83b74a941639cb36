// Pictures in the formats image_io.cpp does not read itself (WebP, TIFF, Radiance HDR, ...), through
// OpenImageIO. Built as a module the image module loads on the first such picture (picture_oiio.h):
// OpenImageIO's ~260 shared libraries cost every process that links them ~0.3 s of CPU at start, and
// most processes (headless runs, tests, the gallery with its own photos) never read such a file. The
// fuzz build links it in directly.
#include "image/picture_oiio.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imagecache.h>
#include <fmt/format.h>

#include <algorithm>
#include <exception>

namespace vitrine {
namespace {

// Why a read failed: the buffer's own message, and any OpenImageIO left in its per-thread global error
// (an ImageInput that failed to open sets that one too; left unread, it is never freed).
std::string readError(OIIO::ImageBuf& buffer) {
  std::string why = buffer.geterror();
  const std::string global = OIIO::geterror();
  if (why.empty()) why = global;
  return why.empty() ? "OpenImageIO could not read it" : why;
}

// An ImageBuf made from a file name reads through OpenImageIO's shared ImageCache, which knows a file by
// its name and modification time in whole seconds: a file replaced under the same name within that
// second was read with the old file's size and channels, writing past the pixel buffer (found by
// fuzz/image_hdr and fuzz/image_exr). Forgetting what the cache knows of the name first makes every
// read see the file as it is now.
OIIO::ImageBuf openFresh(const std::string& path) {
  OIIO::ImageCache::create(true)->invalidate(OIIO::ustring(path), true);
  return OIIO::ImageBuf(path);
}

Picture readWithOpenImageIo(const std::string& path) {
  OIIO::ImageBuf source = openFresh(path);
  if (!source.read(0, 0, true, OIIO::TypeDesc::UINT8)) throw std::runtime_error(readError(source));
  const OIIO::ImageSpec& spec = source.spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) throw std::runtime_error("it has no pixels.");
  // HDR pictures arrive linear; displayed pictures are sRGB-encoded from here on.
  const OIIO::ImageBuf image =
      spec.format.is_floating_point() ? OIIO::ImageBufAlgo::colorconvert(source, "linear", "sRGB") : source;
  const OIIO::ImageSpec& out = image.spec();
  std::vector<uint8_t> channels(size_t(out.width) * out.height * out.nchannels);
  if (!image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, channels.data()))
    throw std::runtime_error(image.geterror());
  Picture picture{uint32_t(out.width), uint32_t(out.height), std::vector<uint8_t>(size_t(out.width) * out.height * 4, 255)};
  const int n = out.nchannels;
  for (size_t i = 0; i < size_t(out.width) * out.height; ++i)
    for (int c = 0; c < 4; ++c) {
      if (c < 3) picture.rgba[i * 4 + c] = channels[i * n + (n >= 3 ? c : 0)];  // grey fills R, G and B
      else if (n == 4 || n == 2) picture.rgba[i * 4 + 3] = channels[i * n + n - 1];
    }
  return picture;
}

}  // namespace
}  // namespace vitrine

extern "C" bool vitrine_read_picture_oiio(const char* path, vitrine::Picture* picture, std::string* why) {
  try {
    *picture = vitrine::readWithOpenImageIo(path);
    return true;
  } catch (const std::exception& error) {
    *why = error.what();
    return false;
  }
}
