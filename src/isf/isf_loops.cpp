#include "isf/isf_loops.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace vitrine::isf {
namespace {

// The token before i that is not a blank, newline or comment; nothing when none.
const Token* previous(const std::vector<Token>& tokens, size_t i) {
  while (i-- > 0)
    if (!spacing(tokens[i])) return &tokens[i];
  return nullptr;
}

// The index of the bracket that closes the one at `open` ('(' or '{'); tokens.size() when none.
size_t closing(const std::vector<Token>& tokens, size_t open) {
  const std::string_view in = tokens[open].text, out = in == "(" ? ")" : "}";
  int depth = 0;
  for (size_t k = open; k < tokens.size(); ++k) {
    if (tokens[k].kind != Token::Kind::Punct) continue;
    if (tokens[k].text == in) ++depth;
    if (tokens[k].text == out && --depth == 0) return k;
  }
  return tokens.size();
}

bool is(const std::vector<Token>& tokens, size_t i, std::string_view text) {
  return i < tokens.size() && tokens[i].text == text;
}

// A decimal or hexadecimal literal with GLSL's suffixes; an octal one ("017") is left out.
std::optional<double> literal(std::string_view text) {
  while (!text.empty() && (text.back() == 'u' || text.back() == 'U' || text.back() == 'f' || text.back() == 'F' ||
                           ((text.back() == 'l' || text.back() == 'L') && text.size() > 2 && text[1] != 'x')))
    text.remove_suffix(1);
  if (text.size() > 1 && text[0] == '0' && text.find_first_of(".eExX") == std::string_view::npos) return std::nullopt;
  const std::string s(text);
  char* end = nullptr;
  const double value = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// [-] NUMBER, or a name the facts fix, at tokens[i] on; i moves past it.
std::optional<double> constant(const std::vector<Token>& tokens, size_t& i, const LoopFacts& facts) {
  i = nextWord(tokens, i);
  double sign = 1.0;
  if (is(tokens, i, "-")) sign = -1.0, i = nextWord(tokens, i + 1);
  if (i >= tokens.size()) return std::nullopt;
  std::optional<double> value;
  if (tokens[i].kind == Token::Kind::Number) value = literal(tokens[i].text);
  if (tokens[i].kind == Token::Kind::Identifier)
    if (const auto it = facts.constants.find(tokens[i].text); it != facts.constants.end()) value = it->second;
  if (!value) return std::nullopt;
  ++i;
  return sign * *value;
}

// Whether a macro's replacement assigns or steps something: "=" alone, an operator-assignment, ++ or --.
bool writes(std::string_view replacement) {
  for (size_t k = 0; k < replacement.size(); ++k) {
    const char c = replacement[k];
    if ((c == '+' || c == '-') && k + 1 < replacement.size() && replacement[k + 1] == c) return true;
    if (c != '=') continue;
    if (k + 1 < replacement.size() && replacement[k + 1] == '=') {
      ++k;  // "==": a comparison
      continue;
    }
    if (k > 0 && (replacement[k - 1] == '!' || replacement[k - 1] == '=')) continue;
    if (k > 0 && (replacement[k - 1] == '<' || replacement[k - 1] == '>') &&
        !(k > 1 && replacement[k - 2] == replacement[k - 1]))
      continue;  // "<=" and ">=", but "<<=" and ">>=" assign
    return true;
  }
  return false;
}

// Whether the body's use of the counter at tokens[k] may change it: an assignment, an
// operator-assignment, ++ or -- before or after.
bool writtenAt(const std::vector<Token>& tokens, size_t k) {
  const auto adjacent = [&](size_t at, std::string_view text) { return is(tokens, at, text); };
  const size_t after = nextWord(tokens, k + 1);
  if (after < tokens.size()) {
    const std::string_view op = tokens[after].text;
    if (op == "=" && !adjacent(after + 1, "=")) return true;
    if ((op == "+" || op == "-") && adjacent(after + 1, op)) return true;
    if ((op == "+" || op == "-" || op == "*" || op == "/" || op == "%" || op == "&" || op == "|" || op == "^") &&
        adjacent(after + 1, "="))
      return true;
    if ((op == "<" || op == ">") && adjacent(after + 1, op) && adjacent(after + 2, "=")) return true;
  }
  size_t before = k;
  while (before > 0 && spacing(tokens[before - 1])) --before;
  return before >= 2 && (tokens[before - 1].text == "+" || tokens[before - 1].text == "-") &&
         tokens[before - 2].text == tokens[before - 1].text;
}

}  // namespace

LoopFacts loopFacts(const std::vector<Token>& tokens) {
  LoopFacts facts;
  int braces = 0, parens = 0;
  std::string function;  // the name before the '(' of a declaration at file scope
  std::map<std::string, size_t, std::less<>> definedAt;  // each const's name, where its declaration names it
  for (size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (t.kind == Token::Kind::Directive) {
      // #define NAME [-]NUMBER, or a macro whose replacement writes (a loop that uses one is guarded).
      const std::vector<Token> words = tokenize(t.text.substr(1));
      size_t k = nextWord(words, 0);
      if (!is(words, k, "define")) continue;
      k = nextWord(words, k + 1);
      if (k >= words.size() || words[k].kind != Token::Kind::Identifier) continue;
      const std::string name(words[k].text);
      const std::string_view replacement = t.text.substr(static_cast<size_t>(words[k].text.data() - t.text.data()) +
                                                         words[k].text.size());
      if (writes(replacement)) facts.writingMacros.insert(name);
      size_t v = k + 1;
      if (const auto value = constant(words, v, facts); value && nextWord(words, v) == words.size())
        facts.constants[name] = *value;
      continue;
    }
    if (t.kind != Token::Kind::Identifier && t.kind != Token::Kind::Punct) continue;
    if (t.text == "{") ++braces;
    if (t.text == "}") --braces;
    if (t.text == "(" && braces == 0 && parens++ == 0) {
      const Token* name = previous(tokens, i);
      function = name && name->kind == Token::Kind::Identifier ? std::string(name->text) : std::string();
    }
    if (t.text == ")" && braces == 0 && parens > 0) --parens;
    if (braces == 0 && parens > 0 && (t.text == "out" || t.text == "inout") && !function.empty())
      facts.writingFunctions.insert(function);
    // const TYPE NAME = [-]NUMBER ;
    if (t.text == "const") {
      size_t k = nextWord(tokens, i + 1);
      if (k >= tokens.size() || tokens[k].kind != Token::Kind::Identifier) continue;
      k = nextWord(tokens, k + 1);
      if (k >= tokens.size() || tokens[k].kind != Token::Kind::Identifier) continue;
      const std::string name(tokens[k].text);
      const size_t at = k;
      k = nextWord(tokens, k + 1);
      if (!is(tokens, k, "=")) continue;
      ++k;
      if (const auto value = constant(tokens, k, facts); value && is(tokens, nextWord(tokens, k), ";")) {
        facts.constants[name] = *value;
        definedAt[name] = at;
      }
    }
  }
  // A name is a constant only where nothing else declares it (a parameter, a local of that name) or
  // writes it: a loop tested against one of those has no fixed count.
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (tokens[i].kind != Token::Kind::Identifier) continue;
    const auto it = facts.constants.find(tokens[i].text);
    if (it == facts.constants.end()) continue;
    if (const auto defined = definedAt.find(it->first); defined != definedAt.end() && defined->second == i) continue;
    const Token* before = previous(tokens, i);
    const bool declared = before && before->kind == Token::Kind::Identifier && before->text != "return" &&
                          before->text != "case";
    if (declared || writtenAt(tokens, i)) facts.constants.erase(it);
  }
  return facts;
}

