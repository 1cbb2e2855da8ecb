#pragma once
// Point lists for the query commands (`geometry`, `shepard`): a CSV file with the header
// `x,y` (2-D) or `x,y,z` (3-D) and one point per line. Blank lines are skipped; anything
// else that is not D finite numbers is an InputError naming the file and the line.
#include <string>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph {

template <int D>
std::vector<VecD<D>> read_points_csv(const std::string& file);

// Same, from text already in memory (`file` is only used in messages).
template <int D>
std::vector<VecD<D>> parse_points_csv(const std::string& text, const std::string& file);

}  // namespace curvsph
