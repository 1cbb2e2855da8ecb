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
// three axes cut): 6 w/a + 3 pi (w/a)^2 + 4 pi/3 (w/a)^3, a = n^(1/3) dx. The continuum
// figure (a disordered fluid fills its box up to the faces); on a lattice whose cut lies
// midway between two layers the halo holds the whole layers within w of the outer owned
// layer: floor(w/dx + 1/2) layers per face where the continuum counts w/dx.
double cube_halo_fraction(double n, double dx, double w);

// Halo fraction of a box of m[d] lattice layers per axis (spacing 1) when the halo is
// every lattice site within w of the box of the owned sites (as parallel/decomposition.cpp
// selects it, across the cut axes only): per nonempty set S of cut axes, the sites beyond the
// box on exactly the axes of S, i.e. prod_{d not in S} m[d] * 2^|S| * N_|S|(w), with N_k(w)
// the positive integer k-tuples of squared length below w^2. For w = 2.6: 2 layers per face
// (N_1 = 2) where the continuum counts 2.6.
// `offset`: the halo is measured from a box reaching `offset` spacings beyond the outer owned
// layer on the cut axes (0.5 for the ORB box of the midpoint rule, whose cut lies midway
// between two layers); a site k layers out is then k - offset from it.
double lattice_halo_fraction(const std::array<double, 3>& m, const std::array<bool, 3>& cut,
                             double w, double offset = 0);

// Ranks whose box lies within w of rank r's box (periodic), r excluded.
int neighbour_count(const std::vector<RankBox>& boxes, int r, double w, double L);

// One step of one rank: the neighbour passes run over the n owned particles (n / rate); a
// halo copy costs `halo_cost` of an owned particle (it still enters the cell list and the
// per-particle factors the pair sums read, but no pair sum of its own). `exchanges` halo or
// migration exchanges with `neighbours` messages of `bytes_per_halo` bytes per halo particle
// in all, `reductions` global reductions (log2 P latencies each) and, as implemented, an
// MPI_Alltoall of the message sizes (P - 1 latencies) before each of the `sized_exchanges`
// whose sizes are not known in advance (migration, halo build; the refreshes of the halo
// reuse its layout). alltoall_sizes = false models a neighbour-only size exchange instead.
struct StepModel {
  double rate = 0;             // particle-steps per second of one rank on one core (measured)
  double halo_cost = 0;        // cost of a halo copy per owned particle's (measured)
  double exchanges = 0;        // exchanges per step (measured from message counts)
  double sized_exchanges = 2;  // of which with an MPI_Alltoall of sizes (migration, halo)
  double bytes_per_halo = 0;   // bytes sent per halo particle per step (measured)
  double reductions = 5;       // dt, imbalance (2), owned bounds, state check per step
  double latency = 2e-6;       // s per message (assumed: InfiniBand-class network)
  double bandwidth = 1e10;     // bytes/s per rank (assumed)
  bool alltoall_sizes = true;
};
struct StepTime {
  double compute = 0, halo_compute = 0, communication = 0;
  double total() const { return compute + halo_compute + communication; }
};
StepTime step_time(const StepModel& m, double n, double halo_fraction, int neighbours, int ranks);

}  // namespace curvsph::scaling
