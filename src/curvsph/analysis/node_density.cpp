#include "curvsph/analysis/node_density.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>

#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/setup/relax.hpp"

namespace curvsph {

double node_density_source_band(const YAML::Node& params, const std::string& file) {
  // Vela Vela §7.1: "50K ghost particles were used to guarantee that every internal
  // particle has a ghost counterpart" — the default mirrors every fluid particle.
  if (!(params && params.IsMap() && params["ghost_support"]))
    return std::numeric_limits<double>::infinity();
  const YAML::Node s = params["ghost_support"];
  if (s.IsScalar() && s.as<std::string>() == "all") return std::numeric_limits<double>::infinity();
  double v = 0;
  if (!YAML::convert<double>::decode(s, v) || !(v > 0))
    throw InputError(file, "analysis.node_density.ghost_support",
                     "must be 'all' or a positive depth");
  return v;
}

template <int D>
void ghost_node_density(const std::vector<Vec<D>>& x, const CellList<D>& cells,
                        const WallSet<D>& walls, GhostMapKind map, double source_band,
                        const WendlandC2<D>& W, GhostNodeDensity<D>& out) {
  GhostOptions<D> go;
  go.map = map;
  // GhostSet mirrors the particles with d < support; +inf (the analysis band) reaches all.
  go.support = static_cast<Real>(source_band);
  go.cells = &cells;
  const std::vector<Vec<D>> v0(x.size(), Vec<D>::Zero());
  out.ghosts.build(x, v0, walls, go);
  out.ghost_cells.configure_like(cells, W.support);
  out.ghost_cells.build(out.ghosts.x);
  node_density<D>(out.ghosts.x, x, cells, &out.ghosts, &out.ghost_cells, W, out.n_ghost);
  node_density<D>(x, x, cells, &out.ghosts, &out.ghost_cells, W, out.n_fluid);
}

namespace {

template <int D>
class NodeDensityAnalysis final : public Analysis<D> {
 public:
  NodeDensityAnalysis(const YAML::Node& params, const Case& c)
      : case_(c), W_(static_cast<Real>(c.h())) {
    if (c.root["walls"] && c.root["walls"].IsSequence())
      walls_ = parse_walls<D>(c.root["walls"], c.file_name(), c.file.parent_path());
    if (walls_.empty())
      throw InputError(c.file_name(), "analysis.node_density", "needs at least one wall");
    ghost_support_ = node_density_source_band(params, c.file_name());
    maps_ = {GhostMapKind::mirror, GhostMapKind::density_preserving};
    const GhostMapKind own = parse_ghost_map(c.boundary.map, c.file_name(), "boundary.map");
    if (own == GhostMapKind::mirror_beta) maps_.push_back(own);
    own_ = own;
  }

  void finish(double, const Particles<D>& P, nlohmann::json& m,
              const std::filesystem::path& out_dir) override {
    const Case& c = case_;
    CellList<D> cells;
    cells.configure(W_.support, c.domain_min, c.domain_max, c.periodic);
    cells.build(P.x);
    const Index n = static_cast<Index>(P.size());
    const Real support = W_.support;

    // Distance of each fluid particle to the nearest wall.
    std::vector<double> dist(n);
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) dist[i] = walls_.closest(P.x[i].template cast<double>()).distance;

    // Reference: fluid-only n of the deep particles.
    std::vector<Real> n_fluid;
    node_density<D>(P.x, P.x, cells, nullptr, nullptr, W_, n_fluid);
    std::vector<Real> deep;
    for (Index i = 0; i < n; ++i)
      if (dist[i] >= support) deep.push_back(n_fluid[i]);
    if (deep.empty()) deep = n_fluid;
    double ref = 0;
    for (Real v : deep) ref += v;
    ref /= static_cast<double>(deep.size());
    m["node_density_ref"] = ref;
    m["node_density_interior_spread"] = relative_spread(deep);
    m["node_density_fluid_particles"] = n;

