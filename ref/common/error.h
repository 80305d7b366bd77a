// The project's exception: what went wrong and where (file, JSON path, pixel, parameter).
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rpu {

// Thrown for every user-facing error. `where()` names the location (e.g.
// "scene.json: curves[2].normals[5]"), `problem()` says what is wrong; `what()` joins them so
// the CLI can print one line.
//
// A message is one line: control characters that a file's keys or strings, or a path, bring into
// `where` or `problem` (a JSON key "a\nb" is legal) are written as escapes: \n, \r, \t, \xHH.
class Error : public std::runtime_error {
 public:
  Error(std::string where, std::string problem)
      : Error(Escaped{one_line(std::move(where)), one_line(std::move(problem))}) {}

  const std::string& where() const { return where_; }
  const std::string& problem() const { return problem_; }

 private:
  struct Escaped {
    std::string where, problem;
  };
  explicit Error(Escaped e)
      : std::runtime_error(e.where.empty() ? e.problem : e.where + ": " + e.problem),
        where_(std::move(e.where)),
        problem_(std::move(e.problem)) {}

  static std::string one_line(std::string s) {
    if (std::none_of(s.begin(), s.end(), is_control)) return s;
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    for (const char c : s) {
      const auto u = static_cast<unsigned char>(c);
      if (!is_control(c)) out += c;
      else if (c == '\n') out += "\\n";
      else if (c == '\r') out += "\\r";
      else if (c == '\t') out += "\\t";
      else out += std::string("\\x") + kHex[u >> 4] + kHex[u & 15];
    }
    return out;
  }
  static bool is_control(char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7f;
  }

  std::string where_;
  std::string problem_;
};

}  // namespace rpu
