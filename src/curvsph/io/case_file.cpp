#include "curvsph/io/case_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "curvsph/core/error.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/io/case_overrides.hpp"
#include "curvsph/io/case_schema.hpp"
#include "curvsph/io/quote.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {
namespace {

// Reads typed values out of one YAML map, remembering the dotted key path for messages. Every
// read consults the schema (io/case_schema.hpp): the table's range applies on top of the
// reader's own checks, and in strict mode an undeclared key or another default is an error.
class Keys {
 public:
  Keys(const YAML::Node& node, std::string file, std::string path)
      : node_(node), file_(std::move(file)), path_(std::move(path)) {
    if (node_ && !node_.IsMap() && !node_.IsNull())
      fail(path_, "must be a mapping of keys (got " + kind(node_) + ")");
  }

  std::string key(const std::string& k) const { return path_.empty() ? k : path_ + "." + k; }
  bool has(const std::string& k) const { return node_ && node_.IsMap() && node_[k]; }
  YAML::Node raw(const std::string& k) const { return has(k) ? node_[k] : YAML::Node(); }
  Keys sub(const std::string& k) const { return Keys(raw(k), file_, key(k)); }
  [[noreturn]] void fail(const std::string& k, const std::string& why) const {
    throw InputError(file_, k, why);
  }

  // The keys allowed here: the schema's (a list that differs from the table is a strict-mode
  // error; outside it the union is accepted, so that a key added without its row still reads).
  void allow(std::initializer_list<const char*> names) const {
    if (!node_ || !node_.IsMap()) return;
    std::set<std::string> ok(names.begin(), names.end());
    const std::vector<std::string> declared = schema::children(path_);
    if (schema::strict() && !declared.empty() &&
        ok != std::set<std::string>(declared.begin(), declared.end()))
      throw std::logic_error("schema: the keys allowed under '" + schema::pattern(path_) +
                             "' differ from src/curvsph/io/schema_table.cpp");
    ok.insert(declared.begin(), declared.end());
    for (const auto& kv : node_) {
      const auto name = kv.first.as<std::string>();
      if (!ok.count(name)) {
        std::string list;
        for (const auto& n : ok) list += (list.empty() ? "" : ", ") + n;
        fail(key(clip(name)), "unknown key (allowed here: " + list + ")");
      }
    }
  }

