#include "curvsph/analysis/throttled_pipe.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"

namespace curvsph {

ChannelGap channel_gap(const WallSet<2>& walls, double x, double y_start, double step,
                       double reach) {
  auto wet = [&](double y) { return walls.closest(Vec2d(x, y)).distance > 0; };
  if (!wet(y_start))
    throw std::runtime_error(fmt::format("channel_gap: ({}, {}) is not in the fluid", x, y_start));
  auto edge = [&](double dir) {
    double in = y_start, out = y_start;
    for (double s = step;; s += step) {
      if (s > reach)
        throw std::runtime_error(
            fmt::format("channel_gap: no wall within {} of ({}, {})", reach, x, y_start));
      out = y_start + dir * s;
      if (!wet(out)) break;
      in = out;
    }
    for (int it = 0; it < 200 && std::abs(out - in) > 1e-15 * std::max(1.0, std::abs(in)); ++it) {
      const double mid = 0.5 * (in + out);
      (wet(mid) ? in : out) = mid;
    }
    return 0.5 * (in + out);
  };
  ChannelGap g;
  g.lo = edge(-1.0);
  g.hi = edge(+1.0);
  return g;
}

namespace {

// SPH interpolation of the velocity at any point from the fluid and its ghosts.
class VelocitySampler {
 public:
  VelocitySampler(const Case& c, const WallSet<2>& walls)
      : walls_(walls), W_(static_cast<Real>(c.h())) {
    cells_.configure(W_.support, c.domain_min, c.domain_max, c.periodic);
    opt_.map = parse_ghost_map(c.boundary.map, c.file_name(), "boundary.map");
    opt_.velocity = parse_ghost_velocity(c.boundary.velocity, c.file_name(), "boundary.velocity");
    opt_.support = W_.support;
    opt_.cells = &cells_;
  }

  void load(const Particles<2>& P) {
    G_.build(P.x, P.v, walls_, opt_);
    const std::size_t n = P.size(), m = G_.size();
    x_.resize(n + m);
    v_.resize(n + m);
    w_.resize(n + m);
    for (std::size_t i = 0; i < n; ++i) {
      x_[i] = P.x[i];
      v_[i] = P.v[i];
      w_[i] = P.mass[i] / P.rho[i];
    }
    for (std::size_t g = 0; g < m; ++g) {
      const Index s = G_.source[g];
      x_[n + g] = G_.x[g];
      v_[n + g] = G_.v[g];
      w_[n + g] = G_.beta[g] * P.mass[s] / P.rho[s];
    }
    cells_.build(x_);
  }

  // Shepard-normalised interpolation (zero where no particle is within the support).
  Vec2d velocity(double x, double y) const {
    Vec<2> q(static_cast<Real>(x), static_cast<Real>(y));
    cells_.wrap(q);
    double sw = 0;
    Vec2d sv = Vec2d::Zero();
    cells_.for_each_neighbor(q, x_, [&](Index j, const Vec<2>&, Real r2) {
      const double wk = w_[j] * W_.value(std::sqrt(r2));
      sw += wk;
      sv += wk * v_[j].cast<double>();
    });
    return sw > 0 ? Vec2d(sv / sw) : Vec2d::Zero();
  }

