#pragma once
// Error types mapped to the exit codes of DESIGN.md §3: bad input → 2, unstable run → 3.
#include <stdexcept>
#include <string>

namespace curvsph {

// Bad input: names the file, the key (dotted path, list elements by index) and the reason.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string key, std::string reason)
      : std::runtime_error(format(file, key, reason)),
        file_(std::move(file)),
        key_(std::move(key)),
        reason_(std::move(reason)) {}
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  const std::string& reason() const { return reason_; }

 private:
  static std::string format(const std::string& file, const std::string& key,
                            const std::string& reason) {
    std::string s = file.empty() ? std::string("input") : file;
    if (!key.empty()) s += ": key '" + key + "'";
    return s + ": " + reason;
  }
  std::string file_, key_, reason_;
};

// A run that went unstable (NaN, density out of range, a particle through a wall).
// `penetration`: particles went through a wall (count of them); `blowup`: NaN or density
// out of range.
class InstabilityError : public std::runtime_error {
 public:
  enum class Kind { blowup, penetration };
  InstabilityError(const std::string& what, long step, long particle, Kind kind = Kind::blowup,
                   long count = 1)
      : std::runtime_error(what), step_(step), particle_(particle), kind_(kind), count_(count) {}
  long step() const { return step_; }
  long particle() const { return particle_; }
  Kind kind() const { return kind_; }
  long count() const { return count_; }

 private:
  long step_;
  long particle_;
  Kind kind_;
  long count_;
};

inline constexpr int kExitInputError = 2;
inline constexpr int kExitInstability = 3;

}  // namespace curvsph