  double number(const std::string& k, std::optional<double> fallback = std::nullopt) const {
    schema::lookup(key(k));
    if (fallback) schema::check_default(key(k), *fallback);
    if (!has(k)) {
      if (fallback) return *fallback;
      fail(key(k), "missing (a number is required)");
    }
    const double v = as_number(node_[k], key(k));
    schema::check_number(file_, key(k), v);
    return v;
  }
  double positive(const std::string& k, std::optional<double> fallback = std::nullopt) const {
    const double v = number(k, fallback);
    if (!(v > 0)) fail(key(k), fmt::format("must be > 0 (got {})", v));
    return v;
  }
  double non_negative(const std::string& k, std::optional<double> fallback = std::nullopt) const {
    const double v = number(k, fallback);
    if (!(v >= 0)) fail(key(k), fmt::format("must be >= 0 (got {})", v));
    return v;
  }
  long integer(const std::string& k, std::optional<long> fallback = std::nullopt) const {
    schema::lookup(key(k));
    if (fallback) schema::check_default(key(k), static_cast<double>(*fallback));
    if (!has(k)) {
      if (fallback) return *fallback;
      fail(key(k), "missing (an integer is required)");
    }
    const double v = as_number(node_[k], key(k));
    if (v != std::floor(v)) fail(key(k), fmt::format("must be an integer (got {})", v));
    // Beyond 2^53 a double no longer holds every integer, and the cast to long overflows.
    if (std::abs(v) > 9007199254740992.0)
      fail(key(k), fmt::format("must be an integer of magnitude <= 2^53 (got {})", v));
    schema::check_number(file_, key(k), v);
    return static_cast<long>(v);
  }
  bool boolean(const std::string& k, bool fallback) const {
    schema::lookup(key(k));
    schema::check_default(key(k), fallback ? 1.0 : 0.0);
    if (!has(k)) return fallback;
    bool b = false;
    if (!node_[k].IsScalar() || !YAML::convert<bool>::decode(node_[k], b))
      fail(key(k), "must be true or false (got " + quote(scalar_text(node_[k])) + ")");
    return b;
  }
  std::string text(const std::string& k, std::optional<std::string> fallback = std::nullopt) const {
    schema::lookup(key(k));
    if (!has(k)) {
      if (fallback) return *fallback;
      fail(key(k), "missing (a string is required)");
    }
    if (!node_[k].IsScalar()) fail(key(k), "must be a string (got " + kind(node_[k]) + ")");
    return node_[k].as<std::string>();
  }
  std::string choice(const std::string& k, std::initializer_list<const char*> options,
                     std::optional<std::string> fallback = std::nullopt) const {
    if (fallback) schema::check_default(key(k), *fallback);
    const std::string v = text(k, fallback);
    std::string list;
    for (const char* o : options) {
      schema::check_option(key(k), o);  // the reader's options are the table's
      if (v == o) return v;
      list += (list.empty() ? "" : " | ") + std::string(o);
    }
    fail(key(k), quote(v) + " is not one of: " + list);
  }
  // A list of exactly `dim` numbers into the first dim components of a Vec3d.
  Vec3d vector(const std::string& k, int dim, std::optional<Vec3d> fallback = std::nullopt) const {
    schema::lookup(key(k));
    if (!has(k)) {
      if (fallback) return *fallback;
      fail(key(k), fmt::format("missing (a list of {} numbers is required)", dim));
    }
    const YAML::Node n = node_[k];
    if (!n.IsSequence() || static_cast<int>(n.size()) != dim)
      fail(key(k), fmt::format("must be a list of {} numbers (dimension {})", dim, dim));
    Vec3d v = Vec3d::Zero();
    for (int d = 0; d < dim; ++d) {
      v[d] = as_number(n[d], key(k) + "." + std::to_string(d));
      schema::check_number(file_, key(k) + "." + std::to_string(d), v[d]);
    }
    return v;
  }
  std::array<bool, 3> flags(const std::string& k, int dim) const {
    std::array<bool, 3> out{false, false, false};
    schema::lookup(key(k));
    if (!has(k)) return out;
    const YAML::Node n = node_[k];
    if (!n.IsSequence() || static_cast<int>(n.size()) != dim)
      fail(key(k), fmt::format("must be a list of {} booleans", dim));
    for (int d = 0; d < dim; ++d) {
      bool b = false;
      if (!YAML::convert<bool>::decode(n[d], b))
        fail(key(k) + "." + std::to_string(d), "must be true or false");
      out[d] = b;
    }
    return out;
  }
  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }

 private:
  static std::string kind(const YAML::Node& n) {
    switch (n.Type()) {
      case YAML::NodeType::Sequence:
        return "a list";
      case YAML::NodeType::Map:
        return "a mapping";
      case YAML::NodeType::Scalar:
        return quote(n.Scalar());
      default:
        return "nothing";
    }
  }
  static std::string scalar_text(const YAML::Node& n) {
    return n.IsScalar() ? n.Scalar() : kind(n);
  }
  double as_number(const YAML::Node& n, const std::string& k) const {
    double v = 0;
    if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !std::isfinite(v))
      fail(k, "must be a finite number (got " + kind(n) + ")");
    return v;
  }

  YAML::Node node_;
  std::string file_;
  std::string path_;
};

