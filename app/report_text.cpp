#include "report_text.h"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "common/error.h"

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
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out)
      throw Error(path.string(), std::string("cannot open for writing: ") + std::strerror(errno));
    out << text;
    out.close();
    if (!out) throw Error(path.string(), "cannot write the file");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw Error(path.string(), "cannot write the file: " + ec.message());
  }
}

}  // namespace rpu::app
