#include "curvsph/io/data_file.hpp"

#include <algorithm>
#include <system_error>

#include "curvsph/core/error.hpp"
#include "curvsph_install_paths.hpp"

namespace curvsph {
namespace fs = std::filesystem;

std::vector<fs::path> data_dirs() {
  std::vector<fs::path> dirs;
  const auto add = [&](const fs::path& d) {
    const fs::path n = d.lexically_normal();
    if (std::find(dirs.begin(), dirs.end(), n) == dirs.end()) dirs.push_back(n);
  };
  // Linux names the running binary in /proc; an install keeps bin/ and share/ side by side
  // whatever its prefix, so this finds the data of a binary installed anywhere.
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) add(exe.parent_path() / ".." / "share" / "curvsph" / "data");
  add(CURVSPH_DATA_DIR);
  return dirs;
}

fs::path resolve_data_file(const std::string& name, const fs::path& case_dir,
                           const std::string& file, const std::string& key) {
  const fs::path p(name);
  std::vector<fs::path> tried;
  if (p.is_absolute()) {
    tried.push_back(p);
  } else {
    tried.push_back(case_dir / p);
    for (const fs::path& d : data_dirs()) tried.push_back((d / p).lexically_normal());
  }
  std::error_code ec;
  for (const fs::path& t : tried)
    if (fs::is_regular_file(t, ec)) return t;
  std::string where;
  for (const fs::path& t : tried) where += (where.empty() ? "" : ", ") + t.string();
  throw InputError(file, key, "file '" + name + "' not found (looked for " + where + ")");
}

}  // namespace curvsph
