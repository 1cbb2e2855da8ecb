// The table of validation studies: one line per study.
#include "curvsph/validation/study.hpp"

namespace curvsph {

StudyResult run_taylor_green_study(const StudyContext& ctx);
StudyResult run_shepard_approach_study(const StudyContext& ctx);  // shepard_approach_study.cpp
StudyResult run_hydrostatic_tank_study(const StudyContext& ctx);  // hydrostatic_tank_study.cpp

const std::vector<Study>& validation_studies() {
  static const std::vector<Study> studies = {
      {"taylor_green", "2-D Taylor–Green vortex, Re = 100: velocity error and decay rate vs dx",
       &run_taylor_green_study},
      {"shepard_approach",
       "Shepard factor approaching a wall, corner, circle (Calderon Figs. 2, 4-7)",
       run_shepard_approach_study},
      {"hydrostatic_tank",
       "2-D tank at rest, boundary integrals, geometric vs volume Shepard (Calderon §3.1)",
       run_hydrostatic_tank_study},
  };
  return studies;
}

}  // namespace curvsph
