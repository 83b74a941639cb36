#include "image/image_file.h"

#include <fcntl.h>
#include <OpenEXR/openexr.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <fstream>
#include <string>
#include <system_error>

#include "core/bounded_file.h"
#include "core/error.h"
#include "core/printable.h"
#include "image/image_io.h"

namespace vitrine {
namespace {

bool startsWith(std::span<const unsigned char> head, std::string_view magic, size_t at = 0) {
  return head.size() >= at + magic.size() &&
         std::equal(magic.begin(), magic.end(), head.begin() + at,
                    [](char m, unsigned char h) { return static_cast<unsigned char>(m) == h; });
}

// OpenEXR's first complaint about a header, kept for the error message (its messages quote attribute
// names and types straight from the file: bytes that are not printable ASCII are written as \xNN).
thread_local std::string exrComplaint;

void keepExrComplaint(exr_const_context_t, exr_result_t code, const char* message) {
  if (!exrComplaint.empty()) return;
  exrComplaint = fmt::format("{} ({})", printable(message ? message : ""), exr_get_error_code_as_string(code));
}

}  // namespace

std::optional<ImageFormat> imageFormatFromName(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".exr") return ImageFormat::Exr;
  if (ext == ".png") return ImageFormat::Png;
  return std::nullopt;
}

std::string_view sniffImageFormat(std::span<const unsigned char> head) {
  using namespace std::string_view_literals;
  if (startsWith(head, "\x76\x2f\x31\x01"sv)) return "EXR";
  if (startsWith(head, "\x89PNG\r\n\x1a\n"sv)) return "PNG";
  if (startsWith(head, "\xff\xd8\xff"sv)) return "JPEG";
  if (startsWith(head, "II*\0"sv) || startsWith(head, "MM\0*"sv)) return "TIFF";
  if (startsWith(head, "#?RADIANCE"sv) || startsWith(head, "#?RGBE"sv)) return "Radiance HDR";
  if (startsWith(head, "GIF87a"sv) || startsWith(head, "GIF89a"sv)) return "GIF";
  if (startsWith(head, "RIFF"sv) && startsWith(head, "WEBP"sv, 8)) return "WebP";
  if (startsWith(head, "BM"sv) && head.size() >= 14) return "BMP";
  return {};
}

void checkExrFile(const std::filesystem::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    const int error = errno;
    throw Error(fmt::format("Cannot read {}: {}.", path.string(), osReason(error)));
  }
  if (!S_ISREG(info.st_mode))
    throw Error(fmt::format("Cannot read {}: it is {}, not a regular file.", path.string(), fileKind(info.st_mode)));
  // O_NONBLOCK: should the path have become a fifo since the stat, the open still returns.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    throw Error(fmt::format("Cannot read {}: {}.", path.string(), osReason(error)));
  }
  std::array<unsigned char, 16> head{};
  const ssize_t got = ::read(fd, head.data(), head.size());
  const int error = errno;
  ::close(fd);
  if (got < 0) throw Error(fmt::format("Cannot read {}: {}.", path.string(), osReason(error)));
  if (got == 0) throw Error(fmt::format("Cannot read {}: it is empty, not an EXR.", path.string()));
  const std::string_view format = sniffImageFormat(std::span(head.data(), size_t(got)));
  if (format == "EXR") return checkExrHeader(path);
  if (!format.empty()) throw Error(fmt::format("Cannot read {}: it is a {} file, not an EXR.", path.string(), format));
  throw Error(fmt::format("Cannot read {}: it is not an EXR (its first bytes are not the EXR magic number).",
                          path.string()));
}

void checkExrHeader(const std::filesystem::path& path) {
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = keepExrComplaint;
  init.max_image_width = init.max_image_height = kMaxExrSide;
  init.max_tile_width = init.max_tile_height = kMaxExrSide;
  // Strict: an attribute that claims more bytes than the file holds, a window or tile size out of range,
  // a required attribute missing, each ends the parse with an error instead of a guess.
  init.flags = EXR_CONTEXT_FLAG_STRICT_HEADER;
  exrComplaint.clear();
  exr_context_t context = nullptr;
  const exr_result_t result = exr_start_read(&context, path.c_str(), &init);
  exr_finish(&context);
  if (result == EXR_ERR_SUCCESS) return;
  std::string why = exrComplaint.empty()
                        ? fmt::format("{} ({})", exr_get_default_error_message(result), exr_get_error_code_as_string(result))
                        : exrComplaint;
  exrComplaint.clear();
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  throw Error(fmt::format("Cannot read {}: its EXR header is inconsistent, refused before decoding: {}{}.",
                          path.string(), why, ec ? "" : fmt::format("; the file is {} bytes", bytes)));
}

bool startsLikeExr(const std::filesystem::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return false;
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  std::array<unsigned char, 4> head{};
  const ssize_t got = ::read(fd, head.data(), head.size());
  ::close(fd);
  return got == ssize_t(head.size()) && sniffImageFormat(std::span(head.data(), head.size())) == "EXR";
}

void checkPngChunks(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 8> signature{};
  if (!in.read(reinterpret_cast<char*>(signature.data()), signature.size()) ||
      sniffImageFormat(std::span(signature.data(), signature.size())) != "PNG")
    return;
  std::error_code ec;
  const uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) return;
  uint64_t at = signature.size();
  std::array<unsigned char, 8> header{};
  // Up to the image data: what follows it is the decoder's to judge (a truncated image is an error it
  // reports, not a hostile header).
  while (at + header.size() <= size && in.seekg(std::streamoff(at)) &&
         in.read(reinterpret_cast<char*>(header.data()), header.size())) {
    const uint64_t length = uint64_t(header[0]) << 24 | uint64_t(header[1]) << 16 | uint64_t(header[2]) << 8 | header[3];
    const std::string type(reinterpret_cast<const char*>(header.data()) + 4, 4);
    if (type == "IDAT" || type == "IEND") return;
    const uint64_t left = size - at - header.size();
    if (length + 4 > left)  // its data and CRC
      throw Error(fmt::format("Cannot read {}: its PNG chunk '{}' claims {} bytes where the file has {} left, "
                              "refused before decoding.",
                              path.string(), printable(type), length, left));
    at += header.size() + length + 4;
  }
}

void checkImageHeader(const std::filesystem::path& path) {
  if (startsLikeExr(path)) return checkExrHeader(path);
  checkPngChunks(path);
}

}  // namespace vitrine
