// The base of every unit testbench (sim/tb/**/tb_*.cpp), after ZipCPU's TESTB<V> (one object
// owns the model, the clock, the reset and the trace) and verilog-axis's stream source and sink
// (random idle cycles on the valid side, random backpressure on the ready side):
//
//   Testbench<Top> tb("tb_rpu_x", argc, argv);  the Verilated context and model (one
//       VerilatedModel, harness/verilated_model.h, as the co-simulation's ports), every register
//       random at power-up (--x-initial unique, RPU_X_SEED), the seed (RPU_SEED) of tb.rng, the
//       vector count (tb.vectors(default), RPU_VECTORS), clock (tick), reset, the FST trace on
//       request (+trace, or RPU_TRACE=1: each failing test keeps <test>.fst in RPU_TRACE_DIR or
//       the working directory), FAILURE lines (fail) and the "matched N items" line (pass, with
//       the longest latency of run()'s items); in a coverage build, the model's line and toggle
//       coverage into RPU_COVERAGE_DIR (harness/coverage_file.h: the counts after the first reset
//       and at the end); with RPU_VECTOR_HASH=file, one line a run: the hash of every matched
//       item's inputs and expected outputs (a refactor that keeps the vectors keeps the lines).
//   tb.run(items, stream)  plays a list of items through a valid_i/valid_o unit (reset first)
//       and checks every result, in order, against its item: the source offers the next item with
//       random gaps (junk on every input in between), holds it until ready_o takes it where the
//       unit has ready_o, and drives random ready_i backpressure where it has ready_i (a held
//       output must stay unchanged); a random tag (tag_i/tag_o) and the fixed latency are checked
//       with the fields; valid_o with no item outstanding, a timeout and a valid_o after the
//       drain fail. tb.check(items, stream, details...): run, then pass; the exit status.
//   Stream<Top, Item>  what the unit's testbench says: its input fields (Inputs: drive, junk and
//       report from one list), its output fields (Outputs: read, compare and report), the latency,
//       the tag width (TAG_W unless told) and the traffic pattern.
//
// A mismatch prints, ibex-style, FAILURE with the cycle, the item number and where the item came
// from, the differing fields, every input field and a table of expected and actual outputs.
#pragma once

#include <verilated.h>

#include <algorithm>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "port_bits.h"
#include "tb_common.h"
#include "verilated_model.h"

