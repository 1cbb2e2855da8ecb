#pragma once
// Particles in structure-of-arrays. Every per-particle field lives here, so a single
// permute() reorders all of them at once (no module sorts its own data) and the output
// writers can visit every field by name.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph {

template <int D>
struct Particles {
  // Kinematics.
  std::vector<Vec<D>> x;  // position
  std::vector<Vec<D>> v;  // velocity
  std::vector<Vec<D>> a;  // acceleration (rate of v)
  // Thermodynamics.
  std::vector<Real> mass;
  std::vector<Real> rho;    // density
  std::vector<Real> drho;   // rate of rho (continuity path)
  std::vector<Real> p;      // pressure
  std::vector<Real> sigma;  // number density sum_j W_ij (Barker eq. 8)
  // Identity.
  std::vector<std::int32_t> phase;  // index into the case's fluids
  std::vector<std::int64_t> id;     // stable id across permutations
  // Open boundaries (solver/open_boundaries.hpp): 0 for a fluid particle, k + 1 for a buffer
  // particle of open boundary k (a neighbour of the fluid, not integrated as fluid).
  std::vector<std::int32_t> buffer;

  std::size_t size() const { return x.size(); }

  void resize(std::size_t n) {
    x.resize(n, Vec<D>::Zero());
    v.resize(n, Vec<D>::Zero());
    a.resize(n, Vec<D>::Zero());
    mass.resize(n, 0);
    rho.resize(n, 0);
    drho.resize(n, 0);
    p.resize(n, 0);
    sigma.resize(n, 0);
    phase.resize(n, 0);
    id.resize(n, 0);
    buffer.resize(n, 0);
  }

  // Visit every field: scalar(name, data) for Real arrays, vector(name, data) for Vec arrays,
  // integer(name, data) for integer arrays. Adding a field means adding it here once.
  template <class F>
  void for_each_field(F&& f) {
    f("position", x);
    f("velocity", v);
    f("acceleration", a);
    f("mass", mass);
    f("density", rho);
    f("density_rate", drho);
    f("pressure", p);
    f("number_density", sigma);
    f("phase", phase);
    f("id", id);
    f("buffer", buffer);
  }
  template <class F>
  void for_each_field(F&& f) const {
    const_cast<Particles*>(this)->for_each_field(
        [&](const char* name, const auto& data) { f(name, data); });
  }

  // Bytes held by the fields (capacity, not size) plus the re-sort scratch that permute()
  // keeps alive after its first call: one buffer of n elements per field element type
  // (Vec, Real, int32, int64).
  std::size_t bytes() const {
    std::size_t b = 0;
    for_each_field([&](const char*, const auto& data) {
      b += data.capacity() * sizeof(typename std::decay_t<decltype(data)>::value_type);
    });
    return b +
           size() * (sizeof(Vec<D>) + sizeof(Real) + sizeof(std::int32_t) + sizeof(std::int64_t));
  }

  // Reorder every field: new[k] = old[order[k]].
  void permute(const std::vector<std::size_t>& order) {
    for_each_field([&](const char*, auto& data) { apply(data, order); });
  }

 private:
  template <class T>
  static void apply(std::vector<T>& data, const std::vector<std::size_t>& order) {
    // One scratch buffer per element type, swapped with the field: after the first re-sort
    // the buffers have the right size and a re-sort allocates nothing.
    static thread_local std::vector<T> tmp;
    tmp.resize(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) tmp[k] = data[order[k]];
    data.swap(tmp);
  }
};

// The particles a neighbour pass computes: [0, owned) — an MPI rank's owned particles; the
// halo copies behind them are neighbours only, their fields come from their owners — or every
// particle when owned < 0 (one rank, tests).
template <int D>
Index computed_count(const Particles<D>& P, Index owned) {
  const auto n = static_cast<Index>(P.size());
  return owned < 0 ? n : std::min(owned, n);
}

}  // namespace curvsph
