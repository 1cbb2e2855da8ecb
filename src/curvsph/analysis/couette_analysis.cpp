#include "curvsph/analysis/couette_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <vector>

#include "curvsph/core/error.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/setup/generate.hpp"

namespace curvsph {

namespace {

void check_no_params(const YAML::Node& params, const std::string& file, const std::string& key) {
  if (!params || params.IsNull()) return;
  if (!params.IsMap()) throw InputError(file, key, "must be a mapping ({})");
  for (const auto& kv : params)
    throw InputError(file, key + "." + kv.first.as<std::string>(),
                     "unknown key (the reference comes from the case's walls; no keys here)");
}

// Rotation rate of a circle wall about `center`: 0 without motion.
double rotation_rate(const Wall<2>& w, const Vec2d& center, const std::string& file,
                     const std::string& key) {
  switch (w.motion.kind) {
    case WallMotion<2>::Kind::none:
      return 0.0;
    case WallMotion<2>::Kind::rotate:
      if ((w.motion.center - center).norm() > 1e-9 * (1 + center.norm()))
        throw InputError(file, key,
                         "the wall must rotate about the circles' common centre for Couette flow");
      return w.motion.omega;
    default:
      throw InputError(file, key, "Couette flow needs walls that rotate (or stand still)");
  }
}

}  // namespace

CouetteSetup couette_from_case(const Case& c, const std::string& key) {
  const std::string file = c.file_name();
  if (c.dimension != 2) throw InputError(file, key, "Couette flow is 2-D");
  const YAML::Node wn = c.root["walls"];
  if (!wn || !wn.IsSequence())
    throw InputError(file, key, "needs two concentric circle walls in `walls:`");
  const WallSet<2> walls = parse_walls<2>(wn, file, c.file.parent_path());
  const CircleWall* inner = nullptr;
  const CircleWall* outer = nullptr;
  std::size_t k_in = 0, k_out = 0;
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const auto* circle = dynamic_cast<const CircleWall*>(&walls[k].body());
    if (!circle) continue;
    if (circle->side() == FluidSide::outside) {
      if (inner) throw InputError(file, key, "more than one circle wall with fluid outside");
      inner = circle;
      k_in = k;
    } else {
      if (outer) throw InputError(file, key, "more than one circle wall with fluid inside");
      outer = circle;
      k_out = k;
    }
  }
  if (!inner || !outer)
    throw InputError(file, key,
                     "needs a circle wall with fluid: outside (inner cylinder) and one with fluid: "
                     "inside (outer cylinder)");
  const Vec2d center = inner->center();
  if ((outer->center() - center).norm() > 1e-9 * (1 + outer->radius()))
    throw InputError(file, key, "the two circle walls are not concentric");
  if (!(inner->radius() < outer->radius()))
    throw InputError(file, key, "the inner circle must be smaller than the outer one");
  CouetteSetup s;
  s.center = center;
  s.flow.r_in = inner->radius();
  s.flow.r_out = outer->radius();
  s.flow.omega_in = rotation_rate(walls[k_in], center, file, fmt::format("walls.{}.motion", k_in));
  s.flow.omega_out =
      rotation_rate(walls[k_out], center, file, fmt::format("walls.{}.motion", k_out));
  return s;
}

namespace {

class CouetteAnalysis final : public Analysis<2> {
 public:
  CouetteAnalysis(CouetteSetup s, std::vector<double> rho0, double dx)
      : s_(s),
        rho0_(std::move(rho0)),
        bins_(std::max(1L, std::lround((s.flow.r_out - s.flow.r_in) / dx))) {}

  void observe(double t, const Particles<2>& P) override {
    if (times_.empty()) {
      density_error_t0_ = density_error(P);
      density_t0_ = density_samples(P);
    }
    times_.push_back(t);
    const Errors e = errors(P);
    abs_errors_.push_back(e.l2_abs);
    profile_errors_.push_back(e.profile);
    rms_.push_back(e.rms);
  }

