// One Verilated model and its clock: the VerilatedContext, the model, its FST trace and its
// coverage file, shared by every C++ harness (tb/tb_base.h: the unit testbenches;
// verilated_ports.h: rpu_top; axi_ports.h: rpu_axi). With random_init every initial register
// value is random from x_seed (the models are built --x-initial unique), so a design that
// depends on one is caught. In a coverage build each model writes its own counts
// (coverage_file.h: after the first reset, mark(), and at finish()).
//   settle()  the inputs set, clk_i low, evaluated: the outputs show this cycle's values;
//   tick()    settle() unless done, then the rising edge; each half is one time step of the
//             trace (when one is open).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <verilated.h>
#if VM_TRACE_FST
#include <verilated_fst_c.h>
#endif

#include "coverage_file.h"

namespace rpu::sim {

template <class V>
struct VerilatedModel {
  struct Options {
    bool random_init = false;      // every register random at power-up, from x_seed
    std::uint64_t x_seed = 0;
    bool trace = false;            // the model may be traced (traceEverOn before it is made)
    int argc = 0;                  // the plusargs ($test$plusargs, +trace)
    char** argv = nullptr;
    std::string coverage_name{};   // "": <program>-<model name>
  };
  // x_seed 0: Verilator's own initial values.
  explicit VerilatedModel(std::uint64_t x_seed) : VerilatedModel(Options{x_seed != 0, x_seed}) {}
  explicit VerilatedModel(const Options& o) : ctx(std::make_unique<VerilatedContext>()) {
    if (o.random_init) {
      ctx->randReset(2);
      ctx->randSeed(static_cast<int>(o.x_seed));
    }
    if (o.argc > 0) ctx->commandArgs(o.argc, o.argv);
    if (o.trace) ctx->traceEverOn(true);
    top = std::make_unique<V>(ctx.get());
    coverage.set_name(o.coverage_name.empty() ? CoverageFile::program() + "-" + top->modelName()
                                              : o.coverage_name);
  }
  ~VerilatedModel() { finish(); }

  void settle() {
    top->clk_i = 0;
    top->eval();
    settled = true;
  }
  void tick() {
    if (!settled) settle();
    dump();
    ctx->timeInc(1);
    top->clk_i = 1;
    top->eval();
    dump();
    ctx->timeInc(1);
    settled = false;
  }

  // An FST trace of every signal from now on (a model Verilated with trace code; the context
  // traced from the start, Options::trace). False when this build has no trace support.
  bool open_trace(const std::string& path) {
#if VM_TRACE_FST
    if constexpr (requires(V& v, VerilatedFstC* f) { v.trace(f, 99); }) {
      ctx->traceEverOn(true);
      fst = std::make_unique<VerilatedFstC>();
      top->trace(fst.get(), 99);
      fst->open(path.c_str());
      return true;
    }
#endif
    (void)path;
    return false;
  }
  void flush_trace() {
#if VM_TRACE_FST
    if (fst) fst->flush();
#endif
  }
  // The final blocks, the trace closed and the coverage counts, once; false when already done.
  bool finish() {
    if (finished) return false;
    finished = true;
    top->final();
#if VM_TRACE_FST
    if (fst) fst->close();
#endif
    coverage.write(*ctx);
    return true;
  }

  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<V> top;
  CoverageFile coverage;
#if VM_TRACE_FST
  std::unique_ptr<VerilatedFstC> fst;
#endif
  bool settled = false, finished = false;

 private:
  void dump() {
#if VM_TRACE_FST
    if (fst) fst->dump(ctx->time());
#endif
  }
};

}  // namespace rpu::sim
