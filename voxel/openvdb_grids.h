// OpenVDB, with the grid and tree classes we use declared as instantiated
// once, in openvdb_grids.cpp: instantiating them in every file that builds or
// writes a grid cost 20-50 s of compile time per file. Include this instead of
// <openvdb/openvdb.h> anywhere that links grotto_voxel.
#pragma once

#include <openvdb/openvdb.h>

#define GROTTO_OPENVDB_INSTANTIATED(TreeT)      \
    extern template class openvdb::Grid<TreeT>; \
    extern template class openvdb::tree::Tree<TreeT::RootNodeType>;

GROTTO_OPENVDB_INSTANTIATED(openvdb::BoolTree)
GROTTO_OPENVDB_INSTANTIATED(openvdb::DoubleTree)
GROTTO_OPENVDB_INSTANTIATED(openvdb::FloatTree)
GROTTO_OPENVDB_INSTANTIATED(openvdb::Int32Tree)
GROTTO_OPENVDB_INSTANTIATED(openvdb::MaskTree)

#undef GROTTO_OPENVDB_INSTANTIATED