  void finish(double /*t*/, const Particles<2>& P, nlohmann::json& m,
              const std::filesystem::path& out_dir) override {
    const Errors e = errors(P);
    const double scale = s_.flow.speed_scale();
    m["density_error_t0"] = density_error_t0_;
    m["density_error_end"] = density_error(P);
    m["velocity_radial_rms"] = e.radial_rms;
    if (scale > 0) {
      m["velocity_l2_error"] = e.l2_abs / scale;
      m["velocity_l2_error_abs"] = e.l2_abs;
      m["velocity_profile_error"] = e.profile / scale;
      m["velocity_scatter_error"] = e.scatter() / scale;
    } else {
      m["velocity_rms"] = e.rms;
    }
    m["couette_r_in"] = s_.flow.r_in;
    m["couette_r_out"] = s_.flow.r_out;
    m["couette_omega_in"] = s_.flow.omega_in;
    m["couette_omega_out"] = s_.flow.omega_out;
    if (out_dir.empty()) return;
    {
      std::ofstream csv(out_dir / "couette_error.csv");
      csv << (scale > 0 ? "time,velocity_l2_error,velocity_l2_error_abs,velocity_profile_error,"
                          "velocity_scatter_error\n"
                        : "time,velocity_rms\n");
      for (std::size_t k = 0; k < times_.size(); ++k) {
        if (scale > 0)
          csv << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", times_[k],
                             abs_errors_[k] / scale, abs_errors_[k], profile_errors_[k] / scale,
                             Errors{abs_errors_[k], 0, 0, profile_errors_[k]}.scatter() / scale);
        else
          csv << fmt::format("{:.9g},{:.9g}\n", times_[k], rms_[k]);
      }
    }
    write_density(out_dir / "couette_density_t0.csv", density_t0_);
    write_density(out_dir / "couette_density_end.csv", density_samples(P));
    std::ofstream csv(out_dir / "couette_profile.csv");
    csv << "r,v_theta,v_r,v_theta_exact\n";
    for (std::size_t i = 0; i < P.size(); ++i) {
      const Polar q = polar(P, i);
      csv << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g}\n", q.r, q.vt, q.vr, s_.flow.v_theta(q.r));
    }
  }

  nlohmann::json save_state() const override {
    return {{"density_error_t0", density_error_t0_},
            {"density_t0", density_t0_},
            {"times", times_},
            {"abs_errors", abs_errors_},
            {"profile_errors", profile_errors_},
            {"rms", rms_}};
  }
  void load_state(const nlohmann::json& s) override {
    s.at("density_error_t0").get_to(density_error_t0_);
    s.at("density_t0").get_to(density_t0_);
    s.at("times").get_to(times_);
    s.at("abs_errors").get_to(abs_errors_);
    s.at("profile_errors").get_to(profile_errors_);
    s.at("rms").get_to(rms_);
  }

 private:
  struct Polar {
    double r, vt, vr;
  };
  // l2_abs: eq. 25 (m/s). Its split: the particles binned in radius (bins_ bins, about dx
  // wide), profile = the same norm of the bin means of v_theta - v(r) (the error of the mean
  // azimuthal profile) and scatter = the norm of the deviations from the bin means (particle
  // noise), so that l2_abs^2 = profile^2 + scatter^2.
  struct Errors {
    double l2_abs = 0, rms = 0, radial_rms = 0, profile = 0;
    double scatter() const { return std::sqrt(std::max(0.0, l2_abs * l2_abs - profile * profile)); }
  };

  Polar polar(const Particles<2>& P, std::size_t i) const {
    const Vec2d d = P.x[i].cast<double>() - s_.center;
    const double r = d.norm();
    const Vec2d er = r > 0 ? Vec2d(d / r) : Vec2d(1, 0);
    const Vec2d et(-er.y(), er.x());
    const Vec2d v = P.v[i].cast<double>();
    return {r, v.dot(et), v.dot(er)};
  }

  Errors errors(const Particles<2>& P) const {
    Errors e;
    const double n = static_cast<double>(std::max<std::size_t>(P.size(), 1));
    std::vector<double> bin_sum(bins_, 0.0), bin_count(bins_, 0.0);
    for (std::size_t i = 0; i < P.size(); ++i) {
      const Polar q = polar(P, i);
      const double dv = q.vt - s_.flow.v_theta(q.r);
      const long b = std::clamp(
          static_cast<long>((q.r - s_.flow.r_in) / (s_.flow.r_out - s_.flow.r_in) * bins_), 0L,
          bins_ - 1);
      bin_sum[b] += dv;
      bin_count[b] += 1;
      e.l2_abs += dv * dv;
      e.rms += q.vt * q.vt + q.vr * q.vr;
      e.radial_rms += q.vr * q.vr;
    }
    for (long b = 0; b < bins_; ++b)
      if (bin_count[b] > 0) e.profile += bin_sum[b] * bin_sum[b] / bin_count[b];
    e.profile = std::sqrt(e.profile / n);
    e.l2_abs = std::sqrt(e.l2_abs / n);
    e.rms = std::sqrt(e.rms / n);
    e.radial_rms = std::sqrt(e.radial_rms / n);
    return e;
  }

  double density_error(const Particles<2>& P) const {
    double err = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      err = std::max(err, std::abs(static_cast<double>(P.rho[i]) / rho0_[P.phase[i]] - 1));
    return err;
  }

  std::vector<std::pair<double, double>> density_samples(const Particles<2>& P) const {
    std::vector<std::pair<double, double>> out(P.size());
    for (std::size_t i = 0; i < P.size(); ++i)
      out[i] = {(P.x[i].cast<double>() - s_.center).norm(),
                static_cast<double>(P.rho[i]) / rho0_[P.phase[i]]};
    return out;
  }

  static void write_density(const std::filesystem::path& path,
                            const std::vector<std::pair<double, double>>& samples) {
    std::ofstream csv(path);
    csv << "r,rho_over_rho0\n";
    for (const auto& [r, rho] : samples) csv << fmt::format("{:.9g},{:.9g}\n", r, rho);
  }

  CouetteSetup s_;
  std::vector<double> rho0_;
  double density_error_t0_ = 0;
  std::vector<std::pair<double, double>> density_t0_;
  long bins_;
  std::vector<double> times_, abs_errors_, profile_errors_, rms_;
};

}  // namespace

