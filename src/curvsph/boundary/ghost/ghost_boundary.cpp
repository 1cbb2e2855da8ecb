#include "curvsph/boundary/ghost/ghost_boundary.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>

#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/boundary/wall_force.hpp"
#include "curvsph/boundary/wall_impact.hpp"
#include "curvsph/core/parallel.hpp"
#include "curvsph/physics/artificial_viscosity.hpp"

namespace curvsph {
namespace {

template <int D>
class GhostBoundary final : public BoundaryModel<D> {
 public:
  explicit GhostBoundary(const BoundaryContext<D>& ctx)
      : walls_(ctx.walls), W_(ctx.kernel), F_(ctx.fluid), fluid_cells_(ctx.cells) {
    const Case& c = ctx.spec;
    options_.map = parse_ghost_map(c.boundary.map, c.file_name(), "boundary.map");
    options_.velocity =
        parse_ghost_velocity(c.boundary.velocity, c.file_name(), "boundary.velocity");
    options_.support = W_.support;
    options_.cells = &fluid_cells_;
    if (c.boundary.wall_force) wall_force_ = WallForce(F_.eos.c0, static_cast<Real>(c.dx));
    layer_ = WallForce(F_.eos.c0, static_cast<Real>(c.dx), kWallLayer);
    dx_ = static_cast<Real>(c.dx);
    hydrostatic_ = c.boundary.ghost_pressure == "hydrostatic";
    no_tension_ = !c.boundary.wall_tension;
    difference_ = c.pressure_difference;
    av_alpha_h_c0_ = static_cast<Real>(c.artificial_alpha) * W_.h * F_.eos.c0;
    av_approaching_ = c.artificial_approaching;
    Vec3d lo = c.domain_min, hi = c.domain_max;
    cells_.configure(W_.support, lo, hi, c.periodic);
  }

  std::string name() const override { return "ghost"; }
  // A ghost behind a convex wall comes closer to a fluid particle than its source by at most
  // a few tenths of a support at the curvatures check_ghost_walls accepts.
  Real halo_reach() const override { return Real(1.25); }

  void check_setup(const Particles<D>& P, const std::string& file) override {
    check_ghost_walls<D>(options_.map, walls_, W_.support, P.x, file);
  }

  void prepare(const Particles<D>& P, Real /*t*/) override {
    G_.build(P.x, P.v, walls_, options_);
    cells_.build(G_.x);
    // Each particle's own ghosts (ghosts are ordered by source): its speed towards each wall
    // is taken along its own normal, so that flow along a curved wall has none (ghosts of
    // neighbours carry the normal at their source's foot, tilted by the curvature).
    own_begin_.assign(P.size(), 0);
    own_end_.assign(P.size(), 0);
    for (std::size_t g = G_.size(); g-- > 0;) {
      const Index s = G_.source[g];
      if (own_end_[s] == 0) own_end_[s] = static_cast<Index>(g + 1);
      own_begin_[s] = static_cast<Index>(g);
    }
  }

  // The speed at which particle i approaches the wall (face) of ghost g, (u_w - u_i).n along
  // i's own normal to it, and (`depth`) i's distance to that wall (the impact pressure's taper):
  // its own single ghost of the same wall whose normal is closest to the ghost's (the faces of a
  // box share a wall index). The free-slip image of i reflects the normal velocity about the
  // wall's, so u_w.n = (u_i + u_slip).n / 2.
  Real approach(const Particles<D>& P, Index i, Index g, Real* depth = nullptr) const {
    Index best = -1;
    double dot = -2;
    for (Index q = own_begin_[i]; q < own_end_[i]; ++q) {
      if (G_.reflections[q] != 1 || G_.wall[q] != G_.wall[g]) continue;
      const double c = G_.normal[q].dot(G_.normal[g]);
      if (c > dot) {
        dot = c;
        best = q;
      }
    }
    if (best < 0) return 0;
    const Vec<D> n = G_.normal[best].template cast<Real>();
    const Vec<D>& slip = G_.v_slip.empty() ? G_.v[best] : G_.v_slip[best];
    if (depth) *depth = static_cast<Real>(G_.source_depth[best]);
    return Real(0.5) * (slip - P.v[i]).dot(n);
  }

