#include "curvsph/io/vtk_writer.hpp"

#include <algorithm>
#include <bit>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace curvsph::io {

const char* vtk_type_name(VtkType t) {
  switch (t) {
    case VtkType::Int8:
      return "Int8";
    case VtkType::UInt8:
      return "UInt8";
    case VtkType::Int32:
      return "Int32";
    case VtkType::Int64:
      return "Int64";
    case VtkType::Float32:
      return "Float32";
    case VtkType::Float64:
      return "Float64";
  }
  return "?";
}

std::size_t vtk_type_size(VtkType t) {
  switch (t) {
    case VtkType::Int8:
    case VtkType::UInt8:
      return 1;
    case VtkType::Int32:
    case VtkType::Float32:
      return 4;
    case VtkType::Int64:
    case VtkType::Float64:
      return 8;
  }
  return 1;
}

VtkType vtk_type_from_name(const std::string& name) {
  for (VtkType t : {VtkType::Int8, VtkType::UInt8, VtkType::Int32, VtkType::Int64, VtkType::Float32,
                    VtkType::Float64}) {
    if (name == vtk_type_name(t)) return t;
  }
  throw std::runtime_error("unsupported VTK data type '" + name + "'");
}

void VtkPolyData::add_array(VtkArray array) {
  auto it = std::find_if(arrays_.begin(), arrays_.end(),
                         [&](const VtkArray& a) { return a.name == array.name; });
  if (it != arrays_.end()) {
    *it = std::move(array);  // same name: replace
  } else {
    arrays_.push_back(std::move(array));
  }
}

const VtkArray* VtkPolyData::find(const std::string& name) const {
  for (const auto& a : arrays_) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

const VtkArray& VtkPolyData::array(const std::string& name) const {
  const VtkArray* a = find(name);
  if (!a) throw std::runtime_error("VTK file has no point array '" + name + "'");
  return *a;
}

namespace {

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Appends one block (UInt64 byte count + data) to the appended section, little-endian.
void append_block(std::string& blob, const std::vector<std::byte>& bytes, std::size_t word) {
  std::uint64_t n = bytes.size();
  std::vector<std::byte> header(sizeof(n));
  std::memcpy(header.data(), &n, sizeof(n));
  if constexpr (std::endian::native == std::endian::big) {
    std::reverse(header.begin(), header.end());
  }
  blob.append(reinterpret_cast<const char*>(header.data()), header.size());
  const std::size_t start = blob.size();
  blob.append(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if constexpr (std::endian::native == std::endian::big) {
    for (std::size_t i = start; i + word <= blob.size(); i += word)
      std::reverse(blob.begin() + static_cast<std::ptrdiff_t>(i),
                   blob.begin() + static_cast<std::ptrdiff_t>(i + word));
  } else {
    (void)word;
    (void)start;
  }
}

void data_array_tag(std::ostringstream& xml, const VtkArray& a, std::size_t offset,
                    const char* indent) {
  xml << indent << "<DataArray type=\"" << vtk_type_name(a.type) << "\" Name=\""
      << xml_escape(a.name) << "\"";
  if (a.components != 1) xml << " NumberOfComponents=\"" << a.components << "\"";
  xml << " format=\"appended\" offset=\"" << offset << "\"/>\n";
}

}  // namespace

void VtkPolyData::write(const std::filesystem::path& path) const {
  const std::size_t n = number_of_points();
  if (points_.bytes.size() != n * 3 * vtk_type_size(points_.type))
    throw std::runtime_error("VTK points array is not a whole number of 3-component tuples");
  for (const auto& a : arrays_) {
    if (a.components < 1 || a.bytes.size() != n * a.components * vtk_type_size(a.type))
      throw std::runtime_error("VTK array '" + a.name + "' has " + std::to_string(a.tuples()) +
                               " tuples, expected " + std::to_string(n));
  }

  // Verts: one vertex per point.
  VtkArray connectivity{"connectivity", VtkType::Int64, 1, {}};
  VtkArray offsets{"offsets", VtkType::Int64, 1, {}};
  connectivity.bytes.resize(n * sizeof(std::int64_t));
  offsets.bytes.resize(n * sizeof(std::int64_t));
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t c = static_cast<std::int64_t>(i), o = c + 1;
    std::memcpy(connectivity.bytes.data() + i * 8, &c, 8);
    std::memcpy(offsets.bytes.data() + i * 8, &o, 8);
  }

  std::string blob;
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
      << "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
      << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
  auto emit = [&](const VtkArray& a, const char* indent) {
    data_array_tag(xml, a, blob.size(), indent);
    append_block(blob, a.bytes, vtk_type_size(a.type));
  };
  xml << "      <PointData>\n";
  for (const auto& a : arrays_) emit(a, "        ");
  xml << "      </PointData>\n      <Points>\n";
  emit(points_, "        ");
  xml << "      </Points>\n      <Verts>\n";
  emit(connectivity, "        ");
  emit(offsets, "        ");
  xml << "      </Verts>\n    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";

  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot open '" + path.string() + "' for writing");
  const std::string head = xml.str();
  out.write(head.data(), static_cast<std::streamsize>(head.size()));
  out.write(blob.data(), static_cast<std::streamsize>(blob.size()));
  out << "\n  </AppendedData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error("error writing '" + path.string() + "'");
}

}  // namespace curvsph::io
