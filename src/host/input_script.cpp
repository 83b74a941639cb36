#include "host/input_script.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <utility>

// Only for the GLFW_KEY_* constants the scenes compare against; no GLFW function is called.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/bounded_file.h"
#include "core/error.h"
#include "core/printable.h"

namespace vitrine::host {
namespace {

constexpr std::uintmax_t kMaxScriptBytes = 1 << 20;
constexpr double kTimeSlack = 1e-6;  // seconds; see InputPlayer

struct NamedKey {
  std::string_view name;
  int key;
};

// Letters, digits and function keys are generated in keyFromName; these are the rest.
constexpr std::array kNamedKeys = {
    NamedKey{"space", GLFW_KEY_SPACE},
    NamedKey{"enter", GLFW_KEY_ENTER},
    NamedKey{"escape", GLFW_KEY_ESCAPE},
    NamedKey{"tab", GLFW_KEY_TAB},
    NamedKey{"backspace", GLFW_KEY_BACKSPACE},
    NamedKey{"left", GLFW_KEY_LEFT},
    NamedKey{"right", GLFW_KEY_RIGHT},
    NamedKey{"up", GLFW_KEY_UP},
    NamedKey{"down", GLFW_KEY_DOWN},
    NamedKey{"minus", GLFW_KEY_MINUS},
    NamedKey{"equal", GLFW_KEY_EQUAL},
    NamedKey{"comma", GLFW_KEY_COMMA},
    NamedKey{"period", GLFW_KEY_PERIOD},
    NamedKey{"slash", GLFW_KEY_SLASH},
    NamedKey{"semicolon", GLFW_KEY_SEMICOLON},
    NamedKey{"apostrophe", GLFW_KEY_APOSTROPHE},
    NamedKey{"grave", GLFW_KEY_GRAVE_ACCENT},
    NamedKey{"backslash", GLFW_KEY_BACKSLASH},
    NamedKey{"left_bracket", GLFW_KEY_LEFT_BRACKET},
    NamedKey{"right_bracket", GLFW_KEY_RIGHT_BRACKET},
};

constexpr std::array kFunctionKeys = {GLFW_KEY_F1, GLFW_KEY_F2, GLFW_KEY_F3, GLFW_KEY_F4,  GLFW_KEY_F5,  GLFW_KEY_F6,
                                      GLFW_KEY_F7, GLFW_KEY_F8, GLFW_KEY_F9, GLFW_KEY_F10, GLFW_KEY_F11, GLFW_KEY_F12};

std::string lowercase(std::string_view text) {
  std::string out(text);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return out;
}

size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// "did you mean 'escape'?" for a near miss, and always the list, so a typo is one look away.
std::string keyHint(std::string_view name) {
  std::string_view closest;
  size_t best = 3;  // farther than two edits is no longer a typo
  for (const NamedKey& known : kNamedKeys) {
    const bool prefix = name.size() >= 2 && known.name.starts_with(name);
    const size_t distance = prefix ? 0 : editDistance(name, known.name);
    if (distance < best) best = distance, closest = known.name;
  }
  std::string hint = closest.empty() ? "known keys: " : fmt::format("did you mean '{}'? Known keys: ", closest);
  hint += "a-z, 0-9, f1-f12";
  for (const NamedKey& known : kNamedKeys) hint += fmt::format(", {}", known.name);
  return hint;
}

std::vector<std::string_view> words(std::string_view line) {
  constexpr std::string_view kSpace = " \t\r\v\f";
  std::vector<std::string_view> out;
  for (size_t start = line.find_first_not_of(kSpace); start != std::string_view::npos;
       start = line.find_first_not_of(kSpace, start)) {
    const size_t end = std::min(line.find_first_of(kSpace, start), line.size());
    out.push_back(line.substr(start, end - start));
    start = end;
  }
  return out;
}

class LineParser {
 public:
  LineParser(std::string_view name, size_t line) : name_(name), line_(line) {}

  [[noreturn]] void fail(std::string_view reason) const {
    throw Error(fmt::format("{}:{}: {}", printable(name_), line_, reason));
  }

