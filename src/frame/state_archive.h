#pragma once
// A scene's simulation state for a checkpoint (record --checkpoint-every): the scene walks its state
// through one function, and the archive either saves each value into bytes or restores it from them, so
// what is written and what is read back can never disagree. Values are the scene's own fields (plain
// data, vectors, deques, optionals, strings) and its declared GPU images and buffers, which the host
// reads back when saving and uploads as the next frame begins when restoring. The bytes are native
// endian and layout: a checkpoint is read by the build and machine kind that wrote it.
#include "core/error.h"
#include "gpu/frame_resources.h"

#include <cstddef>
#include <cstring>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace vitrine {

class StateArchive {
 public:
  static StateArchive saving() { return StateArchive(true, {}); }
  // Reads `bytes`, which must outlive the archive; a value past their end throws vitrine::Error.
  static StateArchive restoring(std::span<const std::byte> bytes) { return StateArchive(false, bytes); }

  bool isRestoring() const { return !saving_; }
  // Saving: everything walked so far.
  const std::vector<std::byte>& bytes() const { return out_; }
  // Restoring: true once every byte was read (a shorter walk than the save's means a different build).
  bool finished() const { return in_.empty(); }

  // Each value in turn, saved or restored in place.
  template <typename... T> void operator()(T&... values) { (field(values), ...); }

  // The whole level-0 contents of a declared image or buffer (the current() one of a pair), declared
  // with `state` set. Saving waits for the device; restoring uploads them as the next frame begins.
  template <typename Handle> void contents(gpu::FrameResources& resources, Handle handle) {
    std::vector<std::byte> bytes = saving_ ? resources.download(handle) : std::vector<std::byte>{};
    field(bytes);
    if (!saving_) resources.restore(handle, std::move(bytes));
  }

 private:
  StateArchive(bool saving, std::span<const std::byte> in) : saving_(saving), in_(in) {}

  void raw(void* data, size_t size) {
    if (size == 0) return;
    if (saving_) {
      const auto* bytes = static_cast<const std::byte*>(data);
      out_.insert(out_.end(), bytes, bytes + size);
      return;
    }
    if (in_.size() < size) throw Error("the simulation state ends early");
    std::memcpy(data, in_.data(), size);
    in_ = in_.subspan(size);
  }
  size_t count(size_t n) {
    uint64_t stored = n;
    raw(&stored, sizeof(stored));
    if (!saving_ && stored > in_.size()) throw Error("the simulation state holds a length past its end");
    return size_t(stored);
  }

  template <typename T> void field(T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "walk the parts of a value that is not plain data");
    raw(&value, sizeof(T));
  }
  template <typename T> void field(std::vector<T>& values) {
    values.resize(count(values.size()));
    if constexpr (std::is_trivially_copyable_v<T>)
      raw(values.data(), values.size() * sizeof(T));
    else
      for (T& value : values) field(value);
  }
  template <typename T> void field(std::deque<T>& values) {
    values.resize(count(values.size()));
    for (T& value : values) field(value);
  }
  template <typename T> void field(std::optional<T>& value) {
    bool present = value.has_value();
    field(present);
    if (!present) return value.reset();
    if (!value) value.emplace();
    field(*value);
  }
  template <typename A, typename B> void field(std::pair<A, B>& pair) { (*this)(pair.first, pair.second); }
  void field(std::string& text) {
    text.resize(count(text.size()));
    raw(text.data(), text.size());
  }

  bool saving_;
  std::vector<std::byte> out_;
  std::span<const std::byte> in_;
};

}  // namespace vitrine
