#pragma once
// The one gate every file Vitrine reads passes before its bytes are read: it must be a regular file of
// at most a stated size. A fifo with no writer blocks open() and read() forever, /dev/zero never ends,
// and a symbolic link can point a checkpoint, a sound or a settings file at either; a decoder or a
// parser handed one of them hangs or grows memory until the machine runs out.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace vitrine {

// Why a file was refused, in words that follow its name ("it is a fifo, not a regular file").
struct FileRefused {
  std::string why;
};

// What a file that is not a regular file is, for a refusal: "a folder", "a character device", "a fifo".
std::string_view fileKind(unsigned mode);

// "1 MiB", "64 KiB", "2 GiB" or "100 bytes": a limit as the refusals state it.
std::string bytesInWords(uintmax_t bytes);

// An open, read-only descriptor on a regular file of at most `maxBytes`. The path is opened without
// blocking (a fifo opens at once instead of waiting for a writer) and the open file itself is checked
// with fstat, so what is checked is what is read, whatever is swapped in at the path meanwhile.
class BoundedFile {
 public:
  // Throws FileRefused: it does not exist, it cannot be opened, it is not a regular file, it is larger.
  BoundedFile(const std::filesystem::path& path, uintmax_t maxBytes);
  ~BoundedFile();
  BoundedFile(const BoundedFile&) = delete;
  BoundedFile& operator=(const BoundedFile&) = delete;

  uintmax_t size() const { return size_; }
  // The whole file; refused if it grew past the limit since it was opened, or cannot be read.
  std::string readAll();
  // Hands the descriptor (blocking again) to a library that reads it and closes it itself.
  int release();

 private:
  int fd_ = -1;
  uintmax_t size_ = 0;
  uintmax_t maxBytes_ = 0;
};

// The whole of the file at `path`, through BoundedFile; throws FileRefused.
std::string readBoundedFile(const std::filesystem::path& path, uintmax_t maxBytes);

// For a library that opens the path itself (an image decoder, FreeType): throws FileRefused unless
// the path is, right now, a regular file of at most `maxBytes`.
void checkBoundedFile(const std::filesystem::path& path, uintmax_t maxBytes);

}  // namespace vitrine
