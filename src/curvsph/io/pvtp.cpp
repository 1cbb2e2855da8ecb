#include "curvsph/io/pvtp.hpp"

#include <fstream>
#include <stdexcept>

namespace curvsph::io {

void write_pvtp(const std::filesystem::path& path, const VtkPolyData& layout,
                const std::vector<std::string>& pieces, const VtkWriteOptions& options) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PPolyData\" version=\"0.1\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
      << "  <PPolyData GhostLevel=\"0\">\n    <PPointData>\n";
  for (const auto& a : layout.arrays())
    out << "      <PDataArray type=\""
        << vtk_type_name(options.float32 && a.type == VtkType::Float64 ? VtkType::Float32 : a.type)
        << "\" Name=\"" << a.name << "\" NumberOfComponents=\"" << a.components << "\"/>\n";
  out << "    </PPointData>\n    <PPoints>\n      <PDataArray type=\""
      << vtk_type_name(layout.points().type) << "\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
  for (const auto& p : pieces) out << "    <Piece Source=\"" << p << "\"/>\n";
  out << "  </PPolyData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace curvsph::io
