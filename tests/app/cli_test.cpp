// The command line as a student meets it (issue 38): --version, help that lists only what a
// subcommand accepts with typed values, `list` naming the shipped scenes, and a scene run by name
// being the same run as by path.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <vector>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "shell_command.h"

namespace {

namespace fs = std::filesystem;

std::pair<int, std::string> rbsim(const std::string& args) {
  return rbsim::test::runCommand(rbsim::test::shellQuote(RBSIM_BINARY) + " " + args + " 2>&1");
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Cli, VersionNamesTheProjectVersionAndTheCommit) {
  const auto [code, output] = rbsim("--version");
  EXPECT_EQ(code, 0);
  const std::regex form("rbsim " + std::regex_replace(std::string(RBSIM_PROJECT_VERSION), std::regex("\\."), "\\.") +
                        " \\(commit ([0-9a-f]{12}(-dirty)?|unknown)\\)\n");
  EXPECT_TRUE(std::regex_match(output, form)) << output;
}

TEST(Cli, ReplayHelpListsOnlyWhatAReplayAccepts) {
  const auto [code, output] = rbsim("replay --help");
  EXPECT_EQ(code, 0);
  for (const char* flag : {"--fps", "--size", "--set", "--plot", "--frames", "--video", "--window"}) {
    EXPECT_NE(output.find(std::string(flag) + " "), std::string::npos) << flag << " missing from:\n" << output;
  }
  for (const char* flag : {"--dt", "--steps", "--integrator", "--inertia", "--compare", "--record", "--phase"}) {
    EXPECT_EQ(output.find(std::string(flag) + " "), std::string::npos) << flag << " listed by replay:\n" << output;
  }
}

TEST(Cli, EveryHelpShowsWhatEachValueIs) {
  for (const char* command : {"--help", "demo --help", "run --help", "replay --help", "list --help"}) {
    const auto [code, output] = rbsim(command);
    EXPECT_EQ(code, 0) << command;
    EXPECT_EQ(output.find("TEXT"), std::string::npos) << "an untyped value in `rbsim " << command << "`:\n" << output;
    EXPECT_EQ(output.find("NONEMPTY"), std::string::npos) << command << ":\n" << output;
  }
  const auto [code, output] = rbsim("run --help");
  for (const char* typed : {"--dt SECONDS", "--size WxH", "--set KEY=VALUE", "--png-level 0-9", "--steps N"}) {
    EXPECT_NE(output.find(typed), std::string::npos) << typed << " in:\n" << output;
  }
}

TEST(Cli, ListNamesEveryShippedSceneWithItsTitle) {
  const auto [code, output] = rbsim("list");
  ASSERT_EQ(code, 0);
  int scenes = 0;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(fs::path(RBSIM_ASSET_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    const std::string name = fs::relative(entry.path(), fs::path(RBSIM_ASSET_DIR) / "scenes").replace_extension().string();
    const std::string title = nlohmann::json::parse(readAll(entry.path())).at("title");
    EXPECT_TRUE(std::regex_search(output, std::regex("\n  " + std::regex_replace(name, std::regex("[/.]"), "\\$&") + " +")))
        << name << " not listed";
    EXPECT_NE(output.find(title), std::string::npos) << title;
    ++scenes;
  }
  EXPECT_GE(scenes, 30);
}

TEST(Cli, ASceneRunByNameIsTheSameRunAsByPath) {
  const fs::path dir = fs::temp_directory_path() / "rbsim_cli_by_name";
  fs::create_directories(dir);
  const std::string byPath = (dir / "by_path.csv").string(), byName = (dir / "by_name.csv").string();
  const std::string path = std::string(RBSIM_ASSET_DIR) + "/scenes/round_shapes.json";
  EXPECT_EQ(rbsim("run " + rbsim::test::shellQuote(path) + " --steps 30 --no-render --quiet --trace " + byPath).first, 0);
  EXPECT_EQ(rbsim("run round_shapes --steps 30 --no-render --quiet --trace " + byName).first, 0);
  EXPECT_EQ(rbsim("run box3d/large_pyramid.json --steps 1 --no-render --quiet").first, 0);
  const std::string a = readAll(byPath), b = readAll(byName);
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, b);
  fs::remove_all(dir);
}

TEST(Cli, ParseErrorsOpenWithTheSamePrefixAsEveryOtherError) {
  for (const char* args : {"", "bogus", "run", "run x.json --dt", "run x.json --size", "demo 2 --phase", "--frobnicate"}) {
    const auto [code, output] = rbsim(args);
    EXPECT_EQ(code, 2) << args;
    EXPECT_EQ(output.rfind("rbsim: error: ", 0), 0u) << "`rbsim " << args << "`: " << output;
    EXPECT_NE(output.find("--help` lists what it accepts"), std::string::npos) << output;
  }
}

// Every `build/rbsim ...` command README.md shows still parses: its subcommand exists, each flag is
// one its --help lists, and a command without placeholders (FILE, N) runs for one step (its shell
// redirection left out).
TEST(Cli, EveryCommandInTheReadmeStillParses) {
  std::istringstream readme(readAll(fs::path(RBSIM_SOURCE_DIR) / "README.md"));
  const std::string marker = "build/rbsim ";
  int commands = 0, ran = 0;
  for (std::string line; std::getline(readme, line);) {
    for (std::size_t at = line.find(marker); at != std::string::npos; at = line.find(marker, at + 1)) {
      std::string command = line.substr(at + marker.size());
      command = command.substr(0, std::min({command.find('`'), command.find('#'), command.find("&&"), command.find('>')}));
      std::istringstream words(command);
      std::vector<std::string> tokens;
      for (std::string w; words >> w;) tokens.push_back(w);
      if (tokens.empty()) continue;
      const std::string sub = tokens.front();
      ASSERT_TRUE(sub == "demo" || sub == "run" || sub == "replay" || sub == "list" || sub == "schema") << line;
      ++commands;
      const std::string help = rbsim(sub + " --help").second;
      bool placeholder = false, window = false;
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string& t = tokens[k];
        if (t.rfind("--", 0) == 0) {
          EXPECT_NE(help.find(t + " "), std::string::npos) << "`rbsim " << sub << "` has no " << t << ": " << line;
          window = window || t == "--window";
        }
        placeholder = placeholder || std::any_of(t.begin(), t.end(), [](char c) { return std::isupper(static_cast<unsigned char>(c)); });
      }
      if (placeholder || window || sub == "replay" || (sub == "demo" && tokens.size() > 1 && tokens[1] == "all")) continue;
      std::string run;
      for (const std::string& t : tokens) run += " " + rbsim::test::shellQuote(t);
      if (sub != "list" && sub != "schema") run += " --steps 1 --no-render --quiet";
      const auto [code, output] = rbsim::test::runCommand("cd " + rbsim::test::shellQuote(RBSIM_SOURCE_DIR) + " && " +
                                                          rbsim::test::shellQuote(RBSIM_BINARY) + run + " 2>&1 > /dev/null");
      EXPECT_EQ(code, 0) << "README's `build/rbsim" << run << "`: " << output;
      ++ran;
    }
  }
  EXPECT_GE(commands, 8);
  EXPECT_GE(ran, 4);
}

}  // namespace
