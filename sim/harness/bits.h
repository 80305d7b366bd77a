// The one bit-packing helper of the simulation: a little-endian bit vector of any width and the
// two's-complement fields packed in it, LSB first (Bits::push) or MSB first like a Verilog
// concatenation (Concat). The co-simulation harness packs descriptors with it, the SystemC
// harness and the stream files carry it, and port_bits.h moves it and single fields in and out
// of Verilator's port types for the harness and the unit testbenches. No Verilator header here.
#pragma once

#include <cstdint>
#include <vector>

#include "fixed/fixed.h"

namespace rpu::sim {

using fixed::i128;
using fixed::u128;

// The low `w` bits of u (all of them for w ≥ 128), and those bits read as a signed value.
inline u128 low_bits(u128 u, int w) { return w >= 128 ? u : u & ((u128{1} << w) - 1); }
inline i128 sign_extend(u128 u, int w) {
  if (w >= 128) return static_cast<i128>(u);
  const u128 sign = u128{1} << (w - 1);
  return static_cast<i128>((low_bits(u, w) ^ sign) - sign);
}

// Bit k is bit k % 32 of word k / 32.
class Bits {
 public:
  Bits() = default;
  explicit Bits(int width) : width_(width), words_(static_cast<size_t>((width + 31) / 32), 0u) {}
  int width() const { return width_; }
  const std::vector<std::uint32_t>& words() const { return words_; }
  std::vector<std::uint32_t>& words() { return words_; }
  bool bit(int k) const { return (words_[static_cast<size_t>(k / 32)] >> (k % 32)) & 1u; }
  void set_bit(int k, bool v) {
    std::uint32_t& w = words_[static_cast<size_t>(k / 32)];
    const std::uint32_t m = 1u << (k % 32);
    w = v ? (w | m) : (w & ~m);
  }
  // Field [lo, lo + w) as unsigned or sign-extended (w ≤ 128; bits past the width read 0).
  u128 field(int lo, int w) const {
    u128 u = 0;
    for (int b = 0; b < w; ++b)
      if (lo + b < width_ && bit(lo + b)) u |= u128{1} << b;
    return u;
  }
  i128 field_signed(int lo, int w) const { return sign_extend(field(lo, w), w); }
  // Writes v's low w bits at lo (two's complement: beyond 128 bits, copies of the sign).
  void set_field(int lo, int w, i128 v) {
    const u128 u = static_cast<u128>(v);
    for (int b = 0; b < w; ++b) set_bit(lo + b, b < 128 ? ((u >> b) & 1) != 0 : v < 0);
  }
  // Appends a w-bit field above the ones before it (LSB-first packing).
  Bits& push(i128 v, int w) {
    const int lo = width_;
    width_ += w;
    words_.resize(static_cast<size_t>((width_ + 31) / 32), 0u);
    set_field(lo, w, v);
    return *this;
  }
  // A vector {z, y, x} of w-bit components (x in the lowest bits).
  Bits& push3(i128 x, i128 y, i128 z, int w) { return push(x, w).push(y, w).push(z, w); }
  template <class V>
  Bits& push3(const V& v, int w) {
    return push3(v.x, v.y, v.z, w);
  }

 private:
  int width_ = 0;
  std::vector<std::uint32_t> words_;
};

// Packs fields MSB first, like a Verilog concatenation {a, b, c}; values are two's complement.
class Concat {
 public:
  void add(i128 value, int width) { fields_.push_back({value, width}); }
  void add3(i128 x, i128 y, i128 z, int width) {  // {z, y, x}
    add(z, width);
    add(y, width);
    add(x, width);
  }
  int width() const {
    int w = 0;
    for (const auto& f : fields_) w += f.width;
    return w;
  }
  Bits bits() const {
    Bits b;
    for (auto it = fields_.rbegin(); it != fields_.rend(); ++it) b.push(it->value, it->width);
    return b;
  }

 private:
  struct Field {
    i128 value;
    int width;
  };
  std::vector<Field> fields_;
};

}  // namespace rpu::sim
