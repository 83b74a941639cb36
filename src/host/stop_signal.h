#pragma once
// Ctrl-C and SIGTERM during a film's run: the run ends at the next frame by throwing, so every
// temporary is removed on the way out, rather than dying with a half-written film beside the target.
#include <string_view>

namespace vitrine::host {

class StopOnSignal {
 public:
  StopOnSignal();   // catches SIGINT and SIGTERM from here on
  ~StopOnSignal();  // gives them back their earlier handlers
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

  // True once either signal has come.
  bool requested() const;
  // Throws vitrine::Error "Interrupted by SIGINT: WHAT" once a signal has come.
  void check(std::string_view what) const;

 private:
  using Handler = void (*)(int);
  Handler previousInt_, previousTerm_;
};

}  // namespace vitrine::host
