#pragma once
// Shared by the harnesses of fuzz/ (libFuzzer entry point LLVMFuzzerTestOneInput): the
// readers that take a path get the input written to a temporary file. Each harness catches
// the exceptions its reader's contract allows for bad input (InputError: exit 2; the VTP
// reader's std::runtime_error); anything else escapes and the fuzzer reports it, as it does
// crashes, hangs and the sanitizers' findings.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace curvsph::fuzz {

// A temporary file of this process holding the input, named *.ext (readers pick the format
// by extension); rewritten on each call.
inline std::string temp_input(const std::uint8_t* data, std::size_t size, const std::string& ext) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("curvsph-fuzz-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / ("input" + ext);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file.string();
}

}  // namespace curvsph::fuzz
