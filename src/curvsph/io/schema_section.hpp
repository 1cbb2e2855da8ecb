#pragma once
// The schema's check of a section whose keys are read by code outside the case reader: the
// parameters of an analysis (`analysis.NAME`) and of an initial flow field (`initial.NAME`),
// which io/case_file.cpp hands over as raw YAML. Their rows in io/schema_table.cpp drive the
// check (issue 34 item 1): unknown keys, a missing required key, the type and the range of
// each value are an InputError naming the file and the key, before the analysis sees them.
#include <yaml-cpp/yaml.h>

#include <string>

namespace curvsph::schema {

// Checks `node` (null: the section without parameters) against the rows under `path`
// ("analysis.throttled_pipe"); nested maps are checked the same way.
void check_section(const YAML::Node& node, const std::string& file, const std::string& path);

}  // namespace curvsph::schema
