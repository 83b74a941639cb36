#pragma once
// SIGINT (Ctrl-C) and SIGTERM (a service manager, a test's kill) turned into a flag that the runs poll:
// the gallery's loop ends as Esc does (settings flushed, the device idled and destroyed in order), a
// headless --remote run writes its last frame, and a film's run throws at the next frame so every
// temporary is removed on the way out. The handler only sets the flag; one flag serves every mode.
#include <string_view>

namespace vitrine {

class StopOnSignal {
 public:
  StopOnSignal();   // catches SIGINT and SIGTERM from here on, the flag cleared
  ~StopOnSignal();  // gives them back their earlier handlers
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

  // True once either signal has come while a StopOnSignal was alive.
  static bool requested();
  // Throws vitrine::Error "Interrupted by SIGINT: WHAT" once a signal has come.
  static void check(std::string_view what);

 private:
  using Handler = void (*)(int);
  Handler previousInt_, previousTerm_;
};

}  // namespace vitrine