  // Barker eq. 20: sigma_i += sum_g beta_g W_ig.
  void add_density(Particles<D>& P) override {
    if (G_.size() == 0) return;
    parallel_for(static_cast<Index>(P.size()), [&](Index i) {
      Real s = 0;
      cells_.for_each_neighbor(P.x[i], G_.x, [&](Index g, const Vec<D>&, Real r2) {
        s += G_.beta[g] * W_.value(std::sqrt(r2));
      });
      if (s == 0) return;
      P.sigma[i] += s;
      P.rho[i] = P.mass[i] * P.sigma[i];
    });
  }

  // Ghost terms of the continuity equation, with the ghosts' free-slip images (ghosts.hpp:
  // why not the no-slip ones); the diffusive term sees the ghost's density (its source's) with
  // the source particle's own renormalised gradient left out.
  // Under a hydrostatic ghost pressure (p_g = p_s + rho_s g.(x_g - x_s), below) the ghost's
  // density is continued the same way, rho_g = rho_s + rho^H(x_g) - rho^H(x_s), and the
  // diffusive term takes the dynamic density rho - rho^H of i and the ghost (Fourtakas et al.
  // 2019, as physics/density.hpp's fourtakas form), which is the source's:
  //   psi_ig = rho_s - rho_i - (rho^H_s - rho^H_i) = rho_s - rho_i + rho_is k.(x_i - x_s),
  // k = g / c0^2, rho_is = (rho_i + rho_s) / 2. The plain difference rho_s - rho_i diffused the
  // hydrostatic profile into the wall (a rate of 0.73 delta rho0 g / c0 next to a floor,
  // tests/boundary/test_ghost_diffusion.cpp): the water lost density along the walls, most
  // where the ghosts outnumber the fluid (a 60 degree V trough at H/dx = 8: 0.14 rho0 g H
  // along its bottom edge after 1 s; the 3-D box at H/dx = 8: 0.0385 rho0 g H RMS against
  // 0.0037, docs/validation/cad_at_rest/findings.md). The fourtakas form took the same part
  // without the factor rho_is (dimensionally short: k.r alone), i.e. the plain difference too.
  void add_density_rate(Particles<D>& P) override {
    if (G_.size() == 0) return;
    const std::vector<Vec<D>>& vg = G_.v_slip.empty() ? G_.v : G_.v_slip;
    const Real delta_h_c0 = F_.delta_sph * W_.h * F_.eos.c0;
    // The hydrostatic part is taken between i and the ghost's source, whose dynamic density
    // the ghost carries: x_i - x_s = r + (x_g - x_s), both minimal-image separations.
    const Vec<D> k = (hydrostatic_ || F_.diffusion == FluidParams<D>::Diffusion::fourtakas)
                         ? Vec<D>(F_.gravity / (F_.eos.c0 * F_.eos.c0))
                         : Vec<D>::Zero();
    parallel_for(static_cast<Index>(P.size()), [&](Index i) {
      Real div = 0, diff = 0;
      cells_.for_each_neighbor(P.x[i], G_.x, [&](Index g, const Vec<D>& r, Real r2) {
        const Index s = G_.source[g];
        const Real f = W_.gradient_factor(std::sqrt(r2));
        const Real Vg = G_.beta[g] * P.mass[s] / P.rho[s];  // beta_g source volumes (above)
        div += Vg * f * (P.v[i] - vg[g]).dot(r);
        diff += Vg * f *
                (-2 * (P.rho[s] - P.rho[i] +
                       Real(0.5) * (P.rho[s] + P.rho[i]) *
                           k.dot(r + cells_.separation(G_.x[g], P.x[s]))));
      });
      P.drho[i] += P.rho[i] * div + delta_h_c0 * diff;
    });
  }

