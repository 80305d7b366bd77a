// Child processes of `rpu sweep` (Yosys reports, the on-demand co-simulation build), and the
// shell text of the commands it emits (jobs.txt, merge.sh). No child is ever run through a
// shell: every one gets an argument vector (posix_spawnp), so no path or parameter can be read
// as shell syntax. Each child leads a process group of its own, and rpu ends those groups when
// it is interrupted (SIGINT, SIGTERM, SIGHUP), so a killed sweep leaves no Yosys or compiler
// running behind it.
#pragma once

#include <string>
#include <vector>

namespace rpu::app {

// Where a child's standard output and error go: a file (created or truncated, or appended to),
// or nowhere. Both may name the same file; it is then opened once, and the two streams share it.
struct ChildOutput {
  std::string stdout_file;  // "" = /dev/null
  std::string stderr_file;  // "" = /dev/null
  bool append = false;      // append instead of truncating
};

// Runs argv[0] (looked up in PATH when it has no '/') with the arguments argv[1..], standard
// input from /dev/null, in a new process group, and waits for it. Returns the exit status, or
// 128 + the signal number when a signal ended it. Throws rpu::Error naming argv[0] when it
// cannot be started (missing, not executable, the output file cannot be opened).
//
// While the child runs, SIGINT, SIGTERM and SIGHUP sent to rpu send SIGTERM to the child (so a
// script can run its trap), then, once it has exited or after 3 s, to its whole process group,
// and then end rpu by the same signal (its default action). A signal ignored when rpu started
// (nohup, a background job of sh) stays ignored.
int run_child(const std::vector<std::string>& argv, const ChildOutput& output = {});

// One word of POSIX sh that stands for exactly `text` (any bytes but NUL): single-quoted, each '
// written as '\''. A text with a newline is produced by printf instead, so that the word, and
// the command holding it, stays on one line (jobs.txt is one command per line); such a word
// needs the assignments in *prelude (run before the command on the same line, "a=…; b=…; ").
// `slot` names the variable used for this word (distinct per word of one command).
std::string shell_word(const std::string& text, std::string* prelude, int slot);

// A whole command line of POSIX sh: any prelude, then `lead` (e.g. "exec "), then the words
// joined by spaces.
std::string shell_command(const std::vector<std::string>& words, const std::string& lead = "");

}  // namespace rpu::app
