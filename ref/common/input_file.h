// Reading a user's input file (scene, sweep) with the project's limits: regular files only, at
// most limits::kMaxInputFileBytes, every failure one rpu::Error naming the file.
#pragma once

#include <string>

namespace rpu {

// The whole content of `path`. `what` names the kind of file in messages ("scene file",
// "sweep file"). Refuses directories, FIFOs, devices and other non-regular files, files larger
// than limits::kMaxInputFileBytes, and unreadable files; never blocks on a FIFO.
std::string read_input_file(const std::string& path, const std::string& what);

}  // namespace rpu