namespace rpu::sim {

inline std::uint64_t env_u64(const char* name, std::uint64_t fallback) {
  const char* env = std::getenv(name);
  return env ? std::strtoull(env, nullptr, 0) : fallback;
}

// The seed: RPU_SEED, else a fixed default; always printed.
inline std::uint64_t test_seed(const char* name, std::uint64_t fallback = 20261121) {
  const std::uint64_t seed = env_u64("RPU_SEED", fallback);
  std::printf("%s: seed %llu (set RPU_SEED to reproduce another)\n", name,
              static_cast<unsigned long long>(seed));
  return seed;
}

// printf-style text (the FAILURE and "matched" lines' details).
inline std::string vformat(const char* fmt, std::va_list ap) {
  std::va_list count;
  va_copy(count, ap);
  const int n = std::vsnprintf(nullptr, 0, fmt, count);
  va_end(count);
  if (n <= 0) return {};
  std::string s(static_cast<size_t>(n), '\0');
  std::vsnprintf(s.data(), s.size() + 1, fmt, ap);
  return s;
}

// The input fields of an item, named once: the base calls the testbench's list to drive an item,
// to put junk on every input of an idle cycle, and to print the inputs of a mismatch.
class Inputs {
 public:
  enum Mode { kDrive, kJunk, kList };
  Inputs(Mode mode, std::mt19937_64& rng) : mode_(mode), rng_(rng) {}
  Mode mode() const { return mode_; }
  // A w-bit field (w ≤ 128) on a port of its own.
  template <class P>
  Inputs& operator()(const char* name, P& port, i128 v, int w) {
    if (mode_ == kList) return note(name, str(v));
    put(port, mode_ == kJunk ? random(w) : v, w);
    return *this;
  }
  // A vector {z, y, x} of w-bit components.
  template <class P, class V>
  Inputs& vec(const char* name, P& port, const V& v, int w) {
    if (mode_ == kList) return note(name, str(v));
    if (mode_ == kJunk) put_vec3(port, random(w), random(w), random(w), w);
    else put_vec3(port, v, w);
    return *this;
  }
  // w-bit fields packed LSB first (the first value in the lowest bits).
  template <class P, class R>
  Inputs& fields(const char* name, P& port, const R& values, int w) {
    Bits b;
    std::string s;
    for (const auto& v : values) {
      b.push(mode_ == kJunk ? random(w) : static_cast<i128>(v), w);
      if (mode_ == kList) s += (s.empty() ? "" : " ") + str(static_cast<i128>(v));
    }
    if (mode_ == kList) return note(name, s);
    put(port, b);
    return *this;
  }
  // A port's whole bit vector (packed by the testbench).
  template <class P>
  Inputs& bits(const char* name, P& port, const Bits& b) {
    if (mode_ == kList) return note(name, std::to_string(b.width()) + " bits");
    Bits junk;
    for (int k = 0; mode_ == kJunk && k < b.width(); k += 32)
      junk.push(random(32), std::min(32, b.width() - k));
    put(port, mode_ == kJunk ? junk : b);
    return *this;
  }
  // Only listed (an input that reaches the unit otherwise, or a value behind the fields).
  Inputs& note(const char* name, const std::string& value) {
    if (mode_ == kList) text_ += std::string(text_.empty() ? "" : "  ") + name + " " + value;
    return *this;
  }
  i128 random(int w) { return random_bits(rng_, w); }  // the junk of an idle cycle
  const std::string& text() const { return text_; }

 private:
  Mode mode_;
  std::mt19937_64& rng_;
  std::string text_;
};

// The output fields of a result: read from the ports and compared with the item's expected
// values modulo 2^w (an expected value that does not fit w bits, signed or unsigned, differs).
class Outputs {
 public:
  // Unsigned (shown sign-extended when the expected value is negative) and signed fields.
  template <class P>
  Outputs& operator()(const char* name, const P& port, i128 want, int w, bool care = true) {
    return add(name, false, w, care, {want}, {get_unsigned(port, w)});
  }
  template <class P>
  Outputs& s(const char* name, const P& port, i128 want, int w, bool care = true) {
    return add(name, true, w, care, {want}, {get_unsigned(port, w)});
  }
  // A vector {z, y, x} of signed w-bit components.
  template <class P, class V>
  Outputs& vec(const char* name, const P& port, const V& want, int w, bool care = true) {
    const Bits b = get_bits(port, 3 * w);
    return add(name, true, w, care,
               {static_cast<i128>(want.x), static_cast<i128>(want.y), static_cast<i128>(want.z)},
               {b.field(0, w), b.field(w, w), b.field(2 * w, w)});
  }
  // A value the testbench read itself (w = 0: compared exactly).
  Outputs& value(const char* name, i128 want, i128 got, bool care = true) {
    return add(name, true, 0, care, {want}, {static_cast<u128>(got)});
  }
  // The next field is compared modulo 2^w even where the expected value does not fit.
  Outputs& modulo() {
    modulo_ = true;
    return *this;
  }
  // Shown with the expected values only (the twin's intermediates).
  Outputs& note(const char* name, const std::string& v) {
    notes_ += std::string(notes_.empty() ? "" : "  ") + name + " " + v;
    return *this;
  }
  bool ok() const { return differs_.empty(); }
  const std::string& differs() const { return differs_; }
  // The expected values, named (the vector record of RPU_VECTOR_HASH).
  std::string expected() const {
    std::string t;
    for (const Field& f : fields_)
      t.append(f.name).append(f.care ? "=" : "~").append(text(f.want, f.n)).append(" ");
    return t;
  }
  // Every field read (a held output must keep them).
  std::vector<u128> read() const {
    std::vector<u128> v;
    for (const Field& f : fields_) v.insert(v.end(), f.got, f.got + f.n);
    return v;
  }
  void print() const {
    std::printf("  %-14s %-30s %s\n", "output", "expected", "actual");
    for (const Field& f : fields_) {
      const i128 got[3] = {shown(f, 0), shown(f, 1), shown(f, 2)};
      const char* mark = !f.care ? " (not compared)" : f.bad ? " <-- differs" : "";
      std::printf("  %-14s %-30s %-30s%s\n", f.name, text(f.want, f.n).c_str(),
                  text(got, f.n).c_str(), mark);
    }
    if (!notes_.empty()) std::printf("  twin: %s\n", notes_.c_str());
  }