std::optional<BoundedLoop> boundedLoop(const std::vector<Token>& tokens, size_t forIndex, const LoopFacts& facts,
                                       int maxTrips) {
  size_t i = nextWord(tokens, forIndex + 1);
  if (!is(tokens, i, "(")) return std::nullopt;
  // The start: TYPE NAME = CONSTANT ;
  i = nextWord(tokens, i + 1);
  if (is(tokens, i, "highp") || is(tokens, i, "mediump") || is(tokens, i, "lowp")) i = nextWord(tokens, i + 1);
  const bool integer = is(tokens, i, "int");  // not uint: a count down past 0 wraps and never ends
  if (!integer && !is(tokens, i, "float")) return std::nullopt;
  i = nextWord(tokens, i + 1);
  if (i >= tokens.size() || tokens[i].kind != Token::Kind::Identifier) return std::nullopt;
  const std::string_view counter = tokens[i].text;
  i = nextWord(tokens, i + 1);
  if (!is(tokens, i, "=")) return std::nullopt;
  ++i;
  const std::optional<double> start = constant(tokens, i, facts);
  i = nextWord(tokens, i);
  if (!start || !is(tokens, i, ";")) return std::nullopt;
  // The test: COUNTER (< | <= | > | >= | !=) CONSTANT ;
  i = nextWord(tokens, i + 1);
  if (!is(tokens, i, counter)) return std::nullopt;
  i = nextWord(tokens, i + 1);
  if (i >= tokens.size()) return std::nullopt;
  std::string op(tokens[i].text);
  if (op != "<" && op != ">" && op != "!") return std::nullopt;
  if (is(tokens, i + 1, "=")) op += "=", ++i;
  if (op == "!") return std::nullopt;
  ++i;
  const std::optional<double> bound = constant(tokens, i, facts);
  i = nextWord(tokens, i);
  if (!bound || !is(tokens, i, ";")) return std::nullopt;
  // The step: ++C, --C, C++, C--, C += CONSTANT, C -= CONSTANT.
  i = nextWord(tokens, i + 1);
  double step = 0.0;
  if ((is(tokens, i, "+") || is(tokens, i, "-")) && is(tokens, i + 1, tokens[i].text)) {
    step = tokens[i].text == "+" ? 1.0 : -1.0;
    i = nextWord(tokens, i + 2);
    if (!is(tokens, i, counter)) return std::nullopt;
    i = nextWord(tokens, i + 1);
  } else if (is(tokens, i, counter)) {
    i = nextWord(tokens, i + 1);
    if (i + 1 >= tokens.size() || (tokens[i].text != "+" && tokens[i].text != "-")) return std::nullopt;
    const double sign = tokens[i].text == "+" ? 1.0 : -1.0;
    if (is(tokens, i + 1, tokens[i].text)) {
      step = sign;
      i = nextWord(tokens, i + 2);
    } else if (is(tokens, i + 1, "=")) {
      i += 2;
      const std::optional<double> by = constant(tokens, i, facts);
      if (!by || *by <= 0.0) return std::nullopt;
      step = sign * *by;
      i = nextWord(tokens, i);
    } else {
      return std::nullopt;
    }
  } else {
    return std::nullopt;
  }
  if (!is(tokens, i, ")")) return std::nullopt;
  i = nextWord(tokens, i + 1);
  if (!is(tokens, i, "{")) return std::nullopt;
  const size_t bodyStart = i;

  // The body, to its closing brace: writing neither the counter nor through anything that may.
  const size_t end = closing(tokens, bodyStart);
  if (end >= tokens.size()) return std::nullopt;
  for (size_t k = bodyStart; k < end; ++k) {
    const Token& t = tokens[k];
    if (t.kind == Token::Kind::Directive) return std::nullopt;
    if (t.kind != Token::Kind::Identifier) continue;
    if (facts.writingFunctions.count(t.text) || facts.writingMacros.count(t.text)) return std::nullopt;
    if (t.text != counter) continue;
    const Token* before = previous(tokens, k);
    if (before && before->text == ".") continue;  // a member of that name
    if (writtenAt(tokens, k)) return std::nullopt;
  }

  // Iterations: from start towards the bound by step; none when the step leads away from it.
  const double a = *start, b = *bound;
  double trips = 0.0;
  if (op == "<" || op == "<=") {
    if (step <= 0.0) return std::nullopt;
    trips = op == "<" ? std::ceil((b - a) / step) : std::floor((b - a) / step) + 1.0;
  } else if (op == ">" || op == ">=") {
    if (step >= 0.0) return std::nullopt;
    trips = op == ">" ? std::ceil((a - b) / -step) : std::floor((a - b) / -step) + 1.0;
  } else {  // "!=": only an integer counter that lands on the bound
    const double steps = (b - a) / step;
    if (!integer || steps < 0.0 || steps != std::floor(steps)) return std::nullopt;
    trips = steps;
  }
  trips = std::max(trips, 0.0);
  if (!integer) {
    // A float counter's sums round. With a step of at least 4 of the float's ulps at the largest value
    // the counter sees, each sum moves it by at least 7/8 of the step: a few more trips, never endless.
    const float largest = static_cast<float>(std::max(std::abs(a), std::abs(b)));
    const double ulp = double(std::nextafter(largest, std::numeric_limits<float>::infinity())) - double(largest);
    if (std::abs(step) < 4.0 * ulp) return std::nullopt;
    trips = std::ceil(trips * 8.0 / 7.0) + 1.0;
  }
  if (trips > maxTrips) return std::nullopt;
  return BoundedLoop{static_cast<int>(trips), bodyStart, end};
}