  // Pressure and viscous terms with the ghost as neighbour j (momentum.hpp's formulas),
  // p_g = p_s. A ghost stands for beta_g particles of its source (the weight it has in the
  // density sum, Barker eq. 20-21: its image volume is beta_g times the source's, and it
  // sits at the source's number density sigma_s), so its pair term is weighted by beta_g
  // with sigma_g = sigma_s. Barker's eq. 22 instead copies sigma_g = sigma_s beta_g
  // unweighted, which contradicts his own "sigma is inversely proportional to V" a line
  // earlier and is unstable: the Couette annulus at rest (omega = 0, dx = 1.875 mm) grows a
  // density oscillation from +-0.3 % to +-9 % and loses a particle through the wall at
  // t ~ 6 s, while this form (and mirror, density_preserving: beta = 1, where both agree)
  // stays within +-0.2 % for 8 s.
  // boundary.ghost_pressure: hydrostatic gives the ghost p_g = p_s + rho_s g.(x_g - x_s), the
  // source's pressure carried across the wall along the hydrostatic gradient (the body-force
  // term of the wall pressure of Adami, Hu & Adams 2012, eq. 27). Under gravity a copied
  // pressure leaves the first row's wall push short by 2 rho g d: the 2-D tank of
  // support/bi_tank.hpp (12 rows, h = 2 dx) with mirror ghosts loses its corner particle
  // through the floor at t = 0.11 s with `copy` and stays at rest to t sqrt(g/H) = 20 with
  // `hydrostatic` (kinetic energy 2.6e-7 M g H). `copy` stays the default (issue 4's contract,
  // the committed ghost studies): in a viscous flow driven by a body force (the throttled
  // pipe) the viscous stress balances the force at the wall, and dp/dn = rho g.n + mu lap u.n
  // is closer to 0 than to rho g.n.
  // With boundary.wall_force each wall closer than 0.1 dx pushes (wall_force.hpp), found
  // through the particle's own single ghost of that wall (one per wall, so a box corner pushes
  // from both or all three faces). Like the boundary integrals, the symmetric pair form pulls
  // a particle in tension (p_s = p_i < 0) towards its ghosts; the force is the safeguard.
  // Measured on the 3-D dam break with mirror ghosts at 0.55/15 before the free-slip images
  // of the continuity equation (dam_break_3d/findings.md, session 12): the front's corner
  // particle crossed the floor at t = 0.058 s without the force, at 0.144 s with it.
  // Always on (wall_impact.hpp, which says why and gives the sources): the impact pressure
  // rho_i c0 max((u_w - u_i).n, 0) added to p_g of every single ghost of a wall i approaches,
  // tapered by i's own depth in front of that wall (none beyond dx),
  // and the contact layer, the wall force's law with d0 = kWallLayer dx, found through i's own
  // ghost like the wall force. Wall loads (wall_loads.hpp): the reaction of each ghost's pair term,
  // on the ghost's wall, at the midpoint of particle and ghost (the pressure term acts along the
  // line through both, so any point of it gives the same moment; the midpoint of a mirror pair is
  // on the wall). A corner ghost's reaction is split between the faces it was reflected across, the
  // component along each face's normal to that face (R decomposed on the faces' normals),
  // what is left (3-D, along the edge of two faces) to the last one. The wall force's
  // reaction acts at the foot point.
  void add_accelerations(Particles<D>& P) override {
    if (G_.size() == 0) return;
    const WallForce wf = wall_force_;
    const bool hydrostatic = hydrostatic_;
    const bool no_tension = no_tension_;
    const bool difference = difference_;
    const Vec<D> grav = F_.gravity;
    const WallForce layer = layer_;
    const Real c0 = F_.eos.c0;
    const Real dx = dx_;
    WallLoadSums<D>* loads = this->loads_;
    const auto react = [&](Index i, Index g, const Vec<D>& R, const VecD<D>& at) {
      // Images reflected more than once within one wall (a polygon's or a CAD solid's
      // corners, facet_images.hpp) have no corner record: the whole reaction is that wall's.
      const auto c = G_.reflections[g] == 1
                         ? G_.corners.end()
                         : std::lower_bound(G_.corners.begin(), G_.corners.end(), g,
                                            [](const typename GhostSet<D>::Corner& a, Index b) {
                                              return a.ghost < b;
                                            });
      if (c == G_.corners.end() || c->ghost != g) {
        loads->add(i, static_cast<std::size_t>(G_.wall[g]), R, at);
        return;
      }
      // R = sum_r a_r n_r + rest, the a_r from the Gram system of the faces' normals (the
      // projections on each normal where they are perpendicular); rest (3-D: along the edge
      // of two faces) goes to the last face.
      const int nr = c->faces;
      Eigen::Matrix3d gram = Eigen::Matrix3d::Identity();
      Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
      for (int r = 0; r < nr; ++r) {
        const VecD<D>& nr_ = c->normal[static_cast<std::size_t>(r)];
        rhs[r] = nr_.dot(R.template cast<double>());
        for (int q = 0; q < nr; ++q) gram(r, q) = nr_.dot(c->normal[static_cast<std::size_t>(q)]);
      }
      const Eigen::Vector3d a = gram.partialPivLu().solve(rhs);
      Vec<D> rest = R;
      for (int r = 0; r < nr; ++r) {
        const Vec<D> part =
            static_cast<Real>(a[r]) * c->normal[static_cast<std::size_t>(r)].template cast<Real>();
        rest -= part;
        loads->add(i, static_cast<std::size_t>(c->wall[static_cast<std::size_t>(r)]),
                   r + 1 < nr ? part : Vec<D>(part + rest), at);
      }
    };
    const auto body = [&](Index i) {
      const Real si = P.sigma[i];
      const Real inv_si2 = 1 / (si * si);
      // boundary.wall_tension: false: the ghost pair terms take p clamped at 0, so the wall
      // never pulls (case_file.hpp).
      const Real pi_s2 = (no_tension ? std::max(P.p[i], Real(0)) : P.p[i]) * inv_si2;
      const Real mu = F_.viscosity[P.phase[i]];
      Vec<D> grad_p = Vec<D>::Zero(), visc = Vec<D>::Zero(), push = Vec<D>::Zero();
      Vec<D> av = Vec<D>::Zero();  // artificial viscosity's ghost terms (acceleration)
      const Real av_ci =
          av_alpha_h_c0_ > 0 ? av_alpha_h_c0_ * F_.rho0[P.phase[i]] / P.rho[i] : Real(0);
      bool any = false;
      const bool track = loads && i < loads->count();
      cells_.for_each_neighbor(P.x[i], G_.x, [&](Index g, const Vec<D>& r, Real r2) {
        const Index s = G_.source[g];
        const Real f = W_.gradient_factor(std::sqrt(r2));
        const Real bg = G_.beta[g];
        const Real sg = P.sigma[s];
        const Real inv_sg2 = 1 / (sg * sg);
        Real pg = P.p[s];
        if (hydrostatic) pg += P.rho[s] * grav.dot(cells_.separation(G_.x[g], P.x[s]));
        // Impact pressure (wall_impact.hpp item 1) of i approaching this ghost's wall. Corner
        // ghosts take none: the single ghosts of each face carry that face's.
        if (G_.reflections[g] == 1) {
          Real d = 0;
          const Real ua = approach(P, i, g, &d);
          pg += wall_impact_pressure(P.rho[i], c0, ua, d / dx, kImpactReachGhosts);
        }
        Vec<D> gp;
        if (difference) {  // pressure_gradient: difference (physics/pressure_gradient.hpp)
          gp = bg * ((pg - P.p[i]) * inv_sg2) * f * r;
        } else {
          if (no_tension) pg = std::max(pg, Real(0));
          gp = bg * (pg * inv_sg2 + pi_s2) * f * r;
        }
        const Vec<D> vs = bg * (inv_sg2 + inv_si2) * f * (P.v[i] - G_.v[g]);
        grad_p += gp;
        visc += vs;
        any = true;
        // The artificial viscosity (physics/artificial_viscosity.hpp) with the ghost as a
        // neighbour of volume beta_g m_s / rho_s and its no-slip velocity: without these terms
        // the wall is free-slip for that viscosity, and the near-wall layer slips by the
        // share of the momentum it carries (couette/findings.md, "Kernel width").
        Vec<D> avg = Vec<D>::Zero();
        if (av_ci > 0) {
          const Real eta2 = Real(0.01) * W_.h * W_.h;
          const Real ux = (P.v[i] - G_.v[g]).dot(r);
          if (av_approaching_)  // the ghost as a neighbour of mass beta_g m_s, density rho_s
            avg = (monaghan_pair_factor(av_alpha_h_c0_, P.rho[i], P.rho[s], f, ux, r2, eta2) * bg *
                   P.mass[s]) *
                  r;
          else
            avg = (av_ci * f * (bg * P.mass[s] / P.rho[s]) * ux / (r2 + eta2)) * r;
          av += avg;
        }
        if (track)
          react(i, g, Vec<D>(gp - mu * vs - P.mass[i] * avg),
                (P.x[i] - Real(0.5) * r).template cast<double>());
        if (s == i && G_.reflections[g] == 1) {
          const Real d = static_cast<Real>(G_.source_depth[g]);
          if (wf.active(d) || layer.active(d)) {
            const Vec<D> pg_push =
                (wf.magnitude(d) + layer.magnitude(d)) * G_.normal[g].template cast<Real>();
            push += pg_push;
            if (track) react(i, g, Vec<D>(-P.mass[i] * pg_push), G_.foot[g]);
          }
        }
      });
      if (!any) return;
      const Real inv_m = 1 / P.mass[i];
      P.a[i] += -inv_m * grad_p + mu * inv_m * visc + push + av;
    };
    if (loads)
      WallLoadSums<D>::for_blocks(static_cast<Index>(P.size()), false, body);
    else
      parallel_for(static_cast<Index>(P.size()), body);
  }

