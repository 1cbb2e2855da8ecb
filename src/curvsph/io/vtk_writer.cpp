#include "curvsph/io/vtk_writer.hpp"

#include <zlib.h>

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

bool vtk_type_is_float(VtkType t) {
  return t == VtkType::Float32 || t == VtkType::Float64;
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

// Little-endian copy of an array's bytes (words of `word` bytes).
std::vector<std::byte> little_endian(const std::vector<std::byte>& bytes, std::size_t word) {
  std::vector<std::byte> out = bytes;
  if constexpr (std::endian::native == std::endian::big) {
    for (std::size_t i = 0; i + word <= out.size(); i += word)
      std::reverse(out.begin() + static_cast<std::ptrdiff_t>(i),
                   out.begin() + static_cast<std::ptrdiff_t>(i + word));
  } else {
    (void)word;
  }
  return out;
}

void append_u64(std::string& blob, std::uint64_t v) {
  for (int k = 0; k < 8; ++k) blob.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

// vtkZLibDataCompressor splits an array into blocks of this many uncompressed bytes (VTK's
// own default) and compresses each on its own, so the blocks are compressed in parallel.
constexpr std::size_t kZlibBlock = 32768;
// zlib level 1: on the 10^5-particle snapshots of README (Outputs) the float32 data
// compress to within 0.2 % of level 6's size in a third to a half of its time.
constexpr int kZlibLevel = 1;

// Appends one array: [UInt64 n][n bytes] raw, or the compressed layout of the file header.
void append_block(std::string& blob, const std::vector<std::byte>& le, bool zlib) {
  if (!zlib) {
    append_u64(blob, le.size());
    blob.append(reinterpret_cast<const char*>(le.data()), le.size());
    return;
  }
  const std::size_t nb = (le.size() + kZlibBlock - 1) / kZlibBlock;
  std::vector<std::vector<unsigned char>> out(nb);
  bool ok = true;
#pragma omp parallel for schedule(dynamic) reduction(&& : ok)
  for (std::ptrdiff_t b = 0; b < static_cast<std::ptrdiff_t>(nb); ++b) {
    const std::size_t begin = static_cast<std::size_t>(b) * kZlibBlock;
    const std::size_t len = std::min(kZlibBlock, le.size() - begin);
    auto& o = out[static_cast<std::size_t>(b)];
    uLongf dest = compressBound(static_cast<uLong>(len));
    o.resize(dest);
    ok = ok && compress2(o.data(), &dest, reinterpret_cast<const Bytef*>(le.data() + begin),
                         static_cast<uLong>(len), kZlibLevel) == Z_OK;
    o.resize(dest);
  }
  if (!ok) throw std::runtime_error("zlib compression failed");
  append_u64(blob, nb);
  append_u64(blob, kZlibBlock);
  append_u64(blob, le.size() % kZlibBlock);  // 0: the last block is full
  for (const auto& o : out) append_u64(blob, o.size());
  for (const auto& o : out) blob.append(reinterpret_cast<const char*>(o.data()), o.size());
}

// The array as written: Float64 narrowed to Float32 when asked.
VtkArray narrowed(const VtkArray& a) {
  if (a.type != VtkType::Float64) return a;
  VtkArray out{a.name, VtkType::Float32, a.components, {}};
  const std::size_t n = a.bytes.size() / 8;
  out.bytes.resize(n * 4);
  for (std::size_t i = 0; i < n; ++i) {
    double d;
    std::memcpy(&d, a.bytes.data() + 8 * i, 8);
    const float f = static_cast<float>(d);
    std::memcpy(out.bytes.data() + 4 * i, &f, 4);
  }
  return out;
}

void data_array_tag(std::ostringstream& xml, const VtkArray& a, std::size_t offset,
                    const char* indent) {
  xml << indent << "<DataArray type=\"" << vtk_type_name(a.type) << "\" Name=\""
      << xml_escape(a.name) << "\"";
  if (a.components != 1) xml << " NumberOfComponents=\"" << a.components << "\"";
  xml << " format=\"appended\" offset=\"" << offset << "\"/>\n";
}

}  // namespace

void VtkPolyData::write(const std::filesystem::path& path, const VtkWriteOptions& options) const {
  const std::size_t n = number_of_points();
  if (points_.bytes.size() != n * 3 * vtk_type_size(points_.type))
    throw std::runtime_error("VTK points array is not a whole number of 3-component tuples");
  for (const auto& a : arrays_) {
    if (a.components < 1 || a.bytes.size() != n * a.components * vtk_type_size(a.type))
      throw std::runtime_error("VTK array '" + a.name + "' has " + std::to_string(a.tuples()) +
                               " tuples, expected " + std::to_string(n));
  }

  // Verts: one vertex per point; Int32 indices while they fit (8 bytes per point less).
  const bool wide = n >= (std::size_t(1) << 31) - 1;
  const VtkType index_type = wide ? VtkType::Int64 : VtkType::Int32;
  VtkArray connectivity{"connectivity", index_type, 1, {}};
  VtkArray offsets{"offsets", index_type, 1, {}};
  auto fill = [&](auto zero) {
    using I = decltype(zero);
    if (cells_ != Cells::verts) {  // the cells given (set_cells)
      auto put = [](VtkArray& a, const std::vector<std::int64_t>& v) {
        a.bytes.resize(v.size() * sizeof(I));
        for (std::size_t i = 0; i < v.size(); ++i) {
          const I c = static_cast<I>(v[i]);
          std::memcpy(a.bytes.data() + i * sizeof(I), &c, sizeof(I));
        }
      };
      put(connectivity, cell_connectivity_);
      put(offsets, cell_offsets_);
      return;
    }
    connectivity.bytes.resize(n * sizeof(I));
    offsets.bytes.resize(n * sizeof(I));
    for (std::size_t i = 0; i < n; ++i) {
      const I c = static_cast<I>(i), o = static_cast<I>(c + 1);
      std::memcpy(connectivity.bytes.data() + i * sizeof(I), &c, sizeof(I));
      std::memcpy(offsets.bytes.data() + i * sizeof(I), &o, sizeof(I));
    }
  };
  if (wide)
    fill(std::int64_t{});
  else
    fill(std::int32_t{});

  std::string blob;
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\""
      << (options.zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") << ">\n"
      << "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\""
      << (cells_ == Cells::verts ? n : 0) << "\" NumberOfLines=\""
      << (cells_ == Cells::lines ? cell_offsets_.size() : 0) << "\" NumberOfStrips=\"0\" "
      << "NumberOfPolys=\"" << (cells_ == Cells::polys ? cell_offsets_.size() : 0) << "\">\n";
  const char* section = cells_ == Cells::lines   ? "Lines"
                        : cells_ == Cells::polys ? "Polys"
                                                 : "Verts";
  auto emit = [&](const VtkArray& a, const char* indent) {
    data_array_tag(xml, a, blob.size(), indent);
    append_block(blob, little_endian(a.bytes, vtk_type_size(a.type)), options.zlib);
  };
  xml << "      <PointData>\n";
  for (const auto& a : arrays_) emit(options.float32 ? narrowed(a) : a, "        ");
  xml << "      </PointData>\n      <Points>\n";
  emit(points_, "        ");
  xml << "      </Points>\n      <" << section << ">\n";
  emit(connectivity, "        ");
  emit(offsets, "        ");
  xml << "      </" << section
      << ">\n    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";

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
