// The table of analyses and initial flow fields: one line per entry.
#include "curvsph/analysis/analysis.hpp"
#include "curvsph/analysis/couette_analysis.hpp"
#include "curvsph/analysis/cylinder_lattice.hpp"
#include "curvsph/analysis/dam_break_analysis.hpp"
#include "curvsph/analysis/droplet_wall.hpp"
#include "curvsph/analysis/hydrostatic_analysis.hpp"
#include "curvsph/analysis/node_density.hpp"
#include "curvsph/analysis/poiseuille_analysis.hpp"
#include "curvsph/analysis/static_droplet.hpp"
#include "curvsph/analysis/surge_front.hpp"
#include "curvsph/analysis/taylor_green_analysis.hpp"
#include "curvsph/analysis/throttled_pipe.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/io/schema_section.hpp"

namespace curvsph {
namespace {

template <int D>
struct Entry {
  const char* name;
  std::unique_ptr<Analysis<D>> (*analysis)(const YAML::Node&, const Case&);
  void (*initial)(const Case&, const YAML::Node&, const Eos&, const std::vector<Real>&,
                  Particles<D>&);
};

const Entry<2> kEntries2[] = {
    {"taylor_green", &make_taylor_green_analysis, &taylor_green_initial},
    {"static_droplet", &make_static_droplet_analysis<2>, nullptr},
    {"droplet_wall", &make_droplet_wall_analysis<2>, nullptr},
    {"couette", &make_couette_analysis, &couette_initial},
    {"poiseuille", &make_poiseuille_analysis, nullptr},
    {"node_density", &make_node_density_analysis<2>, nullptr},
    {"cylinder_lattice", &make_cylinder_lattice_analysis, nullptr},
    {"throttled_pipe", &make_throttled_pipe_analysis, &throttled_pipe_initial},
    {"hydrostatic", &make_hydrostatic_analysis<2>, &hydrostatic_initial<2>},
    {"surge_front", &make_surge_front_analysis, nullptr},
};
const Entry<3> kEntries3[] = {
    {"static_droplet", &make_static_droplet_analysis<3>, nullptr},
    {"node_density", &make_node_density_analysis<3>, nullptr},
    {"hydrostatic", &make_hydrostatic_analysis<3>, &hydrostatic_initial<3>},
    {"dam_break", &make_dam_break_analysis, nullptr},
};

template <int D>
auto& entries() {
  if constexpr (D == 2)
    return kEntries2;
  else
    return kEntries3;
}

template <int D>
std::string names() {
  std::string s;
  for (const auto& e : entries<D>())
    if (*e.name) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s.empty() ? "none" : s;
}

}  // namespace

template <int D>
std::unique_ptr<Analysis<D>> make_analysis(const std::string& name, const YAML::Node& params,
                                           const Case& c) {
  for (const auto& e : entries<D>())
    if (name == e.name && e.analysis) {
      // The table's rows of analysis.NAME type and range the parameters (issue 34 item 1);
      // the analysis then checks what depends on the case.
      schema::check_section(params, c.file_name(), "analysis." + name);
      return e.analysis(params, c);
    }
  throw InputError(c.file_name(), "analysis." + name,
                   "unknown analysis in " + std::to_string(D) + "-D (known: " + names<D>() + ")");
}

template <int D>
void apply_initial_field(const Case& c, const Eos& eos, const std::vector<Real>& rho0,
                         Particles<D>& P) {
  for (const auto& e : entries<D>())
    if (c.initial_field == e.name && e.initial) {
      schema::check_section(c.initial_params, c.file_name(), "initial." + c.initial_field);
      return e.initial(c, c.initial_params, eos, rho0, P);
    }
  throw InputError(
      c.file_name(), "initial." + c.initial_field,
      "unknown initial flow field in " + std::to_string(D) + "-D (known: " + names<D>() + ")");
}

template std::unique_ptr<Analysis<2>> make_analysis<2>(const std::string&, const YAML::Node&,
                                                       const Case&);
template std::unique_ptr<Analysis<3>> make_analysis<3>(const std::string&, const YAML::Node&,
                                                       const Case&);
template void apply_initial_field<2>(const Case&, const Eos&, const std::vector<Real>&,
                                     Particles<2>&);
template void apply_initial_field<3>(const Case&, const Eos&, const std::vector<Real>&,
                                     Particles<3>&);

}  // namespace curvsph
