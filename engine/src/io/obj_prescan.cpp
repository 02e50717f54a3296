#include "io/obj_prescan.h"

#include <climits>
#include <cstdio>
#include <vector>

#include "rbsim/geometry/mesh.h"
#include "rbsim/io/input_error.h"
#include "io/obj_loader.h"

namespace rbsim {

namespace {

// Decimal exponents beyond this overflow or underflow any double; tinyobjloader would also
// overflow its int while reading a longer one.
constexpr int kMaxDecimalExponent = 9999;

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// The number syntax tinyobjloader's tryParseDouble reads in full: [+-] digits [. digits]
// [eE [+-] digits], or [+-] . digits [...]; at least one mantissa digit and, after an 'e', at
// least one exponent digit ("." or "1e" it would read as 0 or 1 without a word).
bool isDecimal(const std::string& s) {
  std::size_t i = 0, digits = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  for (; i < s.size() && isDigit(s[i]); ++i) ++digits;
  if (i < s.size() && s[i] == '.') {
    for (++i; i < s.size() && isDigit(s[i]); ++i) ++digits;
  }
  if (digits == 0) return false;
  if (i == s.size()) return true;
  if (s[i] != 'e' && s[i] != 'E') return false;
  if (++i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  long exponent = 0;
  const std::size_t first = i;
  for (; i < s.size() && isDigit(s[i]); ++i) {
    exponent = std::min<long>(exponent * 10 + (s[i] - '0'), kMaxDecimalExponent + 1);
  }
  return i == s.size() && i > first && exponent <= kMaxDecimalExponent;
}

// A face index: a non-zero int (negative: counted back from the last one defined so far).
bool parseIndex(const std::string& s, long long& out) {
  std::size_t i = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
  if (i == s.size()) return false;
  long long value = 0;
  for (; i < s.size(); ++i) {
    if (!isDigit(s[i])) return false;
    value = value * 10 + (s[i] - '0');
    if (value > INT_MAX) return false;
  }
  out = s[0] == '-' ? -value : value;
  return out != 0;
}

struct Scan {
  const std::string& path;
  std::size_t line = 0;
  std::size_t counts[3] = {0, 0, 0};          // v, vt, vn lines so far
  long long greatest[3] = {0, 0, 0};          // largest positive index of each kind
  std::size_t greatestLine[3] = {0, 0, 0};    // where it was used
  std::size_t greatestFace[3] = {0, 0, 0};    // in which face (counting 'f' lines from 1)
  std::size_t faces = 0;
  std::size_t triangles = 0;

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(path, "line " + std::to_string(line), problem);
  }

  void numbers(const std::vector<std::string>& fields, const char* keyword, const std::string& expected,
               bool countOk) const {
    if (!countOk) {
      fail("'" + std::string(keyword) + "' expects " + expected + "; got " + std::to_string(fields.size()) +
           (fields.size() == 1 ? " field" : " fields"));
    }
    for (std::size_t k = 0; k < fields.size(); ++k) {
      if (!isDecimal(fields[k])) {
        fail("'" + std::string(keyword) + "' field " + std::to_string(k + 1) + " is '" + fields[k] +
             "'; expected a decimal number (like -1.25 or 3e-2)");
      }
    }
  }

  // "v", "v/vt", "v//vn" or "v/vt/vn".
  void corner(const std::string& field, std::size_t position) {
    static const char* const kNames[3] = {"vertex", "texture coordinate", "normal"};
    std::string parts[3];
    int part = 0;
    for (char c : field) {
      if (c == '/') {
        if (++part > 2) break;
      } else {
        parts[part] += c;
      }
    }
    const std::string where = "'f' corner " + std::to_string(position) + " '" + field + "'";
    if (part > 2 || parts[0].empty() || (part == 1 && parts[1].empty())) {
      fail(where + ": expected v, v/vt, v//vn or v/vt/vn with integer indices");
    }
    for (int kind = 0; kind <= part; ++kind) {
      if (kind == 1 && parts[1].empty()) continue;  // v//vn
      long long index = 0;
      if (!parseIndex(parts[kind], index)) {
        fail(where + ": the " + kNames[kind] + " index '" + parts[kind] +
             "' is not a non-zero integer (OBJ counts from 1; negative counts back)");
      }
      if (index < 0 && static_cast<std::size_t>(-index) > counts[kind]) {
        fail(where + ": the " + kNames[kind] + " index " + std::to_string(index) + " counts back past the first; only " +
             std::to_string(counts[kind]) + " are defined above this line");
      }
      if (index > greatest[kind]) {
        greatest[kind] = index;
        greatestLine[kind] = line;
        greatestFace[kind] = faces;
      }
    }
  }

  void face(const std::vector<std::string>& fields) {
    if (fields.size() < 3) {
      fail("a face has fewer than 3 vertices (an 'f' line needs at least 3 indices); got " +
           std::to_string(fields.size()));
    }
    if (fields.size() > kMaxObjFaceCorners) {
      fail("a face of " + std::to_string(fields.size()) + " corners; faces of at most " +
           std::to_string(kMaxObjFaceCorners) + " corners are supported (the OBJ reader keeps the count in 8 bits)");
    }
    ++faces;
    for (std::size_t k = 0; k < fields.size(); ++k) corner(fields[k], k + 1);
    triangles += fields.size() - 2;
  }

  void statement(const std::string& keyword, const std::vector<std::string>& fields) {
    if (keyword == "v") {
      numbers(fields, "v", "3 coordinates x y z (and optionally a weight w, or a colour r g b)",
              fields.size() == 3 || fields.size() == 4 || fields.size() == 6);
      ++counts[0];
    } else if (keyword == "vt") {
      numbers(fields, "vt", "1 to 3 texture coordinates u [v [w]]", !fields.empty() && fields.size() <= 3);
      ++counts[1];
    } else if (keyword == "vn") {
      numbers(fields, "vn", "3 normal components x y z", fields.size() == 3);
      ++counts[2];
    } else if (keyword == "f") {
      face(fields);
    }
  }
};

}  // namespace

ObjCounts prescanObj(const std::string& text, const std::string& path) {
  Scan scan{path};
  std::vector<std::string> fields;
  std::size_t i = 0;
  // Lines end at "\n", "\r\n" or a lone "\r", as tinyobjloader splits them.
  while (i < text.size()) {
    ++scan.line;
    std::size_t end = i;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
    fields.clear();
    std::string keyword;
    bool inToken = false;
    for (std::size_t k = i; k < end; ++k) {
      const unsigned char c = static_cast<unsigned char>(text[k]);
      if (c == ' ' || c == '\t') {
        inToken = false;
        continue;
      }
      if (c < 0x20 || c == 0x7f) {
        char code[8];
        std::snprintf(code, sizeof code, "0x%02x", c);
        scan.fail(std::string("a control character (byte ") + code + ") in the text; an OBJ file is plain text");
      }
      if (!inToken) fields.emplace_back();
      fields.back() += static_cast<char>(c);
      inToken = true;
    }
    if (!fields.empty() && fields[0][0] != '#') {
      keyword = fields[0];
      fields.erase(fields.begin());
      scan.statement(keyword, fields);
    }
    i = end;
    if (i < text.size()) i += (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ? 2 : 1;
  }
  static const char* const kNames[3] = {"vertex", "texture coordinate", "normal"};
  for (int kind = 0; kind < 3; ++kind) {
    if (static_cast<std::size_t>(scan.greatest[kind]) > scan.counts[kind]) {
      throw InputError(path, "line " + std::to_string(scan.greatestLine[kind]),
                       "face " + std::to_string(scan.greatestFace[kind]) + ": " + kNames[kind] +
                           " index out of range: " + std::to_string(scan.greatest[kind]) + ", but the file has " +
                           std::to_string(scan.counts[kind]));
    }
  }
  ObjCounts counts{scan.counts[0], scan.triangles};
  if (counts.vertices > kMaxMeshVertices || counts.triangles > kMaxMeshTriangles) {
    throw InputError(path, "mesh", "has " + std::to_string(counts.vertices) + " vertices and " +
                     std::to_string(counts.triangles) + " triangles (after polygons are split); the limit is " +
                     std::to_string(kMaxMeshVertices) + " vertices and " + std::to_string(kMaxMeshTriangles) +
                     " triangles");
  }
  return counts;
}

}  // namespace rbsim
