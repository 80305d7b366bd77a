// Types and helpers the unit twins share (ref/model/*/rpu_*.h); no RTL module of its own.
// Integer arithmetic only; every format is in docs/fixed-point.md and every narrowing is a named
// fixed:: operation.
#pragma once

#include "model/descriptors.h"

namespace rpu::ref {

using fixed::Overflow;

// Wide integer vector for intermediates (format named where it is produced).
struct WVec3 {
  i128 x = 0, y = 0, z = 0;
  bool operator==(const WVec3&) const = default;
};

inline i128 dot(const WVec3& a, const WVec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline WVec3 widen(const IVec3& v) { return {v.x, v.y, v.z}; }
inline WVec3 operator+(const WVec3& a, const WVec3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline WVec3 operator-(const WVec3& a, const WVec3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
// Each component times k, then `bits` fraction bits dropped (floor).
inline WVec3 scale_truncate(const WVec3& v, i128 k, int bits) {
  return {fixed::truncate(v.x * k, bits), fixed::truncate(v.y * k, bits),
          fixed::truncate(v.z * k, bits)};
}
inline WVec3 saturate_vec(const WVec3& v, int width, Overflow& ovf) {
  return {fixed::saturate(v.x, width, ovf), fixed::saturate(v.y, width, ovf),
          fixed::saturate(v.z, width, ovf)};
}

}  // namespace rpu::ref
