// The dam_break analysis (analysis/dam_break_analysis.hpp) on synthetic records: a Gaussian
// pressure pulse in the "experiment" and a delayed, scaled one in the "run"; every figure is
// compared with its value worked out independently from the two formulas.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "curvsph/analysis/analysis.hpp"
#include "curvsph/core/error.hpp"

using namespace curvsph;

namespace {

double pulse(double t, double t0, double a) {
  return a * std::exp(-std::pow((t - t0) / 0.02, 2));
}

// The experiment file, 1 kHz to t = 2 s: `row(t)` writes the 12 columns after the time
// (P1..P8, then the heights in the data set's order H3, H2, H1, H4).
template <class Row>
void write_experiment(const std::filesystem::path& file, Row row) {
  std::ofstream e(file);
  e << "Time P1 P2 P3 P4 P5 P6 P7 P8 H1 H2 H3 H4\n";
  for (int i = 0; i <= 2000; ++i) {
    e << i * 1e-3 << ' ';
    row(e, i * 1e-3);
    e << '\n';
  }
}

// The run's probes.csv, 1 kHz to t = 1.1 s: `row(t)` writes P1..P8 (p_wall) and H1..H4.
template <class Row>
void write_probes(const std::filesystem::path& file, Row row) {
  std::ofstream p(file);
  p << "time";
  for (int k = 1; k <= 8; ++k) p << ",P" << k << ".p_wall";
  for (int k = 1; k <= 4; ++k) p << ",H" << k << ".height";
  p << '\n';
  for (int i = 0; i <= 1100; ++i) {
    p << i * 1e-3 << ',';
    row(p, i * 1e-3);
    p << '\n';
  }
}

// The analysis's figures for the files in dir, the run ended at t = 1.1 s.
nlohmann::json analyse(const std::filesystem::path& dir) {
  Case c;
  c.file = dir / "case.yaml";
  YAML::Node params;
  params["experiment"] = "exp.dat";
  auto a = make_analysis<3>("dam_break", params, c);
  nlohmann::json m;
  Particles<3> P;
  a->finish(1.1, P, m, dir);
  return m;
}

}  // namespace