std::unique_ptr<Analysis<2>> make_couette_analysis(const YAML::Node& params, const Case& c) {
  check_no_params(params, c.file_name(), "analysis.couette");
  std::vector<double> rho0;
  for (const auto& f : c.fluids) rho0.push_back(f.rho0);
  return std::make_unique<CouetteAnalysis>(couette_from_case(c, "analysis.couette"),
                                           std::move(rho0), c.dx);
}

namespace {

// sigma_i = sum_j W(|x_i - x_j|) over the points `src` (brute force over the radial band that
// can reach x_i: set-up only).
std::vector<double> node_density(const std::vector<Vec2d>& at, const std::vector<Vec2d>& src,
                                 const Vec2d& center, const WendlandC2<2>& W) {
  const double support = W.support;
  std::vector<double> r_src(src.size());
  for (std::size_t j = 0; j < src.size(); ++j) r_src[j] = (src[j] - center).norm();
  std::vector<double> sigma(at.size(), 0.0);
  for (std::size_t i = 0; i < at.size(); ++i) {
    const double ri = (at[i] - center).norm();
    for (std::size_t j = 0; j < src.size(); ++j) {
      if (std::abs(r_src[j] - ri) >= support) continue;
      sigma[i] += W.value(static_cast<Real>((at[i] - src[j]).norm()));
    }
  }
  return sigma;
}

}  // namespace

