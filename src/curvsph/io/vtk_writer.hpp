#pragma once
// VTK XML PolyData (.vtp) output for ParaView, binary appended format:
//   <AppendedData encoding="raw">_ [UInt64 byte count][raw little-endian bytes] ...
// or, with VtkWriteOptions::zlib, VTK's vtkZLibDataCompressor layout per array:
//   [UInt64 nblocks][UInt64 block size][UInt64 last block size, 0: full]
//   [UInt64 compressed size of each block] [the zlib streams of the blocks]
// (the layout vtkXMLDataParser reads; every block is compressed on its own). One vertex per
// point (Verts with connectivity/offsets, Int32 below 2^31 points). Points are always written
// with three components (z = 0 in 2-D). VtkPolyData is a small builder: set the points, add
// named scalar / vector / integer arrays, write(path). from_particles() fills it with the
// fields of Particles<D> (for_each_field, all or a chosen list), so a new field appears in the
// output by itself.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "curvsph/core/particles.hpp"
#include "curvsph/core/types.hpp"

namespace curvsph::io {

enum class VtkType { Int8, UInt8, Int32, Int64, Float32, Float64 };

const char* vtk_type_name(VtkType t);
bool vtk_type_is_float(VtkType t);
std::size_t vtk_type_size(VtkType t);
VtkType vtk_type_from_name(const std::string& name);  // throws std::runtime_error if unknown

template <class T>
constexpr VtkType vtk_type_of() {
  if constexpr (std::is_same_v<T, double>)
    return VtkType::Float64;
  else if constexpr (std::is_same_v<T, float>)
    return VtkType::Float32;
  else if constexpr (std::is_same_v<T, std::int32_t>)
    return VtkType::Int32;
  else if constexpr (std::is_same_v<T, std::int64_t>)
    return VtkType::Int64;
  else if constexpr (std::is_same_v<T, std::int8_t>)
    return VtkType::Int8;
  else if constexpr (std::is_same_v<T, std::uint8_t>)
    return VtkType::UInt8;
  else
    static_assert(sizeof(T) == 0, "unsupported VTK element type");
}

// How write() encodes the arrays (the case keys output.precision and output.compress).
struct VtkWriteOptions {
  // Float64 point-data arrays written as Float32 (halves them; 7 significant digits are
  // what a picture or a profile needs). Points keep their own type: positions stay as exact
  // as the run, so that distances to a wall and a restart's neighbour sums are unchanged.
  bool float32 = false;
  // vtkZLibDataCompressor on every array (ParaView and VTK's readers decompress it).
  bool zlib = false;
};

// One named data array: `components` values per point, stored as native bytes.
struct VtkArray {
  std::string name;
  VtkType type = VtkType::Float64;
  int components = 1;
  std::vector<std::byte> bytes;

  std::size_t tuples() const {
    return bytes.size() / (vtk_type_size(type) * static_cast<std::size_t>(components));
  }
  // Copy out as T (must match `type` exactly; throws otherwise).
  template <class T>
  std::vector<T> as() const;
  // Copy out converted to T from any floating type (T floating) or any integer type (T
  // integral); throws for a float array read as integers or the other way round.
  template <class T>
  std::vector<T> converted() const;
};

class VtkPolyData {
 public:
  // Points (3 components; 2-D input gets z = 0). Element type follows the input (Real).
  template <class S, int D>
  void set_points(std::span<const Eigen::Matrix<S, D, 1>> x);
  template <class S, int D>
  void set_points(const std::vector<Eigen::Matrix<S, D, 1>>& x) {
    set_points(std::span<const Eigen::Matrix<S, D, 1>>(x));
  }

  // Point-data arrays; sizes must equal the number of points (checked in write()).
  template <class T>
  void add_scalar(const std::string& name, std::span<const T> values);
  template <class T>
  void add_scalar(const std::string& name, const std::vector<T>& values) {
    add_scalar(name, std::span<const T>(values));
  }
  // Vectors are written with 3 components (z = 0 for D = 2).
  template <class S, int D>
  void add_vector(const std::string& name, std::span<const Eigen::Matrix<S, D, 1>> values);
  template <class S, int D>
  void add_vector(const std::string& name, const std::vector<Eigen::Matrix<S, D, 1>>& values) {
    add_vector(name, std::span<const Eigen::Matrix<S, D, 1>>(values));
  }
  // Any field of a Particles store: Vec<D> -> vector, arithmetic -> scalar.
  template <class T>
  void add_field(const std::string& name, const std::vector<T>& values);
  void add_array(VtkArray array);

  // The fields of `p` named in `fields` (every field when empty) as PointData, positions as
  // Points (always).
  template <int D>
  static VtkPolyData from_particles(const Particles<D>& p,
                                    const std::vector<std::string>& fields = {});

  std::size_t number_of_points() const { return points_.tuples(); }
  const VtkArray& points() const { return points_; }
  const std::vector<VtkArray>& arrays() const { return arrays_; }
  const VtkArray* find(const std::string& name) const;
  const VtkArray& array(const std::string& name) const;  // throws if absent

  // Writes the .vtp file (creates parent directories). Throws std::runtime_error on I/O errors
  // or inconsistent array sizes.
  void write(const std::filesystem::path& path, const VtkWriteOptions& options = {}) const;

