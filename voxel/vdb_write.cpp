// Writing a .vdb atomically, every write checked.
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "voxel/solid.h"

#include <openvdb/io/Archive.h>

namespace grotto::voxel {
namespace {

// io::File writes the same archive through a stream it never checks, so a full
// disk would leave a truncated grid; this one writes through writeAtomically's.
class CheckedArchive : public openvdb::io::Archive {
public:
    void writeTo(std::ostream& out, const openvdb::GridCPtrVec& grids) const { write(out, grids, /*seekable=*/true); }
};

}  // namespace

void writeGridFile(const openvdb::GridBase::ConstPtr& grid, const std::filesystem::path& out) {
    initializeOpenVdb();
    writeAtomically(out, [&](std::ostream& stream) {
        try {
            CheckedArchive().writeTo(stream, openvdb::GridCPtrVec{grid});
        } catch (const openvdb::Exception& e) {
            throw Error::internal(out.string(), std::string("could not write the grid: ") + e.what());
        }
    });
}

}  // namespace grotto::voxel
