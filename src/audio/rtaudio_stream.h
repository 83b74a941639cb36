#pragma once
// What RtAudio's two streams share: the gallery's sound (audio/engine.cpp) and live audio input
// (live/audio_capture.cpp). Only those two include it, so RtAudio's API stays out of everyone else's
// compile lines (CMakeLists.txt).
#include "core/printable.h"

#include <RtAudio.h>

#include <string>

namespace vitrine::audio {

// Starts an opened stream: "" when it runs, else why not.
inline std::string startStream(RtAudio& audio) {
  audio.startStream();
  return audio.isStreamRunning() ? "" : "the stream did not start";
}

// For the catch (...) around opening a stream: the exception in flight as the one-line reason the
// stream did not open (RtAudio's message or the standard library's); anything else goes on up.
inline std::string openFailure() {
  try {
    throw;
  } catch (const RtAudioError& e) {
    return trimmed(e.getMessage());
  } catch (const std::exception& e) {
    return trimmed(e.what());
  }
}

// Stops the stream, dropping what is queued rather than playing it out, and closes it: for destructors,
// so it never throws (closing a stream that failed leaves nothing to do about it).
inline void closeStream(RtAudio& audio) noexcept {
  try {
    if (audio.isStreamRunning()) audio.abortStream();
    if (audio.isStreamOpen()) audio.closeStream();
  } catch (const RtAudioError&) {
  }
}

// Whether an error RtAudio reports from its own thread (a device unplugged, a sound server gone) has
// stopped the stream. It calls the stream's error callback for it; with none it would throw there and
// end the program.
inline bool stopsTheStream(RtAudioError::Type type) {
  return type != RtAudioError::WARNING && type != RtAudioError::DEBUG_WARNING;
}

}  // namespace vitrine::audio
