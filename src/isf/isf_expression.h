#pragma once
// The sizes a pass's WIDTH and HEIGHT give, as ISF writes them: "$WIDTH/2.0", "floor($HEIGHT*0.5)+1",
// "max($WIDTH,$blurAmount*10)". A small, bounded language: numbers, + - * /, unary minus, parentheses,
// $WIDTH, $HEIGHT and $input for a numeric input, and the functions floor ceil round min max abs pow
// sqrt. Parsed once when the file loads (so a typo is refused with the file's line), evaluated each
// time the render size or an input it names changes.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::isf {

inline constexpr size_t kMaxExpressionBytes = 256;  // longer than any real size expression
inline constexpr int kMaxExpressionDepth = 32;      // nesting of parentheses, calls and unary minus
inline constexpr int kMaxTargetSide = 16384;        // pixels: Vulkan's guaranteed maxImageDimension2D is 4096; GPUs give 16384+

struct ExpressionNode;

class Expression {
 public:
  // Throws vitrine::Error with the reason (no file or line: the caller knows them).
  static Expression parse(std::string_view text);

  Expression(const Expression&);
  Expression& operator=(const Expression&);
  Expression(Expression&&) noexcept;
  Expression& operator=(Expression&&) noexcept;
  ~Expression();

  // The $names it reads, without the '$' ("WIDTH", "blurAmount"), each once, in order of appearance.
  const std::vector<std::string>& variables() const { return variables_; }
  // The value; a variable the lookup does not know reads as nullopt and the evaluation fails.
  std::optional<double> evaluate(const std::function<std::optional<double>(std::string_view)>& lookup) const;
  const std::string& text() const { return text_; }

 private:
  Expression() = default;
  std::unique_ptr<ExpressionNode> root_;
  std::vector<std::string> variables_;
  std::string text_;
};

// A size from an expression's value: NaN or infinity is refused (nullopt, with the reason in *why);
// a value below 1 is raised to 1 and one above kMaxTargetSide lowered to it, with *why saying so.
// Fractions are dropped, as a GL host's integer cast does.
std::optional<int> sizeFromValue(double value, std::string* why);

}  // namespace vitrine::isf
