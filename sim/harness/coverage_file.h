// Where a Verilated model's line and toggle coverage goes (docs/verification.md, section 6): a
// build with RPU_SIM_COVERAGE (scripts/coverage.sh), or the default suite's one coverage target
// (tb_rpu_fifo_cov). Used by the unit testbenches (tb/tb_base.h), the co-simulation's
// VerilatedPorts (one VerilatedContext per instance, several per process, on threads) and the
// SystemC harness. With RPU_COVERAGE_DIR set, each context writes two files there:
//   <name>-<pid>-<n>.base.dat  the counts after the model's first reset (mark())
//   <name>-<pid>-<n>.dat       the counts at the end (write())
// n counts the contexts of the process, so contexts on several threads never share a file; a
// name that exists already (a pid used again in a long run) takes the next n.
// Why the base: --x-initial unique starts every register, and Verilator's own copy of each
// signal that it compares for toggles, at independent random values, so the first evaluation
// counts about half of all bits as toggled whether they ever change or not. A toggle point is
// covered only where the end count exceeds the base (scripts/coverage_report.py --base); line
// points take the end count. Without RPU_COVERAGE_DIR nothing is written, and in a model built
// without coverage (VM_COVERAGE 0) this does nothing.
#pragma once

#include <verilated.h>

#include <string>

#if VM_COVERAGE
#include <verilated_cov.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <filesystem>

#include <unistd.h>
#endif

namespace rpu::sim {

// Two inline namespaces: a program may link a translation unit built with coverage (a Verilated
// model's) beside one built without (tb_rpu_top.cpp includes tb_base.h, rpu_rtl's factories
// include verilated_ports.h), and the two classes must not share a name.
#if VM_COVERAGE
inline namespace coverage_on {

class CoverageFile {
 public:
  // name: the program and the model, e.g. "tb_rpu_fifo_narrow" or "rpu-Vrpu_top_n16_n1_2_iterative"
  // (set_name: when the model, which knows its name, is made after this).
  explicit CoverageFile(std::string name = "model") : name_(std::move(name)) {}
  CoverageFile(const CoverageFile&) = delete;
  CoverageFile& operator=(const CoverageFile&) = delete;
  void set_name(std::string name) { name_ = std::move(name); }

  // The counts so far are the base (the first call only: after the first reset).
  void mark(VerilatedContext& ctx) {
    if (marked_ || !open()) return;
    marked_ = true;
    ctx.coveragep()->write((stem_ + ".base.dat").c_str());
  }
  // The counts at the end (the first call only). A model never marked is marked now: none of its
  // toggles count (its first evaluation cannot be told apart from real changes), all its lines do.
  void write(VerilatedContext& ctx) {
    if (written_ || !open()) return;
    mark(ctx);
    written_ = true;
    ctx.coveragep()->write((stem_ + ".dat").c_str());
  }

  // The program's name (argv[0]'s file name, glibc's short invocation name).
  static std::string program() { return program_invocation_short_name; }

 private:
  static std::atomic<long>& serial() {
    static std::atomic<long> n{0};
    return n;
  }
  bool open() {
    if (!stem_.empty()) return true;
    const char* dir = std::getenv("RPU_COVERAGE_DIR");
    if (!dir || !*dir) return false;
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(dir, ec);
    const std::string base = (fs::path(dir) / name_).string() + "-" + std::to_string(::getpid());
    for (;;) {
      const std::string stem = base + "-" + std::to_string(serial()++);
      if (!fs::exists(stem + ".dat", ec) && !fs::exists(stem + ".base.dat", ec)) {
        stem_ = stem;
        return true;
      }
    }
  }

  std::string name_, stem_;
  bool marked_ = false, written_ = false;
};

}  // namespace coverage_on
#else
inline namespace coverage_off {

class CoverageFile {
 public:
  explicit CoverageFile(const std::string& = {}) {}
  void set_name(const std::string&) {}
  void mark(VerilatedContext&) {}
  void write(VerilatedContext&) {}
  static std::string program() { return {}; }
};

}  // namespace coverage_off
#endif

}  // namespace rpu::sim
