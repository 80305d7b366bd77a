// Values and Bits in and out of Verilator's C++ port types (CData, SData, IData, QData and
// VlWide<N>), for the co-simulation harness and the unit testbenches. A port of w bits takes only
// its w bits: Verilator assumes the bits above a port's width are 0, so a negative value must
// not set them (they would leak into the logic).
#pragma once

#include <verilated.h>

#include "bits.h"

namespace rpu::sim {

// Bits into a port (the words the port holds; the rest of the port cleared) and back.
template <class T>
void put(T& port, const Bits& b) {
  std::uint64_t v = 0;
  for (size_t k = 0; k < b.words().size() && k < 2; ++k)
    v |= static_cast<std::uint64_t>(b.words()[k]) << (32 * k);
  port = static_cast<T>(v);
}
template <std::size_t N>
void put(VlWide<N>& port, const Bits& b) {
  for (std::size_t k = 0; k < N; ++k) port[k] = k < b.words().size() ? b.words()[k] : 0u;
}
template <class T>
Bits get_bits(const T& port, int width) {
  Bits b(width);
  const std::uint64_t v = static_cast<std::uint64_t>(port);
  for (size_t k = 0; k < b.words().size() && k < 2; ++k)
    b.words()[k] = static_cast<std::uint32_t>(v >> (32 * k));
  return b;
}
template <std::size_t N>
Bits get_bits(const VlWide<N>& port, int width) {
  Bits b(width);
  for (std::size_t k = 0; k < N && k < b.words().size(); ++k) b.words()[k] = port[k];
  return b;
}

// A w-bit two's-complement value into a port of (at least) w bits, the bits above it cleared.
template <class T>
void put(T& port, i128 v, int width) {
  port = static_cast<T>(low_bits(static_cast<u128>(v), width));
}
template <std::size_t N>
void put(VlWide<N>& port, i128 v, int width) {
  Bits b(static_cast<int>(32 * N));
  b.set_field(0, width, v);
  put(port, b);
}

// A port's low w bits (w ≤ 128), unsigned or sign-extended.
template <class T>
u128 get_unsigned(const T& port, int width) {
  return low_bits(static_cast<u128>(port), width);
}
template <std::size_t N>
u128 get_unsigned(const VlWide<N>& port, int width) {
  u128 u = 0;
  for (std::size_t k = 0; k < N && 32 * k < 128; ++k) u |= static_cast<u128>(port[k]) << (32 * k);
  return low_bits(u, width);
}
template <class T>
i128 get_signed(const T& port, int width) {
  return sign_extend(get_unsigned(port, width), width);
}

// A vector {z, y, x} of w-bit components, and component c (0 = x) of one, sign-extended.
template <class P>
void put_vec3(P& port, i128 x, i128 y, i128 z, int width) {
  put(port, Bits().push3(x, y, z, width));
}
template <class P, class V>
void put_vec3(P& port, const V& v, int width) {
  put_vec3(port, v.x, v.y, v.z, width);
}
template <class P>
i128 get_comp(const P& port, int c, int width) {
  return get_bits(port, 3 * width).field_signed(c * width, width);
}

}  // namespace rpu::sim
