#pragma once
// The rows of the schema table as written in io/schema_table.cpp (parsed by case_schema.cpp).
namespace curvsph::schema {

// One key: path ("walls.*.radius"), type ("number", "integer", "bool", "string",
// "choice: a | b", "vector" (D numbers), "list", "map"), range ("(0, inf)", "[0, 0.5)", "" for
// any finite value; for vector and list the range of each element), default ("0.1",
// "required", "optional", "derived: how", "-" for a section), unit ("-" for none), meaning.
struct Row {
  const char* path;
  const char* type;
  const char* range;
  const char* fallback;
  const char* unit;
  const char* meaning;
};

// The table and its length.
const Row* rows();
int row_count();

}  // namespace curvsph::schema
