// The image module: EXR through OpenEXR, PNG through libpng and JPEG through libjpeg(-turbo), which
// the core links anyway (FreeType) and which load in milliseconds. Pictures in other formats (WebP,
// TIFF, HDR, ...) go to OpenImageIO, a module loaded on the first such picture (picture_oiio.cpp says
// why); a build without it (VITRINE_WITH_OIIO=OFF, the packed GPU-machine binary) names the formats
// it reads instead.
#include <ImfArray.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfRgbaFile.h>
#include <ImfStringAttribute.h>
#include <fmt/format.h>
#include <jpeglib.h>
#include <png.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <csetjmp>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <span>

#include <cstring>

#if VITRINE_WITH_OIIO
#include <dlfcn.h>
#endif

#include "core/error.h"
#include "core/atomic_file.h"
#include "core/bounded_file.h"
#include "image/image_file.h"
#include "image/image_io.h"
#include "image/picture_oiio.h"

namespace vitrine {

namespace {

Picture readPng(const std::filesystem::path& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str()))
    throw Error(fmt::format("Cannot read {}: {}", path.string(), image.message));
  image.format = PNG_FORMAT_RGBA;
  Picture picture{image.width, image.height, std::vector<uint8_t>(PNG_IMAGE_SIZE(image))};
  if (!png_image_finish_read(&image, nullptr, picture.rgba.data(), 0, nullptr)) {
    const std::string why = image.message;
    png_image_free(&image);
    throw Error(fmt::format("Cannot read {}: {}", path.string(), why));
  }
  return picture;
}

// libjpeg reports a fatal error by calling error_exit, which must not return: it jumps back here.
struct JpegError {
  jpeg_error_mgr manager;
  std::jmp_buf back;
  char message[JMSG_LENGTH_MAX];
};

Picture readJpeg(const std::filesystem::path& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw Error(fmt::format("Cannot read {}: it cannot be opened.", path.string()));
  jpeg_decompress_struct info{};
  JpegError error{};
  info.err = jpeg_std_error(&error.manager);
  error.manager.error_exit = [](j_common_ptr common) {
    auto* e = reinterpret_cast<JpegError*>(common->err);
    e->manager.format_message(common, e->message);
    std::longjmp(e->back, 1);
  };
  Picture picture;
  if (setjmp(error.back)) {
    jpeg_destroy_decompress(&info);
    throw Error(fmt::format("Cannot read {}: {}", path.string(), error.message));
  }
  jpeg_create_decompress(&info);
  jpeg_stdio_src(&info, file.get());
  jpeg_read_header(&info, TRUE);
  info.out_color_space = JCS_EXT_RGBA;
  jpeg_start_decompress(&info);
  picture.width = info.output_width, picture.height = info.output_height;
  picture.rgba.resize(size_t(picture.width) * picture.height * 4);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = picture.rgba.data() + size_t(info.output_scanline) * picture.width * 4;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  return picture;
}

#if VITRINE_WITH_OIIO
using ReadPicture = decltype(&vitrine_read_picture_oiio);

// The OpenImageIO module's entry, loaded once: beside the executable (an installed or packed copy),
// else where the build put it. Null, with the reason in `why`, when neither loads.
ReadPicture openImageIoReader([[maybe_unused]] std::string& why) {
#if VITRINE_OIIO_LINKED
  return &vitrine_read_picture_oiio;
#else
  static std::string failure;
  static const ReadPicture reader = [] () -> ReadPicture {
    std::error_code ec;
    const std::filesystem::path beside = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path() / VITRINE_OIIO_MODULE_NAME;
    for (const std::filesystem::path& module : {beside, std::filesystem::path(VITRINE_OIIO_MODULE)}) {
      if (void* handle = dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL))
        if (void* entry = dlsym(handle, "vitrine_read_picture_oiio")) return reinterpret_cast<ReadPicture>(entry);
      if (const char* error = dlerror()) failure = error;
    }
    return nullptr;
  }();
  why = failure;
  return reader;
#endif
}
#endif

