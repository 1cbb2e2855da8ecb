// `curvsph geometry GEOM.yaml --points IN.csv [--out OUT.csv]` (DESIGN.md §3): for each point,
// the answer of the nearest wall — a way to check a wall (an imported CAD one above all)
// before running a case with it.
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "curvsph/app/command.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/io/points_csv.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph::app {
namespace {

constexpr const char* kColumns = "x,y,z,foot_x,foot_y,foot_z,nx,ny,nz,distance,k1,k2,u,v,wall";

// `+ 0.0` prints -0 as 0: the sign of a zero component means nothing here.
std::string num(double v) {
  return fmt::format("{:.17g}", v + 0.0);
}

template <int D>
void write_rows(const WallSet<D>& walls, const std::vector<VecD<D>>& points, std::ostream& out) {
  out << kColumns << '\n';
  for (const VecD<D>& x : points) {
    const WallPoint<D> p = walls.closest(x);
    const auto z = [](const VecD<D>& v) { return D == 3 ? v[D - 1] : 0.0; };
    out << num(x[0]) << ',' << num(x[1]) << ',' << num(z(x)) << ',' << num(p.foot[0]) << ','
        << num(p.foot[1]) << ',' << num(z(p.foot)) << ',' << num(p.normal[0]) << ','
        << num(p.normal[1]) << ',' << num(z(p.normal)) << ',' << num(p.distance) << ',' << num(p.k1)
        << ',' << num(D == 3 ? p.k2 : 0.0) << ',' << (p.param_count >= 1 ? num(p.param[0]) : "")
        << ',' << (p.param_count >= 2 ? num(p.param[1]) : "") << ',' << p.wall << '\n';
  }
}

template <int D>
int run_geometry(const YAML::Node& root, const std::string& geom, const std::string& points_file,
                 const std::string& out_file) {
  const std::filesystem::path base = std::filesystem::path(geom).parent_path();
  const WallSet<D> walls =
      parse_walls<D>(yaml::child(root, "walls", geom, ""), geom, base, "walls");
  if (walls.empty()) throw InputError(geom, "walls", "no walls: the list is empty");
  const std::vector<VecD<D>> points = read_points_csv<D>(points_file);
  if (out_file.empty()) {
    write_rows(walls, points, std::cout);
    return 0;
  }
  std::ofstream out(out_file);
  if (!out) throw InputError(out_file, "", "cannot write file");
  write_rows(walls, points, out);
  return 0;
}

const CommandRegistration reg{Command{
    "geometry",
    "For each point of a CSV file: closest wall point, normal into the fluid, signed distance, "
    "principal curvatures and surface parameters of the nearest wall",
    [](CLI::App& sub) -> std::function<int()> {
      auto geom = std::make_shared<std::string>();
      auto points = std::make_shared<std::string>();
      auto out = std::make_shared<std::string>();
      sub.add_option("GEOM", *geom,
                     "YAML file with `dimension` (2|3) and `walls:` (a case file "
                     "works too: other keys are ignored)")
          ->required();
      sub.add_option("--points", *points, "CSV file with the header x,y or x,y,z")->required();
      sub.add_option("--out", *out,
                     "output CSV (default: standard output); columns " + std::string(kColumns));
      return [geom, points, out] {
        const YAML::Node root = yaml::load_file(*geom);
        if (!root.IsMap())
          throw InputError(*geom, "", "expected a map with `dimension` and `walls`");
        const long dim = yaml::read_key(root, "dimension", *geom, "", yaml::read_integer);
        if (dim == 2) return run_geometry<2>(root, *geom, *points, *out);
        if (dim == 3) return run_geometry<3>(root, *geom, *points, *out);
        throw InputError(*geom, "dimension", fmt::format("must be 2 or 3, got {}", dim));
      };
    },
    20}};

}  // namespace
}  // namespace curvsph::app