RegionSpec read_region(const Keys& k, int dim) {
  const bool has_random = k.node() && k.node().IsMap() && k.node()["random"];
  if (!k.node() || !k.node().IsMap() || k.node().size() != (has_random ? 2u : 1u))
    k.fail(k.path(),
           "must hold exactly one region: box | disk | ball | annulus | inside_walls "
           "(and optionally random: true)");
  std::string type;
  for (const auto& kv : k.node())
    if (kv.first.as<std::string>() != "random") type = kv.first.as<std::string>();
  RegionSpec r;
  if (has_random) r.random = k.boolean("random", false);
  // inside_walls holds a scalar (true), the other regions a mapping of keys.
  const Keys s = type == "inside_walls" ? k : k.sub(type);
  if (type == "box") {
    s.allow({"min", "max"});
    r.kind = RegionSpec::Kind::box;
    r.min = s.vector("min", dim);
    r.max = s.vector("max", dim);
    for (int d = 0; d < dim; ++d)
      if (!(r.max[d] > r.min[d])) s.fail(s.key("max"), "must exceed min on every axis");
  } else if (type == "disk" || type == "ball") {
    if ((type == "disk") != (dim == 2))
      k.fail(k.key(type),
             type == "disk" ? "a disk is 2-D; use ball in 3-D" : "a ball is 3-D; use disk in 2-D");
    s.allow({"center", "radius"});
    r.kind = type == "disk" ? RegionSpec::Kind::disk : RegionSpec::Kind::ball;
    r.center = s.vector("center", dim);
    r.radius = s.positive("radius");
  } else if (type == "annulus") {
    s.allow({"center", "r_in", "r_out"});
    r.kind = RegionSpec::Kind::annulus;
    r.center = s.vector("center", dim);
    r.r_in = s.non_negative("r_in");
    r.r_out = s.positive("r_out");
    if (!(r.r_out > r.r_in)) s.fail(s.key("r_out"), "must exceed r_in");
  } else if (type == "inside_walls") {
    bool b = false;
    if (!YAML::convert<bool>::decode(k.node()["inside_walls"], b) || !b)
      k.fail(k.key(type), "must be true");
    r.kind = RegionSpec::Kind::inside_walls;
  } else {
    k.fail(k.key(type), "unknown region (box | disk | ball | annulus | inside_walls)");
  }
  return r;
}

// output.fields: names of Particles fields (for_each_field); `position` is always written
// (the points of the data set) and added when left out.
std::vector<std::string> output_fields(const Keys& out) {
  std::vector<std::string> known;
  Particles<2>().for_each_field([&](const char* name, const auto&) { known.push_back(name); });
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  if (!out.has("fields"))
    return {"position", "velocity", "pressure", "density", "mass", "phase", "id"};
  const YAML::Node fl = out.raw("fields");
  if (!fl.IsSequence()) out.fail(out.key("fields"), "must be a list of field names (" + list + ")");
  std::vector<std::string> fields{"position"};
  for (std::size_t k = 0; k < fl.size(); ++k) {
    const std::string f = fl[k].IsScalar() ? fl[k].as<std::string>() : "";
    if (std::find(known.begin(), known.end(), f) == known.end())
      out.fail(out.key("fields") + "." + std::to_string(k), quote(f) + " is not one of: " + list);
    if (std::find(fields.begin(), fields.end(), f) == fields.end()) fields.push_back(f);
  }
  return fields;
}

}  // namespace

Case read_case(const std::filesystem::path& path, const std::vector<std::string>& overrides) {
  YAML::Node root = yaml::load_file(path.string());
  apply_overrides(root, overrides);
  return read_case(root, path);
}

namespace {
Case read_case_tree(YAML::Node root, const std::filesystem::path& path);
}  // namespace

Case read_case(YAML::Node root, const std::filesystem::path& path) {
  // A value yaml-cpp cannot convert where a key reader did not expect it (a tagged mapping
  // key such as `!periodic:`, found by fuzz/fuzz_case) is bad input, not an internal error.
  try {
    return read_case_tree(std::move(root), path);
  } catch (const YAML::Exception& e) {
    throw InputError(path.string(), "", std::string("cannot read the YAML: ") + e.what());
  }
}

