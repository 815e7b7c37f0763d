// Fuzzes the world .json reader. Bad input must end in grotto::Error of kind
// Input (the CLI's exit 2); any other exception, crash or sanitizer report is a bug.
#include "grotto/error.h"
#include "fuzz/input_file.h"
#include "voxel/world_desc.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto file = grotto::fuzz::writeInput(data, size, "world.json");
    try {
        (void)grotto::voxel::loadWorldDesc(file);
    } catch (const grotto::Error& e) {
        if (e.kind() != grotto::Error::Kind::Input) throw;
    }
    return 0;
}
