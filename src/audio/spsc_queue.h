#pragma once
// A bounded single-producer single-consumer ring: the frame loop pushes, the audio callback reads.
// Neither side locks, waits or allocates, so the callback can never be held up by the frame loop.
// Each index is written by one side only; release on the writer's store and acquire on the other
// side's load make a slot's contents visible before the index that publishes it.
#include <array>
#include <atomic>
#include <cstddef>
#include <type_traits>

namespace vitrine::audio {

template <class T, size_t Capacity>
class SpscQueue {
  static_assert(Capacity >= 2 && (Capacity & (Capacity - 1)) == 0, "Capacity must be a power of two");
  static_assert(std::is_trivially_copyable_v<T>, "slots are copied by the two threads without constructors");

 public:
  // Producer only. False when full: the value is not queued.
  bool push(const T& value) {
    const size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail - head_.load(std::memory_order_acquire) == Capacity) return false;
    slots_[tail & (Capacity - 1)] = value;
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }

  // Consumer only. The oldest value, or nullptr when empty; stays queued until pop().
  const T* front() const {
    const size_t head = head_.load(std::memory_order_relaxed);
    if (head == tail_.load(std::memory_order_acquire)) return nullptr;
    return &slots_[head & (Capacity - 1)];
  }

  // Consumer only, after front() returned a value.
  void pop() { head_.store(head_.load(std::memory_order_relaxed) + 1, std::memory_order_release); }

  static constexpr size_t capacity() { return Capacity; }

 private:
  // The indices only grow (wrapping at 2^64 is centuries away); a slot is index mod Capacity.
  // Separate cache lines, so the two threads do not bounce one line between them.
  alignas(64) std::atomic<size_t> head_{0};  // next slot to read: written by the consumer
  alignas(64) std::atomic<size_t> tail_{0};  // next slot to write: written by the producer
  alignas(64) std::array<T, Capacity> slots_{};
};

}  // namespace vitrine::audio
