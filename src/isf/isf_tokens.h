#pragma once
// GLSL text cut into tokens just finely enough to rewrite it without parsing it: identifiers, numbers,
// comments, preprocessor lines, newlines and single characters. Joining every token's text gives the
// input back byte for byte, so a rewrite that changes only some tokens keeps every line where it was.
#include <string_view>
#include <vector>

namespace vitrine::isf {

struct Token {
  enum class Kind { Identifier, Number, Comment, Directive, Newline, Blank, Punct };
  Kind kind = Kind::Punct;
  std::string_view text;  // a view of the input: valid while the input is
};

// Comments run to their end (an unterminated /* to the end of the text); a directive is a line whose
// first non-blank character is '#', up to its newline (a backslash-newline continues it).
std::vector<Token> tokenize(std::string_view glsl);

// Blanks, newlines and comments: what the rewrites step over.
inline bool spacing(const Token& t) {
  return t.kind == Token::Kind::Blank || t.kind == Token::Kind::Newline || t.kind == Token::Kind::Comment;
}
// The index of the first token at or after i that is not spacing; tokens.size() when none.
inline size_t nextWord(const std::vector<Token>& tokens, size_t i) {
  while (i < tokens.size() && spacing(tokens[i])) ++i;
  return i;
}

}  // namespace vitrine::isf
