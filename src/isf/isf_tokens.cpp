#include "isf/isf_tokens.h"

#include <cctype>

namespace vitrine::isf {
namespace {
bool nameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool nameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
}  // namespace

std::vector<Token> tokenize(std::string_view s) {
  std::vector<Token> tokens;
  bool lineStart = true;  // only blanks since the last newline
  size_t i = 0;
  auto push = [&](Token::Kind kind, size_t end) {
    tokens.push_back({kind, s.substr(i, end - i)});
    i = end;
  };
  while (i < s.size()) {
    const char c = s[i];
    size_t j = i + 1;
    if (c == '\n') {
      push(Token::Kind::Newline, j);
      lineStart = true;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      while (j < s.size() && (s[j] == ' ' || s[j] == '\t' || s[j] == '\r' || s[j] == '\f' || s[j] == '\v')) ++j;
      push(Token::Kind::Blank, j);
      continue;
    }
    if (c == '#' && lineStart) {
      while (j < s.size() && s[j] != '\n') j += (s[j] == '\\' && j + 1 < s.size()) ? 2 : 1;
      push(Token::Kind::Directive, std::min(j, s.size()));
      continue;
    }
    lineStart = false;
    if (c == '/' && j < s.size() && s[j] == '/') {
      while (j < s.size() && s[j] != '\n') ++j;
      push(Token::Kind::Comment, j);
    } else if (c == '/' && j < s.size() && s[j] == '*') {
      const size_t end = s.find("*/", j + 1);
      push(Token::Kind::Comment, end == std::string_view::npos ? s.size() : end + 2);
    } else if (nameStart(c)) {
      while (j < s.size() && nameChar(s[j])) ++j;
      push(Token::Kind::Identifier, j);
    } else if (digit(c) || (c == '.' && j < s.size() && digit(s[j]))) {
      // Digits, '.', suffixes and exponents ("1.5e-3", "0x1Fu", "2.0lf"); a sign only right after an 'e'.
      while (j < s.size() && (nameChar(s[j]) || s[j] == '.' ||
                              ((s[j] == '+' || s[j] == '-') && (s[j - 1] == 'e' || s[j - 1] == 'E'))))
        ++j;
      push(Token::Kind::Number, j);
    } else {
      push(Token::Kind::Punct, j);
    }
  }
  return tokens;
}

}  // namespace vitrine::isf
