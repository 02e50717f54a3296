#pragma once
// Numbers given as command-line flags, parsed by rbsim itself rather than by CLI11, whose
// messages ("not in range 0.000000 to 1797693...") name no unit and wrap or reject overflowing
// input without saying so. Each error names the flag, what it expects in words, and the text given.
#include <cstdint>
#include <string>
#include <utility>

namespace rbsim::app {

// Reads `text` as a decimal integer in [min, max]. Throws InputError("", flag, "expected
// <expected>; got <text>, not in range MIN to MAX") for anything else: negative, past 64 bits
// (both said in parentheses), out of range, or "not a whole number" (a word, a fraction).
std::uint64_t parseFlagInteger(const std::string& flag, const std::string& text, std::uint64_t min,
                               std::uint64_t max, const std::string& expected);

// Reads `text` as a decimal number in [min, max] (a plain number: no "inf", "nan" or hex);
// throws InputError naming the flag, what it expects and the text given otherwise.
double parseFlagNumber(const std::string& flag, const std::string& text, double min, double max,
                       const std::string& expected);

// Reads "WIDTHxHEIGHT" (decimal digits only); throws InputError naming `flag` otherwise or when a
// side does not fit 64 bits. The range of each side is the scene's (view.size) to check.
std::pair<std::uint64_t, std::uint64_t> parseImageSize(const std::string& flag, const std::string& text);

// Reads --compare's "KEY=V1,V2[,...]" into the scene's compare block, {"key": KEY, "values":
// [V1, V2, ...]}, as JSON text for a --set of "compare". Each value is JSON when it parses as JSON
// (so [1,2,3] and "a,b" stay one value: commas split only outside brackets and quotes), a string
// otherwise, as --set reads values. Throws InputError naming the flag when there is no "=", no
// key or an empty value; the block's own checks (2 to 8 distinct values) are the scene's.
std::string parseCompareFlag(const std::string& text);

}  // namespace rbsim::app
