"""The C++ docs' examples are the code tests run: a block of docs/cpp-api.md is the text between a
C++ test's markers (as test_changes.py checks "Changes while running"). No module needed."""
from conftest import SOURCE


def block(section):
    """The first code block of a section of docs/cpp-api.md, by its heading."""
    text = (SOURCE / "docs" / "cpp-api.md").read_text().split("## " + section + "\n", 1)[1]
    return text.split("```", 2)[1].split("\n", 1)[1]


def ran(test):
    text = (SOURCE / "tests" / "engine" / test).read_text()
    return text.split("// docs/cpp-api.md begin\n", 1)[1].split("  // docs/cpp-api.md end", 1)[0]


def test_the_shape_ids_example_is_the_one_a_test_runs():
    lines = [line.strip() for line in ran("world/shape_ids_test.cpp").splitlines()]
    assert lines and lines == [line.strip() for line in block("Shape ids").splitlines()]
