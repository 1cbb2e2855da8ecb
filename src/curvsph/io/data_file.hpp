#pragma once
// Data files named in a case (a CAD part, an experiment record): where a relative name is
// looked for, so that a case runs from any directory, in the checkout or installed.
#include <filesystem>
#include <string>
#include <vector>

namespace curvsph {

// The installed data directories, in the order they are searched: <binary's directory>/
// ../share/curvsph/data (an install moved or made with `cmake --install --prefix`), then the
// directory compiled in as CURVSPH_DATA_DIR (<install prefix>/share/curvsph/data). Duplicates
// are dropped; directories need not exist.
std::vector<std::filesystem::path> data_dirs();

// The file `name` names: an absolute name as it is; a relative one beside the case file
// (`case_dir`, the case file's directory), else in each of data_dirs(). The first that exists
// is returned; none: InputError (exit 2) naming `file`, `key` and every place looked in.
std::filesystem::path resolve_data_file(const std::string& name,
                                        const std::filesystem::path& case_dir,
                                        const std::string& file, const std::string& key);

}  // namespace curvsph
