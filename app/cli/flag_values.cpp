#include "cli/flag_values.h"

#include <charconv>
#include <sstream>

#include <nlohmann/json.hpp>

#include "rbsim/io/input_error.h"

namespace rbsim::app {

namespace {

// Only digits: from_chars alone would accept a leading '-' (and we want to say "negative").
bool digitsOnly(const std::string& text) {
  return !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
}

// Parses digits into `value`; false when they overflow 64 bits.
bool fitsIn64Bits(const std::string& digits, std::uint64_t& value) {
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  return error == std::errc() && end == digits.data() + digits.size();
}

}  // namespace

std::uint64_t parseFlagInteger(const std::string& flag, const std::string& text, std::uint64_t min,
                               std::uint64_t max, const std::string& expected) {
  const std::string range = "not in range " + std::to_string(min) + " to " + std::to_string(max);
  const std::string got = "expected " + expected + "; got ";
  std::uint64_t value = 0;
  if (text.size() > 1 && text[0] == '-' && digitsOnly(text.substr(1))) {
    throw InputError("", flag, got + text + " (negative), " + range);
  }
  if (!digitsOnly(text)) throw InputError("", flag, got + "\"" + text + "\", not a whole number");
  if (!fitsIn64Bits(text, value)) throw InputError("", flag, got + text + " (more than 64 bits hold), " + range);
  if (value < min || value > max) throw InputError("", flag, got + text + ", " + range);
  return value;
}

double parseFlagNumber(const std::string& flag, const std::string& text, double min, double max,
                       const std::string& expected) {
  // A JSON number, as --set reads numbers: no "inf", "nan", hex or trailing text.
  const nlohmann::json value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  const std::string got = "expected " + expected + "; got \"" + text + "\"";
  if (!value.is_number()) throw InputError("", flag, got + ", not a number");
  const double number = value.get<double>();
  if (!(number >= min && number <= max)) {
    std::ostringstream range;
    range << ", not in range " << min << " to " << max;
    throw InputError("", flag, got + range.str());
  }
  return number;
}

std::pair<std::uint64_t, std::uint64_t> parseImageSize(const std::string& flag, const std::string& text) {
  const std::string expected = "expected WIDTHxHEIGHT in pixels, e.g. 1280x720, got \"" + text + "\"";
  const std::size_t x = text.find('x');
  if (x == std::string::npos) throw InputError("", flag, expected);
  const std::string width = text.substr(0, x), height = text.substr(x + 1);
  if (!digitsOnly(width) || !digitsOnly(height)) throw InputError("", flag, expected);
  std::uint64_t w = 0, h = 0;
  if (!fitsIn64Bits(width, w) || !fitsIn64Bits(height, h)) {
    throw InputError("", flag, expected + ": a side has more digits than 64 bits hold");
  }
  return {w, h};
}

std::string parseCompareFlag(const std::string& text) {
  const std::string flag = "--compare " + text;
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw InputError("", flag, "expected KEY=V1,V2[,...], e.g. world.integrator=euler-quat,dlm");
  }
  std::vector<std::string> values(1);
  int depth = 0;
  bool quoted = false;
  for (std::size_t i = equals + 1; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '\\' && i + 1 < text.size()) {
        values.back() += c;
        values.back() += text[++i];
        continue;
      }
      if (c == '"') quoted = false;
    } else if (c == '"') {
      quoted = true;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    } else if (c == ',' && depth == 0) {
      values.emplace_back();
      continue;
    }
    values.back() += c;
  }
  nlohmann::json block = {{"key", text.substr(0, equals)}, {"values", nlohmann::json::array()}};
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (values[k].empty()) throw InputError("", flag, "value " + std::to_string(k + 1) + " is empty; expected KEY=V1,V2[,...]");
    nlohmann::json value = nlohmann::json::parse(values[k], nullptr, /*allow_exceptions=*/false);
    block["values"].push_back(value.is_discarded() ? nlohmann::json(values[k]) : value);
  }
  return block.dump();
}

}  // namespace rbsim::app
