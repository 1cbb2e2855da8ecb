#include "curvsph/io/vtk_reader.hpp"

#include <zlib.h>

#include <charconv>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>

namespace curvsph::io {

namespace {

std::string xml_unescape(const std::string& s) {
  static const std::pair<const char*, char> table[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    bool done = false;
    if (s[i] == '&') {
      for (const auto& [ent, c] : table) {
        if (s.compare(i, std::char_traits<char>::length(ent), ent) == 0) {
          out += c;
          i += std::char_traits<char>::length(ent);
          done = true;
          break;
        }
      }
    }
    if (!done) out += s[i++];
  }
  return out;
}

// Attributes of one tag body `<Name a="..." b="...">`.
std::map<std::string, std::string> attributes(const std::string& tag) {
  std::map<std::string, std::string> out;
  std::size_t i = 0;
  while (true) {
    const std::size_t eq = tag.find('=', i);
    if (eq == std::string::npos) break;
    std::size_t k = eq;
    while (k > 0 && tag[k - 1] == ' ') --k;
    std::size_t b = k;
    while (b > 0 && tag[b - 1] != ' ' && tag[b - 1] != '\n' && tag[b - 1] != '\t') --b;
    const std::size_t q1 = tag.find('"', eq);
    const std::size_t q2 = q1 == std::string::npos ? q1 : tag.find('"', q1 + 1);
    if (q2 == std::string::npos) break;
    out[tag.substr(b, k - b)] = xml_unescape(tag.substr(q1 + 1, q2 - q1 - 1));
    i = q2 + 1;
  }
  return out;
}

std::uint64_t u64_at(const std::string& file, std::size_t at) {
  std::uint64_t v = 0;
  for (int k = 7; k >= 0; --k)
    v = (v << 8) | static_cast<unsigned char>(file[at + static_cast<std::size_t>(k)]);
  return v;
}

// [UInt64 n][n bytes].
template <class Fail>
std::vector<std::byte> raw_block(const std::string& file, std::size_t at, const Fail& fail) {
  if (at + 8 > file.size()) fail("appended data truncated");
  const std::uint64_t nbytes = u64_at(file, at);
  if (nbytes > file.size() - at - 8) fail("appended data truncated");
  std::vector<std::byte> out(nbytes);
  if (nbytes) std::memcpy(out.data(), file.data() + at + 8, nbytes);
  return out;
}

// vtkZLibDataCompressor: [nblocks][block size][last block size, 0: full][compressed sizes]
// then the zlib streams (vtk_writer.hpp).
template <class Fail>
std::vector<std::byte> inflate_block(const std::string& file, std::size_t at, const Fail& fail) {
  if (at + 24 > file.size()) fail("appended data truncated");
  const std::uint64_t nb = u64_at(file, at), bs = u64_at(file, at + 8),
                      last = u64_at(file, at + 16);
  if (nb > (file.size() - at - 24) / 8) fail("compressed block header truncated");
  std::size_t src = at + 24 + 8 * nb;
  std::vector<std::byte> out;
  for (std::uint64_t b = 0; b < nb; ++b) {
    const std::uint64_t cs = u64_at(file, at + 24 + 8 * b);
    const std::uint64_t us = (b + 1 == nb && last != 0) ? last : bs;
    if (cs > file.size() - src) fail("compressed data truncated");
    // zlib expands at most about 1032:1: a larger block size is a corrupt header, which
    // would otherwise allocate up to 2^64 bytes.
    if (us / 1032 > cs + 64) fail("corrupt zlib block header");
    const std::size_t o = out.size();
    out.resize(o + us);
    uLongf len = static_cast<uLongf>(us);
    if (uncompress(reinterpret_cast<Bytef*>(out.data() + o), &len,
                   reinterpret_cast<const Bytef*>(file.data() + src),
                   static_cast<uLong>(cs)) != Z_OK ||
        len != us)
      fail("corrupt zlib block");
    src += cs;
  }
  return out;
}

// A non-negative integer attribute (fails on a missing, malformed or out-of-range value
// rather than letting std::stoull's exceptions through).
template <class Fail>
std::uint64_t count_attribute(const std::map<std::string, std::string>& attrs,
                              const std::string& key, const Fail& fail) {
  const auto it = attrs.find(key);
  if (it == attrs.end()) fail("missing attribute " + key);
  std::uint64_t v = 0;
  const std::string& text = it->second;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size())
    fail("attribute " + key + " is not a non-negative integer");
  return v;
}

}  // namespace

