#pragma once
// `--threads N` of `run` and `validate`: N >= 1 (0, negatives and non-numbers are a parse
// error, exit 2), capped at the processors the process may use with a warning on stderr
// (core/threads.hpp says why).
#include <CLI/CLI.hpp>
#include <charconv>
#include <iostream>
#include <string>

#include "curvsph/core/threads.hpp"

namespace curvsph::app {

inline CLI::Option* add_threads_option(CLI::App& sub, int& threads) {
  const CLI::Validator at_least_one(
      [](std::string& s) -> std::string {
        int v = 0;
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (ec == std::errc() && end == s.data() + s.size() && v >= 1) return "";
        return "must be a whole number >= 1, got '" + s + "'";
      },
      "N >= 1");
  return sub
      .add_option("--threads,-t", threads,
                  "OpenMP threads, at most the processors available (default: all)")
      ->check(at_least_one);
}

// The thread count to run with: `requested` (0: unset, the OpenMP default) capped at the
// processors available, with a warning when capped (from `speak`, rank 0 under MPI).
inline int checked_threads(int requested, bool speak = true) {
  const ThreadCount t = cap_threads(requested);
  if (t.capped && speak)
    std::cerr << "warning: --threads " << requested << " exceeds the " << t.available
              << " processors available; using " << t.threads << "\n";
  return t.threads;
}

}  // namespace curvsph::app
