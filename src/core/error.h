#pragma once
// The one error type for everything a user or the environment can get wrong: a sentence that says
// what was wrong and what would be right. main turns it into a message and a non-zero exit.
#include <stdexcept>
#include <string>
#include <system_error>

namespace vitrine {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The operating system's words for an errno value ("No space left on device"), for those sentences.
inline std::string osReason(int error) { return std::system_category().message(error); }

}  // namespace vitrine
