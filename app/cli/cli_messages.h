// What the command line says about itself: its version, and its parse errors in the same form as
// every other error ("rbsim: error: ..."), with a suggestion for a misspelt flag.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace rbsim::app {

// "rbsim 0.20.0 (commit 1a2b3c4d5e6f)": the project version and the git commit it was built from
// ("-dirty" with uncommitted changes, "unknown" outside a git checkout).
std::string versionText();

// Makes CLI11's parse errors read "rbsim: error: ...", naming the nearest flag for an unknown one
// and the help that lists the subcommand's flags. Call before adding subcommands (they copy it).
void formatParseErrors(CLI::App& app);

}  // namespace rbsim::app
