// The schema of every input key (io/case_schema.hpp): one row per key — path, type, range,
// default, unit, meaning. A new key is one row here beside its read in the parser; the test
// suite (strict mode) fails when a reader reads a key this table lacks or defaults otherwise.
// `curvsph keys` and docs/keys.md (`make keys`) print this table.
#include "curvsph/io/schema_table.hpp"

namespace curvsph::schema {
namespace {

// clang-format off
const Row kRows[] = {
// path                              type      range  default  unit  meaning
{"name", "string", "", "derived: the case file's name without .yaml", "-", "free text naming the case (metrics, logs)"},
{"dimension", "integer", "[2, 3]", "required", "-", "2 or 3 (case and geometry files)"},

{"resolution", "map", "", "required", "-", "particle spacing and kernel size"},
{"resolution.dx", "number", "(0, inf)", "required", "m", "particle spacing"},
{"resolution.h_over_dx", "number", "[0.8, 4]", "1.3", "-", "smoothing length h over dx (Wendland C2 kernel, support radius 2h)"},

{"domain", "map", "", "optional", "-", "the domain box; needed for periodic axes (without it: the box around the particles and box walls, grown by its extent)"},
{"domain.min", "vector", "", "required", "m", "lower corner"},
{"domain.max", "vector", "", "required", "m", "upper corner (> min on every axis)"},
{"domain.periodic", "list", "", "all false", "-", "one true|false per axis; a periodic axis spans at least 3 kernel supports"},

{"fluids", "list", "", "required", "-", "the fluids, at least one"},
{"fluids.*.name", "string", "", "derived: fluid0, fluid1, ...", "-", "name (surface_tension pairs refer to it)"},
{"fluids.*.rho0", "number", "(0, inf)", "required", "kg/m^3", "reference density"},
{"fluids.*.viscosity", "number", "[0, inf)", "0", "Pa s", "dynamic viscosity"},
{"fluids.*.velocity", "vector", "", "0", "m/s", "initial velocity"},
{"fluids.*.region", "map", "", "required", "-", "where the fluid starts: exactly one of box | disk | ball | annulus | inside_walls (and optionally random)"},
{"fluids.*.region.random", "bool", "", "false", "-", "random points (seeded by setup.random_seed) instead of the lattice"},
{"fluids.*.region.box", "map", "", "optional", "-", "an axis-aligned box"},
{"fluids.*.region.box.min", "vector", "", "required", "m", "lower corner"},
{"fluids.*.region.box.max", "vector", "", "required", "m", "upper corner (> min on every axis)"},
{"fluids.*.region.disk", "map", "", "optional", "-", "a disk (2-D)"},
{"fluids.*.region.disk.center", "vector", "", "required", "m", "centre"},
{"fluids.*.region.disk.radius", "number", "(0, inf)", "required", "m", "radius"},
{"fluids.*.region.ball", "map", "", "optional", "-", "a ball (3-D)"},
{"fluids.*.region.ball.center", "vector", "", "required", "m", "centre"},
{"fluids.*.region.ball.radius", "number", "(0, inf)", "required", "m", "radius"},
{"fluids.*.region.annulus", "map", "", "optional", "-", "concentric rings between two radii"},
{"fluids.*.region.annulus.center", "vector", "", "required", "m", "centre"},
{"fluids.*.region.annulus.r_in", "number", "[0, inf)", "required", "m", "inner radius"},
{"fluids.*.region.annulus.r_out", "number", "(0, inf)", "required", "m", "outer radius (> r_in)"},
{"fluids.*.region.inside_walls", "bool", "", "optional", "-", "true: the fluid side of the walls (within the domain)"},

{"initial", "map", "", "optional", "-", "one named initial flow field: taylor_green | couette | throttled_pipe | hydrostatic"},
{"initial.taylor_green", "map", "", "optional", "-", "Taylor-Green vortex velocity and pressure (2-D)"},
{"initial.taylor_green.U", "number", "(0, inf)", "1", "m/s", "velocity amplitude"},
{"initial.couette", "map", "", "optional", "-", "v_theta(r) of the walls' rotation and its radial pressure balance (no parameters)"},
{"initial.throttled_pipe", "map", "", "optional", "-", "wall-fitted start of the throttled pipe (2-D)"},
{"initial.throttled_pipe.velocity", "choice: rest | lubrication", "", "rest", "-", "start at rest or with the lubrication profile"},
{"initial.throttled_pipe.flux", "number", "(0, inf)", "derived: the lubrication estimate for the body force", "m^2/s", "flux of the lubrication profile"},
{"initial.hydrostatic", "map", "", "optional", "-", "p = rho0 g (depth - height) with matching densities and masses"},
{"initial.hydrostatic.depth", "number", "(0, inf)", "required", "m", "height of the free surface along -gravity"},
{"initial.hydrostatic.bottom", "number", "", "0", "m", "height of the bottom along -gravity"},

{"eos", "map", "", "derived: required unless gravity gives c0", "-", "equation of state"},
{"eos.type", "choice: tait | linear", "", "tait", "-", "Tait p = p0 + rho0 c0^2/gamma ((rho/rho0)^gamma - 1) or linear p = p0 + c0^2 (rho - rho0)"},
{"eos.c0", "number", "(0, inf)", "derived: 10 sqrt(2 g H) under gravity across a non-periodic axis (H: the tallest fluid region along gravity), else required", "m/s", "numerical speed of sound"},
{"eos.gamma", "number", "(0, inf)", "7", "-", "Tait exponent"},
{"eos.p0", "number", "", "0", "Pa", "background pressure"},

{"density", "map", "", "optional", "-", "how the density evolves"},
{"density.method", "choice: summation | continuity", "", "derived: continuity under gravity across a non-periodic axis, else summation", "-", "density by kernel summation or by the continuity equation"},
{"density.delta_sph", "number", "[0, inf)", "0.1", "-", "delta-SPH density diffusion coefficient (continuity only)"},
{"density.diffusion_term", "choice: antuono | molteni | fourtakas", "", "antuono", "-", "delta-SPH diffusion term (continuity only)"},
{"density.shifting", "number", "[0, 1]", "0", "-", "particle shifting coefficient (typical 0.01-0.05)"},
{"density.clamp", "list", "", "[0.7, 1.3]", "rho0", "[lo, hi] with 0 < lo < 1 < hi: a density outside is clamped and counted; false: outside [0.5, 2] stops the run"},

{"artificial_viscosity", "map", "", "optional", "-", "delta-SPH momentum diffusion"},
{"artificial_viscosity.alpha", "number", "[0, inf)", "0", "-", "artificial viscosity coefficient"},

{"pressure_gradient", "choice: symmetric | difference", "", "symmetric", "-", "pressure term: p_j + p_i (Barker's symmetric form) or p_j - p_i (no force from a uniform background pressure; needs shifting or the transport velocity)"},
{"transport_velocity", "map", "", "optional", "-", "Adami et al.'s transport velocity (summation density, no shifting)"},
{"transport_velocity.background_pressure", "number", "(0, inf)", "derived: rho0 c0^2 of the stiffest fluid", "Pa", "background pressure p_b of the transport velocity"},

{"gravity", "vector", "", "0", "m/s^2", "body acceleration"},

{"forcing", "map", "", "optional", "-", "body forcing"},
{"forcing.drive", "map", "", "optional", "-", "dv/dt = (v0 - v_x)/tau (Vela Vela eq. 36)"},
{"forcing.drive.v0", "number", "", "required", "m/s", "target velocity along x"},
{"forcing.drive.tau", "number", "(0, inf)", "required", "s", "relaxation time"},

{"surface_tension", "list", "", "optional", "-", "CSF surface tension per fluid pair"},
{"surface_tension.*.fluids", "list", "", "required", "-", "two different fluid names [a, b]"},
{"surface_tension.*.coefficient", "number", "[0, inf)", "required", "N/m", "surface tension coefficient"},

{"walls", "list", "", "optional", "-", "the walls (docs/geometry.md); each element has a shape and the shape's keys"},
{"walls.*.shape", "choice: plane | box | circle | ellipse | cylinder | sphere | torus | nurbs_curve | nurbs_surface | cad", "", "required", "-", "the wall's shape"},
{"walls.*.fluid", "choice: inside | outside | left | right | front | back", "", "required", "-", "fluid side: inside | outside (box, circle, ellipse, cylinder, sphere, torus, cad), left | right (nurbs_curve), front | back (nurbs_surface)"},
{"walls.*.contact_angle", "number", "(0, 180)", "optional", "deg", "static contact angle at this wall (surface tension)"},
{"walls.*.point", "vector", "", "required", "m", "a point on the plane (plane) or on the axis (cylinder)"},
{"walls.*.normal", "vector", "", "required", "-", "plane normal into the fluid (non-zero; normalised)"},
{"walls.*.min", "vector", "", "required", "m", "box lower corner"},
{"walls.*.max", "vector", "", "required", "m", "box upper corner (> min)"},
{"walls.*.center", "vector", "", "required", "m", "centre (circle, ellipse, sphere, torus)"},
{"walls.*.radius", "number", "(0, inf)", "required", "m", "radius (circle, cylinder, sphere)"},
{"walls.*.semi_axes", "vector", "(0, inf)", "required", "m", "ellipse semi-axes [a, b] along x, y"},
{"walls.*.axis", "vector", "", "required", "-", "axis direction (cylinder, torus; non-zero; normalised)"},
{"walls.*.major_radius", "number", "(0, inf)", "required", "m", "torus major radius R"},
{"walls.*.minor_radius", "number", "(0, inf)", "required", "m", "torus minor radius a < R"},
{"walls.*.degree", "list", "[1, 15]", "required", "-", "NURBS degree: p (nurbs_curve) or [p, q] (nurbs_surface)"},
{"walls.*.control_points", "list", "", "required", "m", "NURBS control points (nurbs_surface: rows along v); not all equal"},
{"walls.*.weights", "list", "[1e-100, 1e100]", "all 1", "-", "NURBS weights, one per control point; largest / smallest <= 1e12"},
{"walls.*.knots", "list", "", "required", "-", "nurbs_curve knot vector: non-decreasing, control points + degree + 1 values, spans >= 1e-12 of the range"},
{"walls.*.knots_u", "list", "", "required", "-", "nurbs_surface knot vector along u (as knots)"},
{"walls.*.knots_v", "list", "", "required", "-", "nurbs_surface knot vector along v (as knots)"},
{"walls.*.tolerance", "number", "[0, inf)", "0", "m", "NURBS projection tolerance (0: automatic)"},
{"walls.*.name", "string", "", "optional", "-", "label of a NURBS or CAD wall"},
{"walls.*.file", "string", "", "required", "-", "CAD file (STEP, IGES, STL), relative to the case file"},
{"walls.*.scale", "number", "[1e-6, 1e6]", "1", "-", "CAD coordinates times scale = metres"},
{"walls.*.faces", "list", "[0, 1e9]", "all faces", "-", "CAD face indices to keep (0-based)"},
{"walls.*.motion", "map", "", "optional", "-", "exactly one of rotate | translate | oscillate; moves the wall geometry itself"},
{"walls.*.motion.rotate", "map", "", "optional", "-", "rigid rotation"},
{"walls.*.motion.rotate.omega", "number", "", "required", "rad/s", "angular velocity"},
{"walls.*.motion.rotate.center", "vector", "", "required", "m", "centre of rotation"},
{"walls.*.motion.rotate.axis", "vector", "", "required in 3-D", "-", "rotation axis (3-D only; non-zero; normalised)"},
{"walls.*.motion.translate", "map", "", "optional", "-", "rigid translation"},
{"walls.*.motion.translate.velocity", "vector", "", "required", "m/s", "wall velocity"},
{"walls.*.motion.oscillate", "map", "", "optional", "-", "x(t) = x0 + amplitude sin(2 pi frequency t + phase)"},
{"walls.*.motion.oscillate.amplitude", "vector", "", "required", "m", "displacement amplitude per axis"},
{"walls.*.motion.oscillate.frequency", "number", "[0, inf)", "required", "Hz", "oscillation frequency"},
{"walls.*.motion.oscillate.phase", "number", "", "0", "rad", "phase at t = 0"},

{"boundary", "map", "", "optional", "-", "wall boundary method"},
{"boundary.method", "choice: none | ghost | integrals", "", "none", "-", "ghost particles or boundary integrals (a case with walls needs one)"},
{"boundary.map", "choice: mirror | mirror_beta | density_preserving", "", "mirror_beta", "-", "ghost map"},
{"boundary.velocity", "choice: no_slip | free_slip", "", "no_slip", "-", "wall velocity condition"},
{"boundary.shepard", "choice: geometric | volume | monolithic | none", "", "geometric", "-", "Shepard factor of the boundary integrals"},
{"boundary.wall_force", "bool", "", "false", "-", "push (c0^2/dx)(1 - d/d0)^2 off walls closer than d0 = 0.1 dx (Calderon §3.2)"},
{"boundary.pressure", "choice: symmetric | consistent | tensile_control", "", "symmetric", "-", "pressure term of the boundary integrals"},
{"boundary.ghost_pressure", "choice: copy | hydrostatic", "", "derived: hydrostatic under gravity across a non-periodic axis, else copy", "-", "ghost pressure p_s or p_s + rho_s g.(x_g - x_s) (method: ghost)"},
{"boundary.penetration", "choice: project | stop", "", "project", "-", "a particle past a wall is put back (project) or ends the run (stop)"},
{"boundary.wall_tension", "bool", "", "true", "-", "false clamps the wall terms' pressure at 0 (a wall that pushes, never pulls)"},
{"boundary.contact", "number", "[0, 0.5)", "0.1", "dx", "a particle closer to a wall is stopped at this distance (0: off)"},

{"setup", "map", "", "optional", "-", "initial particle set-up"},
{"setup.random_seed", "integer", "[0, 4294967295]", "1", "-", "seed of random regions, jitter and packing"},
{"setup.jitter", "number", "[0, 0.5)", "0", "dx", "random offset of every lattice point per axis"},
{"setup.relax", "map", "", "optional", "-", "particle packing before the run"},
{"setup.relax.max_steps", "integer", "[0, inf)", "2000", "-", "packing steps (0: off)"},
{"setup.relax.tolerance", "number", "(0, inf)", "0.001", "-", "packing stops below this spread (integrals: max h|R|)"},
{"setup.relax.map", "choice: mirror | mirror_beta | density_preserving | integrals", "", "derived: boundary.map", "-", "ghost map of the packing, or integrals (one box region)"},

{"time", "map", "", "required", "-", "time stepping"},
{"time.end", "number", "[0, inf)", "required", "s", "end time"},
{"time.cfl", "number", "(0, 1]", "0.2", "-", "CFL number"},
{"time.dt_max", "number", "[0, inf)", "0", "s", "largest time step (0: no limit)"},
{"time.max_steps", "integer", "[0, inf)", "0", "-", "largest step count (0: no limit)"},
{"time.max_removed_fraction", "number", "[0, 1]", "0.01", "-", "fraction of particles that may leave the domain before the run stops (exit 3)"},

{"parallel", "map", "", "optional", "-", "MPI domain decomposition (ignored on one rank)"},
{"parallel.rebalance_imbalance", "number", "(0, inf)", "0.1", "-", "re-bisect when the largest rank owns more than 1 + this times the mean"},
{"parallel.check_conservation", "bool", "", "false", "-", "check mass and momentum across ranks every step"},
{"parallel.halo_rule", "choice: auto | midpoint | owner", "", "auto", "-", "which rank computes a pair across ranks"},

{"output", "map", "", "optional", "-", "snapshots and probes"},
{"output.every", "number", "[0, inf)", "0", "s", "snapshot interval (0: first and last state only)"},
{"output.probe_every", "number", "[0, inf)", "0", "s", "probe interval (0: as output.every)"},
{"output.vtk", "bool", "", "true", "-", "write VTK snapshots"},
{"output.precision", "choice: float32 | float64", "", "float32", "-", "floating-point type of the snapshot arrays"},
{"output.compress", "choice: zlib | none", "", "zlib", "-", "compression of the snapshot data"},
{"output.fields", "list", "", "[position, velocity, pressure, density, mass, phase, id]", "-", "particle fields written (position always)"},
{"output.restart", "choice: last | every | none", "", "last", "-", "which snapshots get the float64 restart state file beside them (particles_NNNNNN.restart) that --restart continues bit for bit from"},

{"open_boundaries", "list", "", "optional", "-", "inflow and outflow planes (lines in 2-D) with buffer layers (solver/open_boundaries.hpp)"},
{"open_boundaries.*.name", "string", "", "derived: open0, open1, ...", "-", "unique name"},
{"open_boundaries.*.kind", "choice: inflow | outflow", "", "required", "-", "inflow (velocity prescribed) or outflow (pressure prescribed)"},
{"open_boundaries.*.point", "vector", "", "required", "m", "a point of the boundary (inside the domain box)"},
{"open_boundaries.*.normal", "vector", "", "required", "-", "the boundary's normal, pointing into the fluid (non-zero; normalised)"},
{"open_boundaries.*.velocity", "vector | map", "", "required for inflow", "m/s", "inflow velocity [u, v(, w)] or {parabolic: {...}, ramp}"},
{"open_boundaries.*.velocity.ramp", "number", "[0, inf)", "0", "s", "time over which the inflow rises linearly from 0"},
{"open_boundaries.*.velocity.parabolic", "map", "", "optional", "-", "parabolic profile over a segment / rectangle (from, to) or a circle (center, radius)"},
{"open_boundaries.*.velocity.parabolic.max", "number", "(0, inf)", "required", "m/s", "peak velocity of the profile"},
{"open_boundaries.*.velocity.parabolic.from", "vector", "", "required for a segment or rectangle", "m", "one end of the segment (2-D) or corner of the rectangle (3-D)"},
{"open_boundaries.*.velocity.parabolic.to", "vector", "", "required for a segment or rectangle", "m", "the other end or corner"},
{"open_boundaries.*.velocity.parabolic.center", "vector", "", "required for a circle", "m", "centre of the circular profile (3-D)"},
{"open_boundaries.*.velocity.parabolic.radius", "number", "(0, inf)", "required for a circle", "m", "radius of the circular profile (3-D)"},
{"open_boundaries.*.pressure", "number", "", "eos.p0", "Pa", "outflow pressure (equation of state)"},

{"probes", "list", "", "optional", "-", "point probes and free-surface gauges (probes.csv)"},
{"probes.*.name", "string", "", "required", "-", "unique probe name (the CSV column prefix)"},
{"probes.*.point", "vector", "", "required", "m", "probe position"},
{"probes.*.fields", "list", "", "required", "-", "any of p, p_wall, rho, vel"},
{"probes.*.gauge", "map", "", "optional", "-", "a free-surface height gauge (no point or fields of its own)"},
{"probes.*.gauge.point", "vector", "", "required", "m", "start of the gauge line"},
{"probes.*.gauge.direction", "vector", "", "required", "-", "direction of the gauge line (non-zero)"},

{"analysis", "map", "", "optional", "-", "analytic or experimental references; figures in metrics.json"},
{"analysis.taylor_green", "map", "", "optional", "-", "decay of the Taylor-Green vortex (2-D)"},
{"analysis.taylor_green.U", "number", "(0, inf)", "1", "m/s", "velocity amplitude"},
{"analysis.static_droplet", "map", "", "optional", "-", "Laplace pressure of a static drop (no parameters)"},
{"analysis.droplet_wall", "map", "", "optional", "-", "contact angle of a drop on a wall (2-D)"},
{"analysis.droplet_wall.fit_radius_dx", "number", "[0, inf)", "0", "dx", "circle-fit radius (0: half the distance between the contact points)"},
{"analysis.couette", "map", "", "optional", "-", "Couette flow between rotating cylinders (no parameters)"},
{"analysis.poiseuille", "map", "", "optional", "-", "Poiseuille flow in a channel (no parameters)"},
{"analysis.node_density", "map", "", "optional", "-", "node density of fluid and ghost particles"},
{"analysis.node_density.ghost_support", "string", "", "all", "m", "'all' or the depth from the wall of the mirrored particles"},
{"analysis.cylinder_lattice", "map", "", "optional", "-", "flow through a periodic cylinder lattice (no parameters)"},
{"analysis.throttled_pipe", "map", "", "optional", "-", "flux and velocities of the throttled pipe (2-D)"},
{"analysis.throttled_pipe.sections", "integer", "[20, inf)", "48", "-", "flux sections along the pipe"},
{"analysis.throttled_pipe.points", "integer", "[5, inf)", "65", "-", "Simpson nodes per section (made odd)"},
{"analysis.throttled_pipe.midline_points", "integer", "[8, inf)", "192", "-", "points along the midline"},
{"analysis.throttled_pipe.reference_flux", "number", "(0, inf)", "optional", "m^2/s", "an independent steady flux to compare with"},
{"analysis.hydrostatic", "map", "", "optional", "-", "hydrostatic pressure of a tank at rest"},
{"analysis.hydrostatic.depth", "number", "(0, inf)", "required", "m", "height of the free surface along -gravity"},
{"analysis.hydrostatic.bottom", "number", "", "0", "m", "height of the bottom along -gravity"},
{"analysis.surge_front", "map", "", "optional", "-", "surge front of a 2-D dam break against Martin & Moyce"},
{"analysis.surge_front.wall", "number", "", "derived: from the initial particles", "m", "x of the wall behind the column"},
{"analysis.surge_front.width", "number", "(0, inf)", "derived: from the initial particles", "m", "initial column width"},
{"analysis.surge_front.far_wall", "number", "", "optional", "m", "x of the far wall"},
{"analysis.surge_front.experiment", "string", "", "optional", "-", "experiment CSV, relative to the case file"},
{"analysis.dam_break", "map", "", "optional", "-", "pressure and heights of the 3-D dam break against SPHERIC test 2"},
{"analysis.dam_break.experiment", "string", "", "required", "-", "experiment record, relative to the case file"},
};
// clang-format on

}  // namespace

const Row* rows() {
  return kRows;
}

int row_count() {
  return static_cast<int>(sizeof kRows / sizeof kRows[0]);
}

}  // namespace curvsph::schema
