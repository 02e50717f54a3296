// Shader loading failures must say which file is at fault, since shaders are read at run time.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "render/offscreen_renderer.h"
#include "render/render_error.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

TEST(Shaders, MissingDirectoryNamesTheFile) {
  const std::string dir = "/nonexistent/rbsim-shaders";
  try {
    OffscreenRenderer renderer(64, 64, dir);
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(dir + "/"), std::string::npos) << message;
    EXPECT_TRUE(message.find(".vert") != std::string::npos ||
                message.find(".frag") != std::string::npos)
        << message;
  }
}

TEST(Shaders, CompileErrorNamesTheFileAndCarriesTheLog) {
  TempDir dir;
  for (const auto& entry : std::filesystem::directory_iterator(shaderDir())) {
    std::filesystem::copy_file(entry.path(), dir.path() / entry.path().filename());
  }
  std::ofstream(dir.path() / "mesh.frag") << "#version 450\nvoid main() { undeclared = 1.0; }\n";
  try {
    OffscreenRenderer renderer(64, 64, dir.path().string());
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find((dir.path() / "mesh.frag").string()), std::string::npos) << message;
    EXPECT_NE(message.find("undeclared"), std::string::npos) << "GL's log: " << message;
  }
}

// The bodies' vertex shaders call a function another file defines (lighting.glsl): when it is
// missing, the link error names every file of the program.
TEST(Shaders, LinkErrorNamesTheVertexLibraryToo) {
  TempDir dir;
  for (const auto& entry : std::filesystem::directory_iterator(shaderDir())) {
    std::filesystem::copy_file(entry.path(), dir.path() / entry.path().filename());
  }
  std::ofstream(dir.path() / "lighting.glsl") << "#version 450\nvec3 unrelated() { return vec3(0.0); }\n";
  try {
    OffscreenRenderer renderer(64, 64, dir.path().string());
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("link error"), std::string::npos) << message;
    EXPECT_NE(message.find((dir.path() / "lighting.glsl").string()), std::string::npos) << message;
    EXPECT_NE(message.find((dir.path() / "mesh.vert").string()), std::string::npos) << message;
  }
}

TEST(Shaders, DefaultDirectoryFollowsTheEnvironment) {
  setenv("RBSIM_SHADER_DIR", "/some/where", 1);
  EXPECT_EQ(defaultShaderDir(), "/some/where");
  unsetenv("RBSIM_SHADER_DIR");
  EXPECT_TRUE(std::filesystem::exists(defaultShaderDir() + "/mesh.frag")) << defaultShaderDir();
}

}  // namespace
}  // namespace rbsim::render::test