// A box filter down to fit maxSide: each output texel the mean of the source texels it covers.
Picture fitWithin(Picture source, uint32_t maxSide) {
  const uint32_t longest = std::max(source.width, source.height);
  if (longest <= maxSide || maxSide == 0) return source;
  const double scale = double(maxSide) / double(longest);
  Picture out{std::max(1u, uint32_t(source.width * scale)), std::max(1u, uint32_t(source.height * scale)), {}};
  out.rgba.resize(size_t(out.width) * out.height * 4);
  for (uint32_t y = 0; y < out.height; ++y) {
    const uint32_t y0 = uint32_t(uint64_t(y) * source.height / out.height);
    const uint32_t y1 = std::max(y0 + 1, uint32_t(uint64_t(y + 1) * source.height / out.height));
    for (uint32_t x = 0; x < out.width; ++x) {
      const uint32_t x0 = uint32_t(uint64_t(x) * source.width / out.width);
      const uint32_t x1 = std::max(x0 + 1, uint32_t(uint64_t(x + 1) * source.width / out.width));
      uint32_t sum[4] = {0, 0, 0, 0};
      for (uint32_t sy = y0; sy < y1; ++sy)
        for (uint32_t sx = x0; sx < x1; ++sx)
          for (int c = 0; c < 4; ++c) sum[c] += source.rgba[(size_t(sy) * source.width + sx) * 4 + c];
      const uint32_t n = (y1 - y0) * (x1 - x0);
      for (int c = 0; c < 4; ++c) out.rgba[(size_t(y) * out.width + x) * 4 + c] = uint8_t((sum[c] + n / 2) / n);
    }
  }
  return out;
}

}  // namespace

Picture readPicture(const std::filesystem::path& path, uint32_t maxSide) {
  try {
    checkBoundedFile(path, kMaxPictureFileBytes);
  } catch (const FileRefused& refused) {
    throw Error(fmt::format("Cannot read {}: {}.", path.string(), refused.why));
  }
  std::array<unsigned char, 16> head{};
  {
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(head.data()), head.size());
    head.back() = in.gcount() == std::streamsize(head.size()) ? head.back() : 0;
  }
  checkImageHeader(path);  // whatever its name: the readers below pick by content
  const std::string_view format = sniffImageFormat(head);
  Picture picture;
  if (format == "PNG") {
    picture = readPng(path);
  } else if (format == "JPEG") {
    picture = readJpeg(path);
  } else if (format == "EXR") {
    const ImageRgba linear = readImage(path);
    picture = {linear.width, linear.height, srgb8(linear)};
  } else {
#if VITRINE_WITH_OIIO
    std::string why;
    const ReadPicture reader = openImageIoReader(why);
    if (!reader) throw Error(fmt::format("Cannot read {}: OpenImageIO's module did not load ({}).", path.string(), why));
    if (!reader(path.c_str(), &picture, &why)) throw Error(fmt::format("Cannot read {}: {}", path.string(), why));
#else
    throw Error(fmt::format("Cannot read {}: {} this build reads PNG, JPEG and EXR only (built with "
                            "VITRINE_WITH_OIIO=OFF).", path.string(),
                            format.empty() ? std::string("it is no image format known, and") :
                                             fmt::format("it is a {} file, and", format)));
#endif
  }
  return fitWithin(std::move(picture), maxSide);
}

namespace {

// OpenEXR's output stream into memory: the bytes then go to the disk through writeFileAtomically,
// which checks each write (OpenEXR's own file stream says only "File output failed").
class MemoryStream final : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (at_ + uint64_t(n) > bytes.size()) bytes.resize(at_ + uint64_t(n));
    std::memcpy(bytes.data() + at_, c, size_t(n));
    at_ += uint64_t(n);
  }
  uint64_t tellp() override { return at_; }
  void seekp(uint64_t pos) override { at_ = pos; }
  std::vector<unsigned char> bytes;

 private:
  uint64_t at_ = 0;
};

}  // namespace

namespace {

// A channel's display value in [0, 1]: colour on the sRGB curve, alpha as it is.
float displayValue(const ImageRgba& image, size_t i) {
  return i % 4 == 3 ? std::clamp(image.pixels[i], 0.0f, 1.0f) : linearToSrgb(image.pixels[i]);
}

}  // namespace

