#version 450 core
// Deliberately broken: rbsim must print this file name and the GL info log.
void main() {
  gl_Position = undefined_variable;
}
