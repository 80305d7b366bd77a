// Shared pieces of the Verilator testbenches: seeds, wide-signal packing, clocking, and the
// checker's report format (ibex-style: FAILURE with the cycle and the item, or "matched N").
#pragma once

#include <verilated.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>

#include "fixed/fixed.h"

namespace rpu::sim {

using fixed::i128;
using fixed::u128;

// The seed: RPU_SEED from the environment, else a fixed default; always printed.
inline std::uint64_t test_seed(const char* name, std::uint64_t fallback = 20261121) {
  const char* env = std::getenv("RPU_SEED");
  const std::uint64_t seed = env ? std::strtoull(env, nullptr, 0) : fallback;
  std::printf("%s: seed %llu (set RPU_SEED to reproduce another)\n", name,
              static_cast<unsigned long long>(seed));
  return seed;
}

// A Verilated context whose registers all start random (every model is built --x-initial
// unique): a register the reset forgets, or a reset that never comes, shows as a mismatch
// instead of hiding behind all-zero power-up values. RPU_X_SEED picks the values (printed).
inline std::unique_ptr<VerilatedContext> make_context(const char* name) {
  const char* env = std::getenv("RPU_X_SEED");
  const std::uint64_t seed = env ? std::strtoull(env, nullptr, 0) : 20261122;
  std::printf("%s: initial register values from x-seed %llu (set RPU_X_SEED for others)\n", name,
              static_cast<unsigned long long>(seed));
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->randReset(2);
  ctx->randSeed(static_cast<int>(seed & 0x7fffffff));
  return ctx;
}

// Vector count: RPU_VECTORS from the environment scales the default (opt-in long runs).
inline long vector_count(long fallback) {
  const char* env = std::getenv("RPU_VECTORS");
  return env ? std::strtol(env, nullptr, 0) : fallback;
}

inline std::string to_string(i128 v) { return fixed::to_decimal(v); }

// Writing a `width`-bit two's-complement value into a Verilator port of any size.
// Only the port's `width` bits are written: Verilator assumes the bits above a narrow port are
// zero, so a negative value must not set them (they would leak into the logic).
inline u128 port_mask(int width) { return width >= 128 ? ~u128{0} : (u128{1} << width) - 1; }
inline void put(CData& port, i128 v, int width) {
  port = static_cast<CData>(static_cast<u128>(v) & port_mask(width));
}
inline void put(SData& port, i128 v, int width) {
  port = static_cast<SData>(static_cast<u128>(v) & port_mask(width));
}
inline void put(IData& port, i128 v, int width) {
  port = static_cast<IData>(static_cast<u128>(v) & port_mask(width));
}
inline void put(QData& port, i128 v, int width) {
  port = static_cast<QData>(static_cast<u128>(v) & port_mask(width));
}
template <std::size_t N>
void put(VlWide<N>& port, i128 v, int width) {
  const u128 u = static_cast<u128>(v);
  for (std::size_t k = 0; k < N; ++k) {
    const int lo = static_cast<int>(32 * k);
    std::uint32_t word = 0;
    if (lo < 128) word = static_cast<std::uint32_t>(u >> lo);
    else word = v < 0 ? 0xFFFFFFFFu : 0u;
    if (lo + 32 > width) word &= width > lo ? (0xFFFFFFFFu >> (lo + 32 - width)) : 0u;
    port[k] = word;
  }
}

// Reading a port as an unsigned or a sign-extended `width`-bit value.
template <class T>
u128 get_unsigned(const T& port, int width) {
  const u128 u = static_cast<u128>(port);
  return width >= 128 ? u : (u & ((u128{1} << width) - 1));
}
template <std::size_t N>
u128 get_unsigned(const VlWide<N>& port, int width) {
  u128 u = 0;
  for (std::size_t k = 0; k < N && 32 * k < 128; ++k) u |= static_cast<u128>(port[k]) << (32 * k);
  return width >= 128 ? u : (u & ((u128{1} << width) - 1));
}
template <class T>
i128 get_signed(const T& port, int width) {
  const u128 u = get_unsigned(port, width);
  const u128 sign = u128{1} << (width - 1);
  return static_cast<i128>((u ^ sign) - sign);
}

// A 3-component vector packed {z, y, x}, each component `width` bits, into a wide port.
template <std::size_t N>
void put_vec3(VlWide<N>& port, i128 x, i128 y, i128 z, int width) {
  for (std::size_t k = 0; k < N; ++k) port[k] = 0;
  const i128 comps[3] = {x, y, z};
  for (int c = 0; c < 3; ++c) {
    const u128 u = static_cast<u128>(comps[c]);
    for (int b = 0; b < width; ++b) {
      const bool bit = b < 128 ? ((u >> b) & 1) != 0 : comps[c] < 0;
      if (bit) port[static_cast<std::size_t>((c * width + b) / 32)] |= 1u << ((c * width + b) % 32);
    }
  }
}
inline void put_vec3(QData& port, i128 x, i128 y, i128 z, int width) {
  const u128 m = (u128{1} << width) - 1;
  port = static_cast<QData>((static_cast<u128>(x) & m) | ((static_cast<u128>(y) & m) << width) |
                            ((static_cast<u128>(z) & m) << (2 * width)));
}
inline void put_vec3(IData& port, i128 x, i128 y, i128 z, int width) {
  QData q = 0;
  put_vec3(q, x, y, z, width);
  port = static_cast<IData>(q);
}
// Component c (0 = x) of a {z, y, x}-packed port, sign-extended.
template <std::size_t N>
i128 get_comp(const VlWide<N>& port, int c, int width) {
  u128 u = 0;
  for (int b = 0; b < width; ++b) {
    const int bit = c * width + b;
    if ((port[static_cast<std::size_t>(bit / 32)] >> (bit % 32)) & 1) u |= u128{1} << b;
  }
  const u128 sign = u128{1} << (width - 1);
  return static_cast<i128>((u ^ sign) - sign);
}
template <class T>
i128 get_comp(const T& port, int c, int width) {
  const u128 u = (static_cast<u128>(port) >> (c * width)) & ((u128{1} << width) - 1);
  const u128 sign = u128{1} << (width - 1);
  return static_cast<i128>((u ^ sign) - sign);
}

// One clock cycle: inputs set before the rising edge, outputs read after it.
template <class Top>
void tick(Top& top, VerilatedContext& ctx) {
  top.clk_i = 0;
  top.eval();
  ctx.timeInc(1);
  top.clk_i = 1;
  top.eval();
  ctx.timeInc(1);
}

template <class Top>
void reset(Top& top, VerilatedContext& ctx, int cycles = 4) {
  top.rst_ni = 0;
  for (int k = 0; k < cycles; ++k) tick(top, ctx);
  top.rst_ni = 1;
}

}  // namespace rpu::sim
