#include "curvsph/solver/open_boundaries.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "curvsph/core/error.hpp"
#include "curvsph/core/parallel.hpp"
#include "curvsph/parallel/field_pack.hpp"

namespace curvsph {
namespace {

template <int D>
Vec<D> head(const Vec3d& v) {
  return v.head<D>().template cast<Real>();
}

}  // namespace

template <int D>
OpenBoundaries<D>::OpenBoundaries(const Case& c, Real support)
    : specs_(c.open_boundaries), file_(c.file_name()) {
  dx_ = static_cast<Real>(c.dx);
  layers_ = static_cast<int>(std::ceil(support / dx_ - Real(1e-9)));
  depth_ = static_cast<Real>(layers_) * dx_;
  rho0_ = c.fluids.empty() ? Real(1) : static_cast<Real>(c.fluids[0].rho0);
  has_box_ = c.has_domain;
  box_lo_ = c.domain_min.head<D>();
  box_hi_ = c.domain_max.head<D>();
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    const OpenBoundarySpec& s = specs_[k];
    Plane pl;
    pl.point = head<D>(s.point);
    pl.normal = head<D>(s.normal);
    if constexpr (D == 2) {
      pl.tangent[0] = Vec<2>(-pl.normal.y(), pl.normal.x());
    } else {
      // The rectangle's edges are coordinate axes (checked by the reader); otherwise any
      // orthonormal pair: the lattice of the buffer's cross section.
      int axis = 0;
      pl.normal.cwiseAbs().minCoeff(&axis);
      Vec<3> e = Vec<3>::Zero();
      e[axis] = 1;
      if (s.profile == OpenBoundarySpec::Profile::rectangle) {
        int n_axis = 0;
        pl.normal.cwiseAbs().maxCoeff(&n_axis);
        const int a = (n_axis + 1) % 3, b = (n_axis + 2) % 3;
        pl.tangent[0] = Vec<3>::Unit(std::min(a, b));
        pl.tangent[1] = Vec<3>::Unit(std::max(a, b));
      } else {
        pl.tangent[0] = e.cross(pl.normal).normalized();
        pl.tangent[1] = pl.normal.cross(pl.tangent[0]);
      }
    }
    planes_.push_back(pl);
    // Boundary integrals clip plane walls to the domain box: the walls of a channel must
    // continue one kernel support under the buffer for the fluid at the boundary's corners.
    if (c.boundary.method == "integrals" && c.has_domain) {
      const VecD<D> behind = s.point.head<D>() - static_cast<double>(support) * s.normal.head<D>();
      for (int d = 0; d < D; ++d)
        if (behind[d] < box_lo_[d] - 1e-9 * dx_ || behind[d] > box_hi_[d] + 1e-9 * dx_)
          throw InputError(file_, fmt::format("open_boundaries.{}.point", k),
                           fmt::format("with boundary.method: integrals the domain box must "
                                       "reach one kernel support ({:.4g}) behind the boundary, "
                                       "so that the walls' elements continue under its buffer",
                                       static_cast<double>(support)));
    }
  }
}

template <int D>
bool OpenBoundaries<D>::in_section(std::size_t k, const Vec<D>& x) const {
  const OpenBoundarySpec& s = specs_[k];
  const Vec<D> q = x - distance(k, x) * planes_[k].normal;  // onto the plane
  const Real slack = dx_ / 4;  // a point on a face of the box; lattice points lie dx/2 in
  if (has_box_)
    for (int d = 0; d < D; ++d)
      if (q[d] < box_lo_[d] - slack || q[d] > box_hi_[d] + slack) return false;
  switch (s.profile) {
    case OpenBoundarySpec::Profile::segment: {
      const Vec<D> a = head<D>(s.from), e = head<D>(s.to) - a;
      const Real u = (q - a).dot(e) / e.squaredNorm();
      return u >= 0 && u <= 1;
    }
    case OpenBoundarySpec::Profile::rectangle:
      for (int t = 0; t < D - 1; ++t) {
        const Real qt = q.dot(planes_[k].tangent[t]);
        const Real a = head<D>(s.from).dot(planes_[k].tangent[t]);
        const Real b = head<D>(s.to).dot(planes_[k].tangent[t]);
        if (qt < std::min(a, b) || qt > std::max(a, b)) return false;
      }
      return true;
    case OpenBoundarySpec::Profile::circle:
      return (q - head<D>(s.center)).norm() <= static_cast<Real>(s.radius);
    case OpenBoundarySpec::Profile::uniform:
    default:
      return true;
  }
}

