#pragma once
// One rendered image on its way to the writers. Shared, because the PNG and video writers read
// the same pixels and the simulation must not wait for either to finish with them.
#include <cstdint>
#include <memory>
#include <vector>

namespace rbsim::render {

struct OutputFrame {
  long index = 0;  // 0-based frame number, names the PNG
  std::shared_ptr<const std::vector<std::uint8_t>> rgba;  // top row first
};

}  // namespace rbsim::render