namespace {


class Worst {
 public:
  Worst(const std::vector<Token>& tokens, const LoopFacts& facts, long long cap)
      : tokens_(tokens), facts_(facts), cap_(cap) {
    // Function definitions at file scope: NAME ( ... ) { ... }, each overload's body.
    int braces = 0;
    for (size_t i = 0; i < tokens.size(); ++i) {
      const Token& t = tokens[i];
      if (t.kind == Token::Kind::Punct && t.text == "{") ++braces;
      if (t.kind == Token::Kind::Punct && t.text == "}") --braces;
      if (braces != 0 || t.kind != Token::Kind::Identifier) continue;
      const size_t open = nextWord(tokens, i + 1);
      if (!is(tokens, open, "(")) continue;
      const size_t close = closing(tokens, open);
      const size_t body = close < tokens.size() ? nextWord(tokens, close + 1) : tokens.size();
      if (!is(tokens, body, "{")) continue;
      const size_t end = closing(tokens, body);
      if (end >= tokens.size()) continue;
      bodies_[std::string(t.text)].push_back({body + 1, end});
      i = end;
    }
  }

  bool known(std::string_view name) const { return bodies_.count(std::string(name)) > 0; }

  std::optional<long long> ofFunction(const std::string& name) {
    if (const auto it = done_.find(name); it != done_.end()) return it->second;
    if (!open_.insert(name).second) return std::nullopt;  // a cycle: not GLSL, and not followed
    long long most = 0;
    for (const auto& [from, to] : bodies_.at(name)) {
      const std::optional<long long> cost = ofRange(from, to);
      if (!cost) return std::nullopt;
      most = std::max(most, *cost);
    }
    open_.erase(name);
    return done_[name] = most;
  }