template <int D>
Real OpenBoundaries<D>::profile(std::size_t k, const Vec<D>& x) const {
  const OpenBoundarySpec& s = specs_[k];
  const Vec<D> q = x - distance(k, x) * planes_[k].normal;
  switch (s.profile) {
    case OpenBoundarySpec::Profile::segment: {  // plane Poiseuille: 4 s (1 - s)
      const Vec<D> a = head<D>(s.from), e = head<D>(s.to) - a;
      const Real u = (q - a).dot(e) / e.squaredNorm();
      return std::max(Real(0), 4 * u * (1 - u));
    }
    case OpenBoundarySpec::Profile::rectangle: {
      // Schäfer & Turek (1996) 3-D inflow: 16 y z (H - y)(H - z) / H^4 on a square.
      Real f = 1;
      for (int t = 0; t < D - 1; ++t) {
        const Vec<D>& e = planes_[k].tangent[t];
        const Real a = head<D>(s.from).dot(e), b = head<D>(s.to).dot(e);
        const Real u = (q.dot(e) - std::min(a, b)) / std::abs(b - a);
        f *= std::max(Real(0), 4 * u * (1 - u));
      }
      return f;
    }
    case OpenBoundarySpec::Profile::circle: {  // Hagen-Poiseuille: 1 - r^2 / R^2
      const Real r2 = (q - head<D>(s.center)).squaredNorm();
      return std::max(Real(0), 1 - r2 / static_cast<Real>(s.radius * s.radius));
    }
    case OpenBoundarySpec::Profile::uniform:
    default:
      return 1;
  }
}

template <int D>
Vec<D> OpenBoundaries<D>::inflow_velocity(std::size_t k, const Vec<D>& x, double t) const {
  const OpenBoundarySpec& s = specs_[k];
  const Real ramp = s.ramp > 0 ? static_cast<Real>(std::min(1.0, t / s.ramp)) : Real(1);
  if (s.profile == OpenBoundarySpec::Profile::uniform) return ramp * head<D>(s.velocity);
  return ramp * static_cast<Real>(s.u_max) * profile(k, x) * planes_[k].normal;
}

