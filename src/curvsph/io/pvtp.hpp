#pragma once
// Parallel VTK PolyData (.pvtp): one small XML file naming the pieces that the MPI ranks
// wrote (one .vtp each) and the arrays they share, so ParaView opens a time step of a
// decomposed run as one data set (issue 8).
#include <filesystem>
#include <string>
#include <vector>

#include "curvsph/io/vtk_writer.hpp"

namespace curvsph::io {

// `layout` gives the array names, types and component counts (any one piece);
// `pieces` are file names relative to the .pvtp's directory; `options` those the pieces
// were written with (a Float64 array written as Float32 is declared Float32).
void write_pvtp(const std::filesystem::path& path, const VtkPolyData& layout,
                const std::vector<std::string>& pieces, const VtkWriteOptions& options = {});

}  // namespace curvsph::io
