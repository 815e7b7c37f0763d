// Fuzzes .vox reading the whole way a world is made of one: parse, the palette
// as materials, and the int32 grid of placed voxels (budget lowered below
// libFuzzer's -malloc_limit_mb). Bad input must end in grotto::Error of kind
// Input; any other exception, crash or sanitizer report is a bug.
#include "grotto/error.h"
#include "fuzz/input_file.h"
#include "voxel/solid.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto file = grotto::fuzz::writeInput(data, size, "model.vox");
    try {
        grotto::voxel::WorldDesc desc = grotto::voxel::loadWorldDesc(file);
        desc.memoryBudgetBytes = size_t(128) << 20;
        (void)grotto::voxel::makeWorld(grotto::voxel::loadGrid(desc), desc);
    } catch (const grotto::Error& e) {
        if (e.kind() != grotto::Error::Kind::Input) throw;
    }
    return 0;
}
