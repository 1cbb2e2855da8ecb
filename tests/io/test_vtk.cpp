#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>

#include "curvsph/io/pvd_series.hpp"
#include "curvsph/io/vtk_reader.hpp"
#include "curvsph/io/vtk_writer.hpp"

namespace fs = std::filesystem;
using namespace curvsph;

namespace {

fs::path temp_dir(const std::string& name) {
  const fs::path d =
      fs::temp_directory_path() / ("curvsph_test_vtk_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

template <int D>
Particles<D> random_particles(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  std::uniform_int_distribution<std::int64_t> ui(std::numeric_limits<std::int64_t>::min(),
                                                 std::numeric_limits<std::int64_t>::max());
  Particles<D> p;
  p.resize(n);
  p.for_each_field([&](const char*, auto& data) {
    using T = typename std::decay_t<decltype(data)>::value_type;
    for (auto& v : data) {
      if constexpr (std::is_same_v<T, Vec<D>>) {
        for (int k = 0; k < D; ++k) v[k] = static_cast<Real>(u(rng) * std::exp(u(rng) / 100));
      } else if constexpr (std::is_floating_point_v<T>) {
        v = static_cast<T>(u(rng) / 7.0);
      } else {
        v = static_cast<T>(ui(rng));
      }
    }
  });
  return p;
}

template <int D>
void expect_bit_equal(const Particles<D>& a, const Particles<D>& b) {
  ASSERT_EQ(a.size(), b.size());
  std::vector<std::vector<std::byte>> fa, fb;
  a.for_each_field([&](const char*, const auto& data) {
    const auto* p = reinterpret_cast<const std::byte*>(data.data());
    fa.emplace_back(p, p + data.size() * sizeof(data[0]));
  });
  b.for_each_field([&](const char*, const auto& data) {
    const auto* p = reinterpret_cast<const std::byte*>(data.data());
    fb.emplace_back(p, p + data.size() * sizeof(data[0]));
  });
  ASSERT_EQ(fa.size(), fb.size());
  for (std::size_t k = 0; k < fa.size(); ++k) EXPECT_TRUE(fa[k] == fb[k]) << "field " << k;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <int D>
void round_trip(std::size_t n, unsigned seed) {
  const fs::path dir = temp_dir("rt" + std::to_string(D) + "_" + std::to_string(n));
  const Particles<D> p = random_particles<D>(n, seed);
  io::write_vtp(dir / "p.vtp", p);
  const Particles<D> q = io::read_particles<D>(dir / "p.vtp");
  expect_bit_equal(p, q);
  // Vectors are 3-component with z = 0 in 2-D.
  const io::VtkPolyData vtk = io::read_vtp(dir / "p.vtp");
  const auto& vel = vtk.array("velocity");
  EXPECT_EQ(vel.components, 3);
  if constexpr (D == 2) {
    const auto flat = vel.as<Real>();
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(flat[3 * i + 2], Real(0));
  }
  fs::remove_all(dir);
}

}  // namespace

TEST(VtkRoundTrip, Random2D) {
  round_trip<2>(1000, 1);
}
TEST(VtkRoundTrip, Random3D) {
  round_trip<3>(777, 2);
}
TEST(VtkRoundTrip, EmptyAndSingle) {
  round_trip<2>(0, 3);
  round_trip<3>(1, 4);
}

TEST(VtkXml, HeaderAndArrays) {
  const fs::path dir = temp_dir("xml");
  const Particles<3> p = random_particles<3>(17, 5);
  io::write_vtp(dir / "p.vtp", p);
  const std::string s = slurp(dir / "p.vtp");
  const std::string head = s.substr(0, s.find("<AppendedData"));
  EXPECT_EQ(s.rfind("<?xml version=\"1.0\"?>", 0), 0u);
  EXPECT_NE(head.find("<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                      "header_type=\"UInt64\">"),
            std::string::npos);
  EXPECT_NE(head.find("NumberOfPoints=\"17\""), std::string::npos);
  EXPECT_NE(head.find("NumberOfVerts=\"17\""), std::string::npos);
  const std::string real = std::is_same_v<Real, double> ? "Float64" : "Float32";
  EXPECT_NE(head.find("type=\"" + real + "\" Name=\"velocity\" NumberOfComponents=\"3\""),
            std::string::npos);
  EXPECT_NE(head.find("type=\"" + real + "\" Name=\"pressure\" format"), std::string::npos);
  EXPECT_NE(head.find("type=\"Int32\" Name=\"phase\""), std::string::npos);
  EXPECT_NE(head.find("type=\"Int64\" Name=\"id\""), std::string::npos);
  EXPECT_NE(head.find("Name=\"connectivity\""), std::string::npos);
  EXPECT_NE(head.find("Name=\"offsets\""), std::string::npos);
  EXPECT_NE(s.find("<AppendedData encoding=\"raw\">\n   _"), std::string::npos);
  EXPECT_EQ(s.substr(s.size() - 30), "\n  </AppendedData>\n</VTKFile>\n");

  // Tags balance in the XML part (well-formedness of the structure).
  auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t k = head.find(what); k != std::string::npos; k = head.find(what, k + 1)) ++n;
    return n;
  };
  for (const char* tag : {"PolyData", "Piece", "PointData", "Points", "Verts"}) {
    EXPECT_EQ(count(std::string("<") + tag + ">") + count(std::string("<") + tag + " "), 1u) << tag;
    EXPECT_EQ(count(std::string("</") + tag + ">"), 1u) << tag;
  }

  // Offsets: each block is [UInt64 n][n bytes], consecutive, and the last one ends where the
  // closing text begins.
  const std::size_t data0 = s.find('_', s.find("<AppendedData")) + 1;
  std::vector<std::size_t> offsets;
  const std::regex off("offset=\"([0-9]+)\"");
  for (auto it = std::sregex_iterator(head.begin(), head.end(), off); it != std::sregex_iterator();
       ++it)
    offsets.push_back(std::stoull((*it)[1]));
  ASSERT_EQ(offsets.size(), 10u + 1 + 2);  // 10 fields + Points + connectivity + offsets
  std::size_t expect = 0;
  for (std::size_t o : offsets) {
    EXPECT_EQ(o, expect);
    std::uint64_t nbytes = 0;
    std::memcpy(&nbytes, s.data() + data0 + o, 8);
    expect = o + 8 + nbytes;
  }
  EXPECT_EQ(data0 + expect, s.size() - 30);

  // Verts connectivity i, offsets i + 1, Int32 below 2^31 points.
  EXPECT_NE(head.find("type=\"Int32\" Name=\"connectivity\""), std::string::npos);
  EXPECT_NE(head.find("type=\"Int32\" Name=\"offsets\""), std::string::npos);
  std::uint64_t nb = 0;
  std::memcpy(&nb, s.data() + data0 + offsets[11], 8);
  ASSERT_EQ(nb, 17u * 4);
  for (std::int32_t i = 0; i < 17; ++i) {
    std::int32_t c = -1, o = -1;
    std::memcpy(&c, s.data() + data0 + offsets[11] + 8 + 4 * i, 4);
    std::memcpy(&o, s.data() + data0 + offsets[12] + 8 + 4 * i, 4);
    EXPECT_EQ(c, i);
    EXPECT_EQ(o, i + 1);
  }
  fs::remove_all(dir);
}

// zlib (vtkZLibDataCompressor): the arrays come back bit-equal, in blocks of 32768 bytes
// with a partial last block (the sizes in the header checked against the array sizes).
TEST(VtkZlib, RoundTripAndBlockHeader) {
  const fs::path dir = temp_dir("zlib");
  for (std::size_t n : {0u, 1u, 5000u}) {  // 5000 * 24 bytes of velocity: 4 blocks
    const Particles<3> p = random_particles<3>(n, 7);
    io::VtkWriteOptions zlib;
    zlib.zlib = true;
    io::VtkPolyData::from_particles(p).write(dir / "z.vtp", zlib);
    expect_bit_equal(p, io::read_particles<3>(dir / "z.vtp"));
    const std::string s = slurp(dir / "z.vtp");
    EXPECT_NE(s.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
    // The velocity block's header: [nb][32768][last][sizes...].
    const std::regex vel(
        "Name=\"velocity\" NumberOfComponents=\"3\" format=\"appended\" "
        "offset=\"([0-9]+)\"");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(s, m, vel));
    const std::size_t at = s.find('_', s.find("<AppendedData")) + 1 + std::stoull(m[1]);
    std::uint64_t h[3];
    std::memcpy(h, s.data() + at, 24);
    const std::uint64_t bytes = n * 3 * sizeof(Real);
    EXPECT_EQ(h[0], (bytes + 32767) / 32768) << n;
    EXPECT_EQ(h[1], 32768u);
    EXPECT_EQ(h[2], bytes % 32768);
  }
  // Random doubles hardly compress, but the Verts (0, 1, 2, ...) do: the file is smaller.
  const Particles<3> p = random_particles<3>(5000, 8);
  io::VtkWriteOptions zlib;
  zlib.zlib = true;
  io::VtkPolyData::from_particles(p).write(dir / "z.vtp", zlib);
  io::VtkPolyData::from_particles(p).write(dir / "r.vtp");
  EXPECT_LT(fs::file_size(dir / "z.vtp"), fs::file_size(dir / "r.vtp"));
  fs::remove_all(dir);
}

// float32: every floating point-data array narrowed to the nearest float, Points kept exact;
// read_particles converts back. output.fields: only the named arrays.
TEST(VtkFloat32, NarrowsFieldsKeepsPoints) {
  const fs::path dir = temp_dir("f32");
  const Particles<2> p = random_particles<2>(300, 9);
  io::VtkWriteOptions f32;
  f32.float32 = true;
  io::VtkPolyData::from_particles(p, {"position", "velocity", "density", "id"})
      .write(dir / "f.vtp", f32);
  const io::VtkPolyData vtk = io::read_vtp(dir / "f.vtp");
  ASSERT_EQ(vtk.arrays().size(), 3u);
  EXPECT_EQ(vtk.array("velocity").type, io::VtkType::Float32);
  EXPECT_EQ(vtk.array("density").type, io::VtkType::Float32);
  EXPECT_EQ(vtk.array("id").type, io::VtkType::Int64);
  EXPECT_EQ(vtk.find("pressure"), nullptr);
  EXPECT_EQ(vtk.points().type, io::vtk_type_of<Real>());
  const Particles<2> q = io::read_particles<2>(dir / "f.vtp");
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(q.x[i], p.x[i]);
    EXPECT_EQ(q.rho[i], static_cast<Real>(static_cast<float>(p.rho[i])));
    EXPECT_EQ(q.v[i][1], static_cast<Real>(static_cast<float>(p.v[i][1])));
    EXPECT_EQ(q.id[i], p.id[i]);
    EXPECT_EQ(q.p[i], 0);  // not written
  }
  EXPECT_THROW(vtk.array("id").converted<double>(), std::runtime_error);
  fs::remove_all(dir);
}

