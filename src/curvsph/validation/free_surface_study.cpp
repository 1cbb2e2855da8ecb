// `curvsph validate free_surface`: free surfaces hitting walls, run to the end (issue 31).
// Three public cases — a column collapsing onto a cylinder (2-D), onto a sphere (3-D), and the
// classic 2-D dam break against Martin & Moyce's surge front — each with the three ghost maps
// and with boundary integrals, all with the case's defaults (no wall force). Per run: the time
// reached and the stray-particle counters of metrics.json (particles put back from past a wall,
// removed, density clamp events). The dam break's surge front against Martin & Moyce, at a
// resolution that converges, is the surge_front study's (surge_front_study.cpp). --quick: a
// tenth of each run's time.
#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <limits>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph/validation/study.hpp"

namespace curvsph {
namespace {

struct Method {
  const char* name;
  std::vector<std::string> sets;
};

const std::vector<Method>& methods() {
  static const std::vector<Method> m = {
      {"ghost mirror", {"boundary.method=ghost", "boundary.map=mirror"}},
      {"ghost mirror_beta", {"boundary.method=ghost", "boundary.map=mirror_beta"}},
      {"ghost density_preserving", {"boundary.method=ghost", "boundary.map=density_preserving"}},
      // The whole block replaced: the map is a ghost key.
      {"integrals geometric", {"boundary={method: integrals}"}},
  };
  return m;
}

double number_or_nan(const nlohmann::json& m, const char* k) {
  return m.contains(k) && m[k].is_number() ? m[k].get<double>()
                                           : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

StudyResult run_free_surface_study(const StudyContext& ctx) {
  const std::vector<std::string> cases = {"column_on_cylinder_2d", "column_on_sphere_3d",
                                          "dam_break_2d"};
  std::filesystem::create_directories(ctx.out_dir);
  StudyResult r;
  std::ofstream csv(ctx.out_dir / "runs.csv");
  csv << "case,method,t_end,time_reached,particles_initial,particles_projected,particles_removed,"
         "density_clamped,unstable,wall_seconds,wall_contacts,wall_contact_particles\n";
  std::string table =
      "| case | method | t reached / t end | particles | put back from past a wall (events, % "
      "of particles) | wall contacts: events (particles) | removed | density clamped | wall s "
      "|\n|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& name : cases) {
    const auto path = ctx.source_dir / "cases" / (name + ".yaml");
    for (const Method& meth : methods()) {
      std::vector<std::string> sets = {"output.vtk=false"};
      sets.insert(sets.end(), meth.sets.begin(), meth.sets.end());
      Case c;
      try {
        c = read_case(path, sets);
      } catch (const InputError& e) {
        table += fmt::format("| {} | {} | refused: {} | | | | | | |\n", name, meth.name, e.what());
        continue;
      }
      if (ctx.quick) {
        c.t_end /= 10;
        c.output_every = std::min(c.output_every, c.t_end / 5);
      }
      const std::string tag = fmt::format("{}_{}", name, meth.name);
      std::string dir_name = tag;
      std::replace(dir_name.begin(), dir_name.end(), ' ', '_');
      RunOptions o;
      o.out_dir = ctx.out_dir / "runs" / dir_name;
      o.threads = ctx.threads;
      o.progress = true;
      o.overwrite = true;  // the study's own directory, rerun
      nlohmann::json m;
      try {
        m = run_case(c, o);
      } catch (const InputError& e) {
        // A set-up refusal (a ghost map without a root at this curvature and h): a row.
        table += fmt::format("| {} | {} | refused at set-up: {} | | | | | | |\n", name, meth.name,
                             e.what());
        continue;
      } catch (const InstabilityError& e) {
        std::ifstream in(o.out_dir / "metrics_unstable.json");
        m = nlohmann::json::parse(in);
        std::cerr << "free_surface: " << tag << ": " << e.what() << "\n";
      }
      // The per-run directories hold a regenerated run; the study keeps its summaries.
      const double reached = number_or_nan(m, "time_reached");
      const double n0 = number_or_nan(m, "particles_initial");
      const double proj = number_or_nan(m, "particles_projected");
      const double removed = number_or_nan(m, "particles_removed");
      const double clamped = number_or_nan(m, "density_clamped");
      const bool unstable = m.value("unstable", 0) != 0;
      const double contacts = number_or_nan(m, "wall_contacts");
      const double contact_particles = number_or_nan(m, "wall_contact_particles");
      csv << fmt::format("{},{},{},{},{},{},{},{},{},{:.1f},{},{}\n", name, meth.name, c.t_end,
                         reached, n0, proj, removed, clamped, unstable ? 1 : 0,
                         number_or_nan(m, "wall_seconds"), contacts, contact_particles);
      table += fmt::format(
          "| {} | {} | {:.3f} / {:.3f} | {:.0f} | {:.0f} ({:.3f} %) | {:.0f} ({:.0f}) | {:.0f} | "
          "{:.0f} | {:.0f} |\n",
          name, meth.name, reached, c.t_end, n0, proj, 100 * proj / n0, contacts, contact_particles,
          removed, clamped, number_or_nan(m, "wall_seconds"));
      const std::string key =
          fmt::format("free_surface.{}.{}", name, dir_name.substr(name.size() + 1));
      r.metrics[key + ".time_reached"] = reached;
      r.metrics[key + ".particles_projected"] = proj;
      r.metrics[key + ".particles_removed"] = removed;
      r.metrics[key + ".density_clamped"] = clamped;
      r.metrics[key + ".wall_contacts"] = contacts;
      r.metrics[key + ".wall_contact_particles"] = contact_particles;
      r.summary.push_back({key + ".time_reached", reached, fmt::format(">= {}", c.t_end),
                           "runs to the end (issue 31 item 2)", reached >= c.t_end - 1e-9});
      r.summary.push_back({key + ".projected_fraction", proj / n0, "<= 0.001",
                           "particles put back from past a wall (issue 31 item 1)",
                           proj / n0 <= 0.001});
    }
  }
  std::ofstream md(ctx.out_dir / "README.md");
  md << "# Free surfaces against walls\n\n"
     << "Cases `cases/column_on_cylinder_2d.yaml`, `cases/column_on_sphere_3d.yaml` and "
        "`cases/dam_break_2d.yaml`, each run with the three ghost maps and with boundary "
        "integrals (geometric Shepard factor), with the case's own defaults: no wall force, "
        "free-surface defaults (README, \"Defaults\"). Regenerate with `build/curvsph validate "
        "free_surface`"
     << (ctx.quick ? " (these figures: `--quick`, a tenth of each run's time)" : "")
     << ". Why particles reached the walls, and the wall terms that keep them off: "
        "[findings.md](findings.md).\n\n"
     << table
     << "\nThe dam break's surge front against Martin & Moyce (1952), resolved (a/40, a/80), "
        "and the far-wall run-up: [surge_front](../surge_front/README.md).\n\n"
     << summary_markdown(r.summary);
  return r;
}

}  // namespace curvsph
