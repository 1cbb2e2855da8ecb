#pragma once
// Reader for the .vtp files written by VtkPolyData (binary appended, raw or
// vtkZLibDataCompressor blocks, UInt64 headers, little-endian). Not a general VTK reader: it
// understands our own files, which is what round-trip tests and restarts need. Errors (not our
// format, truncated data) throw std::runtime_error naming the file.
#include <filesystem>
#include <string>

#include "curvsph/core/particles.hpp"
#include "curvsph/io/vtk_writer.hpp"

namespace curvsph::io {

VtkPolyData read_vtp(const std::filesystem::path& path);

// Particles<D> back from a file written by write_vtp: every field found by name, converted to
// the field's type (a Float32 file gives Real fields rounded to float); a field absent from
// the file stays zero. Throws if an array has the wrong kind (float for integer) or size.
template <int D>
Particles<D> particles_from_vtk(const VtkPolyData& vtk) {
  Particles<D> p;
  p.resize(vtk.number_of_points());
  auto unpack_vec = [&](const VtkArray& a, auto& data) {
    using V = typename std::decay_t<decltype(data)>::value_type;
    using S = typename V::Scalar;
    if (a.components != 3) throw std::runtime_error("VTK array '" + a.name + "' is not a vector");
    const std::vector<S> flat = a.converted<S>();
    if (flat.size() != 3 * data.size())
      throw std::runtime_error("VTK array '" + a.name + "' has the wrong size");
    for (std::size_t i = 0; i < data.size(); ++i)
      for (int k = 0; k < D; ++k) data[i][k] = flat[3 * i + static_cast<std::size_t>(k)];
  };
  p.for_each_field([&](const char* name, auto& data) {
    using T = typename std::decay_t<decltype(data)>::value_type;
    const VtkArray* a = std::string(name) == "position" ? &vtk.points() : vtk.find(name);
    if (!a) return;
    if constexpr (detail::is_eigen_vec<T>::value) {
      unpack_vec(*a, data);
    } else {
      std::vector<T> v = a->converted<T>();
      if (v.size() != data.size())
        throw std::runtime_error("VTK array '" + a->name + "' has the wrong size");
      data = std::move(v);
    }
  });
  return p;
}
template <int D>
Particles<D> read_particles(const std::filesystem::path& path) {
  return particles_from_vtk<D>(read_vtp(path));
}

}  // namespace curvsph::io