TEST(VtkPolyDataBuilder, ExtraArraysAndNames) {
  const fs::path dir = temp_dir("builder");
  std::vector<Vec2d> pts{{0, 0}, {1, 2}, {3, -4}};
  io::VtkPolyData vtk;
  vtk.set_points(pts);
  vtk.add_scalar<std::int32_t>("kind", std::vector<std::int32_t>{0, 1, 2});
  vtk.add_scalar<float>("gamma <&\">", std::vector<float>{0.5f, 0.25f, 1.0f});
  vtk.add_vector("normal", std::vector<Vec2d>{{0, 1}, {1, 0}, {0.6, 0.8}});
  vtk.write(dir / "walls.vtp");
  const io::VtkPolyData back = io::read_vtp(dir / "walls.vtp");
  EXPECT_EQ(back.number_of_points(), 3u);
  EXPECT_EQ(back.array("kind").as<std::int32_t>(), (std::vector<std::int32_t>{0, 1, 2}));
  EXPECT_EQ(back.array("gamma <&\">").as<float>(), (std::vector<float>{0.5f, 0.25f, 1.0f}));
  EXPECT_EQ(back.array("normal").as<double>(),
            (std::vector<double>{0, 1, 0, 1, 0, 0, 0.6, 0.8, 0}));
  EXPECT_EQ(back.points().as<double>(), (std::vector<double>{0, 0, 0, 1, 2, 0, 3, -4, 0}));
  EXPECT_THROW(back.array("nope"), std::runtime_error);
  EXPECT_THROW(back.array("kind").as<double>(), std::runtime_error);

  io::VtkPolyData bad;
  bad.set_points(pts);
  bad.add_scalar<double>("short", std::vector<double>{1.0});
  EXPECT_THROW(bad.write(dir / "bad.vtp"), std::runtime_error);
  EXPECT_THROW(io::read_vtp(dir / "missing.vtp"), std::runtime_error);
  fs::remove_all(dir);
}