 private:
  struct Field {
    const char* name;
    bool sgn, care, bad;
    int w, n;
    i128 want[3];
    u128 got[3];
  };
  static std::string text(const i128* v, int n) {  // "v" or "(x, y, z)"
    std::string t(n > 1 ? "(" : "");
    for (int c = 0; c < n; ++c) t.append(c ? ", " : "").append(str(v[c]));
    return t + (n > 1 ? ")" : "");
  }
  static i128 shown(const Field& f, int c) {
    if (f.w == 0) return static_cast<i128>(f.got[c]);
    return f.sgn || f.want[c] < 0 ? sign_extend(f.got[c], f.w) : static_cast<i128>(f.got[c]);
  }
  Outputs& add(const char* name, bool sgn, int w, bool care, std::initializer_list<i128> want,
               std::initializer_list<u128> got) {
    Field f{name, sgn, care, false, w, static_cast<int>(want.size()), {}, {}};
    std::copy(want.begin(), want.end(), f.want);
    std::copy(got.begin(), got.end(), f.got);
    for (int c = 0; c < f.n && care; ++c) {
      const i128 v = f.want[c];
      const bool fits = w == 0 || modulo_ || w >= 127 ||
                        (v >= fixed::min_signed(w) && v <= static_cast<i128>(fixed::max_unsigned(w)));
      const u128 want_bits = w == 0 ? static_cast<u128>(v) : low_bits(static_cast<u128>(v), w);
      f.bad = f.bad || !fits || f.got[c] != want_bits;
    }
    modulo_ = false;
    if (f.bad) differs_ += std::string(differs_.empty() ? "" : ", ") + name;
    fields_.push_back(f);
    return *this;
  }
  std::vector<Field> fields_;
  std::string differs_, notes_;
  bool modulo_ = false;
};

// A packed output port read field by field from its top bits down, the order of the RTL's
// concatenation {a, b, c}:
//   Unpack f(get_bits(t.state_o, n + 2 * MdW));  o.value("tau", want, f.u(n));
class Unpack {
 public:
  explicit Unpack(Bits b) : b_(std::move(b)), at_(b_.width()) {}
  i128 u(int w) {  // the next field, unsigned
    at_ -= w;
    return static_cast<i128>(b_.field(at_, w));
  }
  i128 s(int w) {  // the next field, signed
    at_ -= w;
    return b_.field_signed(at_, w);
  }

