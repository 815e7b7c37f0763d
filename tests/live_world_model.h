#pragma once
// The live-world tests' oracle and worlds: a dense model of material ids edited as
// edit.h says, comparisons of voxels and of edit results, and the small worlds
// the tests edit.
#include "voxel/generators.h"
#include "voxel/solid.h"
#include "voxel/world.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace grotto::voxel::test {

// Material ids over a box, in a dense array, edited the way edit.h says: the
// oracle for what World::apply must change.
struct Model {
    IndexBox box;
    glm::dvec3 origin;
    double voxelSize;
    std::vector<int> ids;

    Model(const World& w, IndexBox b) : box(b), origin(w.origin()), voxelSize(w.voxelSize()) {
        const glm::ivec3 n = b.max - b.min + 1;
        ids.resize(size_t(n.x) * n.y * n.z);
        forEach(b, [&](glm::ivec3 v) { at(v) = w.material(v); });
    }
    int& at(glm::ivec3 v) {
        const glm::ivec3 r = v - box.min, n = box.max - box.min + 1;
        return ids[(size_t(r.x) * n.y + r.y) * n.z + r.z];
    }
    template <typename F>
    static void forEach(const IndexBox& b, F f) {
        for (int x = b.min.x; x <= b.max.x; ++x)
            for (int y = b.min.y; y <= b.max.y; ++y)
                for (int z = b.min.z; z <= b.max.z; ++z) f(glm::ivec3(x, y, z));
    }
    bool inside(const Edit& e, glm::ivec3 v) const {
        if (e.shape == Edit::Shape::Box) return e.box.contains(v);
        const glm::dvec3 d = origin + (glm::dvec3(v) + 0.5) * voxelSize - e.centre;
        return glm::dot(d, d) <= e.radius * e.radius;
    }
    EditResult apply(const Edit& e) {
        IndexBox scan = e.box;
        if (e.shape == Edit::Shape::Sphere) {
            const glm::dvec3 c = (e.centre - origin) / voxelSize;
            const double r = e.radius / voxelSize;
            scan = {glm::ivec3(glm::floor(c - r)) - 1, glm::ivec3(glm::ceil(c + r)) + 1};
        }
        EditResult out;
        forEach(scan, [&](glm::ivec3 v) {
            if (!inside(e, v)) return;
            EXPECT_TRUE(box.contains(v)) << "the test's edit leaves the model's box";
            int& id = at(v);
            const int after = e.op == Edit::Op::Carve ? 0 : e.op == Edit::Op::Fill ? e.material : id ? e.material : 0;
            if (after == id) return;
            id = after;
            out.voxels = out.voxels.merged({v, v});
            ++out.changed;
        });
        if (!out.voxels.empty())
            out.box = {origin + glm::dvec3(out.voxels.min) * voxelSize, origin + glm::dvec3(out.voxels.max + 1) * voxelSize};
        return out;
    }
    IndexBox solidBounds() {
        IndexBox b;
        forEach(box, [&](glm::ivec3 v) {
            if (at(v)) b = b.merged({v, v});
        });
        return b;
    }
};

inline void expectSameVoxels(const World& got, const World& want, const IndexBox& over, const std::string& when) {
    uint64_t wrong = 0;
    Model::forEach(over, [&](glm::ivec3 v) { wrong += got.material(v) != want.material(v); });
    EXPECT_EQ(wrong, 0u) << when;
    EXPECT_EQ(got.bounds().min, want.bounds().min) << when;
    EXPECT_EQ(got.bounds().max, want.bounds().max) << when;
    EXPECT_EQ(got.stats().solidVoxels, want.stats().solidVoxels) << when;
}

inline void expectSameResult(const EditResult& got, const EditResult& want, const std::string& what) {
    EXPECT_EQ(got.changed, want.changed) << what;
    EXPECT_EQ(got.voxels.min, want.voxels.min) << what;
    EXPECT_EQ(got.voxels.max, want.voxels.max) << what;
    EXPECT_EQ(got.box.min, want.box.min) << what;
    EXPECT_EQ(got.box.max, want.box.max) << what;
}

inline WorldDesc paletteDesc() {
    WorldDesc d;
    d.materials = defaultMaterials();
    return d;
}

inline World cavesWorld() {
    openvdb::initialize();
    return makeWorld(generateWorld("caves", {.seed = 5, .size = 40}), paletteDesc());
}

// A bool grid with 8^3 active tiles, one against a chunk border: edits inside
// them must voxelize just the part they change.
inline World thinWorldWithTiles() {
    openvdb::initialize();
    auto grid = openvdb::gridPtrCast<openvdb::BoolGrid>(generateWorld("thin", {.seed = 2, .size = 32}));
    grid->tree().addTile(1, openvdb::Coord(24, 8, 24), true, true);
    grid->tree().addTile(1, openvdb::Coord(-8, 16, 0), true, true);
    return makeWorld(grid, paletteDesc());
}

// A 16^3 world of voxel size 0.5 at (10, 20, 30): a slab of material 1 at y < 4.
inline World slabWorld() {
    std::vector<uint8_t> ids(16 * 16 * 16, 0);
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 16; ++x) ids[(z * 16 + y) * 16 + x] = 1;
    return World::fromDense({16, 16, 16}, ids.data(), 0.5, {10, 20, 30});
}

inline glm::dvec3 centreOf(const World& w, glm::ivec3 v) { return w.origin() + (glm::dvec3(v) + 0.5) * w.voxelSize(); }

}  // namespace grotto::voxel::test
