#pragma once
// A numbered assignment demo: scene files played in order into one video. The physics lives in
// the scenes (assets/scenes/), so every demo phase can also be run alone with `rbsim run`.
#include <string>
#include <vector>

namespace rbsim::app {

struct Demo {
  int number = 0;
  std::string name;                // also the video's file name: videos/<name>.mp4
  std::string description;
  std::vector<std::string> scenes;  // relative to the assets/scenes folder
};

const std::vector<Demo>& allDemos();
const Demo* findDemo(int number);

}  // namespace rbsim::app
