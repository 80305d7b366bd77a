#include "common/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "common/error.h"

namespace rpu {

std::filesystem::path output_directory(const std::string& path) {
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  return dir.empty() ? std::filesystem::path(".") : dir;
}

void check_output_path(const std::string& path, const std::string& what) {
  if (path.empty()) throw Error(what, "the output path is empty");
  const std::filesystem::path dir = output_directory(path);
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw Error(path, "the directory " + dir.string() + " does not exist");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw Error(path, "the directory " + dir.string() + " is not writable (" +
                          std::strerror(errno) + ")");
  if (::lstat(path.c_str(), &st) != 0) return;  // a new file
  if (S_ISLNK(st.st_mode) && ::stat(path.c_str(), &st) != 0) return;  // a dangling link
  if (S_ISDIR(st.st_mode)) throw Error(path, "is a directory; expected a file name for the " + what);
  if (!S_ISREG(st.st_mode))
    throw Error(path, "is not a regular file (a device, FIFO or socket); the " + what +
                          " is written to regular files only");
}

std::string temporary_path_beside(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path p(path);
  // The extension is kept last so that format detection by name still works on the temporary.
  std::string name(".");
  name.append(p.filename().string())
      .append(".tmp")
      .append(std::to_string(::getpid()))
      .append("_")
      .append(std::to_string(counter.fetch_add(1)))
      .append(p.extension().string());
  return (output_directory(path) / name).string();
}

void commit_temporary(const std::string& temporary, const std::string& path) {
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(temporary.c_str());
    throw Error(path, std::string("cannot write the file: ") + std::strerror(err));
  }
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  const std::string tmp = temporary_path_beside(path);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0)
    throw Error(path, std::string("cannot open for writing: ") + std::strerror(errno));
  const auto fail = [&](int err) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw Error(path, std::string("cannot write the file: ") + std::strerror(err));
  };
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(n < 0 ? errno : ENOSPC);
    done += static_cast<size_t>(n);
  }
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw Error(path, std::string("cannot write the file: ") + std::strerror(err));
  }
  commit_temporary(tmp, path);
}

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

}  // namespace rpu
