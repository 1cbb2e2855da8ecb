#pragma once
// A short fingerprint of a case file's bytes, for studies that cache finished runs: a cached
// result is reused only while the case it came from is unchanged (any key, any comment).
// FNV-1a, 64 bits (Fowler, Noll & Vo): not cryptographic, but stable across platforms and
// runs, which std::hash is not required to be.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace curvsph {

// FNV-1a 64 of the bytes.
std::uint64_t fnv1a64(std::string_view bytes);
// 16 hex digits of fnv1a64 over the file's contents; throws InputError when unreadable.
std::string case_key(const std::filesystem::path& file);

}  // namespace curvsph
