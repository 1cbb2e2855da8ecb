// The table of validation studies: one line per study.
#include "curvsph/validation/study.hpp"

namespace curvsph {

StudyResult run_taylor_green_study(const StudyContext& ctx);
StudyResult run_shepard_approach_study(const StudyContext& ctx);    // shepard_approach_study.cpp
StudyResult run_couette_study(const StudyContext& ctx);             // couette_study.cpp
StudyResult run_poiseuille_study(const StudyContext& ctx);          // poiseuille_study.cpp
StudyResult run_node_density_study(const StudyContext& ctx);        // node_density_study.cpp
StudyResult run_ghost_cost_study(const StudyContext& ctx);          // ghost_cost_study.cpp
StudyResult run_cylinder_lattice_study(const StudyContext& ctx);    // cylinder_lattice_study.cpp
StudyResult run_throttled_pipe_study(const StudyContext& ctx);      // throttled_pipe_study.cpp
StudyResult run_hydrostatic_tank_study(const StudyContext& ctx);    // hydrostatic_tank_study.cpp
StudyResult run_dam_break_study(const StudyContext& ctx);           // dam_break_study.cpp
StudyResult run_shepard_cost_study(const StudyContext& ctx);        // shepard_cost_study.cpp
StudyResult run_scaling_study(const StudyContext& ctx);             // scaling_study.cpp
StudyResult run_droplet_wall_study(const StudyContext& ctx);        // droplet_wall_study.cpp
StudyResult run_throughput_study(const StudyContext& ctx);          // throughput_study.cpp
StudyResult run_free_surface_study(const StudyContext& ctx);        // free_surface_study.cpp
StudyResult run_moving_cylinder_study(const StudyContext& ctx);     // moving_cylinder_study.cpp
StudyResult run_cad_at_rest_study(const StudyContext& ctx);         // cad_at_rest_study.cpp
StudyResult run_cylinder_benchmark_study(const StudyContext& ctx);  // cylinder_benchmark_study.cpp
StudyResult run_surge_front_study(const StudyContext& ctx);         // surge_front_study.cpp
// oscillating_cylinder_study.cpp
StudyResult run_oscillating_cylinder_study(const StudyContext& ctx);

const std::vector<Study>& validation_studies() {
  static const std::vector<Study> studies = {
      {"taylor_green", "2-D Taylor–Green vortex, Re = 100: velocity error and decay rate vs dx",
       &run_taylor_green_study},
      {"shepard_approach",
       "Shepard factor approaching a wall, corner, circle (Calderon Figs. 2, 4-7)",
       run_shepard_approach_study},
      {"couette", "Couette flow, three ghost maps at four dx (Barker Figs. 1-4)",
       &run_couette_study},
      {"poiseuille", "Plane Poiseuille flow: profile against the parabola", &run_poiseuille_study},
      {"node_density", "Node density across cylinder, sphere, torus walls (Vela Vela Figs. 6-8)",
       &run_node_density_study},
      {"ghost_cost", "Cost of the density-preserving ghost map (Vela Vela Table 1)",
       &run_ghost_cost_study},
      {"cylinder_lattice", "Lattice of cylinders: v_y field and t_max (Vela Vela Figs. 9-10)",
       &run_cylinder_lattice_study},
      {"throttled_pipe",
       "Throttled pipe with NURBS walls (Barker Figs. 8-9): flux, eq. 48 profiles",
       &run_throttled_pipe_study},
      {"hydrostatic_tank",
       "2-D tank at rest, boundary integrals, geometric vs volume Shepard (Calderon §3.1)",
       run_hydrostatic_tank_study},
      {"free_surface",
       "Free surfaces against curved walls, every boundary method: runs to the end, counters",
       &run_free_surface_study},
      {"surge_front",
       "2-D dam break: surge front vs Martin & Moyce (1952), a/20-a/80, far-wall run-up",
       &run_surge_front_study},
      {"cad_at_rest",
       "Water at rest in polygon tanks (60-120 deg corners) and CAD solids, every boundary method",
       &run_cad_at_rest_study},
      {"dam_break_3d", "3-D dam break against a box, SPHERIC test 2 (Calderon §3.2, Figs. 14-17)",
       &run_dam_break_study},
      {"shepard_cost", "Time per step: gamma = 1, volume and geometric Shepard (Calderon Table 1)",
       &run_shepard_cost_study},
      {"scaling", "MPI strong and weak scaling, communication share, halo model (issue 8)",
       &run_scaling_study},
      {"droplet_wall",
       "Drop on a NURBS wall with a dip, contact angle 30-120 deg (Barker §4.2, Fig. 10)",
       &run_droplet_wall_study},
      {"throughput",
       "Particle-steps per second: 3-D dam break (DualSPHysics reference), 10^6 box, Couette",
       &run_throughput_study},
      {"moving_cylinder",
       "Walls that move: towed vs still cylinder (Galilean), oscillating cylinder (Dütsch 1998)",
       &run_moving_cylinder_study},
      {"cylinder_benchmark",
       "Schäfer & Turek (1996) cylinder in a channel, Re = 20: C_D, C_L, dp vs D/dx (issue 33)",
       &run_cylinder_benchmark_study},
      {"oscillating_cylinder",
       "Dütsch et al. (1998) in-line oscillating cylinder, Re = 100, KC = 5: in-line force",
       &run_oscillating_cylinder_study},
  };
  return studies;
}

}  // namespace curvsph