    std::ofstream binned, points;
    if (!out_dir.empty()) {
      binned.open(out_dir / "node_density_binned.csv");
      binned << "map,kind,distance,mean,std,min,max,count,band\n";
      points.open(out_dir / "node_density_points.csv");
      // Positions too, so that a study can bin by where on the wall a point sits (e.g. the
      // poloidal angle on a torus), not only by depth.
      points << "map,kind,distance,n_rel";
      for (int k = 0; k < D; ++k) points << ",x" << k;
      points << ",band\n";
    }
    const double bin = 0.25 * c.dx;
    for (GhostMapKind map : maps_) {
      const std::string name = to_string(map);
      for (const bool solver_band : {false, true}) {
        const std::string band = solver_band ? "solver" : "all";
        const std::string sfx = solver_band ? "_solver_band" : "";
        GhostNodeDensity<D> nd;
        ghost_node_density<D>(P.x, cells, walls_, map, solver_band ? support : ghost_support_, W_,
                              nd);
        const GhostSet<D>& G = nd.ghosts;
        const std::vector<Real>&ng = nd.n_ghost, &nf = nd.n_fluid;
        double dev = 0, fdev = 0;
        long near = 0, fnear = 0;
        for (std::size_t g = 0; g < G.size(); ++g)
          if (G.depth[g] < support) {
            dev += std::abs(ng[g] / ref - 1.0);
            ++near;
          }
        for (Index i = 0; i < n; ++i)
          if (dist[i] < support) {
            fdev += std::abs(nf[i] / ref - 1.0);
            ++fnear;
          }
        dev = near > 0 ? dev / near : 0.0;
        fdev = fnear > 0 ? fdev / fnear : 0.0;
        m["ghost_node_density_dev" + sfx + "_" + name] = dev;
        m["fluid_node_density_dev" + sfx + "_" + name] = fdev;
        m["node_density_ghosts" + sfx + "_" + name] = G.size();
        if (!solver_band)
          m["node_density_sources_without_ghost_" + name] = G.no_root.size() + G.penetrated.size();
        if (map == own_) {
          m["ghost_node_density_dev" + sfx] = dev;
          if (!solver_band) m["node_density_ghosts_near_wall"] = near;
        }
        if (!out_dir.empty())
          write_profile(binned, points, name, band, bin, dist, P, G, nf, ng, ref);
      }
    }
  }

 private:
  // Binned profile against the signed distance (ghosts negative) and a subsample of points.
  void write_profile(std::ofstream& binned, std::ofstream& points, const std::string& name,
                     const std::string& band, double bin, const std::vector<double>& dist,
                     const Particles<D>& P, const GhostSet<D>& G, const std::vector<Real>& nf,
                     const std::vector<Real>& ng, double ref) const {
    struct Acc {
      double s = 0, s2 = 0, mn = 1e300, mx = -1e300;
      long k = 0;
    };
    for (int kind = 0; kind < 2; ++kind) {
      std::map<long, Acc> bins;
      const std::size_t count = kind == 0 ? P.size() : G.size();
      const std::size_t stride = std::max<std::size_t>(1, count / 6000);
      for (std::size_t q = 0; q < count; ++q) {
        const double s = kind == 0 ? dist[q] : -G.depth[q];
        const double v = (kind == 0 ? nf[q] : ng[q]) / ref;
        Acc& a = bins[std::lround(std::floor(s / bin))];
        a.s += v;
        a.s2 += v * v;
        a.mn = std::min(a.mn, v);
        a.mx = std::max(a.mx, v);
        ++a.k;
        if (q % stride == 0) {
          points << fmt::format("{},{},{:.6g},{:.6g}", name, kind == 0 ? "fluid" : "ghost", s, v);
          const Vec<D>& xq = kind == 0 ? P.x[q] : G.x[q];
          for (int k = 0; k < D; ++k) points << fmt::format(",{:.6g}", xq[k]);
          points << "," << band << "\n";
        }
      }
      for (const auto& [b, a] : bins) {
        const double mean = a.s / a.k;
        binned << fmt::format("{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{},{}\n", name,
                              kind == 0 ? "fluid" : "ghost", (b + 0.5) * bin, mean,
                              std::sqrt(std::max(0.0, a.s2 / a.k - mean * mean)), a.mn, a.mx, a.k,
                              band);
      }
    }
  }

  Case case_;
  WendlandC2<D> W_;
  WallSet<D> walls_;
  double ghost_support_;
  std::vector<GhostMapKind> maps_;
  GhostMapKind own_ = GhostMapKind::mirror;
};

}  // namespace

template <int D>
std::unique_ptr<Analysis<D>> make_node_density_analysis(const YAML::Node& params, const Case& c) {
  return std::make_unique<NodeDensityAnalysis<D>>(params, c);
}

template std::unique_ptr<Analysis<2>> make_node_density_analysis<2>(const YAML::Node&, const Case&);
template std::unique_ptr<Analysis<3>> make_node_density_analysis<3>(const YAML::Node&, const Case&);
template void ghost_node_density<2>(const std::vector<Vec<2>>&, const CellList<2>&,
                                    const WallSet<2>&, GhostMapKind, double, const WendlandC2<2>&,
                                    GhostNodeDensity<2>&);
template void ghost_node_density<3>(const std::vector<Vec<3>>&, const CellList<3>&,
                                    const WallSet<3>&, GhostMapKind, double, const WendlandC2<3>&,
                                    GhostNodeDensity<3>&);

}  // namespace curvsph
