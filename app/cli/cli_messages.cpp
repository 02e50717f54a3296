#include "cli/cli_messages.h"

#include <algorithm>
#include <vector>

#include "rbsim/scene/json_fields.h"

namespace rbsim::app {
namespace {

// The subcommand the user chose (the deepest one parsed), or the app itself.
const CLI::App* chosenCommand(const CLI::App* app) {
  const std::vector<CLI::App*> chosen = app->get_subcommands();
  return chosen.empty() ? app : chosenCommand(chosen.front());
}

std::vector<std::string> longFlags(const CLI::App* command) {
  std::vector<std::string> flags;
  for (const CLI::Option* option : command->get_options()) {
    for (const std::string& name : option->get_lnames()) flags.push_back("--" + name);
  }
  return flags;
}

// What the user typed that the command did not take, in the order typed.
std::vector<std::string> unexpectedArguments(const CLI::App* root, const CLI::App* command) {
  std::vector<std::string> unexpected = root->remaining();
  if (command != root) {
    const std::vector<std::string> more = command->remaining();
    unexpected.insert(unexpected.end(), more.begin(), more.end());
  }
  return unexpected;
}

// For an unexpected "--dtt": " (did you mean --dt?)", from the command's own long flags; for a flag
// other subcommands have (--dt given to replay): which ones have it.
std::string flagSuggestion(const CLI::App* root, const CLI::App* command, const std::vector<std::string>& unexpected) {
  const std::vector<std::string> flags = longFlags(command);
  for (const std::string& argument : unexpected) {
    if (argument.rfind("--", 0) != 0) continue;
    const std::string flag = argument.substr(0, argument.find('='));
    std::string owners;
    for (const CLI::App* other : root->get_subcommands(std::function<bool(const CLI::App*)>())) {
      const std::vector<std::string> theirs = longFlags(other);
      if (other == command || std::find(theirs.begin(), theirs.end(), flag) == theirs.end()) continue;
      owners += std::string(owners.empty() ? "" : " and ") + "`rbsim " + other->get_name() + "`";
    }
    if (!owners.empty()) return "; " + flag + " is a flag of " + owners + " only";
    if (const std::string near = nearestKey(flag, flags); !near.empty()) return "; did you mean " + near + "?";
  }
  return "";
}

}  // namespace

std::string versionText() { return std::string("rbsim ") + RBSIM_VERSION + " (commit " + RBSIM_COMMIT + ")"; }

void formatParseErrors(CLI::App& app) {
  app.failure_message([](const CLI::App* root, const CLI::Error& error) {
    const CLI::App* command = chosenCommand(root);
    const std::string name = command == root ? "rbsim" : "rbsim " + command->get_name();
    std::string message = "rbsim: error: " + std::string(error.what());
    if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
      const std::vector<std::string> unexpected = unexpectedArguments(root, command);
      std::string typed;
      for (const std::string& argument : unexpected) typed += " " + argument;
      message = "rbsim: error: `" + name + "` does not take" + typed + flagSuggestion(root, command, unexpected);
    }
    const std::string help = name + " --help";
    return message + "\n" + "(`" + help + "` lists what it accepts)\n";
  });
}

}  // namespace rbsim::app