 private:
  const WallSet<2>& walls_;
  WendlandC2<2> W_;
  CellList<2> cells_;
  GhostOptions<2> opt_;
  GhostSet<2> G_;
  std::vector<Vec<2>> x_, v_;
  std::vector<double> w_;
};

// Simpson's rule over `n` (odd) equally spaced nodes of [a, b].
template <class F>
double simpson(double a, double b, int n, F&& f) {
  const double h = (b - a) / (n - 1);
  double s = f(a) + f(b);
  for (int k = 1; k < n - 1; ++k) s += (k % 2 ? 4.0 : 2.0) * f(a + k * h);
  return s * h / 3.0;
}

double relative_l2(const std::vector<double>& v, const std::vector<double>& ref) {
  double e = 0, r = 0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    e += (v[k] - ref[k]) * (v[k] - ref[k]);
    r += ref[k] * ref[k];
  }
  return r > 0 ? std::sqrt(e / r) : 0.0;
}

class ThrottledPipeAnalysis final : public Analysis<2> {
 public:
  ThrottledPipeAnalysis(const YAML::Node& params, const Case& c) {
    const std::string file = c.file_name(), key = "analysis.throttled_pipe";
    if (c.dimension != 2) throw InputError(file, key, "the throttled pipe is 2-D");
    if (!c.has_domain || !c.periodic[0] || c.periodic[1])
      throw InputError(file, key, "needs a domain periodic along x only");
    if (params && params.IsMap()) {
      for (const auto& kv : params) {
        const auto k = kv.first.as<std::string>();
        if (k == "reference_flux") {
          if (!YAML::convert<double>::decode(kv.second, reference_flux_) || !(reference_flux_ > 0))
            throw InputError(file, key + ".reference_flux", "must be a number > 0 (m^2/s)");
          continue;
        }
        int* target = k == "sections"         ? &sections_
                      : k == "points"         ? &points_
                      : k == "midline_points" ? &midline_points_
                                              : nullptr;
        if (!target)
          throw InputError(
              file, key + "." + k,
              "unknown key (allowed here: sections, points, midline_points, reference_flux)");
        if (!YAML::convert<int>::decode(kv.second, *target))
          throw InputError(file, key + "." + k, "must be an integer");
      }
    } else if (params && !params.IsNull()) {
      throw InputError(file, key, "must be a mapping ({sections: 48})");
    }
    if (sections_ < 20) throw InputError(file, key + ".sections", "must be >= 20 (Barker eq. 47)");
    if (points_ < 5) throw InputError(file, key + ".points", "must be >= 5");
    if (midline_points_ < 8) throw InputError(file, key + ".midline_points", "must be >= 8");
    points_ |= 1;  // Simpson's rule: an odd node count
    if (!c.root["walls"] || !c.root["walls"].IsSequence())
      throw InputError(file, key, "needs walls");
    walls_ = parse_walls<2>(c.root["walls"], file, c.file.parent_path());
    rho0_ = c.fluids.at(0).rho0;
    mu_ = c.fluids.at(0).viscosity;
    x0_ = c.domain_min[0];
    lx_ = c.domain_max[0] - c.domain_min[0];
    const double ly = c.domain_max[1] - c.domain_min[1];
    const double y_mid = 0.5 * (c.domain_min[1] + c.domain_max[1]);
    auto gap = [&](double x) {
      try {
        return channel_gap(walls_, x, y_mid, 0.25 * c.dx, 2 * ly);
      } catch (const std::exception& e) {
        throw InputError(file, key, e.what());
      }
    };
    for (int k = 0; k < sections_; ++k) {
      section_x_.push_back(x0_ + (k + 0.5) * lx_ / sections_);
      section_gap_.push_back(gap(section_x_.back()));
    }
    for (int k = 0; k <= midline_points_; ++k) {
      midline_x_.push_back(x0_ + k * lx_ / midline_points_);
      midline_gap_.push_back(gap(midline_x_.back()));
    }
    throat_gap_ = gap(x0_ + 0.5 * lx_);
    sampler_ = std::make_unique<VelocitySampler>(c, walls_);
  }

  void observe(double t, const Particles<2>& P) override {
    sampler_->load(P);
    fluxes();
    // The mean over x of Q(x) without interpolation: sum_i V_i v_x,i / L_x = (1/L_x) integral of
    // v_x over the fluid. The sections' kernel interpolation lowers a parabolic profile by
    // sigma^2 |v''| (sigma^2 = 0.278 h^2 per coordinate for the 2-D Wendland C2), -1.5 sigma^2 /
    // R^2 of the section flux: -7 % at the throat with h = 1 mm (findings.md, issue 36).
    double q = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      q += static_cast<double>(P.mass[i] / P.rho[i] * P.v[i].x());
    flux_particles_ = q / lx_;
    history_.push_back({t, flux_mean_, flux_variation_, flux_particles_});
  }

