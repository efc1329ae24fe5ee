// generated_parts FOLDER FIRST LAST: writes the generated machined part of every seed
// from FIRST to LAST (tests/occ/generated_parts.h) to FOLDER/part_<seed>.brep, and
// names on stdout the seeds whose part OpenCASCADE crashed building. Exit 2 on a bad
// command line.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "generated_parts.h"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: generated_parts FOLDER FIRST LAST\n");
    return 2;
  }
  const std::filesystem::path folder = argv[1];
  char* end = nullptr;
  const long first = std::strtol(argv[2], &end, 10);
  const bool first_ok = *end == '\0';
  const long last = std::strtol(argv[3], &end, 10);
  if (!first_ok || *end != '\0' || first < 0 || last < first || last > 1000000 || !std::filesystem::is_directory(folder)) {
    std::fprintf(stderr, "generated_parts: FOLDER must exist and 0 <= FIRST <= LAST <= 1000000\n");
    return 2;
  }
  for (long seed = first; seed <= last; ++seed) {
    const std::string path = (folder / ("part_" + std::to_string(seed) + ".brep")).string();
    if (!tquad::write_generated_part(static_cast<std::uint32_t>(seed), path)) std::printf("seed %ld: crashed\n", seed);
  }
  return 0;
}
