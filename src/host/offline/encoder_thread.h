#pragma once
// A film's encoder on a thread of its own, so the next frames render while the last ones are converted
// and encoded: jobs (a frame, a stretch of sound) run in the order posted. A job that throws stops the
// encoding; the later jobs still run, given no encoder, to hand back what they hold (a frame's slot),
// and the error is thrown on the posting thread at its next post() or drain().
#include "film/video_encoder.h"

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace vitrine::host {

class EncoderThread {
 public:
  // A job gets the encoder, or null once an earlier job has failed.
  using Job = std::function<void(film::VideoEncoder*)>;

  // At most `queued` jobs wait at once: post() waits for room, so memory stays flat.
  EncoderThread(film::VideoEncoder& encoder, size_t queued);
  ~EncoderThread();  // runs what is left without the encoder, then joins
  EncoderThread(const EncoderThread&) = delete;
  EncoderThread& operator=(const EncoderThread&) = delete;

  void post(Job job);
  // Waits until every job posted has run; throws the first job's error.
  void drain();
  double postWaits() const { return postWaits_; }  // seconds post() waited for room

 private:
  film::VideoEncoder& encoder_;
  size_t queued_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> jobs_;
  size_t running_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
  double postWaits_ = 0.0;
  std::thread thread_;  // last: started once the rest is ready
  void run();
  void rethrow();
};

}  // namespace vitrine::host
