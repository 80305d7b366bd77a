#include "run_record.h"

#include <array>
#include <cstdio>
#include <memory>

namespace rpu::app {

namespace {

// The first line of a command's standard output, or "" when it cannot run or prints nothing.
std::string first_line(const std::string& cmd) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen((cmd + " 2>/dev/null").c_str(), "r"), ::pclose);
  if (!pipe) return "";
  std::array<char, 512> buf{};
  std::string line;
  if (std::fgets(buf.data(), static_cast<int>(buf.size()), pipe.get())) line = buf.data();
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  return line;
}

std::string quoted(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789-_./:=,+@%") == std::string::npos)
    return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

std::string command_line(int argc, char** argv) {
  std::string s;
  for (int k = 0; k < argc; ++k) s += (k ? " " : "") + quoted(argv[k]);
  return s;
}

nlohmann::json run_record(const std::string& command) {
  const std::string git =
      first_line("git -C " + quoted(RPU_SOURCE_DIR) + " describe --always --dirty --abbrev=12");
  const std::string verilator = first_line("verilator --version");
  const std::string yosys = first_line("yosys -V");
  return {{"command", command},
          {"git_commit", git.empty() ? "unknown" : git},
          {"verilator", verilator.empty() ? "not found" : verilator},
          {"yosys", yosys.empty() ? "not found" : yosys}};
}

}  // namespace rpu::app
