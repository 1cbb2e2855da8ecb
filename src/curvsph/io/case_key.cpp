#include "curvsph/io/case_key.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "curvsph/core/error.hpp"

namespace curvsph {

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // offset basis
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;  // FNV prime
  }
  return h;
}

std::string case_key(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "", "cannot read the case file");
  std::ostringstream s;
  s << in.rdbuf();
  return fmt::format("{:016x}", fnv1a64(s.str()));
}

}  // namespace curvsph
