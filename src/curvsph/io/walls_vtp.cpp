#include "curvsph/io/walls_vtp.hpp"

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include "curvsph/boundary/integrals/wall_elements.hpp"

namespace curvsph {

template <int D>
WallMesh<D> tessellate_walls(const std::vector<const Wall<D>*>& walls, double dx,
                             const Eigen::AlignedBox<double, D>& clip) {
  WallMesh<D> mesh;
  for (const Wall<D>* wall : walls) {
    BoundaryElements<D> el;
    try {
      el = elements_from_wall<D>(*wall, dx, clip);
    } catch (const std::invalid_argument&) {
      continue;  // no discretisation of this wall type (or nothing of it in the box)
    }
    // Vertices merged per wall when they agree to 1e-9 dx (the last vertex of a closed curve
    // is its first one computed again: 2 pi against 0).
    std::map<std::array<std::int64_t, D>, std::int64_t> index;
    const double snap = 1e-9 * dx;
    auto vertex = [&](const VecD<D>& v) {
      std::array<std::int64_t, D> key;
      for (int a = 0; a < D; ++a) key[static_cast<std::size_t>(a)] = std::llround(v[a] / snap);
      const auto [it, fresh] = index.emplace(key, static_cast<std::int64_t>(mesh.points.size()));
      if (fresh) {
        mesh.points.push_back(v);
        mesh.velocity.push_back(wall->motion.velocity_at(v));
      }
      return it->second;
    };
    for (std::size_t e = 0; e < el.size(); ++e) {
      const auto& v = el.vertices[e];
      if constexpr (D == 2) {
        // The generators give each curve's elements in order, end to start: one polyline
        // grows while the next element starts where the last one ended.
        const std::int64_t a = vertex(v[0]), b = vertex(v[1]);
        const bool joins = !mesh.offsets.empty() && mesh.connectivity.back() == a &&
                           (e > 0);  // never across walls: index restarts per wall
        if (joins) {
          mesh.connectivity.push_back(b);
          mesh.offsets.back() = static_cast<std::int64_t>(mesh.connectivity.size());
        } else {
          mesh.connectivity.push_back(a);
          mesh.connectivity.push_back(b);
          mesh.offsets.push_back(static_cast<std::int64_t>(mesh.connectivity.size()));
        }
      } else {
        // Polygons of 3 or 4 vertices as triangles (a fan).
        const int count = el.vertex_count[e];
        const std::int64_t a = vertex(v[0]);
        for (int k = 1; k + 1 < count; ++k) {
          mesh.connectivity.push_back(a);
          mesh.connectivity.push_back(vertex(v[static_cast<std::size_t>(k)]));
          mesh.connectivity.push_back(vertex(v[static_cast<std::size_t>(k + 1)]));
          mesh.offsets.push_back(static_cast<std::int64_t>(mesh.connectivity.size()));
        }
      }
    }
  }
  return mesh;
}

template <int D>
io::VtkPolyData wall_polydata(const WallMesh<D>& mesh) {
  io::VtkPolyData poly;
  poly.set_points(mesh.points);
  poly.add_vector("velocity", mesh.velocity);
  poly.set_cells(D == 2 ? io::VtkPolyData::Cells::lines : io::VtkPolyData::Cells::polys,
                 mesh.connectivity, mesh.offsets);
  return poly;
}

template WallMesh<2> tessellate_walls<2>(const std::vector<const Wall<2>*>&, double,
                                         const Eigen::AlignedBox<double, 2>&);
template WallMesh<3> tessellate_walls<3>(const std::vector<const Wall<3>*>&, double,
                                         const Eigen::AlignedBox<double, 3>&);
template io::VtkPolyData wall_polydata<2>(const WallMesh<2>&);
template io::VtkPolyData wall_polydata<3>(const WallMesh<3>&);

}  // namespace curvsph
