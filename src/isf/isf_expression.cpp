#include "isf/isf_expression.h"

#include "core/error.h"
#include "core/printable.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace vitrine::isf {

struct ExpressionNode {
  enum class Op { Number, Variable, Negate, Add, Subtract, Multiply, Divide, Call };
  Op op = Op::Number;
  double number = 0.0;
  std::string name;  // Variable: without '$'; Call: the function
  std::vector<std::unique_ptr<ExpressionNode>> args;

  std::unique_ptr<ExpressionNode> clone() const {
    auto copy = std::make_unique<ExpressionNode>();
    copy->op = op;
    copy->number = number;
    copy->name = name;
    for (const auto& arg : args) copy->args.push_back(arg->clone());
    return copy;
  }
};

namespace {

using Node = ExpressionNode;
using Op = ExpressionNode::Op;

struct Function {
  std::string_view name;
  size_t arity;
};
constexpr Function kFunctions[] = {{"floor", 1}, {"ceil", 1}, {"round", 1}, {"abs", 1}, {"sqrt", 1},
                                   {"min", 2},   {"max", 2},  {"pow", 2}};

bool isNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Recursive descent over: sum := product (('+'|'-') product)*; product := unary (('*'|'/') unary)*;
// unary := '-' unary | '+' unary | primary; primary := number | $name | name '(' args ')' | '(' sum ')'.
class Parser {
 public:
  Parser(std::string_view text, std::vector<std::string>& variables) : text_(text), variables_(variables) {}

  std::unique_ptr<Node> parseAll() {
    auto node = sum(0);
    skipBlanks();
    if (pos_ < text_.size()) fail(fmt::format("'{}' is not expected here", printable(text_.substr(pos_, 1))));
    return node;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw Error(fmt::format("the size expression \"{}\" does not parse: {} (at character {})", printable(text_), why,
                            pos_ + 1));
  }
  void skipBlanks() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
  }
  bool accept(char c) {
    skipBlanks();
    if (pos_ < text_.size() && text_[pos_] == c) return ++pos_, true;
    return false;
  }
  void enter(int depth) const {
    if (depth > kMaxExpressionDepth) fail(fmt::format("it nests deeper than {} levels", kMaxExpressionDepth));
  }

  std::unique_ptr<Node> binary(Op op, std::unique_ptr<Node> left, std::unique_ptr<Node> right) {
    auto node = std::make_unique<Node>();
    node->op = op;
    node->args.push_back(std::move(left));
    node->args.push_back(std::move(right));
    return node;
  }

  std::unique_ptr<Node> sum(int depth) {
    enter(depth);
    auto left = product(depth + 1);
    for (;;) {
      if (accept('+')) left = binary(Op::Add, std::move(left), product(depth + 1));
      else if (accept('-')) left = binary(Op::Subtract, std::move(left), product(depth + 1));
      else return left;
    }
  }

  std::unique_ptr<Node> product(int depth) {
    auto left = unary(depth);
    for (;;) {
      if (accept('*')) left = binary(Op::Multiply, std::move(left), unary(depth));
      else if (accept('/')) left = binary(Op::Divide, std::move(left), unary(depth));
      else return left;
    }
  }

  std::unique_ptr<Node> unary(int depth) {
    enter(depth);
    if (accept('-')) {
      auto node = std::make_unique<Node>();
      node->op = Op::Negate;
      node->args.push_back(unary(depth + 1));
      return node;
    }
    if (accept('+')) return unary(depth + 1);
    return primary(depth);
  }