 private:
  Bits b_;
  int at_;
};

// The valid and ready patterns of a run (verilog-axis's idle and backpressure generators).
struct Traffic {
  int valid_pct = 85;  // chance that the source offers the next item in a cycle
  int ready_pct = 100;  // chance that the sink is ready (units with ready_i)
  // Phases: every 1..phase_max cycles one percentage of each table (a full stall, ready 0,
  // lasts at most 40 cycles); rude_pct of the phases put junk with valid_i high on the inputs
  // while ready_o is low (it must not be taken).
  long phase_max = 0;
  std::vector<int> valid_table, ready_table;
  int rude_pct = 0;
  std::function<int(long cycle)> valid_at;  // the valid percentage by cycle of the run (bursts)
};

// What one cycle of a run looked like (monitors).
struct Cycle {
  long cycle = 0;                   // since the run began
  bool offered = false, taken = false;
  bool ready_i = true, prev_ready_i = true;
  size_t left = 0;                  // items not taken yet
};

constexpr long kAnyLatency = -1;  // not checked
constexpr long kSameLatency = -2;  // the same for every item (learnt from the first)

template <class Top, class Item>
struct Stream {
  std::function<void(Inputs&, Top&, const Item&)> inputs{};
  std::function<void(Outputs&, const Top&, const Item&)> outputs{};
  std::function<std::string(const Item&)> what{};  // where the item came from (reports)
  std::function<bool(const Item&)> yields{};       // the item gives a result (default: every one)
  long latency = kAnyLatency;                      // cycles from taken to valid_o
  int tag_w = TAG_W;  // > 0: a random tag_i, tag_o compared (0: none, or the bench's own)
  Traffic traffic{};
  long timeout = 0;  // cycles; 0: 4 per item + 1000
  std::function<std::string(const Top&, const Cycle&)> monitor{};  // after the outputs; "": fine
};

struct RunResult {
  bool ok = false;
  long cycles = 0, first_taken = -1, last_taken = -1, max_latency = 0;
  explicit operator bool() const { return ok; }
};

template <class Top>
class Testbench {
 public:
  Testbench(const char* name, int argc, char** argv)
      : name_(name),
        seed(test_seed(name)),
        rng(seed),
        drive_rng_(seed ^ 0x9E3779B97F4A7C15ull),
        m_(model_options(name, argc, argv)) {
    for (int k = 1; k < argc; ++k) args_.emplace_back(argv[k]);
    if (trace_) open_trace(argc > 0 ? argv[0] : name);
  }
  ~Testbench() {
    write_vector_hash();
    m_.finish();
    if (!trace_path_.empty() && !failed_ && !keep_trace_) std::filesystem::remove(trace_path_);
  }
  Top& top() { return *top_; }
  long vectors(long fallback) const {  // RPU_VECTORS, else the testbench's default
    return static_cast<long>(env_u64("RPU_VECTORS", static_cast<std::uint64_t>(fallback)));
  }
  long cycle() const { return cycle_; }
  long matched() const { return matched_; }
  long max_latency() const { return max_latency_; }  // the longest of run()'s items, in cycles
  void add_matched(long n) { matched_ += n; }

  // Inputs settled before the edge (the outputs then show this cycle's combinational values).
  void settle() { m_.settle(); }
  void tick() {
    m_.tick();
    ++cycle_;
  }
  void reset(int cycles = 4) {
    top_->rst_ni = 0;
    for (int k = 0; k < cycles; ++k) tick();
    top_->rst_ni = 1;
    was_reset_ = true;
    m_.coverage.mark(*m_.ctx);  // the toggle base: power-up values and the first reset left out
  }

  // "FAILURE: ..." (the trace flushed and kept); returns 1, the exit status.
  int fail(const char* fmt, ...) __attribute__((format(printf, 2, 3))) {
    std::va_list ap;
    va_start(ap, fmt);
    const std::string what = vformat(fmt, ap);
    va_end(ap);
    std::printf("FAILURE: %s\n", what.c_str());
    return failed();
  }
  // "<name>: matched N items in C cycles (details)"; returns 0.
  int pass(const char* fmt = nullptr, ...) __attribute__((format(printf, 2, 3))) {
    std::printf("%s: matched %ld items in %ld cycles", name_, matched_, cycle_);
    if (max_latency_ > 0) std::printf(", latency %ld", max_latency_);
    std::string details;
    if (fmt) {
      std::va_list ap;
      va_start(ap, fmt);
      details = " (" + vformat(fmt, ap) + ")";
      va_end(ap);
    }
    std::printf("%s\n", details.c_str());
    return 0;
  }
  // A coverage verdict (Tally::too_weak): true, after its FAILURE line, where it names a gap.
  bool weak(const std::string& why) { return !why.empty() && fail("%s", why.c_str()); }
  // One run, then pass(details): a testbench's exit status.
  template <class Items, class Item = typename Items::value_type, class... Args>
  int check(const Items& items, const Stream<Top, Item>& s, const char* fmt = nullptr,
            Args... args) {
    return run(items, s) ? pass(fmt, args...) : 1;
  }

