// Fuzzes .vdb loading: open, read the grid, apply the solid rule. Bad input must
// end in grotto::Error of kind Input; any other exception, crash or sanitizer
// report is a bug. The memory budget is lowered below libFuzzer's -malloc_limit_mb,
// so a grid the loader should refuse by its estimate is not reported as a leak of memory.
#include "common/error.h"
#include "fuzz/input_file.h"
#include "voxel/solid.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto file = grotto::fuzz::writeInput(data, size, "grid.vdb");
    try {
        grotto::voxel::WorldDesc desc = grotto::voxel::loadWorldDesc(file);
        desc.memoryBudgetBytes = size_t(128) << 20;
        // The parse under test (the one call to change when the loader's entry point does).
        const openvdb::GridBase::Ptr grid = grotto::voxel::loadGrid(desc);
        (void)grotto::voxel::makeWorld(grid, desc);
    } catch (const grotto::Error& e) {
        if (e.kind() != grotto::Error::Kind::Input) throw;
    }
    return 0;
}