std::vector<uint8_t> srgb8(const ImageRgba& image) {
  std::vector<uint8_t> out(image.pixels.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = uint8_t(std::lround(255.0f * displayValue(image, i)));
  return out;
}

std::vector<uint16_t> srgb16(const ImageRgba& image) {
  std::vector<uint16_t> out(image.pixels.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = uint16_t(std::lround(65535.0f * displayValue(image, i)));
  return out;
}

namespace {

// Where libpng writes the PNG, and what its error handler leaves before it jumps back.
struct PngWriter {
  std::vector<unsigned char> bytes;
  std::string error;
  std::jmp_buf jump;
};

// libpng's part of encodePng, from setjmp on: libpng reports a fatal error by calling its error
// function, which must not return, so it jumps back here. Nothing in this function has a destructor
// for the jump to skip, nor a local that the jump could leave stale (GCC's -Wclobbered warned when
// the notes' vector was built beside the setjmp). False on an error, in writer.error.
bool writePng(png_structp png, png_infop info, PngWriter& writer, std::span<png_text> texts, const uint8_t* rgba,
              uint32_t width, uint32_t height) {
  if (setjmp(writer.jump)) return false;
  png_set_write_fn(
      png, &writer,
      [](png_structp p, png_bytep data, png_size_t size) {
        auto& out = static_cast<PngWriter*>(png_get_io_ptr(p))->bytes;
        out.insert(out.end(), data, data + size);
      },
      nullptr);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (!texts.empty()) png_set_text(png, info, texts.data(), int(texts.size()));
  png_write_info(png, info);
  for (uint32_t y = 0; y < height; ++y) png_write_row(png, rgba + size_t(y) * width * 4);
  png_write_end(png, info);
  return true;
}

// 8-bit RGBA rows as a PNG in memory, each note a tEXt chunk (libpng's simplified API writes no text).
std::vector<unsigned char> encodePng(const std::filesystem::path& path, const std::vector<uint8_t>& rgba, uint32_t width,
                                     uint32_t height, const ImageNotes& notes) {
  PngWriter writer;
  png_structp png = png_create_write_struct(
      PNG_LIBPNG_VER_STRING, &writer,
      [](png_structp p, png_const_charp message) {
        auto* w = static_cast<PngWriter*>(png_get_error_ptr(p));
        w->error = message;
        std::longjmp(w->jump, 1);
      },
      nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw Error(fmt::format("Cannot write {}: libpng has no memory", path.string()));
  }
  std::vector<png_text> texts(notes.size());
  for (size_t i = 0; i < notes.size(); ++i) {
    texts[i].compression = PNG_TEXT_COMPRESSION_NONE;
    texts[i].key = const_cast<char*>(notes[i].first.c_str());
    texts[i].text = const_cast<char*>(notes[i].second.c_str());
  }
  const bool written = writePng(png, info, writer, texts, rgba.data(), width, height);
  png_destroy_write_struct(&png, &info);
  if (!written) throw Error(fmt::format("Cannot write {}: {}", path.string(), writer.error));
  return std::move(writer.bytes);
}

}  // namespace

void writeImage(const std::filesystem::path& path, const ImageRgba& image, const ImageNotes& notes) {
  const std::optional<ImageFormat> format = imageFormatFromName(path);
  if (!format)
    throw Error(fmt::format("Cannot write {}: name it .exr (linear half float) or .png (8-bit sRGB).", path.string()));
  if (*format == ImageFormat::Png) {
    // Into memory, then to the disk through writeFileAtomically, which checks every write.
    writeFileAtomically(path, encodePng(path, srgb8(image), image.width, image.height, notes));
    return;
  }
  MemoryStream memory;
  try {
    std::vector<Imf::Rgba> half(size_t(image.width) * image.height);
    for (size_t i = 0; i < half.size(); ++i)
      half[i] = Imf::Rgba(image.pixels[i * 4], image.pixels[i * 4 + 1], image.pixels[i * 4 + 2], image.pixels[i * 4 + 3]);
    Imf::Header header(int(image.width), int(image.height));
    for (const auto& [name, value] : notes) header.insert(name, Imf::StringAttribute(value));
    Imf::RgbaOutputFile file(memory, header, Imf::WRITE_RGBA);
    file.setFrameBuffer(half.data(), 1, image.width);
    file.writePixels(int(image.height));
  } catch (const std::exception& e) {
    throw Error(fmt::format("Cannot write {}: {}", path.string(), e.what()));
  }
  writeFileAtomically(path, memory.bytes);
}

bool isWholeImage(const std::filesystem::path& path, uint32_t width, uint32_t height) {
  try {
    if (startsLikeExr(path)) {
      const ImageRgba image = readImage(path);
      return image.width == width && image.height == height;
    }
    const Picture picture = readPicture(path, 0);  // 0: at its own size
    return picture.width == width && picture.height == height;
  } catch (const Error&) {
    return false;
  }
}

ImageRgba readImage(const std::filesystem::path& path) {
  checkExrFile(path);
  try {
    Imf::RgbaInputFile file(path.c_str());
    const auto window = file.dataWindow();
    const int width = window.max.x - window.min.x + 1;
    const int height = window.max.y - window.min.y + 1;
    Imf::Array2D<Imf::Rgba> half(height, width);
    // OpenEXR addresses pixel (x, y) as base + x + y * width, so the base sits before the buffer by the
    // data window's origin, which may be anywhere (a fuzzed file put it far below zero). Pointer
    // arithmetic that leaves the buffer is undefined (UBSan caught the old `&half[0][0] - min...`):
    // the offset is taken in integers, and OpenEXR adds it back inside its own code.
    const std::ptrdiff_t origin = std::ptrdiff_t(window.min.x) + std::ptrdiff_t(window.min.y) * width;
    auto* base = reinterpret_cast<Imf::Rgba*>(reinterpret_cast<std::uintptr_t>(&half[0][0]) -
                                              std::uintptr_t(origin) * sizeof(Imf::Rgba));
    file.setFrameBuffer(base, 1, width);
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
