#pragma once
// Bad user input (scene files, meshes, flags): reported with the file, the field and what was
// expected, and mapped by the app to exit code 2. Never used for internal errors.
#include <stdexcept>
#include <string>

namespace rbsim {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string field, std::string problem)
      : std::runtime_error(format(file, field, problem)),
        file_(std::move(file)), field_(std::move(field)), problem_(std::move(problem)) {}

  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }
  const std::string& problem() const { return problem_; }

 private:
  static std::string format(const std::string& file, const std::string& field,
                            const std::string& problem) {
    std::string out = file.empty() ? std::string("command line") : file;
    if (!field.empty()) out += ": " + field;
    return out + ": " + problem;
  }
  std::string file_, field_, problem_;
};

}  // namespace rbsim
