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

// nlohmann's own DOM builder behind SAX events, with the duplicate-key and depth checks in
// front of it. Its callback parser would do the same checks, but its end_object scans the
// enclosing array for discarded elements, which made a scene of n bodies cost O(n^2) to parse
// (100,000 bodies and joints: 4 s, nearly all of it there).
class StrictSax final : public nlohmann::json_sax<nlohmann::json> {
 public:
  StrictSax(nlohmann::json& root, const std::string& file, const std::string& prefix)
      : dom_(root), file_(file), prefix_(prefix) {}

  bool null() override { return value(dom_.null()); }
  bool boolean(bool b) override { return value(dom_.boolean(b)); }
  bool number_integer(number_integer_t n) override { return value(dom_.number_integer(n)); }
  bool number_unsigned(number_unsigned_t n) override { return value(dom_.number_unsigned(n)); }
  bool number_float(number_float_t x, const string_t& s) override { return value(dom_.number_float(x, s)); }
  bool string(string_t& s) override { return value(dom_.string(s)); }
  bool binary(binary_t& b) override { return value(dom_.binary(b)); }
  bool start_object(std::size_t n) override {
    open(false);
    return dom_.start_object(n);
  }
  bool key(string_t& k) override {
    OpenContainer& object = open_.back();
    object.key = k;
    if (!object.keys.insert(object.key).second) {
      throw InputError(file_, prefix_ + pathOf(open_, object.key),
                       "duplicate key: given twice in the same object (JSON would keep only one of them)");
    }
    return dom_.key(k);
  }
  bool end_object() override { return close(dom_.end_object()); }
  bool start_array(std::size_t n) override {
    open(true);
    return dom_.start_array(n);
  }
  bool end_array() override { return close(dom_.end_array()); }
  // Rethrown as its own type (parse_error: a syntax error; out_of_range: 1e999), which the caller
  // reports with the position; the DOM parser would throw the static type, the base class.
  bool parse_error(std::size_t position, const std::string& token, const nlohmann::detail::exception& e) override {
    if (const auto* syntax = dynamic_cast<const nlohmann::json::parse_error*>(&e)) throw *syntax;
    if (const auto* range = dynamic_cast<const nlohmann::json::out_of_range*>(&e)) throw *range;
    return dom_.parse_error(position, token, e);
  }

 private:
  void open(bool isArray) {
    if (open_.size() >= static_cast<std::size_t>(kMaxJsonDepth)) {
      throw InputError(file_, prefix_ + pathOf(open_, open_.empty() || open_.back().isArray ? "" : open_.back().key),
                       "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels; no scene needs that");
    }
    open_.push_back(OpenContainer{isArray, 0, {}, {}});
  }
  bool close(bool ok) {
    open_.pop_back();
    return value(ok);
  }
  bool value(bool ok) {  // a finished element moves its array on
    if (!open_.empty() && open_.back().isArray) ++open_.back().index;
    return ok;
  }

  nlohmann::detail::json_sax_dom_parser<nlohmann::json> dom_;
  std::string file_, prefix_;
  std::vector<OpenContainer> open_;
};

}  // namespace

nlohmann::json parseStrictJson(const std::string& text, const std::string& file, const std::string& where) {
  const std::string prefix = where.empty() ? std::string() : where + ", ";
  nlohmann::json root;
  StrictSax sax(root, file, prefix);
  try {
    nlohmann::json::sax_parse(text, &sax);
    return root;
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
