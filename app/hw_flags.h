// The command line's hardware-parameter flags (--n, --n1, ..., --metric, --ip, --surf-w,
// --angle-w): one flag per entry of the parameter table (ref/model/hw_params.def), its help the
// entry's meaning, its default shown. Shared by every subcommand that takes them.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "model/hw_params.h"

namespace rpu::app {

class HwFlags {
 public:
  HwFlags();  // the table's defaults

  // Adds every flag to the (sub)command; may be called for several subcommands.
  void add_to(CLI::App& app);
  // The parameters given: a choice by its name (another name refused, naming the flag: "--metric:
  // must be abs or squared, got 'cube'"), then HwParams::validate (rpu::Error naming the flag).
  ref::HwParams params() const;
  // The table's flags that were given to `app`.
  std::vector<std::string> given(const CLI::App& app) const;

 private:
  std::vector<int> value_;         // per table entry: the integer (kRange, kRangeOrOff)
  std::vector<std::string> text_;  // per table entry: the name (kChoice)
};

}  // namespace rpu::app
