// The whole test suite reads input in the schema's strict mode (io/case_schema.hpp): a reader
// that reads a key io/schema_table.cpp does not declare, or defaults otherwise than the table,
// fails the test that exercises it. The environment variable carries the mode to the
// `curvsph` processes the command tests start.
#include <cstdlib>

#include "curvsph/io/case_schema.hpp"

namespace {
const bool kStrictSchema = [] {
  setenv("CURVSPH_STRICT_SCHEMA", "1", 1);
  curvsph::schema::set_strict(true);
  return true;
}();
}  // namespace
