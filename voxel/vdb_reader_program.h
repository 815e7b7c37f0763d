#pragma once
// The reader process's executable (voxel/vdb_reader.cpp), built into the library
// as bytes so that an installed or embedded renderer needs no file beside it.
#include <span>

namespace grotto::voxel {

std::span<const unsigned char> vdbReaderProgram();

}  // namespace grotto::voxel