  // Plays `items` (a vector or deque of Item) through the unit, reset first if it has not been;
  // see the header.
  template <class Items, class Item = typename Items::value_type>
  RunResult run(const Items& items, const Stream<Top, Item>& s) {
    if (!was_reset_) reset();
    Top& t = *top_;
    constexpr bool kReadyO = requires { t.ready_o; };
    constexpr bool kReadyI = requires { t.ready_i; };
    constexpr bool kTag = requires { t.tag_i; t.tag_o; };
    struct Pending {
      size_t index;
      long issued;
      std::uint64_t tag;
    };
    std::deque<Pending> pending;
    const Traffic& tr = s.traffic;
    const auto pct = [&](int p) { return p >= 100 || static_cast<int>(drive_rng_() % 100) < p; };
    const size_t n = items.size();
    long total = 0;
    for (const Item& it : items) total += !s.yields || s.yields(it);
    const long start = cycle_, limit = s.timeout ? s.timeout : 4 * static_cast<long>(n) + 1000;
    const std::uint64_t tag_mask = s.tag_w >= 64 ? ~0ull : (1ull << s.tag_w) - 1;
    RunResult r;
    long matched = 0, phase_left = 0, latency = s.latency;
    int valid_pct = tr.valid_pct, ready_pct = tr.ready_pct;
    size_t next = 0;
    bool presenting = false, rude = false, held = false, prev_ready_i = true;
    std::uint64_t tag = 0;
    std::vector<u128> held_out;
    while (matched < total) {
      Cycle c;
      c.cycle = cycle_ - start;
      if (tr.phase_max > 0 && phase_left-- <= 0) {
        phase_left = 1 + static_cast<long>(drive_rng_() % static_cast<std::uint64_t>(tr.phase_max));
        if (!tr.valid_table.empty()) valid_pct = tr.valid_table[drive_rng_() % tr.valid_table.size()];
        if (!tr.ready_table.empty()) ready_pct = tr.ready_table[drive_rng_() % tr.ready_table.size()];
        rude = pct(tr.rude_pct);
        if (ready_pct == 0) phase_left = 1 + phase_left % 40;
      }
      bool ready_before = true;
      if constexpr (kReadyO) ready_before = t.ready_o;
      if (!presenting && next < n && pct(tr.valid_at ? tr.valid_at(c.cycle) : valid_pct)) {
        presenting = true;
        tag = drive_rng_() & tag_mask;
      }
      const bool garbage = kReadyO && rude && !ready_before && pct(70);
      const bool junk = !presenting || garbage;
      Inputs in(junk ? Inputs::kJunk : Inputs::kDrive, drive_rng_);
      if (n) s.inputs(in, t, items[std::min(next, n - 1)]);
      t.valid_i = presenting || garbage;
      if constexpr (kTag)
        if (s.tag_w) put(t.tag_i, static_cast<i128>(junk ? drive_rng_() & tag_mask : tag), s.tag_w);
      if constexpr (kReadyI) {
        c.ready_i = pct(ready_pct);
        t.ready_i = c.ready_i;
      }
      c.prev_ready_i = prev_ready_i;
      settle();
      bool ready = true;
      if constexpr (kReadyO) {
        ready = t.ready_o;
        if (ready != ready_before)
          return failed(r, "cycle %ld: ready_o follows the inputs combinationally", cycle_);
      }
      c.offered = presenting && !junk;
      c.taken = c.offered && ready;
      if (t.valid_o) {
        if (pending.empty()) return failed(r, "cycle %ld: valid_o with no item outstanding", cycle_);
        const Pending p = pending.front();
        Outputs o;
        s.outputs(o, t, items[p.index]);
        if (held && o.read() != held_out)
          return failed(r, "cycle %ld: the output changed while held (valid_o && !ready_i)", cycle_);
        held = kReadyI && !c.ready_i;
        if (held) held_out = o.read();
        if (!held) {
          if constexpr (kTag)
            if (s.tag_w) o("tag", t.tag_o, static_cast<i128>(p.tag), s.tag_w);
          const long lat = cycle_ - p.issued;
          if (latency == kSameLatency) latency = lat;
          if (latency >= 0) o.value("latency", latency, lat);
          r.max_latency = std::max(r.max_latency, lat);
          max_latency_ = std::max(max_latency_, lat);
          if (!o.ok()) return mismatch(r, s, items, p.index, o);
          if (hash_path_) hash_item(s, items[p.index], o);
          pending.pop_front();
          ++matched;
          ++matched_;
        }
      } else if (held) {
        return failed(r, "cycle %ld: valid_o dropped while held (valid_o && !ready_i)", cycle_);
      }
      c.left = n - next;
      if (s.monitor) {
        const std::string e = s.monitor(t, c);
        if (!e.empty()) return failed(r, "cycle %ld: %s", cycle_, e.c_str());
      }
      prev_ready_i = c.ready_i;
      tick();
      if (c.taken) {
        if (!s.yields || s.yields(items[next])) pending.push_back({next, cycle_ - 1, tag});
        if (r.first_taken < 0) r.first_taken = cycle_ - 1;
        r.last_taken = cycle_ - 1;
        ++next;
        presenting = false;
      }
      if (cycle_ - start > limit)
        return failed(r, "timeout after %ld cycles, %ld of %ld results, %zu of %zu items taken",
                      cycle_ - start, matched, total, next, n);
    }
    // Drained: nothing more may come out.
    t.valid_i = 0;
    if constexpr (kReadyI) t.ready_i = 1;
    for (long k = 0; k < std::max<long>(64, r.max_latency + 8); ++k) {
      settle();
      if (t.valid_o) return failed(r, "cycle %ld: valid_o after the last item", cycle_);
      tick();
    }
    r.ok = true;
    r.cycles = cycle_ - start;
    return r;
  }

