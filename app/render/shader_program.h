#pragma once
// A GLSL program built at run time from a vertex and a fragment file in the shader directory, so
// shaders can be edited without recompiling. Every failure names the file and carries GL's log.
#include <string>

#include <glm/glm.hpp>

#include "gl_api.h"

namespace rbsim::render {

class ShaderProgram {
 public:
  // Reads dir/vertexFile and dir/fragmentFile, compiles and links them; with `vertexLibrary`, a
  // second vertex shader object defining functions the first declares (several objects per stage
  // link into one stage in desktop GL). Throws RenderError naming the file (missing, unreadable,
  // compile error) or every file (link error) with GL's info log.
  ShaderProgram(const std::string& dir, const std::string& vertexFile, const std::string& fragmentFile,
                const std::string& vertexLibrary = "");
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const { glUseProgram(program_); }

  // Uniform setters for the bound program; a name the linker optimised away is silently ignored
  // (location -1), which is GL's own rule and lets shaders drop unused inputs.
  void set(const char* name, const glm::mat4& value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, float value) const;
  void set(const char* name, int value) const;

 private:
  GLuint program_ = 0;
};

// Reads a whole text file; throws RenderError("... <path> ...") if it is missing or unreadable.
std::string readTextFile(const std::string& path);

}  // namespace rbsim::render