template <int D>
void OpenBoundaries<D>::setup(Particles<D>& P, const WallSet<D>& walls) {
  if (!has_box_ && P.size() > 0) {  // the lateral bound: the box of the fill
    box_lo_ = box_hi_ = P.x[0].template cast<double>();
    for (const auto& x : P.x) {
      box_lo_ = box_lo_.cwiseMin(x.template cast<double>());
      box_hi_ = box_hi_.cwiseMax(x.template cast<double>());
    }
    // The lattice's cell faces: the fluid region's box.
    box_lo_.array() -= 0.5 * static_cast<double>(dx_);
    box_hi_.array() += 0.5 * static_cast<double>(dx_);
    has_box_ = true;
  }
  const Real support = depth_;  // >= 2h
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    bool fluid = false;
    for (std::size_t i = 0; i < P.size() && !fluid; ++i) {
      const Real d = distance(k, P.x[i]);
      fluid = d >= 0 && d < support && in_section(k, P.x[i]);
    }
    if (!fluid)
      throw InputError(file_, fmt::format("open_boundaries.{}.normal", k),
                       "no fluid particle within one kernel support in front of the boundary "
                       "(the normal must point into the fluid, and the fluid region reach the "
                       "boundary)");
  }
  // Fill particles behind a boundary, within its cross section, are not fluid.
  keep_.clear();
  for (std::size_t i = 0; i < P.size(); ++i) {
    bool behind = false;
    for (std::size_t k = 0; k < specs_.size() && !behind; ++k)
      behind = distance(k, P.x[i]) < 0 && in_section(k, P.x[i]);
    if (!behind) keep_.push_back(i);
  }
  if (keep_.size() != P.size()) P.permute(keep_);
  // The buffers: `layers_` lattice layers at d = -(m + 1/2) dx, on a lattice of the plane
  // through the profile's corner (or centre, or the point), clear of every wall by 0.3 dx as
  // the fill (setup/generate.cpp).
  std::int64_t id = 0;
  for (const auto i : P.id) id = std::max(id, i + 1);
  const Real mass = rho0_ * static_cast<Real>(std::pow(dx_, D));
  const Real clearance = Real(0.3) * dx_;
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    const OpenBoundarySpec& s = specs_[k];
    const Plane& pl = planes_[k];
    Vec<D> origin = pl.point;
    if (s.profile == OpenBoundarySpec::Profile::segment ||
        s.profile == OpenBoundarySpec::Profile::rectangle)
      origin = head<D>(s.from).cwiseMin(head<D>(s.to));
    if (s.profile == OpenBoundarySpec::Profile::segment) origin = head<D>(s.from);
    if (s.profile == OpenBoundarySpec::Profile::circle) origin = head<D>(s.center);
    Vec<D> tangent[D - 1];
    for (int t = 0; t < D - 1; ++t) tangent[t] = pl.tangent[t];
    if (s.profile == OpenBoundarySpec::Profile::segment)
      tangent[0] = (head<D>(s.to) - head<D>(s.from)).normalized();
    // Lattice index range: the lateral box's corners projected on each tangent.
    long lo[2] = {0, 0}, hi[2] = {0, 0};
    for (int t = 0; t < D - 1; ++t) {
      Real a = std::numeric_limits<Real>::max(), b = -a;
      for (int corner = 0; corner < (1 << D); ++corner) {
        Vec<D> x;
        for (int d = 0; d < D; ++d)
          x[d] = static_cast<Real>((corner >> d) & 1 ? box_hi_[d] : box_lo_[d]);
        const Real u = (x - origin).dot(tangent[t]);
        a = std::min(a, u);
        b = std::max(b, u);
      }
      lo[t] = static_cast<long>(std::floor(a / dx_)) - 1;
      hi[t] = static_cast<long>(std::ceil(b / dx_)) + 1;
    }
    const long hi1 = D == 3 ? hi[1] : lo[1];
    for (long j0 = lo[0]; j0 <= hi[0]; ++j0)
      for (long j1 = lo[1]; j1 <= hi1; ++j1)
        for (int m = 0; m < layers_; ++m) {
          Vec<D> x = origin + (static_cast<Real>(j0) + Real(0.5)) * dx_ * tangent[0];
          if constexpr (D == 3) x += (static_cast<Real>(j1) + Real(0.5)) * dx_ * tangent[1];
          x += (-distance(k, x) - (static_cast<Real>(m) + Real(0.5)) * dx_) * pl.normal;
          if (!in_section(k, x)) continue;
          bool wet = true;
          for (std::size_t w = 0; w < walls.size() && wet; ++w)
            wet = walls[w].closest(x.template cast<double>()).distance > clearance;
          if (!wet) continue;
          const std::size_t i = P.size();
          P.resize(i + 1);
          P.x[i] = x;
          P.v[i] =
              s.kind == OpenBoundarySpec::Kind::inflow ? inflow_velocity(k, x, 0) : Vec<D>::Zero();
          P.mass[i] = mass;
          P.rho[i] = rho0_;
          P.sigma[i] = rho0_ / mass;
          P.id[i] = id++;
          P.buffer[i] = static_cast<std::int32_t>(k + 1);
        }
  }
}

template <int D>
void OpenBoundaries<D>::number_from(const Particles<D>& P) {
  id_stride_ = 0;
  for (const auto i : P.id) id_stride_ = std::max(id_stride_, i + 1);
}

