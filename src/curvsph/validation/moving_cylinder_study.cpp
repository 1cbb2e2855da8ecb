// `curvsph validate moving_cylinder`: walls that move (issue 33 item 4).
//
// (a) Galilean check: the cylinder of cases/towed_cylinder.yaml towed at U through fluid at
// rest, and its twin — the same periodic box, the fluid started at -U past the cylinder held
// still. In the cylinder's frame the two are the same flow, so the drag histories must agree
// (target: the mean drag after the start within 2 %). The force on the cylinder is the fluid's
// momentum balance, F = -sum m_i a_i (analysis/momentum_force.hpp): the box has no other wall,
// so this reference does not depend on how the ghosts act.
// (b) cases/oscillating_cylinder.yaml (Dütsch et al. 1998, Re = 100, KC = 5) over its first
// periods: the in-line force, its first harmonic (amplitude, phase against the cylinder's
// velocity) and the Morison fit F = -C_d rho D |u| u / 2 - C_a rho (pi D^2 / 4) du/dt with the
// cylinder's velocity u (fluid at rest: no Froude-Krylov part), reported without a target: the
// comparison with the paper's force is `validate oscillating_cylinder`'s (a 20 D box).
#include <fmt/format.h>
#include <omp.h>
#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <numbers>
#include <vector>

#include "curvsph/analysis/momentum_force.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/solver.hpp"
#include "curvsph/validation/study.hpp"

