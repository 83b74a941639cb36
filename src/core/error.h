#pragma once
// The one error type for everything a user or the environment can get wrong: a sentence that says
// what was wrong and what would be right. main turns it into a message and a non-zero exit.
#include <stdexcept>

namespace vitrine {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace vitrine
