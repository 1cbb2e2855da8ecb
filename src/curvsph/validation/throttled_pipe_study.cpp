// `curvsph validate throttled_pipe`: Barker & Neethling §4.1 (Figs. 8-9). The throttled pipe
// (cases/throttled_pipe.yaml: NURBS walls, mirror_beta ghosts, no slip, Re ~ 30) started
// from the lubrication flow carrying the reference flux at three resolutions; figures at the
// end time from the analysis `throttled_pipe` (flux constancy, eq. 47; the flux against the
// case's independent lattice-Boltzmann reference; midline v_y; v_x against eq. 48) and the
// midline and throat profiles against the lattice-Boltzmann ones
// (data/throttled_pipe/lb_profiles_ny100.csv, scripts/throttled_pipe_reference.py). Plots:
// velocity magnitude with the walls (Fig. 8b), midline profiles against eq. 48 (Fig. 9),
// Q(x), flux history.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph/validation/run_cache.hpp"
#include "curvsph/validation/study.hpp"

namespace curvsph {
namespace {

// Columns of a CSV file with a header row; `text` columns (the LB file's `line`) are skipped.
std::map<std::string, std::vector<std::string>> read_table(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) names.push_back(c);
  std::map<std::string, std::vector<std::string>> cols;
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::size_t k = 0;
    for (std::string c; std::getline(ls, c, ',') && k < names.size(); ++k)
      cols[names[k]].push_back(c);
  }
  return cols;
}

// Relative L2 difference of the SPH profile v(s) against the reference (s_ref, v_ref), the
// reference interpolated linearly at the SPH stations (`skip_last`: a periodic line whose
// last station repeats the first).
double profile_error(const std::vector<double>& s, const std::vector<double>& v,
                     const std::vector<double>& s_ref, const std::vector<double>& v_ref,
                     bool skip_last) {
  double num = 0, den = 0;
  const std::size_t n = skip_last ? s.size() - 1 : s.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t j = 1;
    while (j + 1 < s_ref.size() && s_ref[j] < s[k]) ++j;
    const double a = std::clamp((s[k] - s_ref[j - 1]) / (s_ref[j] - s_ref[j - 1]), 0.0, 1.0);
    const double r = (1 - a) * v_ref[j - 1] + a * v_ref[j];
    num += (v[k] - r) * (v[k] - r);
    den += r * r;
  }
  return std::sqrt(num / den);
}

std::vector<double> numbers(const std::vector<std::string>& col) {
  std::vector<double> out;
  for (const auto& c : col) out.push_back(std::stod(c));
  return out;
}

}  // namespace

