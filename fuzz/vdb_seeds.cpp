// Writes small .vdb seeds for fuzz_vdb: every generated kind at the smallest size,
// so the fuzzer mutates kilobytes of each grid type rather than the shipped megabytes.
//   fuzz_vdb_seeds DIR
#include "voxel/mkworld.h"

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) return std::fprintf(stderr, "usage: fuzz_vdb_seeds DIR\n"), 2;
    for (const std::string& kind : grotto::voxel::worldKinds())
        if (kind != "mesh")  // needs a mesh file
            grotto::voxel::makeWorldFile(kind, {.size = 8}, std::filesystem::path(argv[1]) / (kind + "-8.vdb"));
    return 0;
}
