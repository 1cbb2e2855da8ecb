// `curvsph shepard GEOM.yaml --points IN.csv --h H --dx DX --mode MODE [--out OUT.csv]`
// (DESIGN.md §3): the Shepard factor gamma at each point for a wall set.
//  - geometric | monolithic: the walls discretised into boundary elements at spacing DX
//    (boundary/integrals/wall_elements.hpp); infinite walls are clipped to the points' bounds
//    grown by 2H (elements further away do not reach any point's support);
//  - volume: particles of volume DX^d on the lattice (i + 1/2) DX on the fluid side of the
//    walls (signed distance of the nearest wall >= 0) within the points' bounds +- 2H;
//  - none: gamma = 1.
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "curvsph/app/command.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/integrals/wall_clip.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/io/points_csv.hpp"
#include "curvsph/io/quote.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph::app {
namespace {

struct ShepardArgs {
  std::string geom, points, out, mode;
  double h = 0, dx = 0;
  bool contour_half = false;
};

constexpr double kMaxLatticeParticles = 5e7;

// A finite number > 0: CLI11's PositiveNumber lets `inf` through (and h = inf gave gamma for
// a kernel that covers everything).
const CLI::Validator kFinitePositive(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !std::isfinite(v) || !(v > 0))
        return "must be a finite number > 0, got " + quote(text);
      return {};
    },
    "FINITE > 0", "finite_positive");

template <int D>
std::vector<double> compute(const WallSet<D>& walls, const std::vector<VecD<D>>& points,
                            const ShepardArgs& a, ShepardMode mode) {
  Bounds<D> bounds;
  for (const auto& p : points) bounds.extend(p);
  if (!bounds.isEmpty()) {
    bounds.min().array() -= 2.0 * a.h;
    bounds.max().array() += 2.0 * a.h;
  }
  ShepardQuadrature quad;
  quad.monolithic_contour_half = a.contour_half;
  BoundaryElements<D> elements;
  std::vector<VecD<D>> fluid;
  std::vector<double> volumes;
  if (mode == ShepardMode::geometric || mode == ShepardMode::monolithic) {
    // Each wall's elements as the solver builds them: infinite walls clipped by the others.
    for (std::size_t k = 0; k < walls.size(); ++k)
      elements.append(clip_by_other_walls<D>(elements_from_wall<D>(walls[k], a.dx, bounds), walls,
                                             k, 1e-9 * a.dx));
  } else if (mode == ShepardMode::volume && !bounds.isEmpty()) {
    Eigen::Array<long, D, 1> lo, hi;
    double count = 1;
    for (int i = 0; i < D; ++i) {
      lo[i] = static_cast<long>(std::floor(bounds.min()[i] / a.dx - 0.5));
      hi[i] = static_cast<long>(std::ceil(bounds.max()[i] / a.dx - 0.5));
      count *= static_cast<double>(hi[i] - lo[i] + 1);
    }
    if (count > kMaxLatticeParticles)
      throw InputError("", "--dx",
                       fmt::format("volume mode needs {:.3g} lattice sites (limit {:.0g}): "
                                   "increase DX or query fewer, closer points",
                                   count, kMaxLatticeParticles));
    const double vol = D == 2 ? a.dx * a.dx : a.dx * a.dx * a.dx;
    Eigen::Array<long, D, 1> idx = lo;
    while (true) {
      VecD<D> y;
      for (int i = 0; i < D; ++i) y[i] = (static_cast<double>(idx[i]) + 0.5) * a.dx;
      if (walls.closest(y).distance >= 0.0) {
        fluid.push_back(y);
        volumes.push_back(vol);
      }
      int k = 0;
      for (; k < D; ++k) {
        if (++idx[k] <= hi[k]) break;
        idx[k] = lo[k];
      }
      if (k == D) break;
    }
  }
  return shepard_factor<D>(mode, elements, points, a.h, fluid, volumes, quad);
}

template <int D>
void write_rows(const std::vector<VecD<D>>& points, const std::vector<double>& gamma,
                std::ostream& out) {
  out << "x,y,z,gamma\n";
  for (std::size_t i = 0; i < points.size(); ++i)
    out << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g}\n", points[i][0] + 0.0, points[i][1] + 0.0,
                       D == 3 ? points[i][D - 1] + 0.0 : 0.0, gamma[i]);
}

template <int D>
int run_shepard(const YAML::Node& root, const ShepardArgs& a, ShepardMode mode) {
  const std::filesystem::path base = std::filesystem::path(a.geom).parent_path();
  const WallSet<D> walls =
      parse_walls<D>(yaml::child(root, "walls", a.geom, ""), a.geom, base, "walls");
  if (walls.empty()) throw InputError(a.geom, "walls", "no walls: the list is empty");
  const std::vector<VecD<D>> points = read_points_csv<D>(a.points);
  std::vector<double> gamma;
  try {
    gamma = compute<D>(walls, points, a, mode);
  } catch (const std::invalid_argument& e) {
    throw InputError(a.geom, "walls", e.what());
  }
  if (a.out.empty()) {
    write_rows<D>(points, gamma, std::cout);
    return 0;
  }
  std::ofstream out(a.out);
  if (!out) throw InputError(a.out, "", "cannot write file");
  write_rows<D>(points, gamma, out);
  return 0;
}

const CommandRegistration reg{Command{
    "shepard",
    "Shepard factor gamma at each point of a CSV file for a wall set (boundary integrals: "
    "geometric | monolithic | volume | none)",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<ShepardArgs>();
      sub.add_option("GEOM", a->geom,
                     "YAML file with `dimension` (2|3) and `walls:` (a case file works too)")
          ->required();
      sub.add_option("--points", a->points, "CSV file with the header x,y or x,y,z")->required();
      sub.add_option("--h", a->h, "smoothing length h (kernel support 2h), > 0")
          ->required()
          ->check(kFinitePositive);
      sub.add_option("--dx", a->dx,
                     "element spacing on the walls (geometric, monolithic) or particle "
                     "spacing of the fluid lattice (volume), > 0")
          ->required()
          ->check(kFinitePositive);
      sub.add_option("--mode", a->mode, "geometric | monolithic | volume | none")->required();
      sub.add_flag("--contour-half", a->contour_half,
                   "monolithic: the paper's rule gamma = 1/2 from the elements a point lies on");
      sub.add_option("--out", a->out,
                     "output CSV (default: standard output); columns x,y,z,gamma (z = 0 in 2-D)");
      return [a] {
        ShepardMode mode;
        try {
          mode = shepard_mode_from_string(a->mode);
        } catch (const std::invalid_argument& e) {
          throw InputError("", "--mode", e.what());
        }
        if (!(a->h > 0)) throw InputError("", "--h", fmt::format("must be > 0, got {}", a->h));
        if (!(a->dx > 0)) throw InputError("", "--dx", fmt::format("must be > 0, got {}", a->dx));
        const YAML::Node root = yaml::load_file(a->geom);
        if (!root.IsMap())
          throw InputError(a->geom, "", "expected a map with `dimension` and `walls`");
        const long dim = yaml::read_key(root, "dimension", a->geom, "", yaml::read_integer);
        if (dim == 2) return run_shepard<2>(root, *a, mode);
        if (dim == 3) return run_shepard<3>(root, *a, mode);
        throw InputError(a->geom, "dimension", fmt::format("must be 2 or 3, got {}", dim));
      };
    },
    25}};

}  // namespace
}  // namespace curvsph::app