  std::unique_ptr<Node> primary(int depth) {
    skipBlanks();
    if (pos_ >= text_.size()) fail("it ends where a value is expected");
    const char c = text_[pos_];
    if (c == '(') {
      ++pos_;
      auto inner = sum(depth + 1);
      if (!accept(')')) fail("a ')' is missing");
      return inner;
    }
    if (c == '$') {
      ++pos_;
      const size_t start = pos_;
      if (pos_ >= text_.size() || !isNameStart(text_[pos_])) fail("'$' is not followed by a name");
      while (pos_ < text_.size() && isNameChar(text_[pos_])) ++pos_;
      auto node = std::make_unique<Node>();
      node->op = Op::Variable;
      node->name = std::string(text_.substr(start, pos_ - start));
      if (std::find(variables_.begin(), variables_.end(), node->name) == variables_.end())
        variables_.push_back(node->name);
      return node;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (isNameStart(c)) return call(depth);
    fail(fmt::format("'{}' is not expected here", printable(text_.substr(pos_, 1))));
  }

  std::unique_ptr<Node> number() {
    // strtod on a bounded copy: the text is not NUL-terminated, and strtod would also read "inf", "nan"
    // and hexadecimal, which only digits, one '.' and an exponent reach here.
    const size_t start = pos_;
    while (pos_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.')) ++pos_;
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      size_t p = pos_ + 1;
      if (p < text_.size() && (text_[p] == '+' || text_[p] == '-')) ++p;
      if (p < text_.size() && std::isdigit(static_cast<unsigned char>(text_[p]))) {
        pos_ = p;
        while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      }
    }
    const std::string digits(text_.substr(start, pos_ - start));
    if (std::count(digits.begin(), digits.end(), '.') > 1 || digits == ".") fail(fmt::format("\"{}\" is not a number", digits));
    auto node = std::make_unique<Node>();
    node->number = std::strtod(digits.c_str(), nullptr);
    return node;
  }

  std::unique_ptr<Node> call(int depth) {
    const size_t start = pos_;
    while (pos_ < text_.size() && isNameChar(text_[pos_])) ++pos_;
    const std::string_view name = text_.substr(start, pos_ - start);
    const auto* function = std::find_if(std::begin(kFunctions), std::end(kFunctions),
                                        [&](const Function& f) { return f.name == name; });
    if (function == std::end(kFunctions))
      fail(fmt::format("\"{}\" is not a function it knows (floor ceil round min max abs pow sqrt), and a "
                       "variable is written with '$'", printable(name)));
    auto node = std::make_unique<Node>();
    node->op = Op::Call;
    node->name = std::string(name);
    if (!accept('(')) fail(fmt::format("{} is not followed by '('", name));
    node->args.push_back(sum(depth + 1));
    while (accept(',')) node->args.push_back(sum(depth + 1));
    if (!accept(')')) fail(fmt::format("a ')' is missing after the arguments of {}", name));
    if (node->args.size() != function->arity)
      fail(fmt::format("{} takes {} argument{}, not {}", name, function->arity, function->arity == 1 ? "" : "s",
                       node->args.size()));
    return node;
  }

  std::string_view text_;
  std::vector<std::string>& variables_;
  size_t pos_ = 0;
};

using Lookup = std::function<std::optional<double>(std::string_view)>;

std::optional<double> evaluateNode(const Node& node, const Lookup& lookup) {
  if (node.op == Op::Number) return node.number;
  if (node.op == Op::Variable) return lookup(node.name);
  std::vector<double> values;
  for (const auto& arg : node.args) {
    const auto value = evaluateNode(*arg, lookup);
    if (!value) return std::nullopt;
    values.push_back(*value);
  }
  switch (node.op) {
    case Op::Negate: return -values[0];
    case Op::Add: return values[0] + values[1];
    case Op::Subtract: return values[0] - values[1];
    case Op::Multiply: return values[0] * values[1];
    case Op::Divide: return values[0] / values[1];  // x/0 is infinity or NaN, which sizeFromValue refuses
    default: break;
  }
  const std::string& f = node.name;
  if (f == "floor") return std::floor(values[0]);
  if (f == "ceil") return std::ceil(values[0]);
  if (f == "round") return std::round(values[0]);
  if (f == "abs") return std::fabs(values[0]);
  if (f == "sqrt") return std::sqrt(values[0]);
  if (f == "min") return std::min(values[0], values[1]);
  if (f == "max") return std::max(values[0], values[1]);
  return std::pow(values[0], values[1]);
}

}  // namespace

Expression Expression::parse(std::string_view text) {
  if (text.size() > kMaxExpressionBytes)
    throw Error(fmt::format("the size expression is {} bytes long; at most {} are read", text.size(), kMaxExpressionBytes));
  Expression expression;
  expression.text_ = std::string(text);
  Parser parser(expression.text_, expression.variables_);
  expression.root_ = parser.parseAll();
  return expression;
}

Expression::Expression(const Expression& other)
    : root_(other.root_ ? other.root_->clone() : nullptr), variables_(other.variables_), text_(other.text_) {}
Expression& Expression::operator=(const Expression& other) {
  if (this != &other) *this = Expression(other);
  return *this;
}
Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;
Expression::~Expression() = default;

std::optional<double> Expression::evaluate(const Lookup& lookup) const {
  return root_ ? evaluateNode(*root_, lookup) : std::nullopt;
}

std::optional<int> sizeFromValue(double value, std::string* why) {
  auto say = [&](std::string text) {
    if (why) *why = std::move(text);
  };
  say("");
  if (!std::isfinite(value)) {
    say(fmt::format("the size is {}, not a number of pixels", std::isnan(value) ? "not a number" : "infinite"));
    return std::nullopt;
  }
  if (value < 1.0) {
    say(fmt::format("the size {:g} is raised to 1 pixel", value));
    return 1;
  }
  if (value > kMaxTargetSide) {
    say(fmt::format("the size {:g} is lowered to {} pixels, the largest side a buffer may have", value, kMaxTargetSide));
    return kMaxTargetSide;
  }
  return static_cast<int>(value);
}

}  // namespace vitrine::isf
