#include "rbsim/scene/strict_json.h"

#include <unordered_set>
#include <vector>

#include "rbsim/io/input_error.h"

namespace rbsim {

namespace {

// Line and column of a byte offset, for JSON syntax errors.
std::string lineAndColumn(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// One open object or array while parsing: enough to name the JSON path of a duplicate key.
struct OpenContainer {
  bool isArray = false;
  std::size_t index = 0;                  // the element being read, for an array
  std::string key;                        // the member being read, for an object
  std::unordered_set<std::string> keys;   // members seen so far, for an object
};

std::string pathOf(const std::vector<OpenContainer>& open, const std::string& last) {
  std::string path;
  for (std::size_t i = 0; i + 1 < open.size(); ++i) {
    if (open[i].isArray) {
      path += "[" + std::to_string(open[i].index) + "]";
    } else {
      path += (path.empty() ? "" : ".") + open[i].key;
    }
  }
  return path + (path.empty() ? "" : ".") + last;
}

}  // namespace

nlohmann::json parseStrictJson(const std::string& text, const std::string& file, const std::string& where) {
  const std::string prefix = where.empty() ? std::string() : where + ", ";
  std::vector<OpenContainer> open;
  using Event = nlohmann::json::parse_event_t;
  const auto finishElement = [&open] {
    if (!open.empty() && open.back().isArray) ++open.back().index;
  };
  const nlohmann::json::parser_callback_t check = [&](int depth, Event event, nlohmann::json& parsed) {
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        if (depth >= kMaxJsonDepth) {
          throw InputError(file, prefix + pathOf(open, open.empty() || open.back().isArray ? "" : open.back().key),
                           "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels; no scene needs that");
        }
        open.push_back(OpenContainer{event == Event::array_start, 0, {}, {}});
        break;
      case Event::key: {
        OpenContainer& object = open.back();
        object.key = parsed.get<std::string>();
        if (!object.keys.insert(object.key).second) {
          throw InputError(file, prefix + pathOf(open, object.key),
                           "duplicate key: given twice in the same object (JSON would keep only one of them)");
        }
        break;
      }
      case Event::object_end:
      case Event::array_end:
        open.pop_back();
        finishElement();
        break;
      case Event::value:
        finishElement();
        break;
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text, check);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file, prefix + lineAndColumn(text, e.byte == 0 ? 0 : e.byte - 1),
                     std::string("invalid JSON: ") + e.what());
  } catch (const nlohmann::json::out_of_range& e) {
    // A number too large for a double (1e999) ends the parse with out_of_range and no position;
    // the message quotes the number, which is found again in the text.
    const std::string what = e.what();
    const std::size_t openQuote = what.find('\''), closeQuote = what.rfind('\'');
    const std::size_t at = openQuote < closeQuote ? text.find(what.substr(openQuote + 1, closeQuote - openQuote - 1))
                                                  : std::string::npos;
    throw InputError(file, prefix + (at == std::string::npos ? std::string() : lineAndColumn(text, at)),
                     "invalid JSON: " + what + " (numbers must be finite doubles)");
  }
}

}  // namespace rbsim
