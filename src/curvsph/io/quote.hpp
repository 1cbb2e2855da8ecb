#pragma once
// Input echoed in messages (a YAML value, a CSV cell, a file's text): at most 80 characters
// and every byte outside printable ASCII written as \xNN, so that a 10 MB cell or raw binary
// never floods or garbles the terminal (issue 34). Every message that quotes input uses these.
#include <string>
#include <string_view>

namespace curvsph {

inline constexpr std::size_t kMaxQuoted = 80;

// `text` clipped to kMaxQuoted characters (then "... (N bytes)") with non-printables escaped.
std::string clip(std::string_view text);
// clip(text) in single quotes.
std::string quote(std::string_view text);

}  // namespace curvsph
