#pragma once
// The performance model of the MPI decomposition (issue 8, `curvsph validate scaling`):
// what orthogonal recursive bisection of a uniformly filled periodic box gives each rank
// (box, halo volume, neighbour ranks), and the time of one step from measured rates.
//
// Halo: the particles within the halo width w of a rank's box (Euclidean distance, as
// parallel/decomposition.cpp selects them), i.e. the Minkowski sum of the box and a ball of
// radius w minus the box, counted only across the axes that were cut (an uncut periodic axis
// is the rank's own).
#include <array>
#include <vector>

namespace curvsph::scaling {

struct RankBox {
  std::array<double, 3> lo{}, hi{};
  std::array<bool, 3> cut{};  // the box is narrower than the domain on this axis
  double volume() const { return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]); }
};

// ORB of the periodic box [0, L]^3 of uniform density over `ranks` ranks: the longest axis
// first, split in proportion to the ranks on each side (as Decomposition::split).
std::vector<RankBox> orb_boxes(int ranks, double L);

// Volume of {x : 0 < dist(x, box) < w} over the cut axes, per unit box volume: the halo
// particles per owned particle at uniform density.
double halo_fraction(const RankBox& b, double w);

// Halo fraction of a cube sub-domain of n particles at spacing dx with halo width w (all
// three axes cut): 6 w/a + 3 pi (w/a)^2 + 4 pi/3 (w/a)^3, a = n^(1/3) dx.
double cube_halo_fraction(double n, double dx, double w);

// Ranks whose box lies within w of rank r's box (periodic), r excluded.
int neighbour_count(const std::vector<RankBox>& boxes, int r, double w, double L);

// One step of one rank: the passes run over owned and halo particles (n (1 + f) / rate),
// `exchanges` halo or migration exchanges with `neighbours` messages of `bytes_per_halo` bytes
// per halo particle in all, `reductions` global reductions (log2 P latencies each) and, as
// implemented (MPI_Alltoall of the message sizes before every exchange), P - 1 latencies per
// exchange. alltoall_sizes = false models a neighbour-only exchange instead.
struct StepModel {
  double rate = 0;            // particle-steps per second of one rank on one core (measured)
  double exchanges = 0;       // exchanges per step (measured from message counts)
  double bytes_per_halo = 0;  // bytes sent per halo particle per step (measured)
  double reductions = 4;      // dt, imbalance (2), state check per step
  double latency = 2e-6;      // s per message (assumed: InfiniBand-class network)
  double bandwidth = 1e10;    // bytes/s per rank (assumed)
  bool alltoall_sizes = true;
};
struct StepTime {
  double compute = 0, halo_compute = 0, communication = 0;
  double total() const { return compute + halo_compute + communication; }
};
StepTime step_time(const StepModel& m, double n, double halo_fraction, int neighbours, int ranks);

}  // namespace curvsph::scaling
