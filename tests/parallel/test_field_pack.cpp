// Migration and halo messages carry the particles' fields exactly; one-rank decomposition is
// the identity.
#include <gtest/gtest.h>

#include "curvsph/parallel/decomposition.hpp"
#include "curvsph/parallel/field_pack.hpp"

namespace curvsph {
namespace {

Particles<3> sample(std::size_t n) {
  Particles<3> p;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Real s = static_cast<Real>(i) + Real(0.25);
    p.x[i] = Vec<3>(s, -s, 2 * s);
    p.v[i] = Vec<3>(1 / (s + 1), s * s, -3);
    p.a[i] = Vec<3>(7, 8, 9);
    p.mass[i] = s / 3;
    p.rho[i] = 1000 + s;
    p.drho[i] = -s;
    p.p[i] = s * s * s;
    p.sigma[i] = 1 / s;
    p.phase[i] = static_cast<std::int32_t>(i % 3);
    p.id[i] = static_cast<std::int64_t>(1000 + i);
  }
  return p;
}

TEST(FieldPack, MigrationCarriesEveryFieldBitForBit) {
  const Particles<3> src = sample(5);
  std::vector<std::byte> buf;
  mpi::pack(src, std::vector<Index>{3, 1}, mpi::FieldSet::all, buf);
  EXPECT_EQ(buf.size(), 2 * mpi::record_bytes(src, mpi::FieldSet::all));
  Particles<3> dst = sample(1);
  EXPECT_EQ(mpi::unpack_append(dst, buf, mpi::FieldSet::all), 2u);
  ASSERT_EQ(dst.size(), 3u);
  for (std::size_t k : {std::size_t(1), std::size_t(2)}) {
    const std::size_t i = k == 1 ? 3 : 1;
    EXPECT_EQ(dst.x[k], src.x[i]);
    EXPECT_EQ(dst.v[k], src.v[i]);
    EXPECT_EQ(dst.a[k], src.a[i]);
    EXPECT_EQ(dst.mass[k], src.mass[i]);
    EXPECT_EQ(dst.rho[k], src.rho[i]);
    EXPECT_EQ(dst.drho[k], src.drho[i]);
    EXPECT_EQ(dst.p[k], src.p[i]);
    EXPECT_EQ(dst.sigma[k], src.sigma[i]);
    EXPECT_EQ(dst.phase[k], src.phase[i]);
    EXPECT_EQ(dst.id[k], src.id[i]);
  }
}

TEST(FieldPack, HaloCopiesLeaveOutTheOwnersResults) {
  const Particles<3> src = sample(2);
  std::vector<std::byte> buf;
  mpi::pack(src, std::vector<Index>{1}, mpi::FieldSet::halo, buf);
  // 3 + 3 doubles of x, v; mass, rho, p, sigma; int32 phase; int64 id; int32 buffer (no a,
  // no drho).
  EXPECT_EQ(buf.size(), 10 * sizeof(Real) + 4 + 8 + 4);
  Particles<3> dst;
  mpi::unpack_append(dst, buf, mpi::FieldSet::halo);
  ASSERT_EQ(dst.size(), 1u);
  EXPECT_EQ(dst.x[0], src.x[1]);
  EXPECT_EQ(dst.p[0], src.p[1]);
  EXPECT_EQ(dst.a[0], Vec<3>::Zero());
  EXPECT_EQ(dst.drho[0], 0);
}

TEST(Decomposition, OneRankIsTheIdentity) {
  Particles<3> p = sample(7);
  const Particles<3> before = p;
  Decomposition<3> d;
  DecompositionOptions o;
  o.halo_width = 1;
  o.check_conservation = true;
  d.configure(o);
  d.distribute(p);
  d.migrate(p);
  d.exchange_halo(p);
  d.refresh(p);
  d.drop_halo(p);
  EXPECT_EQ(d.owned(), 7);
  EXPECT_EQ(p.x, before.x);
  EXPECT_EQ(p.id, before.id);
  EXPECT_EQ(d.global_count(), 7);
  EXPECT_EQ(d.stats().count_error_max, 0);
  EXPECT_EQ(d.stats().id_error_max, 0);
  const Particles<3> all = d.gather(p);
  EXPECT_EQ(all.id, before.id);
}

}  // namespace
}  // namespace curvsph