template <int D>
typename OpenBoundaries<D>::Change OpenBoundaries<D>::after_drift(Particles<D>& P, Real dt) {
  Change ch;
  const std::size_t n = P.size();
  keep_.clear();
  spawn_.clear();
  std::vector<std::pair<std::size_t, std::int32_t>> roles;  // (particle, new buffer value)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t b = P.buffer[i];
    bool keep = true;
    if (b > 0) {
      const auto k = static_cast<std::size_t>(b - 1);
      const Vec<D>& nk = planes_[k].normal;
      if (specs_[k].kind == OpenBoundarySpec::Kind::inflow) {
        // The buffer moves along the normal only: its columns stay on the lattice.
        P.x[i] -= dt * (P.v[i] - P.v[i].dot(nk) * nk);
        if (distance(k, P.x[i]) >= 0) {
          spawn_.push_back(static_cast<Index>(i));
          roles.emplace_back(i, 0);
          ++in_count_;
          in_mass_ += static_cast<double>(P.mass[i]);
        }
      } else {
        const Real d = distance(k, P.x[i]);
        if (d < -depth_) {
          keep = false;
        } else if (d >= 0) {  // drifted back into the fluid
          // The buffer is bidirectional: a copy enters at its back, as at an inflow (below,
          // where that place is empty). Without it a backflow empties the buffer's back, and
          // the support of the fluid at the boundary is full only while the backflow's
          // displacement stays below L - 2h (0.4 dx at h = 1.3 dx): in the Schäfer-Turek
          // channel at c0 = 15 the buffer of 123 particles was down to 80-90 by t = 0.2-0.4 s
          // and the fluid at the outlet's wall corners at 0.70-0.75 rho0.
          returned_.push_back(i);
          roles.emplace_back(i, 0);
          --out_count_;
          out_mass_ -= static_cast<double>(P.mass[i]);
        }
      }
    } else {
      for (std::size_t k = 0; k < specs_.size(); ++k) {
        if (!(distance(k, P.x[i]) < 0) || !in_section(k, P.x[i])) continue;
        ++out_count_;
        out_mass_ += static_cast<double>(P.mass[i]);
        if (specs_[k].kind == OpenBoundarySpec::Kind::outflow)
          roles.emplace_back(i, static_cast<std::int32_t>(k + 1));
        else
          keep = false;  // flowed back out through an inflow
        break;
      }
    }
    if (keep) {
      keep_.push_back(i);
    } else {
      ++ch.count;
      ch.ids += P.id[i];
      ch.ids2 += P.id[i] * P.id[i];
      ch.mass += static_cast<double>(P.mass[i]);
    }
  }
  // A particle that returned from an outflow buffer leaves a copy at the buffer's back, x - L
  // n, unless a particle of that buffer already lies within dx/2 of that place: a particle
  // that jitters across the boundary in the velocity noise (it leaves, returns, leaves) would
  // otherwise add a copy at each return and overfill the buffer (measured: 123 -> 420
  // particles in 0.18 s in the Schäfer-Turek channel at c0 = 15, where the run then stopped).
  // O(returns x buffer particles): returns are few per step.
  for (const std::size_t i : returned_) {
    const auto k = static_cast<std::size_t>(P.buffer[i] - 1);
    const Vec<D> xb = P.x[i] - depth_ * planes_[k].normal;
    bool empty = true;
    for (std::size_t j = 0; j < n && empty; ++j)
      empty = P.buffer[j] != P.buffer[i] || distance(k, P.x[j]) < -depth_ ||
              (P.x[j] - xb).squaredNorm() >= dx_ * dx_ / 4;
    if (empty) spawn_.push_back(static_cast<Index>(i));
  }
  returned_.clear();
  bytes_.clear();
  if (!spawn_.empty()) mpi::pack(P, spawn_, mpi::FieldSet::all, bytes_);  // still buffer
  for (const auto& [i, role] : roles) P.buffer[i] = role;
  if (keep_.size() != n) P.permute(keep_);
  if (spawn_.empty()) return ch;
  const std::size_t first = P.size();
  mpi::unpack_append(P, bytes_, mpi::FieldSet::all);
  for (std::size_t i = first; i < P.size(); ++i) {
    const auto k = static_cast<std::size_t>(P.buffer[i] - 1);
    P.x[i] -= depth_ * planes_[k].normal;  // the buffer's back
    P.a[i] = Vec<D>::Zero();
    P.drho[i] = 0;
    P.id[i] += id_stride_;
    ch.count -= 1;
    ch.ids -= P.id[i];
    ch.ids2 -= P.id[i] * P.id[i];
    ch.mass -= static_cast<double>(P.mass[i]);
  }
  return ch;
}