StudyResult run_throttled_pipe_study(const StudyContext& ctx) {
  const auto case_path = ctx.source_dir / "cases" / "throttled_pipe.yaml";
  const std::vector<double> dxs =
      ctx.quick ? std::vector<double>{5e-4} : std::vector<double>{5e-4, 2.5e-4, 1.25e-4};
  // The SPH flux relaxes from the reference flux to its own value within ~0.3 s, then creeps
  // up by ~0.05 % per 0.1 s (the continuity density's slow rearrangement; findings.md, issue
  // 36 item 2): the two finer dx stop at the same time so that they are compared at the same
  // point of that creep. throttled_pipe_history.csv shows it. ~2 / 12 min at dx = 2.5e-4 /
  // 1.25e-4 on 1 thread.
  const std::vector<std::string> t_ends =
      ctx.quick ? std::vector<std::string>{"0.3"} : std::vector<std::string>{"1.5", "1.2", "1.2"};
  std::filesystem::create_directories(ctx.out_dir);
  // The lattice-Boltzmann midline and throat profiles (ny = 100;
  // scripts/throttled_pipe_reference.py 100 0.115 3.0 1.0 1.0
  // data/throttled_pipe/lb_profiles_ny100.csv).
  const auto lb = read_table(ctx.source_dir / "data" / "throttled_pipe" / "lb_profiles_ny100.csv");
  std::vector<double> lb_mx, lb_mu, lb_ty, lb_tu;
  for (std::size_t k = 0; k < lb.at("line").size(); ++k) {
    const bool mid = lb.at("line")[k] == "midline";
    (mid ? lb_mx : lb_ty).push_back(std::stod(lb.at(mid ? "x" : "y")[k]));
    (mid ? lb_mu : lb_tu).push_back(std::stod(lb.at("u_x")[k]));
  }
  std::ofstream csv(ctx.out_dir / "throttled_pipe.csv");
  csv << "dx,particles,steps,time,flux_variation,reynolds,flux_rel_error,"
         "flux_particles_rel_error,midline_vy_max_rel,centerline_vx_rel_error,"
         "throat_vx_rel_error,centerline_vx_lb_error,throat_vx_lb_error,wall_seconds\n";
  std::string table =
      "| dx | particles | steps | t (s) | flux_particles_rel_error | flux_rel_error | "
      "flux_variation | midline_vy_max_rel | centerline_vx_lb_error | throat_vx_lb_error | "
      "centerline_vx_rel_error | throat_vx_rel_error | wall s |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  StudyResult r;
  std::string finest_dir;
  std::string t_end;
  std::vector<double> flux_errors;
  for (std::size_t run = 0; run < dxs.size(); ++run) {
    const double dx = dxs[run];
    t_end = t_ends[run];
    const std::string tag = fmt::format("dx_{}", dx);
    RunOptions o;
    o.out_dir = ctx.out_dir / tag;
    o.overwrite = true;  // a study redoes its runs in its own folders
    o.threads = ctx.threads;
    auto m = run_or_reuse(
        case_path, {fmt::format("resolution.dx={}", dx), "time.end=" + t_end, "output.every=0.1"},
        o);
    const auto mx = read_table(o.out_dir / "throttled_pipe_midline_x.csv");
    const auto my = read_table(o.out_dir / "throttled_pipe_midline_y.csv");
    m["centerline_vx_lb_error"] =
        profile_error(numbers(mx.at("x")), numbers(mx.at("vx")), lb_mx, lb_mu, true);
    m["throat_vx_lb_error"] =
        profile_error(numbers(my.at("y")), numbers(my.at("vx")), lb_ty, lb_tu, false);
    const double fv = m["flux_variation"], re = m["reynolds"], vy = m["midline_vy_max_rel"],
                 cl = m["centerline_vx_rel_error"], th = m["throat_vx_rel_error"],
                 fe = m.value("flux_rel_error", 0.0), fp = m.value("flux_particles_rel_error", 0.0),
                 cl_lb = m["centerline_vx_lb_error"], th_lb = m["throat_vx_lb_error"];
    flux_errors.push_back(fp);
    csv << fmt::format(
        "{},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},"
        "{:.1f}\n",
        dx, m["particles"].get<long>(), m["steps"].get<long>(), t_end, fv, re, fe, fp, vy, cl, th,
        cl_lb, th_lb, m["wall_seconds"].get<double>());
    table += fmt::format(
        "| {} | {} | {} | {} | {:+.4f} | {:+.4f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | "
        "{:.4f} | {:.0f} |\n",
        dx, m["particles"].get<long>(), m["steps"].get<long>(), t_end, fp, fe, fv, vy, cl_lb, th_lb,
        cl, th, m["wall_seconds"].get<double>());
    for (const char* k :
         {"flux_variation", "reynolds", "flux_rel_error", "flux_particles_rel_error",
          "midline_vy_max_rel", "centerline_vx_rel_error", "centerline_vx_max_rel_error",
          "throat_vx_rel_error", "centerline_vx_lb_error", "throat_vx_lb_error", "flux_mean",
          "flux_particles", "throat_half_width"})
      r.metrics[tag + "_" + k] = m[k];
    if (dx == dxs.back()) {
      for (const char* k :
           {"flux_variation", "reynolds", "flux_rel_error", "flux_particles_rel_error",
            "reference_reynolds", "midline_vy_max_rel", "centerline_vx_rel_error",
            "centerline_vx_max_rel_error", "throat_vx_rel_error", "centerline_vx_lb_error",
            "throat_vx_lb_error", "flux_mean", "flux_particles", "throat_half_width",
            "particle_steps_per_second", "particles", "steps"})
        r.metrics[k] = m[k];
      finest_dir = o.out_dir.string();
    }
  }
  csv.close();
  const auto& M = r.metrics;
  const std::string ref = fmt::format("dx = {}, t = {} s", dxs.back(), t_end);
  const double fv = M["flux_variation"], re = M["reynolds"], vy = M["midline_vy_max_rel"],
               cl = M["centerline_vx_rel_error"], th = M["throat_vx_rel_error"];
  r.summary.push_back(
      {"throttled_pipe.flux_variation", fv, "<= 0.03", "issue 4 (" + ref + ")", fv <= 0.03});
  r.summary.push_back({"throttled_pipe.reynolds", re, "25 .. 35",
                       "Barker §4.1: Re ~ 30 (" + ref + ")", re >= 25 && re <= 35});
  const double fe = M["flux_rel_error"], re_ref = M["reference_reynolds"];
  const double fp = M["flux_particles_rel_error"];
  const std::string lbm = fmt::format(
      "lattice Boltzmann, Re = {:.2f} (scripts/throttled_pipe_reference.py; {})", re_ref, ref);
  r.summary.push_back({"throttled_pipe.flux_particles_rel_error", fp, "-0.03 .. 0.03",
                       "issue 36: " + lbm, std::abs(fp) <= 0.03});
  r.summary.push_back({"throttled_pipe.flux_rel_error", fe, "-0.05 .. 0.05",
                       lbm + "; 48 sections, kernel-interpolated", std::abs(fe) <= 0.05});
  if (flux_errors.size() == 3) {
    // Convergence over the three dx (issue 36). The errors cross zero (the flux falls
    // through Q_ref), so |error| need not fall while the flux converges: the figure is the
    // ratio of successive differences, r = (Q(dx0) - Q(dx1)) / (Q(dx1) - Q(dx2)) with dx
    // (and h) halved each time: r > 1 is a monotone converging sequence, of observed order
    // log2 r. Its Richardson limit Q(dx2) - (Q(dx1) - Q(dx2)) / (r - 1) (Richardson
    // extrapolation with the observed order; Roache 1994, J. Fluids Eng. 116:405) is then the
    // flux at dx -> 0, and its error against the reference the discretisation-free one.
    const double d01 = flux_errors[0] - flux_errors[1], d12 = flux_errors[1] - flux_errors[2];
    const double ratio = d01 / d12;
    const bool converging = std::isfinite(ratio) && ratio > 1;
    const double limit =
        converging ? flux_errors[2] - d12 / (ratio - 1) : std::numeric_limits<double>::quiet_NaN();
    const double order = converging ? std::log2(ratio) : std::numeric_limits<double>::quiet_NaN();
    r.metrics["flux_convergence_ratio"] = ratio;
    r.metrics["flux_convergence_order"] = order;
    r.metrics["flux_richardson_rel_error"] = limit;
    const std::string seq =
        fmt::format("flux_particles_rel_error {:+.4f} / {:+.4f} / {:+.4f} at dx = {} / {} / {}",
                    flux_errors[0], flux_errors[1], flux_errors[2], dxs[0], dxs[1], dxs[2]);
    r.summary.push_back(
        {"throttled_pipe.flux_convergence_ratio", ratio, "> 1 (monotone, converging)",
         fmt::format("issue 36: (Q0 - Q1) / (Q1 - Q2), {}; observed order {:.2f}", seq, order),
         converging});
    r.summary.push_back({"throttled_pipe.flux_richardson_rel_error", limit, "-0.03 .. 0.03",
                         "issue 36: Richardson limit of the three dx (observed order) against "
                         "the lattice-Boltzmann Q_ref",
                         converging && std::abs(limit) <= 0.03});
  }
  r.summary.push_back({"throttled_pipe.midline_vy_max_rel", vy, "<= 0.05",
                       "symmetry, Barker §4.1 (our tolerance)", vy <= 0.05});
  const double cl_lb = M["centerline_vx_lb_error"], th_lb = M["throat_vx_lb_error"];
  r.summary.push_back(
      {"throttled_pipe.centerline_vx_lb_error", cl_lb, "<= 0.05",
       "lattice Boltzmann midline (data/throttled_pipe/lb_profiles_ny100.csv; " + ref + ")",
       cl_lb <= 0.05});
  r.summary.push_back({"throttled_pipe.throat_vx_lb_error", th_lb, "<= 0.05",
                       "lattice Boltzmann throat section (data/throttled_pipe/"
                       "lb_profiles_ny100.csv; " +
                           ref + ")",
                       th_lb <= 0.05});
  r.summary.push_back({"throttled_pipe.centerline_vx_rel_error", cl, "<= 0.05",
                       "Barker eq. 48, Fig. 9a (our tolerance; the lattice-Boltzmann flow "
                       "itself: 0.153)",
                       cl <= 0.05});
  r.summary.push_back({"throttled_pipe.throat_vx_rel_error", th, "<= 0.05",
                       "Barker eq. 48, Fig. 9b (our tolerance; the lattice-Boltzmann flow "
                       "itself: 0.191)",
                       th <= 0.05});
  run_plot_script(ctx, "plot_throttled_pipe.py", {ctx.out_dir.string(), finest_dir});
  std::ofstream md(ctx.out_dir / "README.md");
  md << "# Throttled pipe (Barker & Neethling §4.1, Figs. 8-9)\n\n"
     << "Case `cases/throttled_pipe.yaml`: periodic channel L_x = 0.024, L_y = 0.01, top and "
        "bottom walls cubic B-splines (NURBS, weights 1) narrowing to L_y/2 at mid-length, "
        "rho = 1000, mu = 0.01, body force 115 Pa/m (Re = rho Q / mu = 30 in the independent "
        "lattice-Boltzmann reference, `scripts/throttled_pipe_reference.py`; see the case "
        "file), `boundary: {method: ghost, map: mirror_beta, velocity: no_slip}`, h = 2.5 dx, "
        "continuity density with delta-SPH diffusion (0.1), Tait EOS with c0 = 1 m/s, "
        "p0 = 4 Pa (the case file and findings.md, last section, say why). "
        "Particles in wall-fitted columns, started from the lubrication flow carrying the "
        "reference flux and run to t = "
     << t_ends.front() << " s (dx = " << dxs.front() << ")";
  for (std::size_t k = 1; k < dxs.size(); ++k)
    md << fmt::format("{} {} s (dx = {})", k + 1 < dxs.size() ? "," : " and", t_ends[k], dxs[k]);
  md << ". Regenerate with `build/curvsph validate throttled_pipe` (kept runs are reused: "
        "delete dx_*/ to redo them with a new build).\n\n"
        "Figures (analysis `throttled_pipe`, src/curvsph/analysis/throttled_pipe.hpp): "
        "`flux_particles_rel_error` = sum V v_x / L_x over the particles (the mean over x of "
        "the section flux Q(x), no interpolation) / Q_ref - 1 against the lattice-Boltzmann "
        "reference of the same channel and force (Q_ref = 3.05e-4 m^2/s; converged value "
        "3.054-3.058e-4, findings.md); `flux_rel_error` the same from 48 kernel-interpolated "
        "sections (eq. 47), which read a parabolic profile low by ~1.5 sigma^2/R^2 (h^2); "
        "`flux_variation` = (max - min)/mean of those section fluxes; `midline_vy_max_rel` = "
        "max |v_y| / max v_x on the midline; `centerline_vx_lb_error`, `throat_vx_lb_error` = "
        "relative L2 of v_x on the midline and across the throat against the lattice-Boltzmann "
        "profiles (ny = 100, data/throttled_pipe/lb_profiles_ny100.csv); "
        "`centerline_vx_rel_error`, `throat_vx_rel_error` the same against Barker's eq. 48 "
        "(the seam profile stretched to the local half-width R(x)), an approximation that the "
        "lattice-Boltzmann flow itself misses by 0.153 (midline) and 0.191 (throat) at Re = "
        "30: the jet leaving the throat keeps the seam profile peaked (1.73 x the mean). "
        "Convergence over the three dx (h = 2.5 dx halved with dx): "
        "`flux_convergence_ratio` = (Q0 - Q1) / (Q1 - Q2) of the particle fluxes, > 1 for a "
        "monotone converging sequence of observed order log2 of it (the errors may cross zero "
        "while the flux converges: |error| is not the test); `flux_richardson_rel_error` = the "
        "Richardson limit Q2 - (Q1 - Q2) / (ratio - 1) / Q_ref - 1.\n\n"
     << table << "\n"
     << summary_markdown(r.summary) << "\n"
     << "Read the flux history (dx_*/throttled_pipe_history.csv, right panel of flux.png) "
        "before the figures: a run that still drifts is not at steady state.\n"
     << "\n![velocity magnitude](velocity_field.png)\n\n![midline profiles](profiles.png)\n\n"
        "![flux](flux.png)\n";
  return r;
}

}  // namespace curvsph