  void finish(double t, const Particles<2>& P, nlohmann::json& m,
              const std::filesystem::path& out_dir) override {
    if (history_.empty() || history_.back()[0] != t) observe(t, P);
    const VelocitySampler& s = *sampler_;
    const ChannelGap& g0 = midline_gap_.front();  // reference section: the seam (Barker x = 0)
    const double r0 = g0.half_width();
    // Eq. 48: the reference section's profile, stretched to the local half-width.
    auto eq48 = [&](double y, const ChannelGap& g) {
      const double ratio = r0 / g.half_width();
      return ratio * s.velocity(x0_, g0.center() + (y - g.center()) * ratio).x();
    };
    const std::size_t nm = midline_x_.size();
    std::vector<double> vx(nm), vy(nm), ref(nm), lub(nm);
    double vx_max = 0, vy_max = 0, err_max = 0, ref_max = 0;
    for (std::size_t k = 0; k < nm; ++k) {
      const ChannelGap& g = midline_gap_[k];
      const Vec2d v = s.velocity(midline_x_[k], g.center());
      vx[k] = v.x();
      vy[k] = v.y();
      ref[k] = eq48(g.center(), g);
      lub[k] = 0.75 * flux_mean_ / g.half_width();
      vx_max = std::max(vx_max, vx[k]);
      vy_max = std::max(vy_max, std::abs(vy[k]));
      err_max = std::max(err_max, std::abs(vx[k] - ref[k]));
      ref_max = std::max(ref_max, std::abs(ref[k]));
    }
    // The last station repeats the first (periodic): leave it out of the norms.
    const std::vector<double> vx_p(vx.begin(), vx.end() - 1), ref_p(ref.begin(), ref.end() - 1),
        lub_p(lub.begin(), lub.end() - 1);
    const double xt = x0_ + 0.5 * lx_;
    std::vector<double> ty(points_), tvx(points_), tvy(points_), tref(points_);
    for (int k = 0; k < points_; ++k) {
      ty[k] = throat_gap_.lo + (throat_gap_.hi - throat_gap_.lo) * k / (points_ - 1);
      const Vec2d v = s.velocity(xt, ty[k]);
      tvx[k] = v.x();
      tvy[k] = v.y();
      tref[k] = eq48(ty[k], throat_gap_);
    }

    m["flux_mean"] = flux_mean_;
    m["flux_variation"] = flux_variation_;
    m["reynolds"] = rho0_ * flux_mean_ / mu_;
    if (reference_flux_ > 0) {
      m["reference_flux"] = reference_flux_;
      m["reference_reynolds"] = rho0_ * reference_flux_ / mu_;
      m["flux_rel_error"] = flux_mean_ / reference_flux_ - 1.0;
      m["flux_particles_rel_error"] = flux_particles_ / reference_flux_ - 1.0;
    }
    m["flux_particles"] = flux_particles_;
    m["midline_vy_max_rel"] = vx_max > 0 ? vy_max / vx_max : 0.0;
    m["centerline_vx_rel_error"] = relative_l2(vx_p, ref_p);
    m["centerline_vx_max_rel_error"] = ref_max > 0 ? err_max / ref_max : 0.0;
    m["centerline_vx_rel_error_lubrication"] = relative_l2(vx_p, lub_p);
    m["throat_vx_rel_error"] = relative_l2(tvx, tref);
    m["throat_half_width"] = throat_gap_.half_width();
    m["reference_half_width"] = r0;
    m["midline_vx_max"] = vx_max;
    m["flux_sections"] = sections_;
    if (out_dir.empty()) return;
    std::ofstream fq(out_dir / "throttled_pipe_flux.csv");
    fq << "x,half_width,y_center,flux\n";
    for (std::size_t k = 0; k < section_x_.size(); ++k)
      fq << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g}\n", section_x_[k],
                        section_gap_[k].half_width(), section_gap_[k].center(), flux_[k]);
    std::ofstream fx(out_dir / "throttled_pipe_midline_x.csv");
    fx << "x,half_width,y,vx,vy,vx_eq48,vx_lubrication\n";
    for (std::size_t k = 0; k < nm; ++k)
      fx << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", midline_x_[k],
                        midline_gap_[k].half_width(), midline_gap_[k].center(), vx[k], vy[k],
                        ref[k], lub[k]);
    std::ofstream fy(out_dir / "throttled_pipe_midline_y.csv");
    fy << "x,y,vx,vy,vx_eq48\n";
    for (int k = 0; k < points_; ++k)
      fy << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", xt, ty[k], tvx[k], tvy[k], tref[k]);
    std::ofstream fh(out_dir / "throttled_pipe_history.csv");
    fh << "time,flux_mean,flux_variation,reynolds,flux_particles\n";
    for (const auto& h : history_)
      fh << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", h[0], h[1], h[2],
                        rho0_ * h[1] / mu_, h[3]);
  }

  nlohmann::json save_state() const override { return {{"history", history_}}; }
  void load_state(const nlohmann::json& s) override { s.at("history").get_to(history_); }

 private:
  // Q(x) at every section (eq. 47), their mean and (max - min)/mean.
  void fluxes() {
    flux_.resize(section_x_.size());
    for (std::size_t k = 0; k < section_x_.size(); ++k) {
      const double x = section_x_[k];
      flux_[k] = simpson(section_gap_[k].lo, section_gap_[k].hi, points_,
                         [&](double y) { return sampler_->velocity(x, y).x(); });
    }
    const auto [mn, mx] = std::minmax_element(flux_.begin(), flux_.end());
    double sum = 0;
    for (double q : flux_) sum += q;
    flux_mean_ = sum / static_cast<double>(flux_.size());
    flux_variation_ = flux_mean_ != 0 ? (*mx - *mn) / std::abs(flux_mean_) : 0.0;
  }

  int sections_ = 48, points_ = 65, midline_points_ = 192;
  WallSet<2> walls_;
  double rho0_ = 0, mu_ = 0, x0_ = 0, lx_ = 0;
  std::vector<double> section_x_, midline_x_, flux_;
  std::vector<ChannelGap> section_gap_, midline_gap_;
  ChannelGap throat_gap_;
  std::unique_ptr<VelocitySampler> sampler_;
  double flux_mean_ = 0, flux_variation_ = 0, flux_particles_ = 0;
  double reference_flux_ = 0;  // an independent steady flux for this force (0: none)
  std::vector<std::array<double, 4>> history_;  // t, flux_mean, flux_variation, flux_particles
};

}  // namespace

