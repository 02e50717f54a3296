// The flags of `rbsim demo`, `run` and `replay`: what each subcommand accepts, turned into run
// options and --set assignments. Flags that change the scene become assignments, so a flag and the
// scene key it stands for are checked by the same code (rbsim/scene/override.h).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "rbsim/io/input_error.h"
#include "run/run_options.h"
#include "window/interactive.h"

namespace rbsim::app {

// Which flags a subcommand offers: a replay draws recorded motion, so it has no flag that would
// change the simulation (time step, steps, integrator, inertia, a comparison, a recording).
enum class FlagSet { Simulate, Replay };

struct Flags {
  RunOptions run;
  std::string dt, steps, fps, size, integrator, inertia, particleIntegrator;
  std::string pngLevel, traceEvery, windowFrames, speed;  // numbers, parsed by flag_values.h
  std::string gl;                                  // off-screen GL backend, render/gl_context.h
  std::string compare;                             // KEY=V1,V2[,...]: a compare block
  std::string plot;                                // Q1,Q2,...: view.plots
  // Scene key -> the flag that set it ("view.size" -> "--size 0x0"), so an error the scene reports
  // about the key can say which flag it came from.
  std::map<std::string, std::string> keyFlags;
  bool noRender = false, noOverlay = false, window = false;
  WindowOptions windowOptions;
  std::vector<std::string> sets;

  void attach(CLI::App& cmd, FlagSet set);

  // Checks the flags against each other and returns the run options.
  RunOptions finish(const std::string& defaultVideo);

  // The flag behind a scene error's field, as " (from --size 0x0)", or "" when no flag set it.
  std::string origin(const InputError& e) const;

 private:
  void refuseIgnoredFlags() const;
};

}  // namespace rbsim::app
