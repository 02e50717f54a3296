#!/usr/bin/env python3
"""World stays a conductor (issue 58): class World in engine/include/rbsim/world/world.h declares
at most MAX_PUBLIC public member functions. The counting rule (docs/architecture.md, "The World's
surface"): every public member function declaration counts once, constructors, the destructor and
the assignment operators included, each overload on its own (body(id) and body(id) const are two),
a deleted one too; friends, types, data members and private members do not. What grows the World
beside its core goes into free functions over World in their own headers (world/spawner.h,
world/queries.h, ...). Prints the count and, over the limit, every counted declaration; exits 1.

    python3 tests/layers/check_world_api.py [REPO_DIR]
    python3 tests/layers/check_world_api.py --self-test   # a class over the limit is caught
"""
import os
import re
import sys

HEADER = "engine/include/rbsim/world/world.h"
CLASS = "World"
MAX_PUBLIC = 35

COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
STRING = re.compile(r'"(?:\\.|[^"\\])*"')
FUNCTION_NAME = re.compile(r"(?:\boperator\s*(?:\(\)|[^\s(]+)|~?\b\w+)\s*\($")
NOT_FUNCTION = re.compile(r"^\s*(?:friend|using|typedef|static_assert)\b")
NESTED_TYPE = re.compile(r"^\s*(?:struct|class|union|enum)\b")


def strip_angles(text):
    """The text with every <...> template argument list blanked (nested lists too)."""
    out, depth = [], 0
    for c in text:
        if c == "<":
            depth += 1
        elif c == ">" and depth:
            depth -= 1
        elif depth == 0:
            out.append(c)
    return "".join(out)


def is_function(statement):
    """A member function's declaration: a name directly before the first top-level '('."""
    if NOT_FUNCTION.match(statement) or NESTED_TYPE.match(statement):
        return False
    plain = strip_angles(statement)
    paren = plain.find("(")
    if paren < 0 or "=" in re.sub(r"\boperator\s*\S*$", "", plain[:paren]):
        return False  # a data member, or one initialised by a call
    return FUNCTION_NAME.search(plain[: paren + 1]) is not None


def skip_braces(text, i):
    """The index just past the '}' matching the '{' at text[i]."""
    depth = 0
    while i < len(text):
        if text[i] == "{":
            depth += 1
        elif text[i] == "}":
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    raise ValueError("unbalanced braces")


def public_functions(source, name=CLASS):
    """The public member function declarations of class `name` in `source`, one string each."""
    text = STRING.sub('""', COMMENT.sub(" ", source))
    start = re.search(r"\bclass\s+" + name + r"\b[^;{]*\{", text)
    if not start:
        raise ValueError("no class " + name)
    i, end = start.end(), skip_braces(text, start.end() - 1) - 1
    access, statement, found, parens = "private", "", [], 0
    while i < end:
        c = text[i]
        label = re.match(r"\s*(public|private|protected)\s*:(?!:)", text[i:end]) if not statement.strip() else None
        if label:
            access, i = label.group(1), i + label.end()
            continue
        parens += (c == "(") - (c == ")")
        if parens > 0 or c not in ";{":  # inside a parameter list ("= {}" defaults) or plain text
            statement, i = statement + c, i + 1
        elif c == ";":
            if access == "public" and is_function(statement):
                found.append(" ".join(statement.split()))
            statement, i = "", i + 1
        elif c == "{":
            if is_function(statement):  # an inline body: the declaration ends with it
                if access == "public":
                    found.append(" ".join(statement.split()))
                statement, i = "", skip_braces(text, i)
            else:  # a nested type's body or a brace initialiser: the statement goes on to its ';'
                statement, i = statement + " {} ", skip_braces(text, i)
    return found


def check(repo):
    with open(os.path.join(repo, HEADER), encoding="utf-8") as f:
        functions = public_functions(f.read())
    print(f"{HEADER}: class {CLASS} has {len(functions)} public member functions (limit {MAX_PUBLIC})")
    if len(functions) <= MAX_PUBLIC:
        return 0
    for declaration in functions:
        print("  " + declaration)
    print("Move reads and the parts beside the World's core into free functions over World in their own headers "
          "(docs/architecture.md, \"The World's surface\").")
    return 1


SAMPLE = """
class Other { public: void notCounted(); };
class World {
  friend struct Access;  // not a member function
 public:
  explicit World(const Settings& s);
  ~World();
  World(const World&) = delete;
  World& operator=(World&&) noexcept;
  int& body(int id) { ++version_; return bodies_[id]; }
  const int& body(int id) const { return bodies_[id]; }
  struct Part { int f(); };          /* a nested type: its f is not World's */
  std::array<int, static_cast<int>(Stage::Count)> stats{};
  std::size_t count = size(3);       // a data member initialised by a call
  template <typename Fn> void each(Fn&& fn) const;
  bool operator()(int) const;
  void add(const Plane& p, const Material& m = {});  // a brace in a default argument
 private:
  void hidden();
 protected:
  void alsoHidden();
 public:
  static double time();
};
"""
SAMPLE_FUNCTIONS = ["World", "~World", "World(const World&)", "operator=", "body", "body", "each", "operator()", "add", "time"]


def self_test():
    found = public_functions(SAMPLE)
    assert len(found) == len(SAMPLE_FUNCTIONS), found
    for declaration, name in zip(found, SAMPLE_FUNCTIONS):
        assert name in declaration, (declaration, name)
    # Over the limit the check fails: a header of MAX_PUBLIC + 1 functions.
    import tempfile
    with tempfile.TemporaryDirectory() as repo:
        os.makedirs(os.path.join(repo, os.path.dirname(HEADER)))
        for count, expected in ((MAX_PUBLIC, 0), (MAX_PUBLIC + 1, 1)):
            body = "\n".join(f"  void f{k}();" for k in range(count))
            with open(os.path.join(repo, HEADER), "w", encoding="utf-8") as f:
                f.write(f"class World {{\n public:\n{body}\n private:\n  void g();\n}};\n")
            assert check(repo) == expected, (count, expected)
    print("self-test passed")
    return 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    sys.exit(check(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")))
