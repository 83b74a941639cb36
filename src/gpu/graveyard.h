#pragma once
// Deferred destruction. An object the GPU may still be using — a resized image, a replaced buffer, a
// rebuilt pipeline, a whole scene after a switch — is handed here instead of being destroyed, tagged
// with the serial of the next submission (the last one that can use it). Once the queue's timeline
// has passed that serial the object is destroyed. No resize or reallocation waits for the device.
#include <cstdint>
#include <deque>
#include <memory>
#include <type_traits>
#include <utility>

namespace vitrine::gpu {

class Graveyard {
 public:
  Graveyard() = default;
  Graveyard(const Graveyard&) = delete;
  Graveyard& operator=(const Graveyard&) = delete;

  // Keeps `object` alive until the submission with `serial` has finished.
  template <typename T> void bury(T&& object, uint64_t serial) {
    static_assert(!std::is_lvalue_reference_v<T>, "bury takes ownership: std::move the object in");
    graves_.push_back({serial, std::make_unique<Holder<std::decay_t<T>>>(std::forward<T>(object))});
  }
  // Destroys everything whose serial is at most `completed`, oldest first.
  void collect(uint64_t completed) {
    while (!graves_.empty() && graves_.front().serial <= completed) graves_.pop_front();
  }
  void clear() {
    while (!graves_.empty()) graves_.pop_back();  // newest first: a scene goes before what it retired
  }
  size_t size() const { return graves_.size(); }

 private:
  struct Base {
    virtual ~Base() = default;
  };
  template <typename T> struct Holder final : Base {
    explicit Holder(T&& v) : value(std::move(v)) {}
    T value;
  };
  struct Grave {
    uint64_t serial;
    std::unique_ptr<Base> object;
  };
  std::deque<Grave> graves_;  // serials never decrease along the queue
};

}  // namespace vitrine::gpu
