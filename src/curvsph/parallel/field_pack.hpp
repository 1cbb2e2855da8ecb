#pragma once
// Per-particle fields of Particles<D> to bytes and back, for migration (every field) and
// halo copies (every field a neighbour pass reads). Field-major: all values of the first
// field for the listed particles, then the next field, ..., so a message of k particles is
// k * record_bytes() bytes and needs no per-particle header.
#include <cstddef>
#include <cstring>
#include <string_view>
#include <type_traits>
#include <vector>

#include "curvsph/core/particles.hpp"

namespace curvsph::mpi {

// Which fields travel: every field, or the fields a halo copy needs (acceleration and
// density rate are results of the owner's passes; a halo copy's are never read).
enum class FieldSet { all, halo };

inline bool travels(std::string_view name, FieldSet set) {
  return set == FieldSet::all || (name != "acceleration" && name != "density_rate");
}

template <class T>
T zero_value() {
  if constexpr (std::is_arithmetic_v<T>)
    return T(0);
  else
    return T::Zero();
}

template <int D>
std::size_t record_bytes(const Particles<D>& P, FieldSet set) {
  std::size_t b = 0;
  P.for_each_field([&](const char* name, const auto& data) {
    using T = typename std::decay_t<decltype(data)>::value_type;
    if (travels(name, set)) b += sizeof(T);
  });
  return b;
}

// Appends the listed particles' fields to out.
template <int D, class Idx>
void pack(const Particles<D>& P, const std::vector<Idx>& idx, FieldSet set,
          std::vector<std::byte>& out) {
  std::size_t at = out.size();
  out.resize(at + idx.size() * record_bytes(P, set));
  P.for_each_field([&](const char* name, const auto& data) {
    using T = typename std::decay_t<decltype(data)>::value_type;
    // Fixed-size Eigen vectors are plain arrays of scalars (not formally trivially copyable
    // because of their user-declared constructors); the other fields are arithmetic.
    if constexpr (!std::is_arithmetic_v<T>)
      static_assert(sizeof(T) == sizeof(typename T::Scalar) * T::SizeAtCompileTime);
    if (!travels(name, set)) return;
    for (const Idx i : idx) {
      std::memcpy(out.data() + at, &data[static_cast<std::size_t>(i)], sizeof(T));
      at += sizeof(T);
    }
  });
}

// Appends the particles of a message written by pack() (same FieldSet); fields that did not
// travel are zero. Returns the number of particles appended.
template <int D>
std::size_t unpack_append(Particles<D>& P, const std::vector<std::byte>& in, FieldSet set) {
  const std::size_t rec = record_bytes(P, set);
  const std::size_t k = rec ? in.size() / rec : 0;
  const std::size_t n0 = P.size();
  std::size_t at = 0;
  P.for_each_field([&](const char* name, auto& data) {
    using T = typename std::decay_t<decltype(data)>::value_type;
    data.resize(n0 + k, zero_value<T>());
    if (!travels(name, set)) return;
    std::memcpy(static_cast<void*>(data.data() + n0), in.data() + at, k * sizeof(T));
    at += k * sizeof(T);
  });
  return k;
}

}  // namespace curvsph::mpi
