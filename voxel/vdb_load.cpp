// Reading a .vdb: checked by a reader process under limits, then read for real.
#include "grotto/error.h"
#include "common/file_kind.h"
#include "common/limited_child.h"
#include "voxel/solid.h"
#include "voxel/vdb_reader_program.h"
#include "voxel/vox_read.h"
#include "voxel/vox_world.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace grotto::voxel {

openvdb::GridBase::Ptr loadGrid(const WorldDesc& desc) {
    const std::string path = desc.gridFile.string();
    // A .vox is read by our own parser, which checks every size before it allocates.
    if (isVoxFile(desc.gridFile)) return voxGrid(readVoxFile(desc.gridFile), desc);
    requireInputFile(desc.gridFile, desc.source != desc.gridFile
                                        ? "named by '" + desc.source.string() + "' field 'grid.file'; give an OpenVDB .vdb file"
                                        : "give the path of an OpenVDB .vdb file");
    // OpenVDB allocates whatever sizes a stream claims before anything can check
    // them, so the file is first read by a reader process under limits
    // (voxel/vdb_reader.cpp): a damaged or hostile file ends there, in a clear
    // error, at a bounded cost.
    // Both reads go through one open descriptor, so a file replaced between
    // them cannot reach the second read unchecked.
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw Error(path, std::string("cannot be opened: ") + std::strerror(errno));
    struct stat st {};
    fstat(fd, &st);
    ChildLimits limits;
    limits.memoryBytes = kReaderMemoryBytes;
    limits.cpuSeconds = 1 + int(std::min<uintmax_t>(uintmax_t(st.st_size) / kReaderBytesPerCpuSecond, 3600));
    try {
        runInLimitedChild(path, limits, vdbReaderProgram(),
                          {path, desc.gridName, std::to_string(desc.memoryBudgetBytes)}, fd);
        openvdb::GridBase::Ptr grid = readGridUnguarded(desc, {}, "/proc/self/fd/" + std::to_string(fd));
        close(fd);
        return grid;
    } catch (...) {
        close(fd);
        throw;
    }
}

}  // namespace grotto::voxel