  // The ghosts enter the shift direction as neighbours (beta_g source volumes, as in the
  // density sum). A particle within dx of a wall is not shifted towards it
  // (shift_toward_wall_removed): its own ghost, the one that would repel it, sits at 2d, where
  // grad W vanishes as d -> 0. The Taylor gradients stay the fluid's: with the ghosts' no-slip
  // velocities in grad v, the Couette annulus from rest (dx = 1.875 mm, C = 0.01) blew up at
  // t = 3.4 s; without them it ran to 40 s.
  void add_shift_sums(const Particles<D>& P, Index n, Real dx,
                      ShiftScratch<D>& sums) const override {
    if (G_.size() == 0) return;
    const Real w_dx = W_.value(dx);
    parallel_for(n, [&](Index i) {
      std::array<Vec<D>, 4> close{};  // normals of the walls within dx (own single ghosts)
      int nc = 0;
      cells_.for_each_neighbor(P.x[i], G_.x, [&](Index g, const Vec<D>& r, Real r2) {
        const Index s = G_.source[g];
        const Real rr = std::sqrt(r2);
        const Real Vg = G_.beta[g] * P.mass[s] / P.rho[s];
        sums.s[i] +=
            shift_pair_weight(W_, rr, w_dx, sums.anti_clumping) * Vg * W_.gradient_factor(rr) * r;
        if (s == i && G_.reflections[g] == 1 && G_.source_depth[g] < dx && nc < 4)
          close[static_cast<std::size_t>(nc++)] = G_.normal[g].template cast<Real>();
      });
      for (int k = 0; k < nc; ++k)
        shift_toward_wall_removed(sums.s[i], close[static_cast<std::size_t>(k)]);
    });
  }

