#include "common/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "common/error.h"
#include "common/limits.h"

namespace rpu {

std::string read_input_file(const std::string& path, const std::string& what) {
  // O_NONBLOCK: opening a FIFO with no writer must not block; it is refused below as not
  // regular. fstat on the open descriptor avoids a race between the check and the read.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
    throw Error(path, fmt::format("cannot open the {} ({})", what, std::strerror(errno)));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0)
    throw Error(path, fmt::format("cannot read the {} ({})", what, std::strerror(errno)));
  if (S_ISDIR(st.st_mode)) throw Error(path, fmt::format("is a directory, not a {}", what));
  if (!S_ISREG(st.st_mode))
    throw Error(path, fmt::format("is not a regular file (a device, FIFO or socket); the {} "
                                  "must be a regular file", what));
  if (static_cast<std::uintmax_t>(st.st_size) > limits::kMaxInputFileBytes)
    throw Error(path, fmt::format("the {} is too large: {} bytes, at most {} allowed", what,
                                  st.st_size, limits::kMaxInputFileBytes));
  // Regular files may still lie about their size (/proc, files growing while read): read at most
  // one byte past the limit and refuse if it is reached.
  std::string text;
  char buf[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd, buf, sizeof buf);
    if (got < 0) {
      if (errno == EINTR) continue;
      throw Error(path, fmt::format("cannot read the {} ({})", what, std::strerror(errno)));
    }
    if (got == 0) break;
    text.append(buf, static_cast<size_t>(got));
    if (text.size() > limits::kMaxInputFileBytes)
      throw Error(path, fmt::format("the {} is too large: more than {} bytes", what,
                                    limits::kMaxInputFileBytes));
  }
  return text;
}

}  // namespace rpu