std::unique_ptr<Analysis<2>> make_throttled_pipe_analysis(const YAML::Node& params, const Case& c) {
  return std::make_unique<ThrottledPipeAnalysis>(params, c);
}

void throttled_pipe_initial(const Case& c, const YAML::Node& params, const Eos& /*eos*/,
                            const std::vector<Real>& rho0, Particles<2>& P) {
  const std::string file = c.file_name(), key = "initial.throttled_pipe";
  bool lubrication = false;
  double flux = 0;  // 0: the lubrication estimate for the body force
  if (params && params.IsMap()) {
    for (const auto& kv : params) {
      const auto k = kv.first.as<std::string>();
      if (k == "flux") {
        if (!YAML::convert<double>::decode(kv.second, flux) || !(flux > 0))
          throw InputError(file, key + ".flux", "must be a number > 0 (m^2/s)");
        continue;
      }
      if (k != "velocity")
        throw InputError(file, key + "." + k, "unknown key (allowed: velocity, flux)");
      const auto v = kv.second.IsScalar() ? kv.second.as<std::string>() : std::string();
      if (v != "rest" && v != "lubrication")
        throw InputError(file, key + ".velocity", "must be rest or lubrication");
      lubrication = v == "lubrication";
    }
  } else if (params && !params.IsNull()) {
    throw InputError(file, key, "must be a mapping ({velocity: rest})");
  }
  if (c.dimension != 2 || !c.has_domain || !c.periodic[0] || c.periodic[1])
    throw InputError(file, key, "needs a 2-D domain periodic along x only");
  if (c.fluids.size() != 1) throw InputError(file, key, "needs exactly one fluid");
  if (!c.root["walls"] || !c.root["walls"].IsSequence()) throw InputError(file, key, "needs walls");
  const WallSet<2> walls = parse_walls<2>(c.root["walls"], file, c.file.parent_path());
  const double lx = c.domain_max[0] - c.domain_min[0], ly = c.domain_max[1] - c.domain_min[1];
  const double y_mid = 0.5 * (c.domain_min[1] + c.domain_max[1]);
  const long nx = std::max(1L, std::lround(lx / c.dx));
  const double cx = lx / static_cast<double>(nx);
  auto gap = [&](double x) {
    try {
      return channel_gap(walls, x, y_mid, 0.25 * c.dx, 2 * ly);
    } catch (const std::exception& e) {
      throw InputError(file, key, e.what());
    }
  };
  const FluidSpec& f = c.fluids[0];
  // Lubrication flux for the body force: rho g_x = (3 mu Q / (2 L)) integral of R^-3 dx.
  double inv_r3 = 0;
  for (long i = 0; i < nx; ++i)
    inv_r3 +=
        cx * std::pow(gap(c.domain_min[0] + (static_cast<double>(i) + 0.5) * cx).half_width(), -3);
  const double q = flux > 0 ? flux : 2 * f.rho0 * c.gravity[0] * lx / (3 * f.viscosity * inv_r3);
  // Node density of a column's rectangular lattice (cx, dy) continued without end: the mass
  // rho0 / n makes the summation density start at rho0 in the bulk. rho0 cx dy would start it
  // at n cx dy rho0 (1.0105 rho0 on a square lattice at h = 1.3 dx), i.e. at a pressure of
  // ~11 Pa above the eos's p0 (findings.md §7).
  const WendlandC2<2> W(static_cast<Real>(c.h()));
  auto lattice_density = [&](double ax, double by) {
    const long kx = static_cast<long>(std::ceil(W.support / ax)),
               ky = static_cast<long>(std::ceil(W.support / by));
    double n = 0;
    for (long a = -kx; a <= kx; ++a)
      for (long b = -ky; b <= ky; ++b)
        n += W.value(static_cast<Real>(
            std::hypot(static_cast<double>(a) * ax, static_cast<double>(b) * by)));
    return n;
  };
  std::vector<Vec2d> pos, vel;
  std::vector<double> vol;
  for (long i = 0; i < nx; ++i) {
    const double x = c.domain_min[0] + (static_cast<double>(i) + 0.5) * cx;
    const ChannelGap g = gap(x);
    const double e = 1e-3 * c.dx;
    const ChannelGap gm = gap(x - e), gp = gap(x + e);
    const double dr = (gp.half_width() - gm.half_width()) / (2 * e);
    const double dc = (gp.center() - gm.center()) / (2 * e);
    const long n = std::max(1L, std::lround((g.hi - g.lo) / c.dx));
    const double dy = (g.hi - g.lo) / static_cast<double>(n);
    for (long k = 0; k < n; ++k) {
      pos.emplace_back(x, g.lo + (static_cast<double>(k) + 0.5) * dy);
      vol.push_back(1 / lattice_density(cx, dy));
      // Local Poiseuille profile carrying Q; v_y follows the streamlines y = y_c + eta R.
      const double eta = (pos.back().y() - g.center()) / g.half_width();
      const double u = 0.75 * q / g.half_width() * (1 - eta * eta);
      vel.push_back(lubrication ? Vec2d(u, u * (dc + eta * dr)) : Vec2d(f.velocity.head<2>()));
    }
  }
  P.resize(pos.size());
  for (std::size_t i = 0; i < pos.size(); ++i) {
    P.x[i] = pos[i].cast<Real>();
    P.v[i] = vel[i].cast<Real>();
    P.a[i].setZero();
    P.mass[i] = static_cast<Real>(rho0[0] * vol[i]);
    P.rho[i] = rho0[0];
    P.drho[i] = 0;
    P.p[i] = 0;
    P.sigma[i] = P.rho[i] / P.mass[i];
    P.phase[i] = 0;
    P.id[i] = static_cast<std::int64_t>(i);
  }
}

}  // namespace curvsph
