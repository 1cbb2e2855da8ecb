#pragma once
// The case file (YAML) of DESIGN.md §3, read into plain values. Key names are normative.
// Everything is validated here — unknown keys, wrong types, inconsistent values — so the
// solver can trust what it receives; errors name the file, the dotted key and the reason.
#include <yaml-cpp/yaml.h>

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "curvsph/core/types.hpp"
#include "curvsph/io/open_boundary_spec.hpp"

namespace curvsph {

struct RegionSpec {
  enum class Kind { box, disk, ball, annulus, inside_walls } kind = Kind::box;
  Vec3d min = Vec3d::Zero(), max = Vec3d::Zero();  // box
  Vec3d center = Vec3d::Zero();                    // disk, ball, annulus
  double radius = 0, r_in = 0, r_out = 0;
  // `random: true` next to the region: as many particles as the lattice would hold, at
  // uniformly random positions (setup.random_seed), e.g. as the start of a relaxation.
  bool random = false;
};

struct FluidSpec {
  std::string name;
  double rho0 = 1000;
  double viscosity = 0;  // dynamic, Pa s
  RegionSpec region;
  Vec3d velocity = Vec3d::Zero();
};

struct EosSpec {
  enum class Type { tait, linear } type = Type::tait;
  double c0 = 0;
  double gamma = 7;
  double p0 = 0;
};

struct DensitySpec {
  enum class Method { summation, continuity } method = Method::summation;
  double delta_sph = 0.1;  // Antuono et al. delta; 0 switches the diffusive term off
  // The diffusive term's form (physics/density.hpp): antuono (renormalised gradient, one
  // pass more), molteni (plain density difference), fourtakas (difference less its
  // hydrostatic part).
  enum class Diffusion { antuono, molteni, fourtakas } diffusion = Diffusion::antuono;
  // density.clamp: [lo, hi] in units of each fluid's rho0: a density outside is set to the
  // bound and counted (metrics density_clamped); empty (`clamp: false`): a density outside
  // [0.5, 2] rho0 stops the run with exit 3 (studies that measure when a run fails).
  double clamp_lo = 0.7, clamp_hi = 1.3;
  bool clamp = true;
};

struct BoundarySpec {
  std::string method = "none";  // none | ghost | integrals
  std::string map = "mirror_beta";
  std::string velocity = "no_slip";
  std::string shepard = "geometric";
  bool wall_force = false;  // repulsion closer than 0.1 dx (Calderon §3.2), both methods
  std::string pressure =
      "conservative";  // integrals: conservative | symmetric | consistent | tensile_control | ...
  std::string ghost_pressure = "copy";  // ghost: copy | hydrostatic (p_s + rho_s g.(x_g - x_s))
  // boundary.penetration: what happens to a fluid particle found past a wall (distance <= 0)
  // at a step. project: it is put back on the fluid side along the wall normal with its
  // normal velocity relative to the wall removed, and counted (metrics particles_projected);
  // stop: the run stops with exit 3 (studies that measure when a wall first fails).
  bool penetration_stop = false;
  // boundary.contact: the distance from a wall, in dx, at which a particle is stopped (its
  // normal velocity towards the wall removed; solver/stray_particles.hpp); 0: off.
  double contact = 0.1;
  // boundary.wall_tension: whether a wall may pull on the fluid (its pair terms with a
  // negative pressure sum attract a particle towards the wall). Off, the wall terms take the
  // pressures clamped at 0 (ghosts: p_g and p_i; integrals: p_b + p_i), so a wall only ever
  // pushes. On by default: the rarefaction that follows a dam-break release reflects at the
  // back wall as a transient tension, and a wall that cannot hold it lets the first particle
  // layer tear away (column on a cylinder, mirror_beta: the layer at the back wall leaves it
  // at 1.25 m/s, p down to -35 kPa at t = 0.015 s against -4.7 kPa with the wall holding it,
  // for a hydrostatic 5.9 kPa).
  bool wall_tension = true;
};

// setup.relax (setup/relax.hpp); map: the ghost map of the walls during relaxation
// (default: boundary.map), or `integrals`: the boundary-integral packing of
// setup/relax_integrals.hpp (one fluid with a box region).
struct RelaxSpec {
  bool enabled = false;
  long max_steps = 2000;
  double tolerance = 1e-3;
  std::string map;
  // free_faces: hold (setup/relax_closure.hpp): box-region faces inside the walls are packed
  // against as plane walls.
  bool hold_free_faces = false;
};

struct ProbeSpec {
  std::string name;
  enum class Kind { point, gauge } kind = Kind::point;
  Vec3d point = Vec3d::Zero();
  Vec3d direction = Vec3d::Zero();  // gauge
  std::vector<std::string> fields;  // point: p, p_wall, rho, vel (io/probes.hpp)
  Vec3d normal = Vec3d::Zero();     // point: sensor face normal, unit (zero: none; io/probes.hpp)
};

struct SurfaceTensionSpec {
  int fluid_a = 0, fluid_b = 1;  // indices into Case::fluids
  double coefficient = 0;        // N/m
};

struct Case {
  std::filesystem::path file;  // the case file (for messages and relative paths)
  YAML::Node root;             // the tree after overrides (walls, analysis read it later)
  std::string name;
  int dimension = 2;
  double dx = 0;
  double h_over_dx = 1.3;
  bool has_domain = false;
  Vec3d domain_min = Vec3d::Zero(), domain_max = Vec3d::Zero();
  std::array<bool, 3> periodic{false, false, false};
  std::vector<FluidSpec> fluids;
  EosSpec eos;
  DensitySpec density;
  Vec3d gravity = Vec3d::Zero();
  std::vector<SurfaceTensionSpec> surface_tension;
  bool drive = false;
  double drive_v0 = 0, drive_tau = 1;
  BoundarySpec boundary;
  double shifting = 0;  // particle shifting coefficient C (0: off); see particle_shifting.hpp
  // transport_velocity.background_pressure: p_b of the transport-velocity formulation
  // (physics/transport_velocity.hpp; 0: off)
  double transport_pb = 0;
  // pressure_gradient: difference (p_j - p_i) instead of symmetric (p_j + p_i)
  // (physics/pressure_gradient.hpp).
  bool pressure_difference = false;
  // artificial_viscosity.alpha: the delta-SPH momentum diffusion (physics/artificial_viscosity.hpp;
  // 0: off, the default)
  double artificial_alpha = 0;
  // artificial_viscosity.form: approaching = Monaghan's original form, on approaching pairs
  // only (physics/artificial_viscosity.hpp); false: every pair (the delta-SPH form, default)
  bool artificial_approaching = false;
  unsigned random_seed = 1;
  // setup.jitter: every lattice point moved by a uniform random offset of up to jitter dx per
  // axis (setup.random_seed), 0 <= jitter < 0.5. A start that breaks the lattice's symmetry
  // far above round-off, so that runs in float and double (or on other compilers) disorder
  // alike instead of when their round-off first grows (docs/performance.md).
  double jitter = 0;
  RelaxSpec relax;
  double t_end = 0;
  double cfl = 0.2;
  double dt_max = 0;   // 0: no cap
  long max_steps = 0;  // 0: unlimited
  // time.max_removed_fraction: particles that leave the domain (the domain box, or without one
  // the box of the initial particles and the bounded walls grown by its largest extent on
  // every side, solver/stray_particles.hpp) are
  // removed and counted; more than this fraction of the initial count stops the run (exit 3).
  double max_removed_fraction = 0.01;
  double output_every = 0;  // 0: only first and last
  double probe_every = 0;   // 0: as output_every
  bool write_vtk = true;
  // output.forces_every: the interval of forces.csv's rows (io/forces_csv.hpp); absent (< 0):
  // at the probe times (probe_every, itself as output_every by default) when the case has
  // walls; 0: no forces.csv.
  double forces_every = -1;
  // output.boundary_points: the ghost / wall-element points (boundary_*.vtp) beside each
  // snapshot (true by default); the walls themselves are written whatever it says.
  bool write_boundary_points = true;
  // output.precision (float32 | float64: the particle fields' floating arrays; positions stay
  // float64), output.compress (zlib | none) and output.fields (the Particles field names
  // written; position always), io/vtk_writer.hpp. The default fields are what a picture and
  // a restart need: position, velocity, pressure, density, mass, phase, id.
  bool output_float32 = true;
  bool output_zlib = true;
  std::vector<std::string> output_fields;
  // output.restart: which snapshots get the restart state beside them (SNAPSHOT.restart,
  // solver/restart_state.hpp, what `run --restart` reads): `last` (default; the previous one
  // is removed when the next is written), `every`, or `none`.
  enum class RestartFiles { none, last, every };
  RestartFiles output_restart = RestartFiles::last;
  // parallel: MPI domain decomposition. Re-bisect when the largest rank owns more than
  // (1 + rebalance_imbalance) times the mean; check_conservation sums count, mass and ids
  // over the ranks after every migration (metrics: conservation_*).
  double rebalance_imbalance = 0.1;
  bool check_conservation = false;
  // Which rank computes a pair of the fluid passes (parallel/pair_rule.hpp): `auto` is the
  // midpoint rule (halo of h) unless walls or surface tension read the full 2h neighbourhood
  // of owned particles, then the owner rule (halo of 2h).
  enum class HaloRule { automatic, midpoint, owner } halo_rule = HaloRule::automatic;
  std::vector<ProbeSpec> probes;
  // open_boundaries: inflow and outflow planes with buffer layers (solver/open_boundaries.hpp).
  std::vector<OpenBoundarySpec> open_boundaries;
  // Named initial flow field (`initial: {taylor_green: {U: 1}}`); empty when absent.
  std::string initial_field;
  YAML::Node initial_params;
  // setup.hydrostatic: without `initial`, each fluid region starts at rest-pressure balance
  // under gravity (setup/hydrostatic_start.hpp); on by default with free_surface_defaults.
  bool hydrostatic_start = false;
  // Gravity with a component along an axis that is not periodic: a free surface or a tank is
  // likely, and the defaults of continuity density with delta-SPH and of the hydrostatic ghost
  // pressure apply (README, "Defaults"). Gravity along a periodic axis drives a flow instead.
  bool free_surface_defaults = false;
  double h() const { return h_over_dx * dx; }
  // The failure semantics of studies that measure when a wall or a run first fails: no wall
  // contact, and a particle past a wall and a density outside [0.5, 2] rho0 stop the run
  // (exit 3) instead of being put back or clamped (boundary.contact: 0, penetration: stop,
  // density.clamp: false).
  void make_strays_fatal() {
    boundary.penetration_stop = true;
    boundary.contact = 0;
    density.clamp = false;
  }
  std::string file_name() const { return file.string(); }
};

// Reads and validates a case file, applying `--set` overrides first.
Case read_case(const std::filesystem::path& path, const std::vector<std::string>& overrides = {});
// Same, from an already loaded tree (tests, generated cases).
Case read_case(YAML::Node root, const std::filesystem::path& path_for_messages);

}  // namespace curvsph