TEST(VtkPvd, ListsFilesAndTimesAfterEveryOutput) {
  const fs::path dir = temp_dir("pvd");
  io::PvdSeries series(dir / "series.pvd");
  const std::vector<double> times{0.0, 0.1, 0.30000000000000004, 1e-7};
  for (std::size_t k = 0; k < times.size(); ++k) {
    const std::string name = "particles_" + std::to_string(k) + ".vtp";
    io::write_vtp(dir / name, random_particles<2>(5, static_cast<unsigned>(k)));
    series.add(times[k], dir / name, 0, "particles");  // absolute: stored relative to the .pvd
    series.add(times[k], "walls_" + std::to_string(k) + ".vtp", 1);
    // After every output the file on disk is complete and lists everything so far.
    const auto entries = io::PvdSeries::read(dir / "series.pvd");
    ASSERT_EQ(entries.size(), 2 * (k + 1));
    for (std::size_t j = 0; j <= k; ++j) {
      EXPECT_EQ(entries[2 * j].time, times[j]);
      EXPECT_EQ(entries[2 * j].file, "particles_" + std::to_string(j) + ".vtp");
      EXPECT_EQ(entries[2 * j].part, 0);
      EXPECT_EQ(entries[2 * j].name, "particles");
      EXPECT_EQ(entries[2 * j + 1].name, "");
      EXPECT_EQ(entries[2 * j + 1].file, "walls_" + std::to_string(j) + ".vtp");
      EXPECT_EQ(entries[2 * j + 1].part, 1);
    }
    const std::string text = slurp(dir / "series.pvd");
    EXPECT_NE(text.find("<VTKFile type=\"Collection\""), std::string::npos);
    EXPECT_NE(text.find("</Collection>\n</VTKFile>"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "series.pvd.tmp"));
  }
  fs::remove_all(dir);
}
