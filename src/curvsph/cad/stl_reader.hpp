#pragma once
// STL files (ASCII and binary) read into an indexed triangle mesh, refusing what would
// silently give a wrong wall: a truncated file, a binary file whose triangle count does not
// match its size, non-finite coordinates, and (for a wall that separates an inside from an
// outside) a surface that does not close a volume or is oriented inward.
#include <array>
#include <string>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph::cad {

struct StlMesh {
  std::vector<Vec3d> vertices;                // coordinates as in the file
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
};

// Reads `path`; vertices with bitwise-equal coordinates (after parsing) become one vertex and
// triangles left with a repeated vertex are dropped. Errors: InputError(file, key, reason) with
// the STL's path and the line (ASCII) or triangle (binary) in the reason.
StlMesh read_stl(const std::string& path, const std::string& file, const std::string& key);

// Refuses (InputError) a mesh that is not a closed, consistently oriented, outward surface:
// edges used by one triangle only, by three or more, or twice in the same direction (each with
// its count and one example edge in file coordinates), or a negative enclosed volume.
void require_closed(const StlMesh& mesh, const std::string& path, const std::string& file,
                    const std::string& key);

}  // namespace curvsph::cad
