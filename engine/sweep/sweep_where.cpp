// Parsing and testing --where: a row filter over the values a sweep varies.
#include "engine/sweep/sweep_where.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <string_view>
#include <utility>

#include "engine/base/text.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {
namespace {

using Op = WhereCondition::Op;

constexpr std::array<std::pair<std::string_view, Op>, 6> kOps{{{"<=", Op::less_equal},
                                                               {">=", Op::greater_equal},
                                                               {"==", Op::equal},
                                                               {"!=", Op::not_equal},
                                                               {"<", Op::less},
                                                               {">", Op::greater}}};
constexpr const char* kForm =
    "A OP B (OP one of <=, <, >=, >, ==, !=; A and B a varied key, a number or NUMBER*KEY)";

std::string_view op_text(Op op) {
  for (const auto& [text, o] : kOps) {
    if (o == op) return text;
  }
  return "?";
}

bool parse_number(std::string_view text, double& out) {
  if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, out);
  return !text.empty() && r.ec == std::errc() && r.ptr == end && std::isfinite(out);
}

}  // namespace

bool WhereCondition::holds(const std::vector<double>& numbers) const {
  const auto value = [&](const Term& t) { return t.key ? t.factor * numbers[*t.key] : t.factor; };
  const double a = value(left);
  const double b = value(right);
  switch (op) {
    case Op::less_equal:
      return a <= b;
    case Op::less:
      return a < b;
    case Op::greater_equal:
      return a >= b;
    case Op::greater:
      return a > b;
    case Op::equal:
      return a == b;
    case Op::not_equal:
      break;
  }
  return a != b;
}

std::string WhereCondition::text(const std::vector<VarySpec>& keys) const {
  const auto term = [&](const Term& t) {
    if (!t.key) return number_field(t.factor);
    if (t.factor == 1.0) return keys[*t.key].key;
    return number_field(t.factor) + "*" + keys[*t.key].key;
  };
  return fmt::format("{} {} {}", term(left), op_text(op), term(right));
}

WhereCondition parse_where(const std::string& text, const std::vector<VarySpec>& keys) {
  const auto not_a_form = [&] {
    throw UsageError(fmt::format("--where: '{}' is not {}", printable(text), kForm));
  };
  WhereCondition c;
  std::size_t at = std::string::npos;
  std::size_t width = 0;
  for (const auto& [op, value] : kOps) {
    const std::size_t found = text.find(op);
    if (found != std::string::npos && (found < at || (found == at && op.size() > width))) {
      at = found;
      width = op.size();
      c.op = value;
    }
  }
  if (at == std::string::npos) not_a_form();
  const auto term = [&](std::string_view side) {
    side = trim_blanks(side);
    WhereCondition::Term t;
    if (side.empty() || side.find_first_of("<>=!") != std::string_view::npos) not_a_form();
    std::string_view key = side;
    if (const std::size_t star = side.find('*'); star != std::string_view::npos) {
      // NUMBER*KEY or KEY*NUMBER.
      std::string_view number = trim_blanks(side.substr(0, star));
      key = trim_blanks(side.substr(star + 1));
      if (!parse_number(number, t.factor)) std::swap(number, key);
      if (!parse_number(number, t.factor)) not_a_form();
    } else if (parse_number(side, t.factor)) {
      return t;
    }
    for (std::size_t k = 0; k < keys.size(); ++k) {
      if (keys[k].key == key) t.key = k;
    }
    if (!t.key) {
      std::vector<std::string> names;
      for (const VarySpec& spec : keys) names.push_back(spec.key);
      throw UsageError(fmt::format("--where: {} is not a varied key (known: {})", printable(key),
                                   join_names(names)));
    }
    for (const VaryValue& v : keys[*t.key].values) {
      if (!v.number) {
        throw UsageError(fmt::format("--where: {} takes names ('{}'), not numbers only",
                                     printable(key), printable(v.text)));
      }
    }
    return t;
  };
  c.left = term(std::string_view(text).substr(0, at));
  c.right = term(std::string_view(text).substr(at + width));
  if (!c.left.key && !c.right.key) {
    throw UsageError(fmt::format("--where: '{}' names no varied key", printable(text)));
  }
  return c;
}

}  // namespace mdrsim::cli
