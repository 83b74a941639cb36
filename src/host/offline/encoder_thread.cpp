#include "host/offline/encoder_thread.h"

#include <chrono>
#include <stdexcept>

namespace vitrine::host {

EncoderThread::EncoderThread(film::VideoEncoder& encoder, size_t queued)
    : encoder_(encoder), queued_(queued), thread_([this] { run(); }) {}

EncoderThread::~EncoderThread() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    if (!error_) error_ = std::make_exception_ptr(std::runtime_error("the film was abandoned"));
  }
  changed_.notify_all();
  thread_.join();
}

void EncoderThread::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
    if (jobs_.empty()) return;  // stopping, and nothing left
    Job job = std::move(jobs_.front());
    jobs_.pop_front();
    ++running_;
    const bool failed = error_ != nullptr;
    lock.unlock();
    std::exception_ptr thrown;
    try {
      job(failed ? nullptr : &encoder_);
    } catch (...) {
      thrown = std::current_exception();
    }
    lock.lock();
    if (thrown && !error_) error_ = thrown;
    --running_;
    changed_.notify_all();
  }
}

void EncoderThread::rethrow() {
  if (error_) std::rethrow_exception(error_);
}

void EncoderThread::post(Job job) {
  const auto start = std::chrono::steady_clock::now();
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return jobs_.size() < queued_ || error_; });
  postWaits_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rethrow();
  jobs_.push_back(std::move(job));
  changed_.notify_all();
}

void EncoderThread::drain() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return jobs_.empty() && running_ == 0; });
  rethrow();
}

}  // namespace vitrine::host
