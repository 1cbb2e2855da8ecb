// Solver::save_state / load_state (solver/restart_state.hpp): everything the next step reads
// that a step leaves behind, so that a restarted run repeats the straight run's arithmetic.
// What a step leaves for the next: every particle field, in the solver's order (the sums add
// in that order), a (the first kick reads it; recomputing it at the shifted positions gives
// other forces: 1.3e-5 in velocity one step later in a Taylor-Green run), rho and drho, the
// transport-velocity push b, the cell order of the last neighbour build (the next re-sort,
// every kResortEvery steps, applies it), t, dt and the step count, and the counters reported
// in metrics.json. Scratch arrays (pair factors, shift sums, density gradients, the boundary
// models' ghosts and Shepard factors) are recomputed from the positions at every step.
#include <fmt/format.h>

#include <cmath>

#include "curvsph/core/error.hpp"
#include "curvsph/solver/restart_state.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {

template <int D>
void Solver<D>::save_state(RestartState& s) const {
  // [mpi] every particle on rank 0 (the others return with an empty state); a run on several
  // ranks restarts, but not bit for bit (the ranks' order of sums is not kept).
  const bool parallel = decomp_.active();
  const Particles<D> gathered = parallel ? decomp_.gather(P_) : Particles<D>();
  const mpi::Comm& comm = decomp_.comm();
  const auto total = [&](long v) { return comm.sum(static_cast<std::int64_t>(v)); };
  const std::int64_t clamped = total(stray_.density_clamped), projected = total(stray_.projected),
                     removed = total(stray_.removed), contacts = total(stray_.contacts);
  if (!comm.root()) return;
  const Particles<D>& P = parallel ? gathered : P_;
  auto& h = s.header;
  h["time"] = t_;
  h["dt"] = static_cast<double>(dt_);
  h["stable_step"] = static_cast<double>(stable_step_);
  h["steps"] = steps_;
  h["ranks"] = comm.size();
  h["density_clamped"] = clamped;
  h["particles_projected"] = projected;
  h["particles_removed"] = removed;
  h["wall_contacts"] = contacts;
  h["particles_initial"] = initial_count_;
  if (open_.active()) h["outflow_density_level"] = static_cast<double>(open_.density_level());
  if (initial_density_error_)
    h["initial_density_error"] = {{"max", initial_density_error_->max},
                                  {"local", initial_density_error_->local},
                                  {"local_above_1pct", initial_density_error_->local_above_1pct}};
  const std::size_t n = P.size();
  P.for_each_field([&](const char* name, const auto& data) {
    using T = typename std::decay_t<decltype(data)>::value_type;
    if constexpr (std::is_same_v<T, Vec<D>>) {
      std::vector<double> flat(D * n);
      for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < D; ++k) flat[D * i + static_cast<std::size_t>(k)] = data[i][k];
      s.reals[name] = std::move(flat);
    } else if constexpr (std::is_floating_point_v<T>) {
      s.reals[name] = std::vector<double>(data.begin(), data.end());
    } else {
      s.ints[name] = std::vector<std::int64_t>(data.begin(), data.end());
    }
  });
  std::vector<std::int64_t> ids(contacted_.begin(), contacted_.end());
  std::sort(ids.begin(), ids.end());
  s.ints["contacted_ids"] = std::move(ids);
  if (parallel) return;
  if (tv_.b.size() == n) {
    std::vector<double> flat(D * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < D; ++k) flat[D * i + static_cast<std::size_t>(k)] = tv_.b[i][k];
    s.reals["transport_push"] = std::move(flat);
  }
  // The order resort() would apply (the last build's cell order), for a run that stops
  // before its next re-sort.
  std::vector<std::int64_t> order;
  for (const Index k : cells_.sorted())
    if (k < static_cast<Index>(n)) order.push_back(k);
  if (order.size() == n) s.ints["resort_order"] = std::move(order);
}

