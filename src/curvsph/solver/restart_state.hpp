#pragma once
// The whole state a run continues from (`run --restart SNAPSHOT.vtp`): a sidecar file
// SNAPSHOT.restart written beside a snapshot, so that a run stopped there and restarted on the
// same thread count equals the straight run bit for bit. The snapshot itself cannot serve:
// it may be float32 (output.precision), may leave fields out (output.fields), and lacks what
// is not a particle field (the step, dt, the transport-velocity push b, the order the next
// re-sort applies, counters, the output schedule, the analyses' series).
//
// Format (all numbers little-endian):
//   "curvsph-restart 1\n"
//   the byte count of the JSON header, in decimal, "\n"
//   the JSON header: scalars (identity of the case, time, step, dt, counters, the output
//     schedule, each analysis' state) and "arrays": [{"name", "type": "f64" | "i64", "count"}]
//   the arrays' values in that order, 8 bytes each (doubles: every bit of Real, float or
//     double, survives).
// JSON numbers are written in their shortest round-trip form, so doubles there are exact too.
#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "curvsph/io/case_file.hpp"

namespace curvsph {

struct RestartState {
  nlohmann::json header = nlohmann::json::object();
  std::map<std::string, std::vector<double>> reals;
  std::map<std::string, std::vector<std::int64_t>> ints;
};

// SNAPSHOT.vtp (or .pvtp) -> SNAPSHOT.restart.
std::filesystem::path restart_state_path(const std::filesystem::path& snapshot);

// Writes atomically (a temporary file renamed), so that a run killed while writing leaves
// the previous sidecar or none, never a truncated one.
void write_restart_state(const std::filesystem::path& file, const RestartState& s);
// Reads bytes written by write_restart_state; anything else (truncated, corrupt, another
// format) throws InputError naming `name` (the file) and the key at fault.
RestartState parse_restart_state(const std::string& bytes, const std::string& name);
RestartState read_restart_state(const std::filesystem::path& file);

// The header's identity of the case: name, dimension, dx and the build's Real.
void stamp_case(RestartState& s, const Case& c);
// Throws InputError (exit 2) naming the sidecar and the key when the state was written by
// another case, dimension, dx or Real.
void check_case(const RestartState& s, const Case& c, const std::string& file);

// Header accessors that throw InputError(file, "restart key", reason) on a missing key or a
// wrong type instead of nlohmann's exceptions.
double header_number(const RestartState& s, const std::string& key, const std::string& file);
std::int64_t header_integer(const RestartState& s, const std::string& key, const std::string& file);
// The array `key` of `count` values (count < 0: any); throws InputError otherwise.
const std::vector<double>& real_array(const RestartState& s, const std::string& key,
                                      std::int64_t count, const std::string& file);
const std::vector<std::int64_t>& int_array(const RestartState& s, const std::string& key,
                                           std::int64_t count, const std::string& file);

}  // namespace curvsph