template <int D>
void OpenBoundaries<D>::buffer_state(Particles<D>& P, const CellList<D>& cells,
                                     const WendlandC2<D>& W, const Eos& eos,
                                     const std::vector<Real>& rho0, double t, Index owned) {
  parallel_for(owned, [&](Index i) {
    const std::int32_t b = P.buffer[i];
    if (b == 0) return;
    const auto k = static_cast<std::size_t>(b - 1);
    const OpenBoundarySpec& s = specs_[k];
    // Zeroth-order extrapolation from the fluid: Shepard averages over fluid neighbours,
    // volumes m_j / rho_j.
    Real sw = 0, srho = 0;
    Vec<D> sv = Vec<D>::Zero();
    cells.for_each_neighbor(P.x[i], P.x, [&](Index j, const Vec<D>&, Real r2) {
      if (P.buffer[j] != 0) return;
      const Real w = W.value(std::sqrt(r2)) * P.mass[j] / P.rho[j];
      sw += w;
      srho += w * P.rho[j];
      sv += w * P.v[j];
    });
    const Real r0 = rho0[static_cast<std::size_t>(P.phase[i])];
    if (s.kind == OpenBoundarySpec::Kind::inflow) {
      P.v[i] = inflow_velocity(k, P.x[i], t);
      P.rho[i] = sw > 0 ? srho / sw : r0;
      P.p[i] = eos.pressure(P.rho[i], r0);
    } else {
      // The density the fluid's own sum has at rest at the prescribed pressure (the level
      // kappa, open_boundaries.hpp), and the pressure of that density.
      const Real p_set = s.pressure ? static_cast<Real>(*s.pressure) : eos.p0;
      P.rho[i] = level_ * eos.density(p_set, r0);
      P.p[i] = eos.pressure(P.rho[i], r0);
      // The velocity at the mirror point x - 2 d n, a point of the fluid for every buffer
      // particle (d >= -L): a particle deep in the buffer has few or no fluid neighbours, and
      // one that kept its velocity from the last it had left the back at it while the flow
      // at the boundary had turned (the buffer of the Schäfer-Turek channel at c0 = 15 lost a
      // third of its particles in 0.15 s, and the fluid next to the holes went to 0.75 rho0).
      const Vec<D> xm = P.x[i] - 2 * distance(k, P.x[i]) * planes_[k].normal;
      Real mw = 0;
      Vec<D> mv = Vec<D>::Zero();
      cells.for_each_neighbor(xm, P.x, [&](Index j, const Vec<D>&, Real r2) {
        if (P.buffer[j] != 0) return;
        const Real w = W.value(std::sqrt(r2)) * P.mass[j] / P.rho[j];
        mw += w;
        mv += w * P.v[j];
      });
      if (mw > 0) P.v[i] = mv / mw;
    }
    P.sigma[i] = P.rho[i] / P.mass[i];
  });
}

template <int D>
bool OpenBoundaries<D>::has_outflow() const {
  return std::any_of(specs_.begin(), specs_.end(), [](const OpenBoundarySpec& s) {
    return s.kind == OpenBoundarySpec::Kind::outflow;
  });
}

template <int D>
typename OpenBoundaries<D>::LevelSums OpenBoundaries<D>::density_level_sums(
    const Particles<D>& P, const std::vector<Real>& rho_set, const WallSet<D>& walls,
    Index owned) const {
  // Particles within a support of a wall have ghosts or boundary terms in their sum, and a
  // lattice cut by a curved wall leaves them off the lattice's level (0.76-1.01 rho0 around
  // the Schäfer-Turek cylinder): the interior alone measures the arrangement's level.
  const double support = static_cast<double>(depth_);  // >= 2h
  LevelSums s;
  for (Index i = 0; i < owned; ++i) {
    if (P.buffer[i] != 0) continue;
    const VecD<D> x = P.x[i].template cast<double>();
    bool interior = true;
    for (std::size_t w = 0; w < walls.size() && interior; ++w)
      interior = walls[w].distance_lower_bound(x) >= support ||
                 std::abs(walls[w].closest(x).distance) >= support;
    if (!interior) continue;
    const double q = static_cast<double>(P.rho[i]) / rho_set[static_cast<std::size_t>(i)];
    s.sum += std::llround((q - 1) * kLevelUnit);
    s.count += 1;
  }
  return s;
}

template <int D>
void OpenBoundaries<D>::freeze(Particles<D>& P, Index owned) const {
  parallel_for(owned, [&](Index i) {
    if (P.buffer[i] == 0) return;
    P.a[i] = Vec<D>::Zero();
    P.drho[i] = 0;
  });
}

template <int D>
void OpenBoundaries<D>::hold(const Particles<D>& P, Index owned) {
  held_.clear();
  for (Index i = 0; i < owned; ++i)
    if (P.buffer[i] != 0) held_.push_back({i, P.x[i], P.v[i], P.rho[i]});
}

template <int D>
void OpenBoundaries<D>::restore(Particles<D>& P) const {
  for (const Held& h : held_) {
    P.x[h.i] = h.x;
    P.v[h.i] = h.v;
    P.rho[h.i] = h.rho;
  }
}

template class OpenBoundaries<2>;
template class OpenBoundaries<3>;

}  // namespace curvsph
