// Bad input never crashes: each case in tests/data/bad/cases.json runs the real rbsim binary and
// must exit with code 2 and a message naming the file, the field and what was expected.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

struct BadCase {
  std::string name;
  std::vector<std::string> args;
  std::vector<std::string> expect;
};

// Names the case in test output instead of GoogleTest's byte dump.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

std::vector<BadCase> loadCases() {
  std::ifstream in(std::string(RBSIM_BAD_DATA_DIR) + "/cases.json");
  const nlohmann::json doc = nlohmann::json::parse(in);
  std::vector<BadCase> cases;
  for (const auto& c : doc.at("cases")) {
    BadCase bad{c.at("name"), {}, c.at("expect").get<std::vector<std::string>>()};
    for (std::string arg : c.at("args")) {
      const std::size_t at = arg.find("{dir}");
      if (at != std::string::npos) arg.replace(at, 5, RBSIM_BAD_DATA_DIR);
      bad.args.push_back(arg);
    }
    cases.push_back(bad);
  }
  return cases;
}

std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Runs rbsim with the arguments; returns (exit code, stdout + stderr).
std::pair<int, std::string> runRbsim(const std::vector<std::string>& args) {
  std::string command = shellQuote(RBSIM_BINARY);
  for (const std::string& a : args) command += " " + shellQuote(a);
  command += " --quiet 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer{};
  while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) output.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, ExitsTwoWithAMessageNamingTheField) {
  const BadCase& c = GetParam();
  const auto [code, output] = runRbsim(c.args);
  EXPECT_EQ(code, 2) << output;
  for (const std::string& fragment : c.expect) {
    EXPECT_NE(output.find(fragment), std::string::npos) << "missing \"" << fragment << "\" in: " << output;
  }
  EXPECT_EQ(output.find("internal error"), std::string::npos) << output;
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInput, ::testing::ValuesIn(loadCases()),
                         [](const auto& info) { return info.param.name; });

TEST(BadInputControl, TheValidSceneRunsCleanly) {
  // The control case: the same data folder's valid scene exits 0, so the cases above fail for
  // the reason they name and not because the harness cannot run the binary.
  const auto [code, output] = runRbsim({"run", std::string(RBSIM_BAD_DATA_DIR) + "/valid.json", "--no-render"});
  EXPECT_EQ(code, 0) << output;
}

}  // namespace
