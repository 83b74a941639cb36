#pragma once
// Points stderr at /dev/null for its lifetime. ALSA, JACK, PulseAudio and RtAudio print each probing
// failure straight to stderr (dozens of lines on a machine without sound); the device classes probe
// under one of these and print the one line a user needs themselves (audio/engine.cpp, live/).
namespace vitrine {

class HiddenStderr {
 public:
  HiddenStderr();
  ~HiddenStderr();  // stderr back as it was, everything written meanwhile dropped
  HiddenStderr(const HiddenStderr&) = delete;
  HiddenStderr& operator=(const HiddenStderr&) = delete;

 private:
  int saved_ = -1;
};

}  // namespace vitrine
