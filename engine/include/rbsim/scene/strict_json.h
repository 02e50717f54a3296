#pragma once
// JSON text to a document, strictly: RFC 8259 leaves duplicate keys to the reader, and
// nlohmann-json keeps the last one, so a scene that sets "mass" twice would run with one of the
// two values without a word. Here a duplicate key is an error naming its JSON path, a syntax
// error names line and column, and nesting is bounded so no input can exhaust the stack.
#include <string>

#include <nlohmann/json.hpp>

namespace rbsim {

// Deeper than any scene needs (a body's orientation matrix sits at depth 6); far below what
// would strain the parser's or a recursive walker's stack.
inline constexpr int kMaxJsonDepth = 64;

// Throws InputError(file, ...) on a syntax error, a number that is not a finite double, a
// duplicate key or nesting deeper than kMaxJsonDepth. `what` names the text in messages
// ("" for a file; "--set value" for an override).
nlohmann::json parseStrictJson(const std::string& text, const std::string& file, const std::string& where = "");

}  // namespace rbsim
