// Fuzzes .vdb reading: open, read the grid, apply the solid rule. Bad input must
// end in grotto::Error of kind Input; any other exception, crash or sanitizer
// report is a bug. The memory budget is lowered below libFuzzer's -malloc_limit_mb,
// so a grid refused by its stated size is refused before that limit trips.
#include "grotto/error.h"
#include "fuzz/input_file.h"
#include "voxel/solid.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto file = grotto::fuzz::writeInput(data, size, "grid.vdb");
    try {
        grotto::voxel::WorldDesc desc = grotto::voxel::loadWorldDesc(file);
        desc.memoryBudgetBytes = size_t(128) << 20;
        // The in-process parse (loadGrid runs it in a limited child first, which
        // would hide a finding here behind a clean refusal).
        const openvdb::GridBase::Ptr grid = grotto::voxel::readGridUnguarded(desc);
        (void)grotto::voxel::makeWorld(grid, desc);
    } catch (const grotto::Error& e) {
        if (e.kind() != grotto::Error::Kind::Input) throw;
    }
    return 0;
}
