#pragma once
// The page of text the glass refracts by default, as the original refracts its own README: a title
// and a few paragraphs set in a column, wrapped once in em so the page looks the same at any size.
#include "text/font.h"

#include <string>
#include <vector>

namespace vitrine::glass {

struct PageLine {
  std::string text;
  bool title = false;
  float baselineEm = 0.0f;  // from the top of the column, in body em
};

inline constexpr float kPageColumnEm = 34.0f;  // the column's width in body em
inline constexpr float kPageTitleScale = 2.2f;  // title em per body em

// Wraps the page's paragraphs to the column, measuring words with `measure(text, title)` in em of
// their own font size.
template <typename Measure> std::vector<PageLine> wrapPage(const std::vector<std::string>& paragraphs, Measure measure);

// The page's own words: what the scene is, in the scene's voice.
const std::vector<std::string>& pageParagraphs();

template <typename Measure>
std::vector<PageLine> wrapPage(const std::vector<std::string>& paragraphs, Measure measure) {
  std::vector<PageLine> lines;
  float y = kPageTitleScale;  // the title's first baseline
  bool first = true;
  for (const std::string& paragraph : paragraphs) {
    const bool title = first;
    const float scale = title ? kPageTitleScale : 1.0f;
    std::string line;
    size_t start = 0;
    while (start <= paragraph.size()) {
      size_t end = paragraph.find(' ', start);
      if (end == std::string::npos) end = paragraph.size();
      const std::string word = paragraph.substr(start, end - start);
      const std::string candidate = line.empty() ? word : line + " " + word;
      if (!line.empty() && measure(candidate, title) * scale > kPageColumnEm) {
        lines.push_back({line, title, y});
        y += 1.45f * scale;
        line = word;
      } else {
        line = candidate;
      }
      start = end + 1;
    }
    if (!line.empty()) lines.push_back({line, title, y});
    y += (title ? 1.6f : 2.2f) * scale;
    first = false;
  }
  return lines;
}

}  // namespace vitrine::glass
