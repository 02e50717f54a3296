#include "demos/demo.h"

namespace rbsim::app {

Demo demo1Particles();
Demo demo2Unconstrained();
Demo demo3Broadphase();
Demo demo4Narrowphase();
Demo demo5Contact();
Demo demo6Implicit();
Demo demo7Soft();
Demo demo8Machinery();

const std::vector<Demo>& allDemos() {
  static const std::vector<Demo> demos = {demo1Particles(), demo2Unconstrained(), demo3Broadphase(), demo4Narrowphase(), demo5Contact(), demo6Implicit(),
                                           demo7Soft(), demo8Machinery()};
  return demos;
}

const Demo* findDemo(int number) {
  for (const Demo& demo : allDemos()) {
    if (demo.number == number) return &demo;
  }
  return nullptr;
}

}  // namespace rbsim::app