  const std::vector<Index>& penetrated() const override { return G_.penetrated; }
  // A particle closer than the support to a wall has its own single ghost of that wall
  // (source_depth = its distance); one past a wall is in `penetrated`.
  void within(Real reach, std::vector<Index>& out) const override {
    out.insert(out.end(), G_.penetrated.begin(), G_.penetrated.end());
    for (std::size_t g = 0; g < G_.size(); ++g)
      if (G_.reflections[g] == 1 && G_.source_depth[g] < reach) out.push_back(G_.source[g]);
  }

  void append_output(std::vector<Vec<D>>& x, std::vector<int>& kind) const override {
    x.insert(x.end(), G_.x.begin(), G_.x.end());
    kind.insert(kind.end(), G_.size(), 1);
  }

  WallImages<D> images() const override {
    return {&G_.x, &G_.source, &G_.beta, &G_.wall, &G_.normal, &G_.reflections, &cells_};
  }

  const GhostSet<D>& ghosts() const { return G_; }

 private:
  const WallSet<D>& walls_;
  const WendlandC2<D>& W_;
  const FluidParams<D>& F_;
  const CellList<D>& fluid_cells_;
  GhostOptions<D> options_;
  WallForce wall_force_;      // range 0 (never active) unless boundary.wall_force
  WallForce layer_;           // the contact layer (wall_impact.hpp item 2), always on
  bool hydrostatic_ = false;  // boundary.ghost_pressure: hydrostatic
  bool no_tension_ = false;   // boundary.wall_tension: false
  bool difference_ = false;   // pressure_gradient: difference
  Real av_alpha_h_c0_ = 0;    // artificial_viscosity.alpha h c0 (0: off)
  // artificial_viscosity.form: approaching
  bool av_approaching_ = false;
  Real dx_ = 0;  // particle spacing: the reach of the impact pressure (wall_impact.hpp)
  GhostSet<D> G_;
  std::vector<Index> own_begin_, own_end_;  // each particle's own ghosts [begin, end)
  CellList<D> cells_;
};

}  // namespace

template <int D>
std::unique_ptr<BoundaryModel<D>> make_ghost_boundary(const BoundaryContext<D>& ctx) {
  auto m = std::make_unique<GhostBoundary<D>>(ctx);
  return m;
}

template std::unique_ptr<BoundaryModel<2>> make_ghost_boundary<2>(const BoundaryContext<2>&);
template std::unique_ptr<BoundaryModel<3>> make_ghost_boundary<3>(const BoundaryContext<3>&);

}  // namespace curvsph
