#include "curvsph/cad/stl_reader.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "curvsph/core/error.hpp"
#include "curvsph/geometry/mesh_topology.hpp"

namespace curvsph::cad {
namespace {

// Triangle soup -> indexed mesh. std::map compares coordinates with <, so 0.0 and -0.0 are
// one vertex, as they are one point.
class Indexer {
 public:
  int operator()(const Vec3d& p) {
    const auto [it, fresh] = index_.try_emplace({p.x(), p.y(), p.z()}, int(mesh.vertices.size()));
    if (fresh) mesh.vertices.push_back(p);
    return it->second;
  }
  void add(const std::array<Vec3d, 3>& t) {
    const std::array<int, 3> i{(*this)(t[0]), (*this)(t[1]), (*this)(t[2])};
    if (i[0] != i[1] && i[1] != i[2] && i[2] != i[0]) mesh.triangles.push_back(i);
  }
  StlMesh mesh;

 private:
  std::map<std::array<double, 3>, int> index_;
};

// Binary STL (80-byte header, uint32 count, then per triangle 12 little-endian float32 and a
// uint16): the file size must be exactly 84 + 50 count.
StlMesh read_binary(const std::string& data, const std::string& path, const std::string& file,
                    const std::string& key) {
  std::uint32_t n = 0;
  std::memcpy(&n, data.data() + 80, 4);
  const std::uint64_t want = 84 + 50 * std::uint64_t(n);
  if (data.size() != want)
    throw InputError(file, key,
                     fmt::format("binary STL '{}' declares {} triangles, which take {} bytes, but "
                                 "the file has {} bytes (truncated or corrupt)",
                                 path, n, want, data.size()));
  Indexer ix;
  for (std::uint32_t t = 0; t < n; ++t) {
    float f[12];
    std::memcpy(f, data.data() + 84 + 50 * std::uint64_t(t), sizeof f);
    std::array<Vec3d, 3> tri;
    for (int c = 0; c < 3; ++c) {
      tri[c] = Vec3d(f[3 + 3 * c], f[4 + 3 * c], f[5 + 3 * c]);
      if (!tri[c].allFinite())
        throw InputError(file, key,
                         fmt::format("binary STL '{}': triangle {} has a non-finite vertex "
                                     "({}, {}, {})",
                                     path, t, tri[c].x(), tri[c].y(), tri[c].z()));
    }
    ix.add(tri);
  }
  return std::move(ix.mesh);
}

// ASCII STL: `solid name` { `facet normal nx ny nz` `outer loop` 3 x `vertex x y z` `endloop`
// `endfacet` } `endsolid name`, possibly several solids. Anything else, or an end before
// `endsolid`, is an error naming the line.
StlMesh read_ascii(const std::string& data, const std::string& path, const std::string& file,
                   const std::string& key) {
  enum class State { start, solid, facet, loop, loop_done, after };
  State st = State::start;
  Indexer ix;
  std::array<Vec3d, 3> tri;
  int nvert = 0;
  long line_no = 0;
  std::istringstream in(data);
  std::string line;
  const auto fail = [&](const std::string& why) {
    return InputError(file, key, fmt::format("ASCII STL '{}' line {}: {}", path, line_no, why));
  };
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream ls(line);
    std::string word;
    if (!(ls >> word)) continue;
    if (st == State::start || st == State::after) {
      if (word != "solid") throw fail(fmt::format("expected `solid`, found `{}`", word));
      st = State::solid;
    } else if (st == State::solid && word == "facet") {
      st = State::facet;
    } else if (st == State::solid && word == "endsolid") {
      st = State::after;
    } else if (st == State::facet && word == "outer") {
      st = State::loop;
      nvert = 0;
    } else if (st == State::loop && word == "vertex") {
      if (nvert == 3) throw fail("a facet with more than 3 vertices");
      double c[3];
      for (double& x : c) {
        std::string tok;
        char* end = nullptr;
        if (!(ls >> tok) || (x = std::strtod(tok.c_str(), &end), *end != '\0'))
          throw fail("a vertex needs three numbers");
      }
      tri[nvert] = Vec3d(c[0], c[1], c[2]);
      if (!tri[nvert].allFinite())
        throw fail(fmt::format("non-finite vertex ({}, {}, {})", c[0], c[1], c[2]));
      ++nvert;
    } else if (st == State::loop && word == "endloop") {
      if (nvert != 3) throw fail(fmt::format("a facet with {} vertices (3 needed)", nvert));
      st = State::loop_done;
    } else if (st == State::loop_done && word == "endfacet") {
      ix.add(tri);
      st = State::solid;
    } else {
      throw fail(fmt::format("unexpected `{}`", word));
    }
  }
  if (st != State::after)
    throw InputError(
        file, key,
        fmt::format("ASCII STL '{}' ends at line {} {} (truncated file?)", path, line_no,
                    st == State::solid ? "without `endsolid`" : "inside a facet"));
  return std::move(ix.mesh);
}

std::string point(const Vec3d& p) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x(), p.y(), p.z());
}

}  // namespace

StlMesh read_stl(const std::string& path, const std::string& file, const std::string& key) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(file, key, fmt::format("cannot open STL file '{}'", path));
  const std::string data((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  // A binary file may begin with "solid" too: an ASCII file has no NUL byte, a binary one
  // with a plausible size almost always has (float zeros, the counts' high bytes).
  const std::size_t first = data.find_first_not_of(" \t\r\n");
  const bool ascii = first != std::string::npos && data.compare(first, 5, "solid") == 0 &&
                     data.find('\0') == std::string::npos;
  StlMesh mesh;
  if (ascii) {
    mesh = read_ascii(data, path, file, key);
  } else {
    if (data.size() < 84)
      throw InputError(file, key,
                       fmt::format("STL file '{}' has {} bytes: neither ASCII (`solid` ...) nor "
                                   "binary (84 bytes at least)",
                                   path, data.size()));
    mesh = read_binary(data, path, file, key);
  }
  if (mesh.triangles.empty())
    throw InputError(file, key, fmt::format("STL file '{}' has no triangle", path));
  return mesh;
}

void require_closed(const StlMesh& mesh, const std::string& path, const std::string& file,
                    const std::string& key) {
  const MeshEdges e = mesh_edges(mesh.triangles);
  const auto refuse = [&](long count, const std::array<int, 2>& ex, const char* what) {
    throw InputError(
        file, key,
        fmt::format("STL '{}' does not bound a volume, which `fluid: inside|outside` needs: {} "
                    "edge(s) {}, e.g. from {} to {}",
                    path, count, what, point(mesh.vertices[ex[0]]), point(mesh.vertices[ex[1]])));
  };
  if (e.boundary > 0)
    refuse(e.boundary, e.boundary_example, "used by one triangle only (an open surface)");
  if (e.non_manifold > 0)
    refuse(e.non_manifold, e.non_manifold_example, "shared by three triangles or more");
  if (e.misoriented > 0)
    refuse(e.misoriented, e.misoriented_example,
           "walked twice in the same direction (triangles not consistently oriented)");
  // Enclosed volume by the divergence theorem, sum of det(a, b, c) / 6: negative when the
  // triangles face inward, which would swap the fluid's side.
  double vol = 0.0;
  for (const auto& t : mesh.triangles)
    vol += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6.0;
  if (!(vol > 0.0))
    throw InputError(file, key,
                     fmt::format("STL '{}' encloses a volume of {:.6g}: its triangles face "
                                 "inward (STL wants them counter-clockwise seen from outside)",
                                 path, vol));
}

}  // namespace curvsph::cad