  double number(std::string_view what, std::string_view text) const {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    // from_chars reads "nan" and "inf" and reports overflow as out of range: all three are not finite.
    if ((ec != std::errc() && ec != std::errc::result_out_of_range) || end != text.data() + text.size())
      fail(fmt::format("{} '{}' is not a number", what, printable(text)));
    if (ec == std::errc::result_out_of_range || !std::isfinite(value))
      fail(fmt::format("{} '{}' is not a finite number", what, printable(text)));
    return value;
  }

  float coordinate(std::string_view what, std::string_view text) const {
    const double value = number(what, text);
    if (value < 0.0 || value > 1.0)
      fail(fmt::format("{} {} is outside 0..1 (normalised output coordinates, origin top-left)", what, printable(text)));
    return float(value);
  }

  void expectArguments(std::string_view verb, size_t got, size_t expected, std::string_view usage) const {
    if (got != expected)
      fail(fmt::format("'{}' takes {} argument{}{}, got {}", verb, expected, expected == 1 ? "" : "s", usage, got));
  }

 private:
  std::string_view name_;
  size_t line_;
};

}  // namespace

std::optional<int> keyFromName(std::string_view name) {
  const std::string lower = lowercase(name);
  if (lower.size() == 1 && lower[0] >= 'a' && lower[0] <= 'z') return GLFW_KEY_A + (lower[0] - 'a');
  if (lower.size() == 1 && lower[0] >= '0' && lower[0] <= '9') return GLFW_KEY_0 + (lower[0] - '0');
  if (lower.size() >= 2 && lower.size() <= 3 && lower[0] == 'f') {
    int n = 0;
    const auto [end, ec] = std::from_chars(lower.data() + 1, lower.data() + lower.size(), n);
    if (ec == std::errc() && end == lower.data() + lower.size() && lower[1] != '0' && n >= 1 && n <= 12)
      return kFunctionKeys[size_t(n - 1)];
  }
  for (const NamedKey& known : kNamedKeys)
    if (known.name == lower) return known.key;
  return std::nullopt;
}

InputScript parseInputScript(std::string_view text, std::string_view name) {
  InputScript script;
  script.name = name;
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 byte-order mark
  double previousTime = 0.0;
  size_t lineNumber = 0;
  while (!text.empty()) {
    const size_t newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    text = newline == std::string_view::npos ? std::string_view() : text.substr(newline + 1);
    ++lineNumber;
    line = line.substr(0, line.find('#'));
    const std::vector<std::string_view> word = words(line);
    if (word.empty()) continue;

    const LineParser parse(name, lineNumber);
    InputEvent event;
    event.line = lineNumber;
    event.time = parse.number("time", word[0]);
    if (event.time < 0.0) parse.fail(fmt::format("time {} is negative", printable(word[0])));
    if (event.time < previousTime)
      parse.fail(
          fmt::format("time {} is before the previous event's {}; times must not decrease", printable(word[0]),
                      previousTime));
    previousTime = event.time;
    if (word.size() < 2) parse.fail("expected a verb after the time: move, leave, down, up, wheel, key, hold, release or action");

    const std::string_view verb = word[1];
    const size_t arguments = word.size() - 2;
    if (verb == "move") {
      parse.expectArguments(verb, arguments, 2, " (X Y)");
      event.kind = InputEvent::Kind::Move;
      event.position = {parse.coordinate("X", word[2]), parse.coordinate("Y", word[3])};
    } else if (verb == "down" || verb == "up" || verb == "leave") {
      parse.expectArguments(verb, arguments, 0, "");
      event.kind = verb == "down" ? InputEvent::Kind::Down : verb == "up" ? InputEvent::Kind::Up : InputEvent::Kind::Leave;
    } else if (verb == "wheel") {
      parse.expectArguments(verb, arguments, 1, " (STEPS)");
      event.kind = InputEvent::Kind::Wheel;
      const double steps = parse.number("wheel steps", word[2]);
      if (std::abs(steps) > std::numeric_limits<float>::max())
        parse.fail(fmt::format("wheel steps {} are out of range", printable(word[2])));
      event.wheel = float(steps);
    } else if (verb == "key" || verb == "hold" || verb == "release") {
      parse.expectArguments(verb, arguments, 1, " (NAME)");
      event.kind = verb == "key" ? InputEvent::Kind::Key : verb == "hold" ? InputEvent::Kind::Hold : InputEvent::Kind::Release;
      const std::optional<int> key = keyFromName(word[2]);
      if (!key) parse.fail(fmt::format("unknown key '{}'; {}", printable(word[2]), keyHint(lowercase(word[2]))));
      event.key = *key;
    } else if (verb == "action") {
      if (arguments < 1) parse.fail("'action' takes the action's name, then its numbers");
      event.kind = InputEvent::Kind::Action;
      event.action.name = std::string(word[2]);
      for (size_t i = 3; i < word.size(); ++i) {
        const double value = parse.number("action argument", word[i]);
        if (std::abs(value) > std::numeric_limits<float>::max())
          parse.fail(fmt::format("action argument {} is out of range", printable(word[i])));
        event.action.args.push_back(float(value));
      }
    } else {
      parse.fail(fmt::format("unknown verb '{}'; expected move, leave, down, up, wheel, key, hold, release or action",
                             printable(word[1])));
    }
    script.events.push_back(event);
  }
  return script;
}

std::string whereInScript(const InputScript& script, const InputEvent& event, std::string_view reason) {
  return fmt::format("{}:{}: {}", printable(script.name), event.line, reason);
}

InputScript loadInputScript(const std::filesystem::path& path, std::string* text) {
  std::string bytes;
  try {
    bytes = readBoundedFile(path, kMaxScriptBytes);  // scripts are meant to be written by hand
  } catch (const FileRefused& refused) {
    throw Error(fmt::format("Cannot read input script {}: {}.", printable(path.string()), refused.why));
  }
  InputScript script = parseInputScript(bytes, path.string());
  if (text) *text = std::move(bytes);
  return script;
}

InputPlayer::InputPlayer(InputScript script) : script_(std::move(script)) {}

void InputPlayer::observe(VkExtent2D outputPixels, bool pressed, float wheel) {
  const glm::vec2 size(outputPixels.width, outputPixels.height);
  tracker_.observe(Pointer{position_ * size, outputPixels, held_, pressed, wheel, inside_}, /*menuWantsMouse=*/false);
}

StepInput InputPlayer::step(double stepTime, VkExtent2D outputPixels) {
  StepInput input;
  for (; next_ < script_.events.size() && script_.events[next_].time <= stepTime + kTimeSlack; ++next_) {
    const InputEvent& event = script_.events[next_];
    // Keys go straight to the scene, not through the mouse. A held key is pressed once, then held.
    if (event.kind == InputEvent::Kind::Key || event.kind == InputEvent::Kind::Hold) {
      input.keysPressed.push_back(event.key);
      if (event.kind == InputEvent::Kind::Hold && std::find(keysHeld_.begin(), keysHeld_.end(), event.key) == keysHeld_.end())
        keysHeld_.push_back(event.key);
      continue;
    }
    if (event.kind == InputEvent::Kind::Release) {
      std::erase(keysHeld_, event.key);
      continue;
    }
    if (event.kind == InputEvent::Kind::Action) {
      input.actions.push_back(event.action);
      continue;
    }
    if (event.kind == InputEvent::Kind::Move) position_ = event.position, inside_ = true;
    if (event.kind == InputEvent::Kind::Leave) inside_ = false;
    if (event.kind == InputEvent::Kind::Down) held_ = true;
    if (event.kind == InputEvent::Kind::Up) held_ = false;
    observe(outputPixels, event.kind == InputEvent::Kind::Down,
            event.kind == InputEvent::Kind::Wheel ? event.wheel : 0.0f);
  }
  observe(outputPixels, false, 0.0f);  // a step with no events still sees the cursor, at this output size
  input.cursor = tracker_.take();
  input.keysHeld = keysHeld_;
  return input;
}

}  // namespace vitrine::host
