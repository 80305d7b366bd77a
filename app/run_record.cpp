#include "run_record.h"

#include <array>
#include <fstream>
#include <vector>
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

namespace rpu::app {

namespace {

// The cells of a Markdown table row, trimmed ("| a | b |" → {"a", "b"}).
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (size_t k = 1; k < line.size(); ++k) {
    if (line[k] == '|') {
      const size_t b = cur.find_first_not_of(' '), e = cur.find_last_not_of(' ');
      out.push_back(b == std::string::npos ? "" : cur.substr(b, e - b + 1));
      cur.clear();
    } else {
      cur += line[k];
    }
  }
  return out;
}

}  // namespace

nlohmann::json docs_resources(bool defaults, bool unrolled, const std::string& scene_arg) {
  if (!defaults)
    return {{"note", "docs/throughput.md holds the default parameters only"}};
  const std::string path = std::string(RPU_SOURCE_DIR) + "/docs/throughput.md";
  std::ifstream f(path);
  if (!f) return {{"note", "docs/throughput.md not found in the checkout"}};
  const std::string form = unrolled ? "unrolled" : "iterative";
  const std::string scene =
      scene_arg.starts_with("builtin:") ? scene_arg.substr(std::string("builtin:").size()) : "";
  nlohmann::json out = {{"form", form}, {"from", "docs/throughput.md"}};
  std::vector<std::string> fps_header;
  std::string line;
  while (std::getline(f, line)) {
    if (!line.starts_with("| ")) continue;
    const std::vector<std::string> c = cells(line);
    if (c.size() >= 10 && c[0] == form && !out.contains("lut_sites")) {
      out["source"] = c[1];
      out["lut_sites"] = c[2];
      out["ff"] = c[3];
      out["dsp48e1"] = c[4];
      out["bram36"] = c[5];
      out["sta_ns"] = c[7];
      out["routed_clock"] = c[9];
    } else if (!c.empty() && c[0] == "scene (frames/s)") {
      fps_header = c;
    } else if (!fps_header.empty() && !scene.empty() && c.size() == fps_header.size() &&
               c.size() > 3 && c[0] == scene && c[1] == form) {
      // | scene | form | pairs per frame | one column per part |
      for (size_t k = 3; k < c.size(); ++k) out["fps_1080p"][fps_header[k]] = c[k];
    }
  }
  if (!out.contains("lut_sites")) return {{"note", "no " + form + " row in docs/throughput.md"}};
  if (!out.contains("fps_1080p"))
    out["fps_1080p"] = "docs/throughput.md projects the built-in curve and texture scenes only";
  return out;
}

}  // namespace rpu::app
