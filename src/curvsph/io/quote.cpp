#include "curvsph/io/quote.hpp"

#include <fmt/format.h>

namespace curvsph {

std::string clip(std::string_view text) {
  std::string out;
  std::size_t shown = 0;
  for (const char ch : text) {
    if (shown >= kMaxQuoted) break;
    const auto b = static_cast<unsigned char>(ch);
    // A backslash is escaped too, so that "\x41" in the input cannot read as an escape.
    if (b < 0x20 || b >= 0x7f || b == '\\')
      out += fmt::format("\\x{:02x}", b);
    else
      out += ch;
    ++shown;
  }
  if (shown < text.size()) out += fmt::format("... ({} bytes)", text.size());
  return out;
}

std::string quote(std::string_view text) {
  // Appended rather than "'" + clip(text): GCC 12 warns (-Wrestrict) on that operator+.
  std::string out(1, '\'');
  out += clip(text);
  out += '\'';
  return out;
}

}  // namespace curvsph
