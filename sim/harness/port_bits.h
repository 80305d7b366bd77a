// Moving Bits and integers in and out of Verilator's C++ port types (CData … VlWide<N>).
#pragma once

#include <verilated.h>

#include "rtl_types.h"

namespace rpu::sim {

template <class T>
inline void to_port(T& port, const Bits& b) {
  std::uint64_t v = 0;
  for (size_t k = 0; k < b.words().size() && k < 2; ++k)
    v |= static_cast<std::uint64_t>(b.words()[k]) << (32 * k);
  port = static_cast<T>(v);
}
template <std::size_t N>
inline void to_port(VlWide<N>& port, const Bits& b) {
  for (std::size_t k = 0; k < N; ++k) port[k] = k < b.words().size() ? b.words()[k] : 0u;
}

template <class T>
inline u128 port_u(const T& port, int width) {
  const u128 u = static_cast<u128>(port);
  return width >= 128 ? u : (u & ((u128{1} << width) - 1));
}
template <std::size_t N>
inline u128 port_u(const VlWide<N>& port, int width) {
  u128 u = 0;
  for (std::size_t k = 0; k < N && 32 * k < 128; ++k) u |= static_cast<u128>(port[k]) << (32 * k);
  return width >= 128 ? u : (u & ((u128{1} << width) - 1));
}
template <class T>
inline i128 port_s(const T& port, int width) {
  const u128 u = port_u(port, width);
  const u128 sign = u128{1} << (width - 1);
  return static_cast<i128>((u ^ sign) - sign);
}
// Component c (0 = x) of a {z, y, x}-packed port, sign-extended.
template <class T>
inline i128 port_comp(const T& port, int c, int width) {
  Bits b(3 * width);
  if constexpr (requires { port[0]; }) {
    for (size_t k = 0; k < b.words().size(); ++k) b.words()[k] = port[k];
  } else {
    const std::uint64_t v = port;
    b.words()[0] = static_cast<std::uint32_t>(v);
    if (b.words().size() > 1) b.words()[1] = static_cast<std::uint32_t>(v >> 32);
  }
  return b.field_signed(c * width, width);
}

}  // namespace rpu::sim