namespace curvsph {
namespace {

constexpr double pi = std::numbers::pi;

struct ForceHistory {
  std::vector<double> t, fx, fy;
  long particles = 0, steps = 0, projected = 0;
};

ForceHistory run_forces(const Case& c) {
  Solver<2> s(c);
  s.initialize();
  ForceHistory h;
  h.particles = static_cast<long>(s.particles().size());
  const VecD<2> g = c.gravity.head<2>();
  while (s.time() < c.t_end * (1 - 1e-12)) {
    s.step(static_cast<Real>(c.t_end - s.time()));
    const VecD<2> f = wall_force_from_momentum<2>(s.particles(), s.decomposition().owned(), g);
    h.t.push_back(s.time());
    h.fx.push_back(f.x());
    h.fy.push_back(f.y());
  }
  h.steps = s.steps();
  h.projected = s.stray_counts().projected;
  return h;
}

// Mean of v over the steps with t in [a, b), weighted by the step length.
double window_mean(const ForceHistory& h, const std::vector<double>& v, double a, double b) {
  double s = 0, w = 0;
  for (std::size_t k = 1; k < h.t.size(); ++k) {
    if (h.t[k] < a || h.t[k] >= b) continue;
    const double dt = h.t[k] - h.t[k - 1];
    s += v[k] * dt;
    w += dt;
  }
  return w > 0 ? s / w : 0;
}

}  // namespace

StudyResult run_moving_cylinder_study(const StudyContext& ctx) {
  if (ctx.threads > 0) omp_set_num_threads(ctx.threads);
  std::filesystem::create_directories(ctx.out_dir);
  StudyResult r;
  std::ofstream md(ctx.out_dir / "README.md");
  md << "# Walls that move: towed and oscillating cylinder\n\n"
        "Regenerate with `build/curvsph validate moving_cylinder` (src/curvsph/validation/"
        "moving_cylinder_study.cpp). Forces on the cylinder from the fluid's momentum balance "
        "F = -sum m_i a_i (periodic boxes with no other wall; src/curvsph/analysis/"
        "momentum_force.hpp).\n\n";

  // (a) Galilean check.
  {
    const auto path = ctx.source_dir / "cases" / "towed_cylinder.yaml";
    YAML::Node towed = YAML::LoadFile(path.string());
    if (ctx.quick) towed["time"]["end"] = 0.6;
    towed["output"]["vtk"] = false;
    YAML::Node fixed = YAML::Clone(towed);
    const double U = towed["walls"][0]["motion"]["translate"]["velocity"][0].as<double>();
    fixed["walls"][0].remove("motion");
    fixed["fluids"][0]["velocity"] = std::vector<double>{-U, 0.0};
    const Case ca = read_case(towed, path);
    const Case cb = read_case(fixed, path);
    const double D = 2 * towed["walls"][0]["radius"].as<double>();
    const double rho = towed["fluids"][0]["rho0"].as<double>();
    const double q = 0.5 * rho * U * U * D;  // C_D = F / q
    const ForceHistory a = run_forces(ca), b = run_forces(cb);
    // Drag = -F_x in both: the towed cylinder moves to +x, the twin's stream goes to -x (the
    // force on the still cylinder is along -x too).
    const double T = ca.t_end, t0 = 0.5 * D / U;  // after the impulsive start
    const double cd_a = -window_mean(a, a.fx, t0, T + 1) / q;
    const double cd_b = -window_mean(b, b.fx, t0, T + 1) / q;
    const double rel = std::abs(cd_a - cd_b) / std::abs(cd_b);
    // Windows of D/(2U): the largest relative difference of the windowed drags.
    const double bin = 0.5 * D / U;
    std::ofstream csv(ctx.out_dir / "galilean.csv");
    csv << "t_mid,cd_towed,cd_fixed,cl_towed,cl_fixed\n";
    double worst = 0;
    for (double s = 0; s + 0.5 * bin < T; s += bin) {
      const double ea = -window_mean(a, a.fx, s, s + bin) / q;
      const double eb = -window_mean(b, b.fx, s, s + bin) / q;
      csv << fmt::format("{:.6g},{:.8g},{:.8g},{:.8g},{:.8g}\n", s + 0.5 * bin, ea, eb,
                         window_mean(a, a.fy, s, s + bin) / q,
                         window_mean(b, b.fy, s, s + bin) / q);
      if (s >= t0) worst = std::max(worst, std::abs(ea - eb) / std::abs(eb));
    }
    r.metrics["galilean_cd_towed"] = cd_a;
    r.metrics["galilean_cd_fixed"] = cd_b;
    r.metrics["galilean_cd_relative_difference"] = rel;
    r.metrics["galilean_window_max_relative_difference"] = worst;
    r.metrics["galilean_particles"] = a.particles;
    r.metrics["galilean_steps_towed"] = a.steps;
    r.metrics["galilean_steps_fixed"] = b.steps;
    r.metrics["galilean_projected"] = a.projected + b.projected;
    const std::string ref = fmt::format(
        "towed at U vs stream -U past the still cylinder, Re = 20, D/dx = {:.0f}, t in [{:.2g}, "
        "{:.2g}] s",
        D / ca.dx, t0, T);
    r.summary.push_back(
        {"moving_cylinder.galilean_cd_relative_difference", rel, "<= 0.02", ref, rel <= 0.02});
    md << "## (a) Galilean check\n\n"
       << "`cases/towed_cylinder.yaml` (towed at U = " << U
       << ", fluid at rest) and its twin (the fluid started at -U, the cylinder held still), "
       << a.particles << " particles, " << a.steps << " / " << b.steps << " steps.\n\n"
       << fmt::format(
              "| | towed | still | relative difference |\n|---|---|---|---|\n"
              "| mean C_D over t in [{:.2g}, {:.2g}] s | {:.4f} | {:.4f} | {:.2e} |\n"
              "| largest difference of C_D over windows of D/(2U) | | | {:.2e} |\n\n",
              t0, T, cd_a, cd_b, rel, worst)
       << fmt::format("Particles put back from past a wall: {}.\n\n", a.projected + b.projected)
       << summary_markdown(r.summary) << "\n![drag histories](galilean.png)\n\n";
  }

  // (b) The oscillating cylinder, first periods.
  {
    const auto path = ctx.source_dir / "cases" / "oscillating_cylinder.yaml";
    YAML::Node root = YAML::LoadFile(path.string());
    const YAML::Node osc = root["walls"][0]["motion"]["oscillate"];
    const double A = osc["amplitude"][0].as<double>(), f = osc["frequency"].as<double>();
    const double phi = osc["phase"].as<double>();
    const double periods = ctx.quick ? 0.2 : 2.0;
    root["time"]["end"] = periods / f;
    root["output"]["vtk"] = false;
    const Case c = read_case(root, path);
    const double D = 2 * root["walls"][0]["radius"].as<double>();
    const double rho = root["fluids"][0]["rho0"].as<double>();
    const ForceHistory h = run_forces(c);
    const double w = 2 * pi * f, Um = A * w;
    // Least squares over the last period (or the whole run when shorter) of
    // F = -C_d (rho D / 2) |u| u - C_a rho (pi D^2 / 4) du/dt.
    const double from = std::max(0.0, c.t_end - 1 / f);
    Eigen::MatrixXd M(0, 2);
    std::vector<double> rhs;
    std::vector<std::array<double, 2>> rows;
    double c1 = 0, s1 = 0, span = 0;
    std::ofstream csv(ctx.out_dir / "oscillating.csv");
    csv << "t,fx,fy,u_cylinder\n";
    for (std::size_t k = 0; k < h.t.size(); ++k) {
      const double t = h.t[k];
      const double u = Um * std::cos(w * t + phi), du = -Um * w * std::sin(w * t + phi);
      csv << fmt::format("{:.6g},{:.8g},{:.8g},{:.8g}\n", t, h.fx[k], h.fy[k], u);
      if (t < from || k == 0) continue;
      rows.push_back({-0.5 * rho * D * std::abs(u) * u, -rho * pi * D * D / 4 * du});
      rhs.push_back(h.fx[k]);
      const double dt = h.t[k] - h.t[k - 1];
      c1 += h.fx[k] * std::cos(w * t + phi) * dt;  // first harmonic against u's phase
      s1 += h.fx[k] * std::sin(w * t + phi) * dt;
      span += dt;
    }
    M.resize(static_cast<Eigen::Index>(rows.size()), 2);
    Eigen::VectorXd y(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t k = 0; k < rows.size(); ++k) {
      M(static_cast<Eigen::Index>(k), 0) = rows[k][0];
      M(static_cast<Eigen::Index>(k), 1) = rows[k][1];
      y(static_cast<Eigen::Index>(k)) = rhs[k];
    }
    const Eigen::Vector2d coef = M.colPivHouseholderQr().solve(y);
    const double amp = 2 * std::hypot(c1, s1) / span / (0.5 * rho * Um * Um * D);
    const double phase = std::atan2(s1, c1) * 180 / pi;  // of F against the velocity, degrees
    r.metrics["oscillating_cd_morison"] = coef(0);
    r.metrics["oscillating_ca_morison"] = coef(1);
    r.metrics["oscillating_first_harmonic_amplitude_coefficient"] = amp;
    r.metrics["oscillating_first_harmonic_phase_deg"] = phase;
    r.metrics["oscillating_steps"] = h.steps;
    r.metrics["oscillating_particles"] = h.particles;
    r.metrics["oscillating_projected"] = h.projected;
    md << "## (b) In-line oscillating cylinder, Re = 100, KC = 5\n\n"
       << fmt::format(
              "`cases/oscillating_cylinder.yaml` (D/dx = {:.0f}, box 10 D periodic), {:.3g} "
              "periods, {} particles, {} steps, {} particles put back. Over the last period "
              "(from t = {:.3g} s): Morison fit C_d = {:.3f}, C_a = {:.3f}; first harmonic of "
              "F_x: amplitude {:.3f} (in units of rho U_max^2 D / 2), phase {:.1f} deg against "
              "the cylinder's velocity.\n\n",
              D / c.dx, periods, h.particles, h.steps, h.projected, from, coef(0), coef(1), amp,
              phase)
       << "The comparison with Dütsch et al.'s (1998) in-line force is `curvsph validate "
          "oscillating_cylinder` (docs/validation/oscillating_cylinder/, a 20 D box).\n\n"
       << "![in-line force](oscillating.png)\n";
  }
  run_plot_script(ctx, "plot_moving_cylinder.py", {ctx.out_dir.string()});
  return r;
}

}  // namespace curvsph
