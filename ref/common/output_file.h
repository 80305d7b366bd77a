// Writing a user's output file (images, reports, waveforms) without silent loss or clobbering:
// every output goes to a temporary file beside it and is renamed over the target only once every
// write and the close succeeded, so a failure (full disk, file-size limit) leaves no partial
// file and the previous content intact.
//
// The contract (README, "Limits"): outputs are regular files. An existing directory, device,
// FIFO or socket at the target (or as the target of a symlink there) is refused with one line
// naming the path; a symlink at the target is replaced by the new file, never written through.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace rpu {

// The directory an output path lives in ("." for a bare file name).
std::filesystem::path output_directory(const std::string& path);

// Checks, before any work is done, that `path` can become a regular file: not empty, its
// directory exists and is writable, and nothing but a regular file (or a symlink, which is
// replaced) sits at the path. `what` names the kind of output in messages ("image", "waveform").
void check_output_path(const std::string& path, const std::string& what);

// A temporary file name beside `path`, unique within this process and across processes.
std::string temporary_path_beside(const std::string& path);

// Moves a finished temporary over `path` (replacing a symlink there, never following it);
// removes the temporary on failure. Throws rpu::Error naming `path`.
void commit_temporary(const std::string& temporary, const std::string& path);

// Writes `bytes` to `path` through a temporary and a rename: every write and the close are
// checked, so a full disk or a file-size limit is reported and leaves no file behind.
void write_file_atomically(const std::string& path, std::string_view bytes);

// True when `a` and `b` name the same file (device and inode; symlinks followed). False when
// either does not exist.
bool same_file(const std::string& a, const std::string& b);

}  // namespace rpu
