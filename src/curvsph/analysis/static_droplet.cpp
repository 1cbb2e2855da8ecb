#include "curvsph/analysis/static_droplet.hpp"

#include <cmath>

#include "curvsph/core/error.hpp"

namespace curvsph {
namespace {

template <int D>
class StaticDroplet final : public Analysis<D> {
 public:
  StaticDroplet(int drop, Vec3d center, double radius, double reference, double h)
      : drop_(drop), center_(center), radius_(radius), reference_(reference), h_(h) {}

  void finish(double, const Particles<D>& P, nlohmann::json& m,
              const std::filesystem::path&) override {
    double p_in = 0, p_out = 0, vmax = 0;
    long n_in = 0, n_out = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      const double r = (P.x[i].template cast<double>() - center_.head<D>()).norm();
      if (P.phase[i] == drop_ && r < radius_ / 2) {
        p_in += P.p[i];
        ++n_in;
      } else if (P.phase[i] != drop_ && r > radius_ + 4 * h_) {
        p_out += P.p[i];
        ++n_out;
      }
      vmax = std::max(vmax, static_cast<double>(P.v[i].norm()));
    }
    const double jump = (n_in ? p_in / n_in : 0) - (n_out ? p_out / n_out : 0);
    m["laplace_pressure"] = jump;
    m["laplace_pressure_reference"] = reference_;
    m["laplace_pressure_rel_error"] = std::abs(jump - reference_) / reference_;
    m["max_spurious_velocity"] = vmax;
  }

 private:
  int drop_;
  Vec3d center_;
  double radius_, reference_, h_;
};

}  // namespace

template <int D>
std::unique_ptr<Analysis<D>> make_static_droplet_analysis(const YAML::Node& params, const Case& c) {
  const std::string key = "analysis.static_droplet";
  if (params && params.IsMap() && params.size() > 0)
    throw InputError(c.file_name(), key + "." + params.begin()->first.as<std::string>(),
                     "unknown key (static_droplet takes no parameters)");
  if (c.surface_tension.empty())
    throw InputError(c.file_name(), key,
                     "needs a surface_tension pair (the drop is its second fluid)");
  const auto& st = c.surface_tension.front();
  const RegionSpec& r = c.fluids.at(st.fluid_b).region;
  if (r.kind != RegionSpec::Kind::disk && r.kind != RegionSpec::Kind::ball)
    throw InputError(c.file_name(), key, "the drop fluid's region must be a disk or a ball");
  if (!(st.coefficient > 0)) throw InputError(c.file_name(), key, "needs a coefficient > 0");
  const double reference = (D == 2 ? 1.0 : 2.0) * st.coefficient / r.radius;
  return std::make_unique<StaticDroplet<D>>(st.fluid_b, r.center, r.radius, reference, c.h());
}

template std::unique_ptr<Analysis<2>> make_static_droplet_analysis<2>(const YAML::Node&,
                                                                      const Case&);
template std::unique_ptr<Analysis<3>> make_static_droplet_analysis<3>(const YAML::Node&,
                                                                      const Case&);

}  // namespace curvsph