VtkPolyData read_vtp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open '" + path.string() + "'");
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto fail = [&](const std::string& what) {
    throw std::runtime_error("'" + path.string() + "': " + what);
  };

  const std::size_t appended = file.find("<AppendedData");
  bool zlib = false;
  if (file.find("<VTKFile") == std::string::npos ||
      file.find("type=\"PolyData\"") == std::string::npos)
    fail("not a VTK PolyData file");
  if (appended == std::string::npos)
    fail("no <AppendedData> section (only appended files are read)");
  {
    const std::size_t vtk = file.find("<VTKFile");
    const auto head = attributes(file.substr(vtk, file.find('>', vtk) - vtk));
    if (head.count("header_type") && head.at("header_type") != "UInt64")
      fail("header_type must be UInt64");
    if (head.count("compressor")) {
      if (head.at("compressor") != "vtkZLibDataCompressor")
        fail("compressor '" + head.at("compressor") + "' is not read (vtkZLibDataCompressor is)");
      zlib = true;
    }
    if (head.count("byte_order") && head.at("byte_order") != "LittleEndian")
      fail("byte_order must be LittleEndian");
    const std::size_t a = file.find('>', appended);
    const auto app = attributes(file.substr(appended, a - appended));
    if (!app.count("encoding") || app.at("encoding") != "raw") fail("encoding must be raw");
  }
  const std::size_t underscore = file.find('_', file.find('>', appended));
  if (underscore == std::string::npos) fail("missing '_' marker of the appended data");
  const std::size_t data0 = underscore + 1;

  VtkPolyData out;
  std::size_t n_points = 0;
  {
    const std::size_t piece = file.find("<Piece");
    if (piece == std::string::npos || piece > appended) fail("no <Piece>");
    const auto attrs = attributes(file.substr(piece, file.find('>', piece) - piece));
    n_points = count_attribute(attrs, "NumberOfPoints", fail);
  }

  // Walk the XML part, tracking the enclosing section of each DataArray.
  std::string section;
  for (std::size_t pos = 0; pos < appended;) {
    const std::size_t lt = file.find('<', pos);
    if (lt == std::string::npos || lt >= appended) break;
    const std::size_t gt = file.find('>', lt);
    if (gt == std::string::npos) fail("unterminated tag");
    const std::string tag = file.substr(lt + 1, gt - lt - 1);
    pos = gt + 1;
    for (const char* s : {"PointData", "Points", "Verts", "CellData"}) {
      const std::string name(s);
      if (tag.rfind(name, 0) == 0 && (tag.size() == name.size() || tag[name.size()] == ' ' ||
                                      tag[name.size()] == '/' || tag[name.size()] == '>'))
        section = name;
      if (tag == "/" + name) section.clear();
    }
    if (tag.rfind("DataArray", 0) != 0) continue;
    const auto attrs = attributes(tag);
    if (!attrs.count("format") || attrs.at("format") != "appended")
      fail("DataArray not in appended format");
    VtkArray a;
    a.name = attrs.count("Name") ? attrs.at("Name") : "";
    if (!attrs.count("type")) fail("DataArray without type");
    a.type = vtk_type_from_name(attrs.at("type"));
    const std::uint64_t components =
        attrs.count("NumberOfComponents") ? count_attribute(attrs, "NumberOfComponents", fail) : 1;
    if (components < 1 || components > 64) fail("NumberOfComponents must be 1 to 64");
    a.components = static_cast<int>(components);
    const std::uint64_t offset = count_attribute(attrs, "offset", fail);
    if (offset > file.size() - data0) fail("offset past the end of the appended data");
    a.bytes =
        zlib ? inflate_block(file, data0 + offset, fail) : raw_block(file, data0 + offset, fail);
    if (section == "Points") {
      out.set_points_array(std::move(a));
    } else if (section == "PointData") {
      if (a.tuples() != n_points) fail("array '" + a.name + "' size differs from NumberOfPoints");
      out.add_array(std::move(a));
    }
  }
  if (out.number_of_points() != n_points) fail("Points size differs from NumberOfPoints");
  return out;
}

}  // namespace curvsph::io
