// The project's exception: what went wrong and where (file, JSON path, pixel, parameter).
#pragma once

#include <stdexcept>
#include <string>

namespace rpu {

// Thrown for every user-facing error. `where()` names the location (e.g.
// "scene.json: curves[2].normals[5]"), `problem()` says what is wrong; `what()` joins them so
// the CLI can print one line.
class Error : public std::runtime_error {
 public:
  Error(std::string where, std::string problem)
      : std::runtime_error(where.empty() ? problem : where + ": " + problem),
        where_(std::move(where)),
        problem_(std::move(problem)) {}

  const std::string& where() const { return where_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string where_;
  std::string problem_;
};

}  // namespace rpu