template <int D>
void Solver<D>::load_state(const RestartState& s, const std::string& file) {
  // The removal box is the initial particles' (solver.cpp initialize()): this solver's
  // particles are still the case's initial ones here.
  removal_box_ = removal_box<D>(case_.has_domain, case_.domain_min, case_.domain_max,
                                case_.periodic, P_.x, walls_, case_.dx);
  const std::vector<std::int64_t>& ids = int_array(s, "id", -1, file);
  const auto n = static_cast<std::int64_t>(ids.size());
  Particles<D> P;
  P.resize(ids.size());
  P.for_each_field([&](const char* name, auto& data) {
    using T = typename std::decay_t<decltype(data)>::value_type;
    if constexpr (std::is_same_v<T, Vec<D>>) {
      const auto& flat = real_array(s, name, D * n, file);
      for (std::size_t i = 0; i < data.size(); ++i)
        for (int k = 0; k < D; ++k)
          data[i][k] = static_cast<Real>(flat[D * i + static_cast<std::size_t>(k)]);
    } else if constexpr (std::is_floating_point_v<T>) {
      const auto& v = real_array(s, name, n, file);
      for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<T>(v[i]);
    } else {
      const auto& v = int_array(s, name, n, file);
      for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<T>(v[i]);
    }
  });
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.phase[i] < 0 || static_cast<std::size_t>(P.phase[i]) >= F_.rho0.size())
      throw InputError(file, "arrays.phase",
                       fmt::format("particle {} has phase {}, the case has {} fluids", i,
                                   P.phase[i], F_.rho0.size()));
  const double t = header_number(s, "time", file);
  const std::int64_t steps = header_integer(s, "steps", file);
  if (!std::isfinite(t) || steps < 0)
    throw InputError(file, "time", "time and steps must be finite and >= 0");
  P_ = std::move(P);
  for (Index i = 0; i < static_cast<Index>(P_.size()); ++i) cells_.wrap(P_.x[i]);
  t_ = t;
  steps_ = static_cast<long>(steps);
  dt_ = static_cast<Real>(header_number(s, "dt", file));
  stable_step_ = static_cast<Real>(header_number(s, "stable_step", file));
  initial_count_ = header_integer(s, "particles_initial", file);
  // [mpi] the counters are totals over the ranks: rank 0 carries them on.
  const bool root = decomp_.comm().root();
  const auto counter = [&](const char* key) {
    return root ? static_cast<long>(header_integer(s, key, file)) : 0L;
  };
  stray_.density_clamped = counter("density_clamped");
  stray_.projected = counter("particles_projected");
  stray_.removed = counter("particles_removed");
  stray_.contacts = counter("wall_contacts");
  contacted_.clear();
  if (root)
    for (const std::int64_t id : int_array(s, "contacted_ids", -1, file)) contacted_.insert(id);
  if (const auto it = s.header.find("outflow_density_level");
      it != s.header.end() && it->is_number())
    open_.set_density_level(static_cast<Real>(it->get<double>()));
  if (const auto it = s.header.find("initial_density_error");
      it != s.header.end() && it->is_object()) {
    InitialDensityError e;
    try {
      e.max = it->value("max", 0.0);
      e.local = it->value("local", 0.0);
      e.local_above_1pct = it->value("local_above_1pct", 0L);
    } catch (const nlohmann::json::exception& x) {
      throw InputError(file, "initial_density_error", x.what());
    }
    initial_density_error_ = e;
  }
  tv_.b.clear();
  if (tv_.enabled() && s.reals.count("transport_push")) {
    const auto& flat = real_array(s, "transport_push", D * n, file);
    tv_.b.resize(P_.size());
    for (std::size_t i = 0; i < P_.size(); ++i)
      for (int k = 0; k < D; ++k)
        tv_.b[i][k] = static_cast<Real>(flat[D * i + static_cast<std::size_t>(k)]);
  }
  restart_order_.clear();
  if (s.ints.count("resort_order")) {
    const auto& order = int_array(s, "resort_order", n, file);
    std::vector<char> seen(P_.size(), 0);
    for (const std::int64_t k : order) {
      if (k < 0 || k >= n || seen[static_cast<std::size_t>(k)])
        throw InputError(file, "arrays.resort_order", "is not a permutation of the particles");
      seen[static_cast<std::size_t>(k)] = 1;
      restart_order_.push_back(static_cast<Index>(k));
    }
  }
  restored_ = true;
}

template void Solver<2>::save_state(RestartState&) const;
template void Solver<3>::save_state(RestartState&) const;
template void Solver<2>::load_state(const RestartState&, const std::string&);
template void Solver<3>::load_state(const RestartState&, const std::string&);

}  // namespace curvsph