  // Internal use by the reader.
  void set_points_array(VtkArray a) { points_ = std::move(a); }

  // Cells instead of one vertex per point (the walls output): polylines (2-D walls) or
  // polygons (3-D walls), cell c made of the points connectivity[offsets[c-1] .. offsets[c])
  // (offsets: the end of each cell, as VTK stores them).
  enum class Cells { verts, lines, polys };
  void set_cells(Cells kind, std::vector<std::int64_t> connectivity,
                 std::vector<std::int64_t> offsets) {
    cells_ = kind;
    cell_connectivity_ = std::move(connectivity);
    cell_offsets_ = std::move(offsets);
  }

 private:
  Cells cells_ = Cells::verts;
  std::vector<std::int64_t> cell_connectivity_, cell_offsets_;
  VtkArray points_{"Points", VtkType::Float64, 3, {}};
  std::vector<VtkArray> arrays_;
};

// Convenience: write every field of `p` to `path`.
template <int D>
void write_vtp(const std::filesystem::path& path, const Particles<D>& p) {
  VtkPolyData::from_particles(p).write(path);
}

// ---------------------------------------------------------------------------------------
// Template implementations.

namespace detail {
template <class T>
void append_bytes(std::vector<std::byte>& out, const T& v) {
  const auto* b = reinterpret_cast<const std::byte*>(&v);
  out.insert(out.end(), b, b + sizeof(T));
}
template <class T>
struct is_eigen_vec : std::false_type {};
template <class S, int D>
struct is_eigen_vec<Eigen::Matrix<S, D, 1>> : std::true_type {};
}  // namespace detail

template <class T>
std::vector<T> VtkArray::as() const {
  if (vtk_type_of<T>() != type)
    throw std::runtime_error("VTK array '" + name + "' has type " + vtk_type_name(type) +
                             ", requested " + vtk_type_name(vtk_type_of<T>()));
  std::vector<T> out(bytes.size() / sizeof(T));
  if (!out.empty()) std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

template <class S, int D>
void VtkPolyData::set_points(std::span<const Eigen::Matrix<S, D, 1>> x) {
  static_assert(D == 2 || D == 3);
  VtkArray a{"Points", vtk_type_of<S>(), 3, {}};
  a.bytes.reserve(x.size() * 3 * sizeof(S));
  for (const auto& p : x) {
    for (int k = 0; k < 3; ++k) detail::append_bytes(a.bytes, k < D ? p[k] : S(0));
  }
  points_ = std::move(a);
}

template <class T>
void VtkPolyData::add_scalar(const std::string& name, std::span<const T> values) {
  VtkArray a{name, vtk_type_of<T>(), 1, {}};
  a.bytes.resize(values.size() * sizeof(T));
  if (!values.empty()) std::memcpy(a.bytes.data(), values.data(), a.bytes.size());
  add_array(std::move(a));
}

template <class S, int D>
void VtkPolyData::add_vector(const std::string& name,
                             std::span<const Eigen::Matrix<S, D, 1>> values) {
  static_assert(D == 2 || D == 3);
  VtkArray a{name, vtk_type_of<S>(), 3, {}};
  a.bytes.reserve(values.size() * 3 * sizeof(S));
  for (const auto& p : values) {
    for (int k = 0; k < 3; ++k) detail::append_bytes(a.bytes, k < D ? p[k] : S(0));
  }
  add_array(std::move(a));
}

template <class T>
void VtkPolyData::add_field(const std::string& name, const std::vector<T>& values) {
  if constexpr (detail::is_eigen_vec<T>::value) {
    add_vector(name, values);
  } else {
    add_scalar(name, values);
  }
}

template <class T>
std::vector<T> VtkArray::converted() const {
  if (vtk_type_of<T>() == type) return as<T>();
  if (std::is_floating_point_v<T> != vtk_type_is_float(type))
    throw std::runtime_error("VTK array '" + name + "' has type " + vtk_type_name(type) +
                             ", not convertible to " + vtk_type_name(vtk_type_of<T>()));
  const std::size_t n = bytes.size() / vtk_type_size(type);
  std::vector<T> out(n);
  auto copy = [&](auto zero) {
    using S = decltype(zero);
    for (std::size_t i = 0; i < n; ++i) {
      S v;
      std::memcpy(&v, bytes.data() + i * sizeof(S), sizeof(S));
      out[i] = static_cast<T>(v);
    }
  };
  switch (type) {
    case VtkType::Int8:
      copy(std::int8_t{});
      break;
    case VtkType::UInt8:
      copy(std::uint8_t{});
      break;
    case VtkType::Int32:
      copy(std::int32_t{});
      break;
    case VtkType::Int64:
      copy(std::int64_t{});
      break;
    case VtkType::Float32:
      copy(float{});
      break;
    case VtkType::Float64:
      copy(double{});
      break;
  }
  return out;
}

template <int D>
VtkPolyData VtkPolyData::from_particles(const Particles<D>& p,
                                        const std::vector<std::string>& fields) {
  VtkPolyData out;
  out.set_points(p.x);
  p.for_each_field([&](const char* name, const auto& data) {
    if (std::string(name) == "position") return;  // written as Points
    if (!fields.empty() && std::find(fields.begin(), fields.end(), name) == fields.end()) return;
    out.add_field(name, data);
  });
  return out;
}

}  // namespace curvsph::io