namespace {
Case read_case_tree(YAML::Node root, const std::filesystem::path& path) {
  Case c;
  c.file = path;
  c.root = root;
  const std::string file = path.string();
  if (!root.IsMap()) throw InputError(file, "", "the case file must be a YAML mapping");
  // Again after the --set overrides (the file itself was checked by load_file): a line number
  // would point into the override's text, not the file.
  yaml::reject_duplicate_keys(root, file, false);
  const Keys top(root, file, "");
  top.allow({"name",
             "dimension",
             "resolution",
             "domain",
             "fluids",
             "eos",
             "density",
             "gravity",
             "forcing",
             "walls",
             "boundary",
             "setup",
             "time",
             "output",
             "probes",
             "analysis",
             "initial",
             "surface_tension",
             "parallel",
             "artificial_viscosity",
             "transport_velocity",
             "pressure_gradient",
             "open_boundaries"});
  c.name = top.text("name", path.stem().string());
  const long dim = top.integer("dimension");
  if (dim != 2 && dim != 3) top.fail("dimension", fmt::format("must be 2 or 3 (got {})", dim));
  c.dimension = static_cast<int>(dim);
  const int D = c.dimension;

  const Keys res = top.sub("resolution");
  res.allow({"dx", "h_over_dx"});
  c.dx = res.positive("dx");
  c.h_over_dx = res.positive("h_over_dx", 1.3);
  if (c.h_over_dx < 0.8 || c.h_over_dx > 4)
    res.fail(res.key("h_over_dx"), "must lie in [0.8, 4] for the Wendland C2 kernel");

  if (top.has("domain")) {
    const Keys dom = top.sub("domain");
    dom.allow({"min", "max", "periodic"});
    c.has_domain = true;
    c.domain_min = dom.vector("min", D);
    c.domain_max = dom.vector("max", D);
    c.periodic = dom.flags("periodic", D);
    for (int d = 0; d < D; ++d) {
      if (!(c.domain_max[d] > c.domain_min[d]))
        dom.fail(dom.key("max"), "must exceed min on every axis");
      const double cells = (c.domain_max[d] - c.domain_min[d]) / (2 * c.h());
      if (c.periodic[d] && cells < 3)
        dom.fail(dom.key("periodic"),
                 fmt::format("periodic axis {} spans only {:.2f} kernel supports (2h = {}); at "
                             "least 3 are needed",
                             d, cells, 2 * c.h()));
    }
  }

  const YAML::Node fluids = top.raw("fluids");
  if (!fluids || !fluids.IsSequence() || fluids.size() == 0)
    top.fail("fluids", "missing (a list with at least one fluid is required)");
  for (std::size_t i = 0; i < fluids.size(); ++i) {
    const Keys f(fluids[i], file, "fluids." + std::to_string(i));
    f.allow({"name", "rho0", "viscosity", "region", "velocity"});
    FluidSpec s;
    s.name = f.text("name", "fluid" + std::to_string(i));
    s.rho0 = f.positive("rho0");
    s.viscosity = f.non_negative("viscosity", 0.0);
    if (!f.has("region")) f.fail(f.key("region"), "missing (where the fluid starts)");
    s.region = read_region(f.sub("region"), D);
    s.velocity = f.vector("velocity", D, Vec3d::Zero());
    c.fluids.push_back(s);
  }

  // Gravity is read here (before the fluids' sound speed and the density method need it).
  c.gravity = top.vector("gravity", D, Vec3d::Zero());
  for (int d = 0; d < D; ++d)
    if (c.gravity[d] != 0 && !c.periodic[static_cast<std::size_t>(d)])
      c.free_surface_defaults = true;

  const Keys eos = top.sub("eos");
  // Under gravity across a non-periodic axis the fastest speed a column of height H reaches is
  // about sqrt(2 g H) (free fall), and c0 = 10 sqrt(2 g H) keeps density changes near 1 % (Mach
  // 0.1; Monaghan 1994): eos.c0 may then be left out, H being the tallest fluid region's extent
  // along gravity.
  std::optional<double> c0_default;
  if (c.free_surface_defaults) {
    const Vec3d ghat = c.gravity.normalized();
    double H = 0;
    bool known = true;
    for (const FluidSpec& f : c.fluids) {
      const RegionSpec& r = f.region;
      switch (r.kind) {
        case RegionSpec::Kind::box:
          H = std::max(H, (r.max - r.min).cwiseAbs().dot(ghat.cwiseAbs()));
          break;
        case RegionSpec::Kind::disk:
        case RegionSpec::Kind::ball:
          H = std::max(H, 2 * r.radius);
          break;
        case RegionSpec::Kind::annulus:
          H = std::max(H, 2 * r.r_out);
          break;
        case RegionSpec::Kind::inside_walls:
          known = false;
          break;
      }
    }
    if (known && H > 0) c0_default = 10 * std::sqrt(2 * c.gravity.norm() * H);
  }
  if (!top.has("eos") && !c0_default)
    top.fail("eos",
             "missing ({type: tait|linear, c0, p0}; c0 may be left out only under gravity "
             "with fluid regions of known height)");
  eos.allow({"type", "c0", "gamma", "p0"});
  c.eos.type = eos.choice("type", {"tait", "linear"}, "tait") == "tait" ? EosSpec::Type::tait
                                                                        : EosSpec::Type::linear;
  c.eos.c0 = eos.positive("c0", c0_default);
  c.eos.gamma = eos.positive("gamma", 7.0);
  c.eos.p0 = eos.number("p0", 0.0);

  const Keys den = top.sub("density");
  den.allow({"method", "delta_sph", "diffusion_term", "shifting", "clamp"});
  // The continuity equation with delta-SPH diffusion (Antuono et al. 2010, 2012;
  // physics/density.hpp) is every case's default. With a free surface, summation density
  // underestimates the density of every particle whose support the surface cuts, which then
  // pulls the surface together. In a confined sheared flow, summation ties the pressure to the
  // particle arrangement: the disordered particles carry pressure noise (4.6 Pa rms in the
  // throttled pipe, h = 2 dx) whose stress resists the shear like an extra viscosity (flux
  // -8 %); the continuity density changes only by compression (noise 0.1 Pa) and the pipe meets
  // its 3 % target (docs/validation/throttled_pipe/findings.md). Summation only when asked, or
  // with transport_velocity, whose density follows the transported positions (Adami et al.
  // 2013) and which is read below.
  c.density.method =
      den.choice("method", {"summation", "continuity"},
                 top.has("transport_velocity") ? "summation" : "continuity") == "summation"
          ? DensitySpec::Method::summation
          : DensitySpec::Method::continuity;
  if (den.has("clamp")) {
    const YAML::Node cl = den.raw("clamp");
    bool on = true;
    if (cl.IsScalar() && YAML::convert<bool>::decode(cl, on) && !on) {
      c.density.clamp = false;
    } else {
      const Vec3d b = den.vector("clamp", 2);
      if (!(b[0] > 0 && b[0] < 1 && b[1] > 1 && std::isfinite(b[1])))
        den.fail(den.key("clamp"),
                 fmt::format("must be [lo, hi] with 0 < lo < 1 < hi (fractions of rho0), or "
                             "false (got [{}, {}])",
                             b[0], b[1]));
      c.density.clamp_lo = b[0];
      c.density.clamp_hi = b[1];
    }
  }
  c.density.delta_sph = den.non_negative("delta_sph", 0.1);
  c.shifting = den.non_negative("shifting", 0.0);
  if (c.shifting > 1) den.fail(den.key("shifting"), "must be <= 1 (typical: 0.01-0.05)");
  if (den.has("delta_sph") && c.density.method == DensitySpec::Method::summation)
    den.fail(den.key("delta_sph"), "only applies to method: continuity");
  const std::string term =
      den.choice("diffusion_term", {"antuono", "molteni", "fourtakas"}, "antuono");
  c.density.diffusion = term == "antuono"   ? DensitySpec::Diffusion::antuono
                        : term == "molteni" ? DensitySpec::Diffusion::molteni
                                            : DensitySpec::Diffusion::fourtakas;
  if (den.has("diffusion_term") && c.density.method == DensitySpec::Method::summation)
    den.fail(den.key("diffusion_term"), "only applies to method: continuity");

  // pressure_gradient (physics/pressure_gradient.hpp): symmetric for every case, confined
  // ones included. The difference form removes the background pressure's force on the
  // particle disorder but also the order it keeps: alone it clumps the particles (throttled
  // pipe, Couette from rest), with shifting or the transport velocity it misses the targets
  // the other way (throttled_pipe/findings.md, couette/findings.md).
  c.pressure_difference =
      top.choice("pressure_gradient", {"symmetric", "difference"}, "symmetric") == "difference";

  if (top.has("transport_velocity")) {
    const Keys tv = top.sub("transport_velocity");
    tv.allow({"background_pressure"});
    double stiff = 0;  // rho0 c0^2 of the stiffest fluid: Adami et al.'s p_b
    for (const FluidSpec& f : c.fluids) stiff = std::max(stiff, f.rho0 * c.eos.c0 * c.eos.c0);
    c.transport_pb = tv.positive("background_pressure", stiff);
    if (c.density.method != DensitySpec::Method::summation)
      tv.fail(tv.path(),
              "needs density.method: summation (the density follows the "
              "transported positions)");
    if (c.shifting > 0)
      tv.fail(tv.path(), "and density.shifting both regularise the particles; use one");
  }

  if (top.has("artificial_viscosity")) {
    const Keys av = top.sub("artificial_viscosity");
    av.allow({"alpha", "form"});
    c.artificial_alpha = av.non_negative("alpha", 0.0);
    c.artificial_approaching =
        av.choice("form", {"all_pairs", "approaching"}, "all_pairs") == "approaching";
  }

  if (top.has("forcing")) {
    const Keys frc = top.sub("forcing");
    frc.allow({"drive"});
    if (frc.has("drive")) {
      const Keys drv = frc.sub("drive");
      drv.allow({"v0", "tau"});
      c.drive = true;
      c.drive_v0 = drv.number("v0");
      c.drive_tau = drv.positive("tau");
    }
  }

  if (top.has("surface_tension")) {
    const YAML::Node st = top.raw("surface_tension");
    if (!st.IsSequence())
      top.fail("surface_tension", "must be a list of {fluids: [a, b], coefficient}");
    for (std::size_t k = 0; k < st.size(); ++k) {
      const Keys e(st[k], file, "surface_tension." + std::to_string(k));
      e.allow({"fluids", "coefficient"});
      SurfaceTensionSpec s;
      s.coefficient = e.non_negative("coefficient");
      const YAML::Node names = e.raw("fluids");
      if (!names || !names.IsSequence() || names.size() != 2)
        e.fail(e.key("fluids"), "must name two fluids: [a, b]");
      int idx[2] = {-1, -1};
      for (int m = 0; m < 2; ++m) {
        const std::string nm = names[m].IsScalar() ? names[m].as<std::string>() : "";
        for (std::size_t f = 0; f < c.fluids.size(); ++f)
          if (c.fluids[f].name == nm) idx[m] = static_cast<int>(f);
        if (idx[m] < 0)
          e.fail(e.key("fluids") + "." + std::to_string(m), quote(nm) + " is not a fluid name");
      }
      if (idx[0] == idx[1]) e.fail(e.key("fluids"), "needs two different fluids");
      s.fluid_a = idx[0];
      s.fluid_b = idx[1];
      c.surface_tension.push_back(s);
    }
  }

  const Keys bnd = top.sub("boundary");
  bnd.allow({"method", "map", "velocity", "shepard", "wall_force", "pressure", "ghost_pressure",
             "penetration", "wall_tension", "contact"});
  c.boundary.method = bnd.choice("method", {"none", "ghost", "integrals"}, "none");
  c.boundary.map =
      bnd.choice("map", {"mirror", "mirror_beta", "density_preserving"}, "mirror_beta");
  c.boundary.velocity = bnd.choice("velocity", {"no_slip", "free_slip"}, "no_slip");
  c.boundary.shepard =
      bnd.choice("shepard", {"geometric", "volume", "monolithic", "none"}, "geometric");
  c.boundary.wall_force = bnd.boolean("wall_force", false);
  c.boundary.pressure = bnd.choice("pressure",
                                   {"symmetric", "consistent", "tensile_control", "conservative",
                                    "conservative_wall", "conservative_pairs"},
                                   "conservative");
  // Under gravity across a non-periodic axis the ghost carries its source's pressure along the
  // hydrostatic gradient (ghost_boundary.cpp: a copied pressure leaves a tank's first row
  // short of its wall push by 2 rho g d).
  c.boundary.ghost_pressure = bnd.choice("ghost_pressure", {"copy", "hydrostatic"},
                                         c.free_surface_defaults ? "hydrostatic" : "copy");
  c.boundary.penetration_stop = bnd.choice("penetration", {"project", "stop"}, "project") == "stop";
  c.boundary.wall_tension = bnd.boolean("wall_tension", true);
  c.boundary.contact = bnd.non_negative("contact", 0.1);
  if (c.boundary.contact >= 0.5)
    bnd.fail(bnd.key("contact"),
             "must be below 0.5 (a fraction of dx; the first particle row "
             "sits at dx/2)");
  if (bnd.has("ghost_pressure") && c.boundary.method != "ghost")
    bnd.fail(bnd.key("ghost_pressure"),
             "applies to method: ghost (boundary integrals always extrapolate the wall pressure "
             "with its hydrostatic part)");
  const YAML::Node walls = top.raw("walls");
  if (top.has("walls") && !walls.IsSequence()) top.fail("walls", "must be a list of walls");
  const bool has_walls = top.has("walls") && walls.size() > 0;
  if (has_walls && c.boundary.method == "none")
    bnd.fail(bnd.key("method"), "the case has walls; choose ghost or integrals");

  const Keys setup = top.sub("setup");
  setup.allow({"random_seed", "jitter", "relax", "hydrostatic"});
  const long seed = setup.integer("random_seed", 1);
  if (seed < 0) setup.fail(setup.key("random_seed"), "must be >= 0");
  c.random_seed = static_cast<unsigned>(seed);
  c.jitter = setup.number("jitter", 0.0);
  if (!(c.jitter >= 0 && c.jitter < 0.5))
    setup.fail(setup.key("jitter"), "must be in [0, 0.5) (a fraction of dx)");
  if (setup.has("relax")) {
    const Keys relax = setup.sub("relax");
    relax.allow({"max_steps", "tolerance", "map", "free_faces"});
    c.relax.enabled = true;
    c.relax.max_steps = relax.integer("max_steps", 2000);
    if (c.relax.max_steps < 0) relax.fail(relax.key("max_steps"), "must be >= 0");
    c.relax.tolerance = relax.positive("tolerance", 1e-3);
    c.relax.map = relax.choice("map", {"mirror", "mirror_beta", "density_preserving", "integrals"},
                               c.boundary.map);
    c.relax.hold_free_faces = relax.choice("free_faces", {"open", "hold"}, "open") == "hold";
  }
  // A tank under gravity started at p = 0 everywhere first compresses acoustically (its walls
  // ring about its weight, 1.40 of it at 0.01 s in tests/setup/test_hydrostatic_start.cpp),
  // so a free-surface case without `initial` starts hydrostatic (setup/hydrostatic_start.hpp);
  // an explicit `initial` field keeps its own.
  c.hydrostatic_start =
      setup.boolean("hydrostatic", c.free_surface_defaults && !top.has("initial"));
  if (c.hydrostatic_start && top.has("initial"))
    setup.fail(setup.key("hydrostatic"),
               "true conflicts with `initial` (which sets the initial pressure itself)");
  if (c.hydrostatic_start && !c.free_surface_defaults)
    setup.fail(setup.key("hydrostatic"), "true needs gravity across a non-periodic axis");

  const Keys time = top.sub("time");
  if (!top.has("time")) top.fail("time", "missing ({end, cfl})");
  time.allow({"end", "cfl", "dt_max", "max_steps", "max_removed_fraction"});
  c.t_end = time.non_negative("end");
  c.cfl = time.positive("cfl", 0.2);
  if (c.cfl > 1) time.fail(time.key("cfl"), "must be <= 1");
  c.dt_max = time.non_negative("dt_max", 0.0);
  c.max_steps = time.integer("max_steps", 0);
  if (c.max_steps < 0) time.fail(time.key("max_steps"), "must be >= 0");
  c.max_removed_fraction = time.non_negative("max_removed_fraction", 0.01);
  if (c.max_removed_fraction > 1)
    time.fail(time.key("max_removed_fraction"), "must lie in [0, 1] (a fraction of the particles)");

  // MPI domain decomposition (issue 8); ignored on one rank.
  const Keys par = top.sub("parallel");
  par.allow({"rebalance_imbalance", "check_conservation", "halo_rule"});
  c.rebalance_imbalance = par.positive("rebalance_imbalance", 0.1);
  c.check_conservation = par.boolean("check_conservation", false);
  const std::string rule = par.choice("halo_rule", {"auto", "midpoint", "owner"}, "auto");
  c.halo_rule = rule == "midpoint" ? Case::HaloRule::midpoint
                : rule == "owner"  ? Case::HaloRule::owner
                                   : Case::HaloRule::automatic;

  const Keys out = top.sub("output");
  out.allow({"every", "probe_every", "vtk", "precision", "compress", "fields", "restart",
             "forces_every", "boundary_points"});
  c.output_every = out.non_negative("every", 0.0);
  c.probe_every = out.non_negative("probe_every", 0.0);
  if (out.has("forces_every")) c.forces_every = out.non_negative("forces_every");
  c.write_boundary_points = out.boolean("boundary_points", true);
  c.write_vtk = out.boolean("vtk", true);
  c.output_float32 = out.choice("precision", {"float32", "float64"}, "float32") == "float32";
  c.output_zlib = out.choice("compress", {"zlib", "none"}, "zlib") == "zlib";
  c.output_fields = output_fields(out);
  const std::string restart = out.choice("restart", {"last", "every", "none"}, "last");
  c.output_restart = restart == "every"  ? Case::RestartFiles::every
                     : restart == "none" ? Case::RestartFiles::none
                                         : Case::RestartFiles::last;

  const YAML::Node probes = top.raw("probes");
  if (top.has("probes") && !probes.IsSequence()) top.fail("probes", "must be a list of probes");
  std::set<std::string> probe_names;
  for (std::size_t i = 0; top.has("probes") && i < probes.size(); ++i) {
    const Keys pk(probes[i], file, "probes." + std::to_string(i));
    pk.allow({"name", "point", "fields", "gauge", "normal"});
    ProbeSpec p;
    p.name = pk.text("name");
    if (!probe_names.insert(p.name).second) pk.fail(pk.key("name"), "duplicate probe name");
    if (pk.has("gauge")) {
      if (pk.has("point") || pk.has("fields") || pk.has("normal"))
        pk.fail(pk.key("gauge"), "a gauge takes no point, fields or normal of its own");
      const Keys g = pk.sub("gauge");
      g.allow({"point", "direction"});
      p.kind = ProbeSpec::Kind::gauge;
      p.point = g.vector("point", D);
      p.direction = g.vector("direction", D);
      if (p.direction.norm() == 0) g.fail(g.key("direction"), "must not be zero");
      p.direction.normalize();
    } else {
      p.point = pk.vector("point", D);
      if (pk.has("normal")) {
        p.normal = pk.vector("normal", D);
        if (p.normal.norm() == 0) pk.fail(pk.key("normal"), "must not be zero");
        p.normal.normalize();
      }
      const YAML::Node fl = pk.raw("fields");
      if (!fl || !fl.IsSequence() || fl.size() == 0)
        pk.fail(pk.key("fields"), "missing (a list of: p, p_wall, rho, vel)");
      for (std::size_t k = 0; k < fl.size(); ++k) {
        const std::string f = fl[k].IsScalar() ? fl[k].as<std::string>() : "";
        if (f != "p" && f != "p_wall" && f != "rho" && f != "vel")
          pk.fail(pk.key("fields") + "." + std::to_string(k),
                  "must be one of: p, p_wall, rho, vel");
        p.fields.push_back(f);
      }
    }
    c.probes.push_back(p);
  }

  if (top.has("initial")) {
    const YAML::Node ini = top.raw("initial");
    if (!ini.IsMap() || ini.size() != 1)
      top.fail("initial", "must name exactly one initial flow field, e.g. {taylor_green: {U: 1}}");
    c.initial_field = ini.begin()->first.as<std::string>();
    c.initial_params = ini.begin()->second;
  }
  c.open_boundaries = read_open_boundaries(top.raw("open_boundaries"), c);
  if (!c.open_boundaries.empty()) {
    // The buffer particles' marks are part of the state a snapshot must hold (a restart).
    if (!out.has("fields")) c.output_fields.push_back("buffer");
    if (c.transport_pb > 0)
      top.fail("transport_velocity",
               "not available with open_boundaries (its per-particle push is not defined for "
               "buffer particles)");
  }
  if (top.has("analysis") && !top.raw("analysis").IsMap())
    top.fail("analysis", "must be a mapping of analysis names to their parameters");
  return c;
}
}  // namespace

}  // namespace curvsph
