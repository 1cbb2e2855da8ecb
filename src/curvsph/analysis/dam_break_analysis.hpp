#pragma once
// SPHERIC benchmark test 2 (Kleefsman et al. 2005; Calderon-Sanchez et al. §3.2): the 3-D dam
// break against a box, compared with the MARIN experiment. Parameters:
//   analysis: {dam_break: {experiment: PATH}}
// PATH (relative to the case file, or absolute) is the benchmark's record
// (test_case_2_exp_data.dat: time, P1..P8, then the heights at x = 1.488, 0.992, 0.496,
// 2.638 m, i.e. H3, H2, H1, H4 in the benchmark's numbering: data/spheric2/README.md).
// The run's probes.csv must hold P1..P8 (field p_wall, or p) and gauges H1..H4.
//
// Figures (pressures in Pa, times in s; NaN = not reached):
//   p1_peak, p1_peak_time, p2_peak: maximum over t <= min(1.5 s, end);
//   p1_impact_time: first time P1 exceeds 20 % of the experimental P1 peak (the same for the
//   experiment: p1_impact_time_exp); p1_peak_exp, p1_peak_time_exp, p2_peak_exp;
//   p1_first_peak, p1_first_peak_time, p1_first_peak_ratio (over p1_peak_exp): the first
//   impact's peak, P1's maximum over [p1_impact_time, p1_impact_time + p1_rise_time_exp],
//   p1_rise_time_exp = p1_peak_time_exp - p1_impact_time_exp (the experiment's impact-to-peak
//   time, 0.020 s: the same rule gives the experiment's own peak);
//   h2_at_1s (and _exp): the water height at H2 (x = 0.992) at t = 1 s;
//   p1_rms_error .. p4_rms_error: RMS of (simulated - experimental) pressure over
//   t in [0, min(1.5 s, end)], divided by the experimental P1 peak (a dry sensor reads 0);
//   h1_rms_error .. h4_rms_error: RMS of (simulated - experimental) height over the same
//   window, divided by the initial water depth 0.55 m;
//   p1_min .. p8_min, sensor_min: each sensor's lowest reading over the window (Pa), and
//   the lowest of the eight;
//   rms_window_end: the end of that window.
// Writes dam_break_comparison.csv: time, then NAME (simulated) and NAME_exp (experiment,
// interpolated) for P1..P8 and H1..H4, at the probe times.
#include "curvsph/analysis/analysis.hpp"

namespace curvsph {

std::unique_ptr<Analysis<3>> make_dam_break_analysis(const YAML::Node& params, const Case& c);

}  // namespace curvsph
