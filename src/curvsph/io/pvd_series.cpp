#include "curvsph/io/pvd_series.hpp"

#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace curvsph::io {

PvdSeries::PvdSeries(std::filesystem::path pvd_path) : path_(std::move(pvd_path)) {}

namespace {
std::string escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else if (c == '<')
      out += "&lt;";
    else
      out += c;
  }
  return out;
}
}  // namespace

void PvdSeries::add(double time, const std::filesystem::path& file, int part,
                    const std::string& name) {
  std::filesystem::path rel = file;
  if (file.is_absolute()) {
    const auto dir = std::filesystem::absolute(path_).parent_path();
    const auto r = file.lexically_relative(dir);
    if (!r.empty() && *r.begin() != "..") rel = r;
  }
  entries_.push_back({time, rel.generic_string(), part, name});
  rewrite();
}

void PvdSeries::rewrite() const {
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
  for (const auto& e : entries_) {
    // ParaView's PVD reader names a block after the DataSet's `name` attribute.
    const std::string name = e.name.empty() ? "" : " name=\"" + escaped(e.name) + "\"";
    xml << fmt::format("    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"{}\"{} file=\"{}\"/>\n",
                       e.time, e.part, name, escaped(e.file));
  }
  xml << "  </Collection>\n</VTKFile>\n";

  if (path_.has_parent_path()) std::filesystem::create_directories(path_.parent_path());
  std::filesystem::path tmp = path_;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open '" + tmp.string() + "' for writing");
    out << xml.str();
    out.flush();
    if (!out) throw std::runtime_error("error writing '" + tmp.string() + "'");
  }
  std::filesystem::rename(tmp, path_);  // atomic on POSIX: readers see the old or the new file
}

std::vector<PvdSeries::Entry> PvdSeries::read(const std::filesystem::path& pvd_path) {
  std::ifstream in(pvd_path);
  if (!in) throw std::runtime_error("cannot open '" + pvd_path.string() + "'");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto attr = [](const std::string& tag, const std::string& key) {
    const std::size_t k = tag.find(" " + key + "=\"");
    if (k == std::string::npos) return std::string();
    const std::size_t b = k + key.size() + 3;
    std::string v = tag.substr(b, tag.find('"', b) - b);
    std::string out;
    for (std::size_t i = 0; i < v.size();) {
      if (v.compare(i, 5, "&amp;") == 0)
        out += '&', i += 5;
      else if (v.compare(i, 6, "&quot;") == 0)
        out += '"', i += 6;
      else if (v.compare(i, 4, "&lt;") == 0)
        out += '<', i += 4;
      else
        out += v[i++];
    }
    return out;
  };
  std::vector<Entry> out;
  for (std::size_t pos = text.find("<DataSet"); pos != std::string::npos;
       pos = text.find("<DataSet", pos + 1)) {
    const std::string tag = text.substr(pos, text.find('>', pos) - pos);
    const std::string part = attr(tag, "part");
    out.push_back({std::stod(attr(tag, "timestep")), attr(tag, "file"),
                   part.empty() ? 0 : std::stoi(part), attr(tag, "name")});
  }
  return out;
}

}  // namespace curvsph::io
