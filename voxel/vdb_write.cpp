// Writing a .vdb: atomically, and read back before it replaces the target.
#include "common/atomic_file.h"
#include "common/error.h"
#include "voxel/solid.h"

#include <openvdb/io/File.h>

namespace grotto::voxel {

void writeGridFile(const openvdb::GridBase::ConstPtr& grid, const std::filesystem::path& out) {
    initializeOpenVdb();
    writeAtomically(out, [&](const std::filesystem::path& tmp) {
        try {
            openvdb::io::File file(tmp.string());
            file.write(openvdb::GridCPtrVec{grid});
            file.close();
            // OpenVDB does not check its stream: read the file back before it
            // replaces the target, so a full disk cannot leave a truncated grid.
            openvdb::io::File check(tmp.string());
            check.open(false);
            check.readGrid(grid->getName());
        } catch (const openvdb::Exception& e) {
            throw Error(out.string(), std::string("could not write the grid: ") + e.what(),
                        "check free disk space and permissions");
        }
    });
}

}  // namespace grotto::voxel
