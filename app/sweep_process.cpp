#include "sweep_process.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <string_view>

#include <fmt/format.h>

#include "common/error.h"
#include "common/limits.h"

extern char** environ;

namespace rpu::app {

namespace {

// The signals that end rpu and, first, its children.
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};

// The process groups of the running children, one slot each (0 = free). A signal handler reads
// them, so they are lock-free atomics in static storage: process-wide state by nature (there is
// one signal disposition per process), private to this file.
constexpr size_t kSlots = limits::kMaxThreads + 64;  // one child per worker at most
std::array<std::atomic<pid_t>, kSlots> g_groups{};
// Threads between posix_spawn and registering the new group; the handler waits for them, so a
// child started just as the signal arrives is ended too.
std::atomic<int> g_spawning{0};
std::atomic<bool> g_stopping{false};

void pause_ms(long ms) {
  const timespec pause{0, ms * 1000000};  // nanosleep is async-signal-safe
  nanosleep(&pause, nullptr);
}

// Ends every child: first SIGTERM to each group's leader alone, so that a script can run its
// trap and end what it started in process groups of its own (yosys_report.sh ends the
// `timeout` groups of its Yosys runs; signalled as a whole group at once, its subshells would
// die under it and its trap would not run); after the leaders have exited, or 3 s, SIGTERM to
// the whole groups, for whatever a leader left behind (compilers under ninja).
extern "C" void stop_children(int sig) {
  g_stopping.store(true);
  while (g_spawning.load() > 0) pause_ms(1);
  for (auto& g : g_groups) {
    const pid_t pgid = g.load();
    if (pgid > 0) ::kill(pgid, SIGTERM);
  }
  for (int t = 0; t < 300; ++t) {
    bool running = false;
    for (auto& g : g_groups) {
      const pid_t pgid = g.load();
      siginfo_t info{};
      if (pgid > 0 && ::waitid(P_PID, static_cast<id_t>(pgid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
          info.si_pid == 0)
        running = true;
    }
    if (!running) break;
    pause_ms(10);
  }
  for (auto& g : g_groups) {
    const pid_t pgid = g.load();
    if (pgid > 0) ::kill(-pgid, SIGTERM);
  }
  // End rpu by the same signal (its default action) once this handler returns.
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void install_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : kStopSignals) {
      struct sigaction old {};
      ::sigaction(sig, nullptr, &old);
      if (old.sa_handler == SIG_IGN) continue;  // started with the signal ignored (nohup, &)
      struct sigaction sa {};
      sa.sa_handler = stop_children;
      ::sigemptyset(&sa.sa_mask);
      for (int s : kStopSignals) ::sigaddset(&sa.sa_mask, s);
      ::sigaction(sig, &sa, nullptr);
    }
  });
}

size_t register_group(pid_t pgid) {
  for (size_t k = 0; k < kSlots; ++k) {
    pid_t expected = 0;
    if (g_groups[k].compare_exchange_strong(expected, pgid)) return k;
  }
  return kSlots;  // cannot happen (more children than workers); the child is then not tracked
}

// posix_spawn's attribute and file-action objects, destroyed on every path.
struct SpawnSetup {
  posix_spawnattr_t attr;
  posix_spawn_file_actions_t actions;
  SpawnSetup() {
    posix_spawnattr_init(&attr);
    posix_spawn_file_actions_init(&actions);
  }
  ~SpawnSetup() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
  }
  SpawnSetup(const SpawnSetup&) = delete;
  SpawnSetup& operator=(const SpawnSetup&) = delete;
};

// The signal mask of this thread with the stop signals blocked, restored on every path.
struct BlockStopSignals {
  sigset_t old;
  BlockStopSignals() {
    sigset_t block;
    sigemptyset(&block);
    for (int s : kStopSignals) sigaddset(&block, s);
    pthread_sigmask(SIG_BLOCK, &block, &old);
  }
  ~BlockStopSignals() { pthread_sigmask(SIG_SETMASK, &old, nullptr); }
};

}  // namespace

