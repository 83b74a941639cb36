#pragma once
// A bounded single-producer single-consumer ring of floats: the capture callback writes, the frame
// loop reads. Neither side locks, waits or allocates (the slots are allocated once, at construction),
// so the audio thread is never held up by the frame loop. Each index is written by one side only;
// release on the writer's store and acquire on the other side's load make the samples visible before
// the index that publishes them (as audio/spsc_queue.h does for commands).
#include <algorithm>
#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vitrine::live {

class FloatRing {
 public:
  // Room for at least `capacity` samples (rounded up to a power of two, so a slot is index & mask).
  explicit FloatRing(size_t capacity)
      : slots_(std::bit_ceil(std::max<size_t>(capacity, 2))), mask_(slots_.size() - 1) {}
  FloatRing(const FloatRing&) = delete;
  FloatRing& operator=(const FloatRing&) = delete;

  // Producer only. Writes what fits and returns how many; the rest is dropped (and counted) rather
  // than waiting for a consumer that may be paused.
  size_t push(std::span<const float> samples) {
    const size_t tail = tail_.load(std::memory_order_relaxed);
    const size_t room = slots_.size() - (tail - head_.load(std::memory_order_acquire));
    const size_t n = std::min(room, samples.size());
    for (size_t i = 0; i < n; ++i) slots_[(tail + i) & mask_] = samples[i];
    tail_.store(tail + n, std::memory_order_release);
    if (n < samples.size()) dropped_.fetch_add(samples.size() - n, std::memory_order_relaxed);
    return n;
  }

  // Consumer only. Moves up to out.size() of the oldest samples into `out`; returns how many.
  size_t pop(std::span<float> out) {
    const size_t head = head_.load(std::memory_order_relaxed);
    const size_t n = std::min(tail_.load(std::memory_order_acquire) - head, out.size());
    for (size_t i = 0; i < n; ++i) out[i] = slots_[(head + i) & mask_];
    head_.store(head + n, std::memory_order_release);
    return n;
  }

  // Either side: a snapshot, exact only on the consumer's side.
  size_t size() const { return tail_.load(std::memory_order_acquire) - head_.load(std::memory_order_acquire); }
  size_t capacity() const { return slots_.size(); }
  // Samples the producer could not store because the consumer fell behind.
  uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  // The indices only grow (wrapping at 2^64 is millennia away at audio rates); a slot is index & mask.
  // Separate cache lines, so the two threads do not bounce one line between them.
  alignas(64) std::atomic<size_t> head_{0};  // next sample to read: written by the consumer
  alignas(64) std::atomic<size_t> tail_{0};  // next sample to write: written by the producer
  alignas(64) std::atomic<uint64_t> dropped_{0};
  std::vector<float> slots_;
  size_t mask_;
};

}  // namespace vitrine::live
