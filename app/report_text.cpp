#include "report_text.h"

#include "common/output_file.h"

namespace rpu::app {

std::string escape_html(std::string_view text) {
  std::string s;
  s.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': s += "&amp;"; break;
      case '<': s += "&lt;"; break;
      case '>': s += "&gt;"; break;
      case '"': s += "&quot;"; break;
      case '\'': s += "&#39;"; break;
      default: s += c;
    }
  }
  return s;
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  check_output_path(path.string(), "file");
  write_file_atomically(path.string(), text);
}

}  // namespace rpu::app
