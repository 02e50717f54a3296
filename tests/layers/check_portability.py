#!/usr/bin/env python3
"""The engine is standard C++17 (issue 57): no compiler builtin, GNU attribute or POSIX-only name
in its public headers or sources, so MSVC, clang and mingw-w64 build it as GCC does. Code only:
comments and string literals are skipped. The one file allowed to name a compiler's extension is
engine/src/math/portable.h, which hides each behind a standard fallback (docs/ci.md, Portability).
Prints every hit (file, line, what, the portable spelling) and exits 1.

    python3 tests/layers/check_portability.py [REPO_DIR]
    python3 tests/layers/check_portability.py --self-test   # each forbidden name is found
"""
import os
import re
import sys

TREES = ("engine/include", "engine/src")
SOURCES = (".h", ".cpp")
ALLOWED = {"engine/src/math/portable.h"}  # the wrappers, each behind #if on the compiler
# (pattern, what it is, what to write instead)
FORBIDDEN = [
    (r"\bM_(?:PI|PI_2|PI_4|1_PI|2_PI|2_SQRTPI|E|LOG2E|LOG10E|LN2|LN10|SQRT2|SQRT1_2)[lf]?\b",
     "a POSIX <math.h> constant (MSVC defines it only with _USE_MATH_DEFINES)", "kPi in rbsim/math/types.h"),
    (r"\b__builtin_\w+", "a GCC/Clang builtin", "a wrapper in engine/src/math/portable.h"),
    (r"\b__attribute__\b|\[\[\s*gnu::", "a GNU attribute", "a standard [[attribute]]"),
    (r"\b__restrict__\b|\b__int128\b|\b__typeof__\b|\btypeof\b", "a GNU extension", "standard C++"),
    (r"\b__PRETTY_FUNCTION__\b", "a GNU macro", "__func__"),
    (r"#\s*pragma\s+(?:GCC|clang)\b", "a compiler-specific pragma", "code every compiler accepts"),
    (r"\bssize_t\b", "a POSIX type", "std::ptrdiff_t or std::int64_t"),
    (r"\baligned_alloc\b|\bposix_memalign\b|\balloca\b", "an allocation MSVC lacks", "operator new with std::align_val_t"),
    (r"#\s*include\s*<(?:unistd|pthread|dlfcn|dirent|fcntl|strings|alloca|x86intrin|sys/[\w/]+)\.h>",
     "a POSIX or x86-GCC header", "the standard library (<thread>, <filesystem>, <chrono>)"),
]
PATTERNS = [(re.compile(p), what, instead) for p, what, instead in FORBIDDEN]
STRING = re.compile(r'"(?:\\.|[^"\\])*"')
QUOTE_CHAR = re.compile(r"'\\?\"'")  # '"' or '\"', which would open a string


def code_lines(text):
    """(line number, the line's code): comments and string literals blanked, #include kept."""
    in_block = False
    for number, line in enumerate(text.split("\n"), 1):
        line = QUOTE_CHAR.sub("' '", line)
        code = ""
        i = 0
        while i < len(line):
            if in_block:
                end = line.find("*/", i)
                if end < 0:
                    i = len(line)
                else:
                    in_block, i = False, end + 2
                continue
            if line.startswith("//", i):
                break
            if line.startswith("/*", i):
                in_block, i = True, i + 2
                continue
            code += line[i]
            i += 1
        if not re.match(r"\s*#\s*include", code):
            code = STRING.sub('""', code)
        yield number, code


def check(repo):
    problems = []
    for tree in TREES:
        for folder, dirs, names in os.walk(os.path.join(repo, tree)):
            dirs.sort()
            for name in sorted(names):
                if not name.endswith(SOURCES):
                    continue
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, repo).replace(os.sep, "/")
                if rel in ALLOWED:
                    continue
                with open(path, encoding="utf-8", errors="replace") as f:
                    text = f.read()
                for number, code in code_lines(text):
                    for pattern, what, instead in PATTERNS:
                        m = pattern.search(code)
                        if m:
                            problems.append(f"{rel}:{number}: {m.group(0)} is {what}; use {instead}")
    return problems


def self_test():
    """A made-up engine with one forbidden name a line, plus the same names in comments, strings
    and the allowed wrapper: exactly the code lines are reported."""
    import tempfile
    bad = [
        "const double a = 2.0 * M_PI;",
        "double h = M_SQRT1_2;",
        "__builtin_prefetch(p, 1);",
        "if (__builtin_expect(x, 0)) {}",
        "__attribute__((always_inline)) void f();",
        "[[gnu::always_inline]] void g();",
        "double* __restrict__ q;",
        "ssize_t n = 0;",
        "#pragma GCC diagnostic push",
        "#include <unistd.h>",
        "#include <sys/mman.h>",
        "void* p = aligned_alloc(64, 128);",
        "const char* f = __PRETTY_FUNCTION__;",
    ]
    clean = [
        "// M_PI is POSIX; __builtin_prefetch is GCC's",
        "/* ssize_t and __attribute__ */ int x = 0;",
        "/* a block",
        "   M_PI inside it */",
        'const char* s = "M_PI and __builtin_trap";',
        "const double b = 2.0 * kPi;",
        "#include <cmath>",
        "int m_pi = M_PIECE;",
        "char q = '\"'; const char* t = \"__builtin_trap\";",
    ]
    with tempfile.TemporaryDirectory() as repo:
        files = {
            "engine/include/rbsim/bad.h": "\n".join(bad) + "\n",
            "engine/src/clean.cpp": "\n".join(clean) + "\n",
            "engine/src/math/portable.h": "__builtin_prefetch(p, 1);\n",
            "app/not_engine.cpp": "const double a = M_PI;\n",
        }
        for rel, text in files.items():
            os.makedirs(os.path.join(repo, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(repo, rel), "w", encoding="utf-8") as f:
                f.write(text)
        problems = check(repo)
    expected = [f"engine/include/rbsim/bad.h:{n}:" for n in range(1, len(bad) + 1)]
    ok = len(problems) == len(bad) and all(any(p.startswith(e) for p in problems) for e in expected)
    print("self-test", "passed" if ok else "FAILED", *problems, sep="\n")
    return 0 if ok else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    repo = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    problems = check(repo)
    for p in problems:
        print(p)
    print(f"check_portability: {len(problems)} problems", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