TEST(DamBreakAnalysis, FiguresOfSyntheticRecords) {
  const auto dir = std::filesystem::temp_directory_path() / "curvsph_test_dam_break";
  std::filesystem::create_directories(dir);
  write_experiment(dir / "exp.dat", [](std::ostream& e, double t) {
    e << pulse(t, 0.40, 10000) << ' ' << pulse(t, 0.40, 5000) << " 0 0 0 0 0 0 " << 0.3 * t << ' '
      << 0.2 * t << ' ' << 0.1 * t << " 0.5";
  });
  // Run: P1 delayed by 10 ms and scaled by 0.9, P2 exact; H2 = 0.2 t + 0.01.
  write_probes(dir / "probes.csv", [](std::ostream& p, double t) {
    p << pulse(t, 0.41, 9000) << ',' << pulse(t, 0.40, 5000) << ",nan,0,0,0,0," << -300 * t
      << ",0.1," << 0.2 * t + 0.01 << ",0.3,0.5";
  });
  const nlohmann::json m = analyse(dir);
  EXPECT_NEAR(m["p1_peak"].get<double>(), 9000, 1e-6);
  EXPECT_NEAR(m["p1_peak_time"].get<double>(), 0.41, 1e-9);
  EXPECT_NEAR(m["p1_peak_exp"].get<double>(), 10000, 1e-6);
  EXPECT_NEAR(m["p2_peak"].get<double>(), 5000, 1e-6);
  // First 1 ms sample above 2000 Pa: 9000 exp(-u^2) > 2000 <=> u < sqrt(ln 4.5).
  EXPECT_NEAR(m["p1_impact_time"].get<double>(),
              std::ceil((0.41 - 0.02 * std::sqrt(std::log(4.5))) * 1e3) * 1e-3, 1e-9);
  EXPECT_NEAR(m["p1_impact_time_exp"].get<double>(),
              std::ceil((0.40 - 0.02 * std::sqrt(std::log(5.0))) * 1e3) * 1e-3, 1e-9);
  // H2 is the second height column of the file (0.2 t), the run's H2 is 0.2 t + 0.01.
  EXPECT_NEAR(m["h2_at_1s"].get<double>(), 0.21, 1e-9);
  EXPECT_NEAR(m["h2_at_1s_exp"].get<double>(), 0.2, 1e-9);
  // RMS over t <= 1.1: P2 identical; P1 by a sum over the samples.
  double e2 = 0;
  for (int i = 0; i <= 1100; ++i) {
    const double t = i * 1e-3;
    e2 += std::pow(pulse(t, 0.41, 9000) - pulse(t, 0.40, 10000), 2);
  }
  EXPECT_NEAR(m["p1_rms_error"].get<double>(), std::sqrt(e2 / 1101) / 10000, 1e-6);
  EXPECT_NEAR(m["p2_rms_error"].get<double>(), 0.0, 1e-6);
  // P3 is dry (reads 0) against an experimental 0, P4 0 against 0.
  EXPECT_NEAR(m["p3_rms_error"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(m["p4_rms_error"].get<double>(), 0.0, 1e-12);
  // Heights over the 0.55 m depth: H1 0.1 against 0.1 t, H2 off by 0.01 everywhere, H3 0.3
  // against 0.3 t, H4 exact (the file's columns are H3, H2, H1, H4).
  double h1 = 0, h3 = 0;
  for (int i = 0; i <= 1100; ++i) {
    const double t = i * 1e-3;
    h1 += std::pow(0.1 - 0.1 * t, 2);
    h3 += std::pow(0.3 - 0.3 * t, 2);
  }
  EXPECT_NEAR(m["h1_rms_error"].get<double>(), std::sqrt(h1 / 1101) / 0.55, 1e-9);
  EXPECT_NEAR(m["h2_rms_error"].get<double>(), 0.01 / 0.55, 1e-9);
  EXPECT_NEAR(m["h3_rms_error"].get<double>(), std::sqrt(h3 / 1101) / 0.55, 1e-9);
  EXPECT_NEAR(m["h4_rms_error"].get<double>(), 0.0, 1e-12);
  // Lowest readings: P8 = -300 t reaches -330 Pa at the run's end; the dry P3 reads 0.
  EXPECT_NEAR(m["p8_min"].get<double>(), -330, 1e-6);
  EXPECT_NEAR(m["p3_min"].get<double>(), 0, 1e-12);
  EXPECT_NEAR(m["sensor_min"].get<double>(), -330, 1e-6);
  EXPECT_TRUE(std::filesystem::exists(dir / "dam_break_comparison.csv"));

  // A missing experiment file is an input error naming the key.
  Case c;
  c.file = dir / "case.yaml";
  YAML::Node bad;
  bad["experiment"] = "missing.dat";
  try {
    make_analysis<3>("dam_break", bad, c);
    FAIL() << "no error for a missing experiment file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("analysis.dam_break.experiment"), std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

// The first impact's peak is P1's maximum within the experiment's impact-to-peak time of the
// run's own impact; a later, larger maximum (the ringing after the impact) is p1_peak only.
TEST(DamBreakAnalysis, FirstImpactPeakIgnoresLaterMaxima) {
  const auto dir = std::filesystem::temp_directory_path() / "curvsph_test_dam_break_first";
  std::filesystem::create_directories(dir);
  write_experiment(dir / "exp.dat", [](std::ostream& e, double t) {
    e << pulse(t, 0.40, 10000) << " 0 0 0 0 0 0 0 0.1 0.1 0.1 0.1";
  });
  write_probes(dir / "probes.csv", [](std::ostream& p, double t) {
    p << pulse(t, 0.41, 9000) + pulse(t, 0.60, 20000) << ",0,0,0,0,0,0,0,0.1,0.1,0.1,0.1";
  });
  const nlohmann::json m = analyse(dir);
  // Impacts: first 1 ms samples above 2000 Pa (the later pulse is ~0 there).
  const double imp_exp = std::ceil((0.40 - 0.02 * std::sqrt(std::log(5.0))) * 1e3) * 1e-3;
  const double imp = std::ceil((0.41 - 0.02 * std::sqrt(std::log(4.5))) * 1e3) * 1e-3;
  const double rise = 0.40 - imp_exp;  // the experiment's peak sample is t = 0.400
  EXPECT_NEAR(m["p1_rise_time_exp"].get<double>(), rise, 1e-9);
  // Brute force over the run's samples in [imp, imp + rise].
  double expected = 0, at = 0;
  for (int i = 0; i <= 1100; ++i) {
    const double t = i * 1e-3, v = pulse(t, 0.41, 9000) + pulse(t, 0.60, 20000);
    if (t >= imp - 1e-9 && t <= imp + rise + 1e-9 && v > expected) expected = v, at = t;
  }
  EXPECT_NEAR(at, 0.41, 1e-9);  // the window holds the first pulse's peak, not the second
  EXPECT_NEAR(m["p1_first_peak"].get<double>(), expected, 1e-6);
  EXPECT_NEAR(m["p1_first_peak_time"].get<double>(), at, 1e-9);
  EXPECT_NEAR(m["p1_first_peak_ratio"].get<double>(), expected / 10000, 1e-9);
  EXPECT_NEAR(m["p1_peak"].get<double>(), 20000, 1e-3);
  EXPECT_NEAR(m["p1_peak_time"].get<double>(), 0.60, 1e-9);
  std::filesystem::remove_all(dir);
}
