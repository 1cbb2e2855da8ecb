#pragma once
// VTK XML PolyData (.vtp) output for ParaView, binary appended format:
//   <AppendedData encoding="raw">_ [UInt64 byte count][raw little-endian bytes] ...
// One vertex per point (Verts with connectivity/offsets). Points are always written with
// three components (z = 0 in 2-D). VtkPolyData is a small builder: set the points, add
// named scalar / vector / integer arrays, write(path). from_particles() fills it with every
// field of Particles<D> (for_each_field), so a new field appears in the output by itself.
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

  // Every field of `p` as PointData, positions as Points.
  template <int D>
  static VtkPolyData from_particles(const Particles<D>& p);

  std::size_t number_of_points() const { return points_.tuples(); }
  const VtkArray& points() const { return points_; }
  const std::vector<VtkArray>& arrays() const { return arrays_; }
  const VtkArray* find(const std::string& name) const;
  const VtkArray& array(const std::string& name) const;  // throws if absent

  // Writes the .vtp file (creates parent directories). Throws std::runtime_error on I/O errors
  // or inconsistent array sizes.
  void write(const std::filesystem::path& path) const;

  // Internal use by the reader.
  void set_points_array(VtkArray a) { points_ = std::move(a); }

 private:
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

template <int D>
VtkPolyData VtkPolyData::from_particles(const Particles<D>& p) {
  VtkPolyData out;
  out.set_points(p.x);
  p.for_each_field([&](const char* name, const auto& data) {
    if (std::string(name) == "position") return;  // written as Points
    out.add_field(name, data);
  });
  return out;
}

}  // namespace curvsph::io
