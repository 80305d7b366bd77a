// Text output of the reports (rpu compare, rpu sweep): HTML/XML escaping and whole-file writes.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace rpu::app {

// The text with & < > " ' replaced by entities, safe in HTML/SVG text and attribute values.
std::string escape_html(std::string_view text);

// Writes the file through a temporary beside it and a rename, every write and the close checked,
// so a failed or interrupted run never leaves half a file (common/output_file.h: a symlink at the
// path is replaced, not followed; a directory or device there is refused). Throws rpu::Error
// naming the path.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace rpu::app