 private:
  // RPU_VECTOR_HASH=file: every matched item's source, inputs and expected outputs folded into
  // one FNV-1a hash per program and arguments, appended to the file at exit ("<program args>:
  // items N hash H latency L"). Two runs with the same lines played the same vectors.
  template <class Item>
  void hash_item(const Stream<Top, Item>& s, const Item& it, const Outputs& o) {
    Inputs list(Inputs::kList, drive_rng_);
    s.inputs(list, *top_, it);
    const std::string rec = (s.what ? s.what(it) : std::string()) + "|" + list.text() + "|" +
                            o.expected() + "\n";
    for (const unsigned char ch : rec) vector_hash_ = (vector_hash_ ^ ch) * 0x100000001B3ull;
    ++hashed_;
  }
  void write_vector_hash() const {
    if (!hash_path_) return;
    std::string line = program_invocation_short_name;
    for (const std::string& a : args_) line += " " + a;
    char tail[128];
    std::snprintf(tail, sizeof tail, ": items %ld hash %016llx latency %ld\n", hashed_,
                  static_cast<unsigned long long>(vector_hash_), max_latency_);
    line += tail;
    if (std::FILE* f = std::fopen(hash_path_, "a")) {
      std::fputs(line.c_str(), f);
      std::fclose(f);
    }
  }
  // The model's options: random power-up values from RPU_X_SEED (printed), and a trace on
  // request (+trace keeps it; RPU_TRACE=1 keeps it only for a failing run).
  typename VerilatedModel<Top>::Options model_options(const char* name, int argc, char** argv) {
    const std::uint64_t x_seed = env_u64("RPU_X_SEED", 20261122);
    std::printf("%s: initial register values from x-seed %llu (set RPU_X_SEED for others)\n",
                name, static_cast<unsigned long long>(x_seed));
    for (int k = 1; k < argc; ++k) keep_trace_ = keep_trace_ || std::string(argv[k]) == "+trace";
    trace_ = keep_trace_ || env_u64("RPU_TRACE", 0) != 0;
    typename VerilatedModel<Top>::Options o;
    o.random_init = true;  // every register random at power-up (the model is --x-initial unique)
    o.x_seed = x_seed & 0x7fffffff;
    o.trace = trace_;
    o.argc = argc;
    o.argv = argv;
    o.coverage_name = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : name;
    return o;
  }
  void open_trace(const char* argv0) {
    const char* dir = std::getenv("RPU_TRACE_DIR");
    const std::string path = std::string(dir ? dir : ".") + "/" +
                             std::filesystem::path(argv0).filename().string() + ".fst";
    if (!m_.open_trace(path)) {
      std::printf("%s: this build has no trace support (configure with -DRPU_SIM_TRACE=ON)\n",
                  name_);
      return;
    }
    trace_path_ = path;
    std::printf("%s: FST trace %s\n", name_, trace_path_.c_str());
  }
  int failed() {
    failed_ = true;
    if (!trace_path_.empty()) {
      m_.flush_trace();
      std::printf("  trace: %s\n", trace_path_.c_str());
    }
    std::fflush(stdout);
    return 1;
  }
  RunResult failed(RunResult& r, const char* fmt, ...) __attribute__((format(printf, 3, 4))) {
    std::va_list ap;
    va_start(ap, fmt);
    const std::string what = vformat(fmt, ap);
    va_end(ap);
    std::printf("FAILURE %s\n", what.c_str());
    failed();
    return r;
  }
  template <class Items, class Item>
  RunResult mismatch(RunResult& r, const Stream<Top, Item>& s, const Items& items, size_t index,
                     const Outputs& o) {
    const Item& it = items[index];
    std::printf("FAILURE cycle %ld item %zu%s%s%s: %s differ%s\n", cycle_, index,
                s.what ? " (" : "", s.what ? s.what(it).c_str() : "", s.what ? ")" : "",
                o.differs().c_str(), o.differs().find(',') == std::string::npos ? "s" : "");
    Inputs list(Inputs::kList, drive_rng_);
    s.inputs(list, *top_, it);
    std::printf("  inputs: %s\n", list.text().c_str());
    o.print();
    failed();
    return r;
  }

  const char* name_;

 public:
  const std::uint64_t seed;
  std::mt19937_64 rng;  // the vector generator's stream (seed)

 private:
  std::mt19937_64 drive_rng_;  // valid gaps, backpressure, junk and tags
  bool keep_trace_ = false, trace_ = false;  // set by model_options(), before the model
  VerilatedModel<Top> m_;       // the context, the model, its trace and coverage
  Top* const top_ = m_.top.get();
  std::string trace_path_;      // the open trace's file ("" without one)
  bool failed_ = false, was_reset_ = false;
  long cycle_ = 0, matched_ = 0, max_latency_ = 0;
  const char* hash_path_ = std::getenv("RPU_VECTOR_HASH");
  std::vector<std::string> args_;
  std::uint64_t vector_hash_ = 0xCBF29CE484222325ull;
  long hashed_ = 0;
};

}  // namespace rpu::sim

// A testbench is one translation unit on this base: the project's namespace and the wide integer
// types are its vocabulary.
using namespace rpu;  // NOLINT(google-build-using-namespace)
using sim::i128;
using sim::u128;
