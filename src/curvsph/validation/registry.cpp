// The table of validation studies: one line per study.
#include "curvsph/validation/study.hpp"

namespace curvsph {

StudyResult run_taylor_green_study(const StudyContext& ctx);
StudyResult run_shepard_approach_study(const StudyContext& ctx);  // shepard_approach_study.cpp
StudyResult run_throttled_pipe_study(const StudyContext& ctx);    // throttled_pipe_study.cpp

const std::vector<Study>& validation_studies() {
  static const std::vector<Study> studies = {
      {"taylor_green", "2-D Taylor–Green vortex, Re = 100: velocity error and decay rate vs dx",
       &run_taylor_green_study},
      {"shepard_approach",
       "Shepard factor approaching a wall, corner, circle (Calderon Figs. 2, 4-7)",
       run_shepard_approach_study},
      {"throttled_pipe",
       "Throttled pipe with NURBS walls (Barker Figs. 8-9): flux, eq. 48 profiles",
       &run_throttled_pipe_study},
  };
  return studies;
}

}  // namespace curvsph
