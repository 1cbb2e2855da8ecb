#pragma once
// Selections without a branch, for tests that go either way about as often (a kernel
// evaluated at points near the edge of its support): a mispredicted branch costs ~15-20
// cycles, more than the whole evaluation. g++ 12 keeps `c ? x : 0` on doubles a branch even
// at -O3 (it will not if-convert a scalar floating-point select), so the select is done on
// the bits.
#include <bit>
#include <cstdint>
#include <type_traits>

namespace curvsph {

// x where c holds, +0 (all bits clear) otherwise.
template <class T>
inline T keep_if(bool c, T x) {
  static_assert(std::is_floating_point_v<T> && (sizeof(T) == 4 || sizeof(T) == 8));
  using U = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
  return std::bit_cast<T>(std::bit_cast<U>(x) & (U(0) - U(c)));
}

}  // namespace curvsph