std::vector<double> reference_node_density(const Case& c, const CouetteSetup& s,
                                           const WendlandC2<2>& W, const Particles<2>& P) {
  const std::size_t n = P.size();
  std::vector<Vec2d> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = P.x[i].cast<double>();
  // The particles are the generator's rings of one annulus (not relaxed, not dropped): the
  // reference is the same ring pattern continued beyond both walls (setup/generate.hpp), far
  // enough (an even number of rings, so the alternation of ring phases carries on) to fill
  // the kernel support of every particle. The walls' ghosts then change sigma only by the
  // wall's own error, which density_error_t0 is there to measure.
  if (c.fluids.size() == 1 && c.fluids[0].region.kind == RegionSpec::Kind::annulus) {
    const RegionSpec& reg = c.fluids[0].region;
    const AnnulusRings rings = annulus_rings(reg, c.dx);
    std::vector<GeneratedPoint> own;
    append_annulus_rings(reg, rings, 0, rings.count, c.dx, own);
    bool same = own.size() == n;
    for (std::size_t i = 0; same && i < n; ++i)
      same = (own[i].x.head<2>() - x[i]).norm() <= 1e-6 * c.dx;
    if (same) {
      long k = static_cast<long>(std::ceil(W.support / rings.dr)) + 1;
      k += k % 2;
      std::vector<GeneratedPoint> beyond;
      append_annulus_rings(reg, rings, -k, 0, c.dx, beyond);
      append_annulus_rings(reg, rings, rings.count, rings.count + k, c.dx, beyond);
      std::vector<Vec2d> all = x;
      for (const auto& g : beyond) all.push_back(g.x.head<2>());
      return node_density(x, all, s.center, W);
    }
  }
  // Any other arrangement (relaxed by setup.relax, several fluids): the particles whose
  // kernel support lies inside the fluid (more than 2h from both walls) take their own sigma;
  // those nearer a wall, whose arrangement beyond the wall is unknown, the mean of the
  // former, so their initial density keeps the arrangement's own spread there as well as the
  // wall's error.
  std::vector<double> sigma = node_density(x, x, s.center, W);
  std::vector<bool> bulk(n);
  double sum = 0;
  long interior = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = (x[i] - s.center).norm();
    bulk[i] = r - s.flow.r_in >= W.support && s.flow.r_out - r >= W.support;
    if (!bulk[i]) continue;
    sum += sigma[i];
    ++interior;
  }
  if (interior == 0) {  // a gap narrower than 4h: no particle is clear of both walls
    for (double v : sigma) sum += v;
    interior = static_cast<long>(std::max<std::size_t>(n, 1));
  }
  const double mean = sum / static_cast<double>(interior);
  for (std::size_t i = 0; i < n; ++i)
    if (!bulk[i]) sigma[i] = mean;
  return sigma;
}

void couette_initial(const Case& c, const YAML::Node& params, const Eos& eos,
                     const std::vector<Real>& rho0, Particles<2>& P) {
  check_no_params(params, c.file_name(), "initial.couette");
  const CouetteSetup s = couette_from_case(c, "initial.couette");
  const std::size_t n = P.size();
  std::vector<double> r(n), volume(n), dp(n);
  for (std::size_t i = 0; i < n; ++i) {
    r[i] = (P.x[i].cast<double>() - s.center).norm();
    volume[i] = P.mass[i] / rho0[P.phase[i]];
  }
  // Mass calibration. The solver's density is rho_i = m_i sigma_i with sigma_i = sum_j W_ij
  // (Barker eq. 8), so a particle's initial density is exactly the target when
  // m_i = rho_i / sigma_ref,i, sigma_ref,i being its node density with the walls taken away.
  const WendlandC2<2> W(static_cast<Real>(c.h()));
  const std::vector<double> sigma_ref = reference_node_density(c, s, W, P);
  // Radial balance with zero volume-weighted mean, so the mean pressure stays p0.
  double sum = 0, vol = 0;
  for (std::size_t i = 0; i < n; ++i) {
    dp[i] = s.flow.pressure(r[i], rho0[P.phase[i]]);
    sum += dp[i] * volume[i];
    vol += volume[i];
  }
  const double mean = vol > 0 ? sum / vol : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2d d = P.x[i].cast<double>() - s.center;
    const Vec2d et = r[i] > 0 ? Vec2d(-d.y() / r[i], d.x() / r[i]) : Vec2d(0, 0);
    P.v[i] = (s.flow.v_theta(r[i]) * et).cast<Real>();
    const Real p = static_cast<Real>(dp[i] - mean + eos.p0);
    P.rho[i] = eos.density(p, rho0[P.phase[i]]);
    P.mass[i] = static_cast<Real>(P.rho[i] / sigma_ref[i]);
    P.p[i] = p;
  }
}

}  // namespace curvsph
