// grotto-vdb-reader: the reader process loadGrid starts (voxel/vdb_load.cpp),
// carried inside the library. It reads one grid from the .vdb open on descriptor
// 3 under the limits it is given (common/limited_child.h), so a damaged or
// hostile file ends here. Arguments after the limits: FILE (the name errors
// give), GRID (empty: the first) and the world's memory budget in bytes.
#include "grotto/error.h"
#include "common/limited_child.h"
#include "voxel/vdb_read.h"

int main(int argc, char** argv) {
    grotto::serveAsLimitedChild(argc, argv, [](const std::vector<std::string>& args) {
        if (args.size() != 3) throw grotto::Error::internal("grotto-vdb-reader", "expected FILE GRID BUDGET_BYTES");
        grotto::voxel::WorldDesc desc;
        desc.gridFile = args[0];
        desc.gridName = args[1];
        desc.memoryBudgetBytes = std::stoull(args[2]);
        // A grid whose metadata states its size (OpenVDB writes it) may use that,
        // within the world's budget, plus room for the reader's own buffers.
        grotto::voxel::readGridUnguarded(
            desc,
            [](size_t estimate) { grotto::allowChildMemory(estimate + estimate / 2 + grotto::voxel::kReaderMemoryBytes); },
            "/proc/self/fd/3");
    });
}
