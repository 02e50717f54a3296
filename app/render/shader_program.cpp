#include "shader_program.h"

#include <fstream>
#include <sstream>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "render_error.h"

namespace rbsim::render {

namespace {

std::string shaderLog(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
  glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return log.data();
}

std::string programLog(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
  glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return log.data();
}

GLuint compile(GLenum stage, const std::string& path) {
  const std::string source = readTextFile(path);
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = shaderLog(shader);
    glDeleteShader(shader);
    throw RenderError("shader compile error in " + path + ":\n" + log);
  }
  return shader;
}

}  // namespace

std::string readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw RenderError("cannot read shader file " + path +
                      " (set RBSIM_SHADER_DIR to the folder holding rbsim's shaders/)");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

ShaderProgram::ShaderProgram(const std::string& dir, const std::string& vertexFile,
                             const std::string& fragmentFile, const std::string& vertexLibrary) {
  std::vector<std::string> paths = {dir + "/" + vertexFile, dir + "/" + fragmentFile};
  if (!vertexLibrary.empty()) paths.push_back(dir + "/" + vertexLibrary);
  const GLenum stages[] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_VERTEX_SHADER};
  std::vector<GLuint> shaders;
  try {
    for (std::size_t k = 0; k < paths.size(); ++k) shaders.push_back(compile(stages[k], paths[k]));
  } catch (...) {
    for (const GLuint shader : shaders) glDeleteShader(shader);
    throw;
  }
  program_ = glCreateProgram();
  for (const GLuint shader : shaders) glAttachShader(program_, shader);
  glLinkProgram(program_);
  // The program keeps the compiled stages alive; flag the shader objects for deletion now.
  for (const GLuint shader : shaders) glDeleteShader(shader);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = programLog(program_);
    glDeleteProgram(program_);
    std::string names = paths[0];
    for (std::size_t k = 1; k < paths.size(); ++k) names += " + " + paths[k];
    throw RenderError("shader link error for " + names + ":\n" + log);
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(program_); }

void ShaderProgram::set(const char* name, const glm::mat4& value) const {
  glUniformMatrix4fv(glGetUniformLocation(program_, name), 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec2& value) const {
  glUniform2fv(glGetUniformLocation(program_, name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec3& value) const {
  glUniform3fv(glGetUniformLocation(program_, name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec4& value) const {
  glUniform4fv(glGetUniformLocation(program_, name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, float value) const {
  glUniform1f(glGetUniformLocation(program_, name), value);
}
void ShaderProgram::set(const char* name, int value) const {
  glUniform1i(glGetUniformLocation(program_, name), value);
}

}  // namespace rbsim::render
