// The one place our grid and tree classes are instantiated in full: libopenvdb
// holds only the members it uses itself, and voxel/openvdb_grids.h stops every
// other file from instantiating them again. Not the vector grid: only tests
// write one (as bad input), and its 20 s of compile time were in every build.
#include "voxel/openvdb_grids.h"

#define GROTTO_OPENVDB_INSTANTIATE(TreeT) \
    template class openvdb::Grid<TreeT>;  \
    template class openvdb::tree::Tree<TreeT::RootNodeType>;

GROTTO_OPENVDB_INSTANTIATE(openvdb::BoolTree)
GROTTO_OPENVDB_INSTANTIATE(openvdb::DoubleTree)
GROTTO_OPENVDB_INSTANTIATE(openvdb::FloatTree)
GROTTO_OPENVDB_INSTANTIATE(openvdb::Int32Tree)
GROTTO_OPENVDB_INSTANTIATE(openvdb::MaskTree)