int run_child(const std::vector<std::string>& argv, const ChildOutput& output) {
  if (argv.empty()) throw Error("rpu sweep", "no command to run");
  install_handlers();
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  SpawnSetup setup;
  const int mode = O_WRONLY | O_CREAT | (output.append ? O_APPEND : O_TRUNC);
  const char* out = output.stdout_file.empty() ? "/dev/null" : output.stdout_file.c_str();
  const char* err = output.stderr_file.empty() ? "/dev/null" : output.stderr_file.c_str();
  posix_spawn_file_actions_addopen(&setup.actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&setup.actions, 1, out, mode, 0644);
  if (!output.stderr_file.empty() && output.stderr_file == output.stdout_file)
    posix_spawn_file_actions_adddup2(&setup.actions, 1, 2);
  else
    posix_spawn_file_actions_addopen(&setup.actions, 2, err, mode, 0644);

  pid_t pid = 0;
  size_t slot = kSlots;
  int rc = 0;
  {
    // No stop signal may run its handler on this thread between the spawn and the
    // registration (the handler would wait for this very thread).
    const BlockStopSignals blocked;
    // The child starts in its own process group, with the stop signals at their default
    // action and the mask this thread had before blocking them.
    sigset_t defaults;
    sigemptyset(&defaults);
    for (int s : kStopSignals) sigaddset(&defaults, s);
    posix_spawnattr_setpgroup(&setup.attr, 0);
    posix_spawnattr_setsigdefault(&setup.attr, &defaults);
    posix_spawnattr_setsigmask(&setup.attr, &blocked.old);
    posix_spawnattr_setflags(&setup.attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF |
                                               POSIX_SPAWN_SETSIGMASK);
    ++g_spawning;
    if (g_stopping.load()) {
      --g_spawning;
      throw Error(argv[0], "not started: rpu is being stopped");
    }
    rc = posix_spawnp(&pid, args[0], &setup.actions, &setup.attr, args.data(), environ);
    if (rc == 0) slot = register_group(pid);
    --g_spawning;
  }
  if (rc != 0)
    throw Error(argv[0], fmt::format("cannot start the program: {}", std::strerror(rc)));

  // Wait without reaping, forget the group, then reap: the pid cannot be reused (and another
  // process group signalled) while it is still registered.
  siginfo_t info{};
  while (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT) != 0 && errno == EINTR) {
  }
  if (slot < kSlots) g_groups[slot].store(0);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 255;
}

std::string shell_word(const std::string& text, std::string* prelude, int slot) {
  // Plain words (options, ids, most paths) stay bare.
  constexpr std::string_view kPlain =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_./:@+,-";
  if (!text.empty() && text.find_first_not_of(kPlain) == std::string::npos) return text;
  if (text.find('\n') == std::string::npos) {
    std::string word = "'";
    for (char c : text) word += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return word + "'";
  }
  // printf's format, single-quoted: % and \ doubled, the newline as \012, a ' as '\''. A final
  // "." keeps trailing newlines from the command substitution, and ${v%.} removes it.
  std::string format;
  for (char c : text) {
    switch (c) {
      case '%': format += "%%"; break;
      case '\\': format += "\\\\"; break;
      case '\n': format += "\\012"; break;
      case '\'': format += "'\\''"; break;
      default: format += c;
    }
  }
  const std::string var = fmt::format("rpu_word{}", slot);
  *prelude += fmt::format("{}=$(printf '{}.'); ", var, format);
  return fmt::format("\"${{{}%.}}\"", var);
}

std::string shell_command(const std::vector<std::string>& words, const std::string& lead) {
  std::string prelude, command;
  int slot = 0;
  for (const std::string& w : words)
    command.append(command.empty() ? "" : " ").append(shell_word(w, &prelude, slot++));
  return prelude + lead + command;
}

}  // namespace rpu::app
