#pragma once
// ParaView collection (.pvd) of a time series. After every add() the whole file is rewritten
// (to a temporary name, then renamed), so a run killed midway still leaves a valid series
// listing every output written so far.
#include <filesystem>
#include <string>
#include <vector>

namespace curvsph::io {

class PvdSeries {
 public:
  struct Entry {
    double time;
    std::string file;  // relative to the .pvd's directory when under it
    int part;
    std::string name;  // the block's name in ParaView ("particles", "boundary"); may be empty
  };

  explicit PvdSeries(std::filesystem::path pvd_path);

  // Registers `file` (absolute, or relative to the .pvd's directory) at `time` and rewrites
  // the .pvd. `part` distinguishes several blocks at one time (fluid, walls, ...); `name`
  // (the DataSet's name attribute) is what ParaView lists the block as.
  void add(double time, const std::filesystem::path& file, int part = 0,
           const std::string& name = "");

  const std::vector<Entry>& entries() const { return entries_; }
  const std::filesystem::path& path() const { return path_; }

  // Reads the (time, file, part, name) entries of a .pvd written by this class.
  static std::vector<Entry> read(const std::filesystem::path& pvd_path);

 private:
  void rewrite() const;
  std::filesystem::path path_;
  std::vector<Entry> entries_;
};

}  // namespace curvsph::io