 private:
  long long add(long long a, long long b) const { return std::min(cap_, a + b); }
  long long times(long long a, long long b) const { return b != 0 && a > cap_ / b ? cap_ : std::min(cap_, a * b); }

  // Tokens [from, to): every loop there and every call of a function the text defines.
  std::optional<long long> ofRange(size_t from, size_t to) {
    long long cost = 0;
    for (size_t k = from; k < to; ++k) {
      const Token& t = tokens_[k];
      if (t.kind != Token::Kind::Identifier) continue;
      if (t.text == "while" || t.text == "do") return std::nullopt;
      if (t.text == "for") {
        const std::optional<BoundedLoop> loop = boundedLoop(tokens_, k, facts_, int(std::min<long long>(cap_, 1 << 30)));
        if (!loop) return std::nullopt;
        const std::optional<long long> body = ofRange(loop->bodyStart + 1, loop->bodyEnd);
        if (!body) return std::nullopt;
        cost = add(cost, times(loop->trips, 1 + *body));
        k = loop->bodyEnd;
        continue;
      }
      if (known(t.text) && is(tokens_, nextWord(tokens_, k + 1), "(")) {
        const std::optional<long long> call = ofFunction(std::string(t.text));
        if (!call) return std::nullopt;
        cost = add(cost, *call);
      }
    }
    return cost;
  }

  const std::vector<Token>& tokens_;
  const LoopFacts& facts_;
  long long cap_;
  std::map<std::string, std::vector<std::pair<size_t, size_t>>> bodies_;
  std::map<std::string, long long> done_;
  std::set<std::string> open_;
};

}  // namespace

std::optional<long long> worstIterations(const std::vector<Token>& tokens, const LoopFacts& facts,
                                         std::string_view entry, long long cap) {
  Worst worst(tokens, facts, cap);
  if (!worst.known(entry)) return std::nullopt;
  // A macro that holds a loop or names a function hides work from the count.
  for (const Token& t : tokens) {
    if (t.kind != Token::Kind::Directive) continue;
    for (const Token& word : tokenize(t.text.substr(1)))
      if (word.kind == Token::Kind::Identifier &&
          (word.text == "for" || word.text == "while" || word.text == "do" || worst.known(word.text)))
        return std::nullopt;
  }
  return worst.ofFunction(std::string(entry));
}

}  // namespace vitrine::isf
