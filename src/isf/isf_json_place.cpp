#include "isf/isf_json_place.h"

namespace vitrine::isf {
namespace {

class Walker {
 public:
  explicit Walker(std::string_view s) : s_(s) {}

  size_t place(const JsonPath& path) {
    skipBlanks();
    size_t found = pos_;
    for (const auto& step : path) {
      if (!descend(step)) return found;
      skipBlanks();
      found = pos_;
    }
    return found;
  }

 private:
  void skipBlanks() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' || s_[pos_] == '\r')) ++pos_;
  }
  // Past a string starting at pos_ (on its opening quote); returns its raw text.
  std::string_view string() {
    const size_t start = ++pos_;
    while (pos_ < s_.size() && s_[pos_] != '"') pos_ += s_[pos_] == '\\' ? 2 : 1;
    const std::string_view text = s_.substr(start, std::min(pos_, s_.size()) - start);
    ++pos_;
    return text;
  }
  // Past one value; iterative over nesting, so no input can exhaust the stack.
  void skipValue() {
    skipBlanks();
    int depth = 0;
    while (pos_ < s_.size()) {
      const char c = s_[pos_];
      if (c == '"') {
        string();
      } else if (c == '[' || c == '{') {
        ++depth, ++pos_;
      } else if (c == ']' || c == '}') {
        if (depth == 0) return;
        --depth, ++pos_;
      } else if (c == ',' && depth == 0) {
        return;
      } else {
        ++pos_;
      }
      if (depth == 0 && (c == '"' || c == ']' || c == '}')) return;
    }
  }
  // Moves pos_ onto the value the step names, inside the container at pos_.
  bool descend(const std::variant<std::string, size_t>& step) {
    if (pos_ >= s_.size()) return false;
    const char open = s_[pos_];
    if (open != '{' && open != '[') return false;
    ++pos_;
    for (size_t index = 0;; ++index) {
      skipBlanks();
      if (pos_ >= s_.size() || s_[pos_] == '}' || s_[pos_] == ']') return false;
      if (open == '{') {
        if (s_[pos_] != '"') return false;
        const std::string_view key = string();
        skipBlanks();
        if (pos_ >= s_.size() || s_[pos_] != ':') return false;
        ++pos_;
        skipBlanks();
        if (const auto* wanted = std::get_if<std::string>(&step); wanted && *wanted == key) return true;
      } else if (const auto* wanted = std::get_if<size_t>(&step); wanted && *wanted == index) {
        return true;
      }
      skipValue();
      skipBlanks();
      if (pos_ >= s_.size() || s_[pos_] != ',') return false;
      ++pos_;
    }
  }

  std::string_view s_;
  size_t pos_ = 0;
};

}  // namespace

size_t jsonPlace(std::string_view json, const JsonPath& path) { return Walker(json).place(path); }

}  // namespace vitrine::isf
