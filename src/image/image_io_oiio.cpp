#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/filesystem.h>
#include <fmt/format.h>

#include <algorithm>

#include "core/error.h"
#include "core/atomic_file.h"
#include "image/image_file.h"
#include "image/image_io.h"

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
OIIO::ImageBuf openFresh(const std::filesystem::path& path) {
  OIIO::ImageCache::create(true)->invalidate(OIIO::ustring(path.string()), true);
  return OIIO::ImageBuf(path.string());
}

// Linear floats as sRGB display values clamped to [0, 1], still floats: what a PNG and a film frame
// quantise (OpenImageIO rounds to the nearest code in both, get_pixels and the PNG writer alike).
OIIO::ImageBuf srgbBuffer(const ImageRgba& image, const ImageNotes& notes = {}) {
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
  for (const auto& [name, value] : notes) spec.attribute(name, value);
  OIIO::ImageBuf buffer(spec, const_cast<float*>(image.pixels.data()));
  return OIIO::ImageBufAlgo::clamp(OIIO::ImageBufAlgo::colorconvert(buffer, "linear", "sRGB"), 0.0f, 1.0f);
}

template <typename T>
std::vector<T> quantised(const ImageRgba& image, OIIO::TypeDesc type) {
  std::vector<T> out(image.pixels.size());
  const OIIO::ImageBuf encoded = srgbBuffer(image);
  if (!encoded.get_pixels(OIIO::ROI::All(), type, out.data()))
    throw Error(fmt::format("Cannot encode a {}x{} frame as sRGB: {}", image.width, image.height, encoded.geterror()));
  return out;
}

}  // namespace

bool canWritePng() { return true; }

std::vector<uint8_t> srgb8(const ImageRgba& image) { return quantised<uint8_t>(image, OIIO::TypeDesc::UINT8); }
std::vector<uint16_t> srgb16(const ImageRgba& image) { return quantised<uint16_t>(image, OIIO::TypeDesc::UINT16); }

void writeImage(const std::filesystem::path& path, const ImageRgba& image, const ImageNotes& notes) {
  const std::optional<ImageFormat> format = imageFormatFromName(path);
  if (!format)
    throw Error(fmt::format("Cannot write {}: name it .exr (linear half float) or .png (8-bit sRGB).", path.string()));
  const bool png = *format == ImageFormat::Png;
  OIIO::ImageBuf encoded;
  if (png) {
    encoded = srgbBuffer(image, notes);  // as srgb8 makes a film's frame
    encoded.set_write_format(OIIO::TypeDesc::UINT8);
  } else {
    OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
    for (const auto& [name, value] : notes) spec.attribute(name, value);
    encoded.copy(OIIO::ImageBuf(spec, const_cast<float*>(image.pixels.data())));
    encoded.set_write_format(OIIO::TypeDesc::HALF);
  }
  // Encoded in memory: OpenImageIO's PNG writer does not check its writes (on a full disk it reported
  // success for a file cut short), so the bytes go to the disk through writeFileAtomically, which does.
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  encoded.set_write_ioproxy(&memory);
  if (!encoded.write(path.string(), OIIO::TypeUnknown, png ? "png" : "openexr"))
    throw Error(fmt::format("Cannot write {}: {}", path.string(), encoded.geterror()));
  writeFileAtomically(path, bytes);
}

bool isWholeImage(const std::filesystem::path& path, uint32_t width, uint32_t height) {
  try {
    checkImageHeader(path);
    OIIO::ImageBuf buffer = openFresh(path);
    // A truncated file fails the read (its last rows are missing), a corrupt one the decode.
    const bool read = buffer.read(0, 0, true, OIIO::TypeDesc::FLOAT);
    const bool whole = read && !buffer.has_error() && buffer.spec().width == int(width) &&
                       buffer.spec().height == int(height);
    (void)readError(buffer);  // forget what OpenImageIO kept of the failure
    return whole;
  } catch (const Error&) {
    return false;
  }
}

ImageRgba readImage(const std::filesystem::path& path) {
  checkExrFile(path);
  OIIO::ImageBuf buffer = openFresh(path);
  if (!buffer.read(0, 0, true, OIIO::TypeDesc::FLOAT))
    throw Error(fmt::format("Cannot read {}: {}", path.string(), readError(buffer)));
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

bool canReadPictures() { return true; }

Picture readPicture(const std::filesystem::path& path, uint32_t maxSide) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(fmt::format("Cannot read {}: it is not a regular file.", path.string()));
  checkImageHeader(path);  // whatever its name: OpenImageIO picks by content too
  OIIO::ImageBuf source = openFresh(path);
  if (!source.read(0, 0, true, OIIO::TypeDesc::UINT8))
    throw Error(fmt::format("Cannot read {}: {}", path.string(), readError(source)));
  const OIIO::ImageSpec& spec = source.spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw Error(fmt::format("Cannot read {}: it has no pixels.", path.string()));
  // HDR pictures (EXR) arrive linear; displayed pictures are sRGB-encoded from here on.
  OIIO::ImageBuf image = spec.format.is_floating_point() ? OIIO::ImageBufAlgo::colorconvert(source, "linear", "sRGB")
                                                         : source;
  const float scale = std::min(1.0f, float(maxSide) / float(std::max(spec.width, spec.height)));
  if (scale < 1.0f) {
    const int w = std::max(1, int(spec.width * scale)), h = std::max(1, int(spec.height * scale));
    image = OIIO::ImageBufAlgo::resize(image, "", 0.0f, OIIO::ROI(0, w, 0, h, 0, 1, 0, spec.nchannels));
  }
  const OIIO::ImageSpec& out = image.spec();
  std::vector<uint8_t> channels(size_t(out.width) * out.height * out.nchannels);
  if (!image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, channels.data()))
    throw Error(fmt::format("Cannot read {}: {}", path.string(), image.geterror()));
  Picture picture{uint32_t(out.width), uint32_t(out.height), std::vector<uint8_t>(size_t(out.width) * out.height * 4, 255)};
  const int n = out.nchannels;
  for (size_t i = 0; i < size_t(out.width) * out.height; ++i)
    for (int c = 0; c < 4; ++c) {
      if (c < 3) picture.rgba[i * 4 + c] = channels[i * n + (n >= 3 ? c : 0)];  // grey fills R, G and B
      else if (n == 4 || n == 2) picture.rgba[i * 4 + 3] = channels[i * n + n - 1];
    }
  return picture;
}

}  // namespace vitrine
