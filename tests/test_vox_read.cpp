// The MagicaVoxel .vox reader (voxel/vox_read.h) on files written by
// tests/vox_writer.h: what it reads, where voxels land, and files from anywhere.
#include "voxel/vox_read.h"

#include "grotto/error.h"
#include "tests/vox_writer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace grotto::voxel {
namespace {

using test::VoxDict;
using test::VoxWriter;
using Voxels = std::vector<std::array<uint8_t, 4>>;
namespace fs = std::filesystem;

const std::string kFile = "scenes/hostile.vox";

VoxScene parse(const std::vector<uint8_t>& bytes) { return parseVox(bytes, kFile); }

// The message of the grotto::Error parsing `bytes` throws; a failure unless it names the file.
std::string refusal(const std::vector<uint8_t>& bytes) {
    try {
        parse(bytes);
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(kFile), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        return what;
    }
    ADD_FAILURE() << "parsed";
    return {};
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A matrix from its rows (glm stores columns).
glm::imat3 rows(glm::ivec3 r0, glm::ivec3 r1, glm::ivec3 r2) {
    glm::imat3 m;
    for (int c = 0; c < 3; ++c) m[c] = glm::ivec3(r0[c], r1[c], r2[c]);
    return m;
}
const glm::imat3 kTurnZ = rows({0, -1, 0}, {1, 0, 0}, {0, 0, 1});  // 90 degrees about z: x' = -y, y' = x
const glm::imat3 kMirrorX = rows({-1, 0, 0}, {0, 1, 0}, {0, 0, 1});
const uint8_t kTurnZByte = test::voxRotationByte(kTurnZ);
const uint8_t kMirrorXByte = test::voxRotationByte(kMirrorX);

// Root transform 0 and its group 1 holding `children`, as MagicaVoxel writes a scene.
VoxWriter& sceneRoot(VoxWriter& w, const std::vector<int32_t>& children) {
    return w.transform(0, 1, glm::ivec3(0), VoxWriter::kIdentity, -1).group(1, children);
}

glm::ivec3 placed(const VoxScene& s, size_t instance, std::array<uint8_t, 4> voxel) {
    return placeVoxel(s, s.instances.at(instance), voxel);
}

TEST(VoxRead, OneModelRoundTrip) {
    std::array<VoxColor, 256> entries;
    for (int i = 0; i < 256; ++i) entries[i] = {uint8_t(i), uint8_t(255 - i), uint8_t(i * 7), uint8_t(100 + i / 4)};
    const Voxels voxels = {{0, 0, 0, 1}, {2, 1, 3, 7}, {1, 0, 2, 255}};
    Voxels written = voxels;
    written.push_back({1, 1, 1, 0});  // colour index 0: skipped
    const VoxScene s = parse(VoxWriter(150).model({3, 2, 4}, written).palette(entries).bytes());
    EXPECT_EQ(s.version, 150u);
    ASSERT_EQ(s.models.size(), 1u);
    EXPECT_EQ(s.models[0].size, glm::ivec3(3, 2, 4));
    EXPECT_EQ(s.models[0].voxels, voxels);
    EXPECT_TRUE(s.hasPalette);
    // RGBA entry i is colour index i + 1; the 256th entry has no index.
    EXPECT_EQ(s.palette[1], entries[0]);
    EXPECT_EQ(s.palette[7], entries[6]);
    EXPECT_EQ(s.palette[255], entries[254]);
    EXPECT_EQ(s.palette[0], VoxColor{});
    ASSERT_EQ(s.instances.size(), 1u);  // no scene graph: the model at the origin
    EXPECT_EQ(s.instances[0].model, 0u);
    EXPECT_EQ(s.instances[0].rotation, glm::imat3(1));
    EXPECT_EQ(s.instances[0].translation, glm::ivec3(0));
    EXPECT_EQ(s.placedVoxels(), 3u);
    EXPECT_FALSE(s.materials[1].present);
}

TEST(VoxRead, NoPaletteChunkIsMagicaVoxelsDefault) {
    const VoxScene s = parse(VoxWriter().model({1, 1, 1}, {{0, 0, 0, 1}}).bytes());
    EXPECT_FALSE(s.hasPalette);
    // MagicaVoxel-file-format-vox.txt, section 8: 0xffffffff, 0xffccffff, 0xff0000ee, 0xff111111 (0xAABBGGRR).
    EXPECT_EQ(s.palette[1], (VoxColor{255, 255, 255, 255}));
    EXPECT_EQ(s.palette[2], (VoxColor{255, 255, 204, 255}));
    EXPECT_EQ(s.palette[216], (VoxColor{238, 0, 0, 255}));
    EXPECT_EQ(s.palette[255], (VoxColor{17, 17, 17, 255}));
}

TEST(VoxRead, RotationByteAsTheSpecWritesIt) {
    // The extension spec's example: rows (0 1 0), (0 0 -1), (-1 0 0) are byte 1 | 2 << 2 | 1 << 5 | 1 << 6.
    EXPECT_EQ(voxRotation(1 | 2 << 2 | 1 << 5 | 1 << 6), rows({0, 1, 0}, {0, 0, -1}, {-1, 0, 0}));
    EXPECT_EQ(voxRotation(VoxWriter::kIdentity), glm::imat3(1));
    int valid = 0;
    for (int byte = 0; byte < 128; ++byte)
        if (const auto m = voxRotation(byte)) {
            ++valid;
            EXPECT_EQ(test::voxRotationByte(*m), byte);
        }
    EXPECT_EQ(valid, 48);  // 6 permutations x 8 signs
    EXPECT_FALSE(voxRotation(0));    // both rows in column 0
    EXPECT_FALSE(voxRotation(3));    // column 3
    EXPECT_FALSE(voxRotation(128));  // beyond the 7 bits
}

// Expected cells worked out by hand: MagicaVoxel turns a voxel's cell about the
// grid point floor(size / 2) of its model and adds the translation, cell =
// floor(R (v + 1/2 - pivot)) + t; Grotto's cell is then (x, z, -y - 1).
TEST(VoxRead, VoxelsLandWhereMagicaVoxelPutsThem) {
    VoxWriter w;
    w.model({3, 3, 1}, {{2, 0, 0, 1}, {1, 1, 0, 2}})                // odd: pivot (1, 1, 0)
        .model({4, 2, 2}, {{0, 0, 0, 3}, {3, 1, 1, 4}})             // even: pivot (2, 1, 1)
        .model({1, 1, 3}, {{0, 0, 0, 5}, {0, 0, 1, 6}, {0, 0, 2, 7}})  // a column along MagicaVoxel's z
        .model({1, 1, 3}, {{0, 0, 0, 5}, {0, 0, 2, 7}});
    sceneRoot(w, {2, 4, 6, 8})
        .transform(2, 3, {10, 0, 0}, kTurnZByte).shape(3, 0)
        .transform(4, 5, {0, 5, 0}, kMirrorXByte).shape(5, 1)
        .transform(6, 7, {-7, 3, 20}).shape(7, 2)
        .transform(8, 9, {0, 0, 0}, kTurnZByte).shape(9, 3);
    const VoxScene s = parse(w.bytes());
    ASSERT_EQ(s.instances.size(), 4u);
    EXPECT_EQ(s.instances[0].rotation, kTurnZ);
    EXPECT_EQ(s.instances[0].translation, glm::ivec3(10, 0, 0));
    EXPECT_EQ(s.instances[1].rotation, kMirrorX);

    // Odd size, turned: (2,0,0) - pivot = (1,-1,0), centre (1.5,-0.5,0.5) -> (0.5,1.5,0.5): cell
    // (0,1,0) + t = (10,1,0). The middle voxel's centre (0.5,0.5,0.5) -> (-0.5,0.5,0.5): cell (9,0,0).
    EXPECT_EQ(placed(s, 0, {2, 0, 0, 1}), glm::ivec3(10, 0, -2));
    EXPECT_EQ(placed(s, 0, {1, 1, 0, 2}), glm::ivec3(9, 0, -1));
    // Even size, mirrored: (0,0,0) -> centre (-1.5,-0.5,-0.5) -> (1.5,-0.5,-0.5): cell (1,-1,-1) + t
    // = (1,4,-1); (3,1,1) -> (1.5,0.5,0.5) -> (-1.5,0.5,0.5): cell (-2,0,0) + t = (-2,5,0).
    EXPECT_EQ(placed(s, 1, {0, 0, 0, 3}), glm::ivec3(1, -1, -5));
    EXPECT_EQ(placed(s, 1, {3, 1, 1, 4}), glm::ivec3(-2, 0, -6));
    // Up stays up: the column (pivot z = 1) spans MagicaVoxel z 19..21 at (-7, 3), Grotto y 19..21.
    EXPECT_EQ(placed(s, 2, {0, 0, 0, 5}), glm::ivec3(-7, 19, -4));
    EXPECT_EQ(placed(s, 2, {0, 0, 1, 6}), glm::ivec3(-7, 20, -4));
    EXPECT_EQ(placed(s, 2, {0, 0, 2, 7}), glm::ivec3(-7, 21, -4));
    // ... and turned about z it is still upright: x and z stay, y climbs.
    const glm::ivec3 bottom = placed(s, 3, {0, 0, 0, 5}), top = placed(s, 3, {0, 0, 2, 7});
    EXPECT_EQ(top - bottom, glm::ivec3(0, 2, 0));
}

TEST(VoxRead, HiddenLayersAndNodesAreSkipped) {
    VoxWriter w;
    for (int m = 0; m < 5; ++m) w.model({1, 1, 1}, {{0, 0, 0, uint8_t(m + 1)}});
    sceneRoot(w, {2, 4, 6, 8, 10})
        .transform(2, 3, {0, 0, 0}, VoxWriter::kIdentity, 0).shape(3, 0)
        .transform(4, 5, {0, 0, 0}, VoxWriter::kIdentity, 1).shape(5, 1)        // on hidden layer 1
        .transform(6, 7, {0, 0, 0}, VoxWriter::kIdentity, 0, true).shape(7, 2)  // a hidden node
        .transform(8, 9, {0, 0, 0}, VoxWriter::kIdentity, 0).shape(9, 3)
        .transform(10, 11, {0, 0, 0}, VoxWriter::kIdentity, 0, true).group(11, {12})  // a hidden group
        .transform(12, 13).shape(13, 4)
        .layer(0, false)
        .layer(1, true);
    const VoxScene s = parse(w.bytes());
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.instances[0].model, 0u);
    EXPECT_EQ(s.instances[1].model, 3u);
    EXPECT_EQ(s.placedVoxels(), 2u);
    EXPECT_EQ(s.models.size(), 5u);  // hidden models are still read
}

TEST(VoxRead, NestedGroupsComposeTransforms) {
    VoxWriter w;
    w.model({1, 1, 1}, {{0, 0, 0, 1}});
    w.transform(0, 1, {100, 0, 0}, kTurnZByte, -1).group(1, {2})
        .transform(2, 3, {1, 2, 3}).group(3, {4})
        .transform(4, 5, {0, 0, 1}).shape(5, 0);
    const VoxScene s = parse(w.bytes());
    ASSERT_EQ(s.instances.size(), 1u);
    // R = Rz, t = Rz (1, 2, 3 + 1) + (100, 0, 0) = (-2, 1, 4) + (100, 0, 0).
    EXPECT_EQ(s.instances[0].rotation, kTurnZ);
    EXPECT_EQ(s.instances[0].translation, glm::ivec3(98, 1, 4));
    // The 1x1x1 model's centre (0.5, 0.5, 0.5) turns to (-0.5, 0.5, 0.5): cell (97, 1, 4).
    EXPECT_EQ(placed(s, 0, {0, 0, 0, 1}), glm::ivec3(97, 4, -2));
}

TEST(VoxRead, SharedShapeNodesAreInstances) {
    // MagicaVoxel shares a model's shape node among the transforms that place it.
    VoxWriter w;
    w.model({2, 2, 2}, {{0, 0, 0, 1}, {1, 1, 1, 2}});
    sceneRoot(w, {2, 4}).transform(2, 3, {-5, 0, 0}).shape(3, 0).transform(4, 3, {5, 0, 0});
    const VoxScene s = parse(w.bytes());
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.instances[0].translation, glm::ivec3(-5, 0, 0));
    EXPECT_EQ(s.instances[1].translation, glm::ivec3(5, 0, 0));
    EXPECT_EQ(s.placedVoxels(), 4u);
}

TEST(VoxRead, FrameZeroIsUsed) {
    VoxWriter w;
    w.model({1, 1, 1}, {{0, 0, 0, 1}}).model({1, 1, 1}, {{0, 0, 0, 2}});
    sceneRoot(w, {2})
        .transformFrames(2, 3, {}, 0, {{{"_f", "3"}, {"_t", "5 5 5"}}, {{"_f", "0"}, {"_t", "1 2 3"}}})
        .shapeFrames(3, {{0, {{"_f", "2"}}}, {1, {{"_f", "0"}}}});
    const VoxScene s = parse(w.bytes());
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].translation, glm::ivec3(1, 2, 3));
    EXPECT_EQ(s.instances[0].model, 1u);
}

TEST(VoxRead, SeveralModelsWithoutAGraphPlaceTheFirst) {
    // An old animation (PACK): its models are frames; MagicaVoxel shows the first.
    const VoxScene s = parse(
        VoxWriter(150).pack(2).model({1, 1, 1}, {{0, 0, 0, 1}}).model({2, 1, 1}, {{1, 0, 0, 1}}).bytes());
    EXPECT_EQ(s.models.size(), 2u);
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].model, 0u);
    EXPECT_TRUE(has(refusal(VoxWriter(150).pack(3).model({1, 1, 1}, {{0, 0, 0, 1}}).bytes()), "says the file holds 3"));
}

TEST(VoxRead, MaterialsByColourIndex) {
    VoxWriter w;
    w.model({1, 1, 1}, {{0, 0, 0, 5}})
        .material(5, {{"_type", "_metal"}, {"_rough", "0.25"}, {"_metal", "0.8"}, {"_ior", "0.5"}, {"_spec", "0.7"}})
        .material(7, {{"_type", "_emit"}, {"_emit", "0.6"}, {"_flux", "2"}, {"_ldr", "0.1"}})
        .material(9, {{"_type", "_glass"}, {"_trans", "0.4"}, {"_ri", "1.45"}, {"_ior", "0.3"}})
        .material(11, {{"_alpha", "0.3"}, {"_weight", "0.5"}, {"_unknown", "x"}})
        .material(256, {{"_type", "_metal"}});  // index 0: no voxels
    const VoxScene s = parse(w.bytes());
    const VoxMaterial& metal = s.materials[5];
    EXPECT_TRUE(metal.present);
    EXPECT_EQ(metal.type, "_metal");
    EXPECT_FLOAT_EQ(metal.rough, 0.25f);
    EXPECT_FLOAT_EQ(metal.metal, 0.8f);
    EXPECT_FLOAT_EQ(metal.spec, 0.7f);
    EXPECT_FLOAT_EQ(metal.ior, 1.5f);  // _ior is the index minus 1
    const VoxMaterial& emit = s.materials[7];
    EXPECT_EQ(emit.type, "_emit");
    EXPECT_FLOAT_EQ(emit.emit, 0.6f);
    EXPECT_FLOAT_EQ(emit.flux, 2.0f);
    EXPECT_FLOAT_EQ(emit.ldr, 0.1f);
    const VoxMaterial& glass = s.materials[9];
    EXPECT_EQ(glass.type, "_glass");
    EXPECT_FLOAT_EQ(glass.trans, 0.4f);
    EXPECT_FLOAT_EQ(glass.ior, 1.45f);  // _ri, the index itself, wins
    EXPECT_EQ(s.materials[11].type, "_diffuse");
    EXPECT_FLOAT_EQ(s.materials[11].trans, 0.3f);
    EXPECT_FLOAT_EQ(s.materials[11].weight, 0.5f);
    EXPECT_FALSE(s.materials[6].present);
    EXPECT_FLOAT_EQ(s.materials[6].rough, 0.1f);
    EXPECT_FALSE(s.materials[0].present);
    EXPECT_TRUE(has(refusal(VoxWriter().model({1, 1, 1}, {{0, 0, 0, 1}}).material(3, {{"_rough", "soft"}}).bytes()),
                    "'_rough' is 'soft'"));
    EXPECT_TRUE(has(refusal(VoxWriter().model({1, 1, 1}, {{0, 0, 0, 1}}).material(257, {}).bytes()), "257"));
}

// A small file with every kind of chunk, for the hostile tests.
std::vector<uint8_t> smallScene(bool withPalette) {
    VoxWriter w;
    w.model({3, 2, 2}, {{0, 0, 0, 1}, {2, 1, 1, 2}, {1, 0, 1, 3}}).model({1, 1, 2}, {{0, 0, 1, 4}});
    sceneRoot(w, {2, 4})
        .transformFrames(2, 3, {{"_name", "a"}}, 0, {{{"_r", std::to_string(kTurnZByte)}, {"_t", "1 -2 3"}}})
        .shape(3, 0)
        .transform(4, 5, {4, 0, 0}, kMirrorXByte, 1)
        .shape(5, 1)
        .layer(0, false)
        .layer(1, false)
        .material(2, {{"_type", "_metal"}, {"_metal", "1"}});
    if (withPalette) {
        std::array<VoxColor, 256> entries;
        for (int i = 0; i < 256; ++i) entries[i] = {uint8_t(i), 1, 2, 255};
        w.palette(entries);
    }
    return w.bytes();
}

TEST(VoxReadHostile, EveryTruncationIsRefused) {
    const std::vector<uint8_t> bytes = smallScene(true);
    ASSERT_EQ(parse(bytes).instances.size(), 2u);
    for (size_t n = 0; n < bytes.size(); ++n) {
        SCOPED_TRACE(n);
        refusal(std::vector<uint8_t>(bytes.begin(), bytes.begin() + std::ptrdiff_t(n)));
    }
}

TEST(VoxReadHostile, BitFlipsParseOrAreRefused) {
    const std::vector<uint8_t> bytes = smallScene(false);
    int parsed = 0, refused = 0;
    for (size_t i = 0; i < bytes.size(); ++i)
        for (int bit = 0; bit < 8; ++bit) {
            std::vector<uint8_t> flipped = bytes;
            flipped[i] ^= uint8_t(1 << bit);
            try {
                const VoxScene s = parse(flipped);
                ++parsed;
                ASSERT_LE(s.placedVoxels(), kMaxVoxPlacedVoxels);
                for (const VoxInstance& inst : s.instances) {
                    ASSERT_LT(inst.model, s.models.size());
                    for (const auto& v : s.models[inst.model].voxels) {
                        ASSERT_LT(v[0], s.models[inst.model].size.x);
                        ASSERT_NE(v[3], 0);
                        const glm::ivec3 p = placeVoxel(s, inst, v);
                        ASSERT_LE(std::abs(p.x) + std::abs(p.y) + std::abs(p.z), 3 * (kMaxVoxTranslation + 256));
                    }
                }
            } catch (const Error& e) {
                ++refused;
                ASSERT_TRUE(has(e.what(), kFile)) << e.what();
            }
        }
    EXPECT_GT(parsed, 0);
    EXPECT_GT(refused, 0);
}

TEST(VoxReadHostile, HugeChunkSize) {
    std::vector<uint8_t> bytes = VoxWriter().model({1, 1, 1}, {{0, 0, 0, 1}}).bytes();
    bytes[24] = 0xF0, bytes[25] = bytes[26] = bytes[27] = 0xFF;  // SIZE's content size
    const std::string what = refusal(bytes);
    EXPECT_TRUE(has(what, "chunk 'SIZE' at byte 20: claims 4294967280 bytes of content")) << what;
    std::vector<uint8_t> main = VoxWriter().model({1, 1, 1}, {{0, 0, 0, 1}}).bytes();
    main[16] = main[17] = main[18] = main[19] = 0xFF;  // MAIN's children size
    EXPECT_TRUE(has(refusal(main), "chunk 'MAIN' at byte 8: claims 4294967295 bytes of children"));
}

TEST(VoxReadHostile, HugeCounts) {
    std::vector<uint8_t> trn;
    test::appendU32(trn, 0);
    test::appendU32(trn, 0x7FFFFFFF);  // the attributes' entry count
    const std::string what = refusal(VoxWriter().model({1, 1, 1}, {{0, 0, 0, 1}}).chunk("nTRN", trn).bytes());
    EXPECT_TRUE(has(what, "chunk 'nTRN' at byte")) << what;
    EXPECT_TRUE(has(what, "entry count is 2147483647")) << what;

    std::vector<uint8_t> size, xyzi;
    for (int a = 0; a < 3; ++a) test::appendU32(size, 256);
    test::appendU32(xyzi, 0x40000000);  // voxels, with none there
    EXPECT_TRUE(has(refusal(VoxWriter().chunk("SIZE", size).chunk("XYZI", xyzi).bytes()), "voxel count is 1073741824"));

    std::vector<uint8_t> grp;
    test::appendU32(grp, 1);
    test::appendDict(grp, {});
    test::appendU32(grp, 0xFFFFFFFF);  // children
    EXPECT_TRUE(has(refusal(VoxWriter().model({1, 1, 1}, {{0, 0, 0, 1}}).chunk("nGRP", grp).bytes()),
                    "child count is 4294967295"));
}

TEST(VoxReadHostile, BrokenSceneGraphs) {
    const auto scene = [](auto build) {
        VoxWriter w;
        w.model({1, 1, 1}, {{0, 0, 0, 1}});
        build(w);
        return refusal(w.bytes());
    };
    EXPECT_TRUE(has(scene([](VoxWriter& w) { sceneRoot(w, {2}).transform(2, 1); }), "cycle"));
    EXPECT_TRUE(has(scene([](VoxWriter& w) { sceneRoot(w, {2}).transform(2, 0); }), "cycle"));
    EXPECT_TRUE(has(scene([](VoxWriter& w) { sceneRoot(w, {2, 2}).transform(2, 3).shape(3, 0); }),
                    "only shape nodes (nSHP) may be shared"));
    EXPECT_TRUE(has(scene([](VoxWriter& w) { sceneRoot(w, {9}); }), "lists child node 9, which no nTRN"));
    EXPECT_TRUE(has(scene([](VoxWriter& w) { sceneRoot(w, {2}).transform(2, 3).shape(3, 4); }), "refers to model 4"));
    EXPECT_TRUE(has(scene([](VoxWriter& w) { w.group(1, {}); }), "without its root, node 0"));
    EXPECT_TRUE(has(scene([](VoxWriter& w) { sceneRoot(w, {}).group(1, {}); }), "node 1 is defined twice"));
    EXPECT_TRUE(has(scene([](VoxWriter& w) {
                        for (int32_t id = 0; id < 80; ++id) w.transform(id, id + 1);
                        w.shape(80, 0);
                    }),
                    "nested more than 64 nodes deep"));
}

TEST(VoxReadHostile, BadTransforms) {
    const auto frame = [](const VoxDict& f) {
        VoxWriter w;
        w.model({1, 1, 1}, {{0, 0, 0, 1}});
        sceneRoot(w, {2}).transformFrames(2, 3, {}, 0, {f}).shape(3, 0);
        return refusal(w.bytes());
    };
    EXPECT_TRUE(has(frame({{"_r", "0"}}), "'_r' is '0', not a rotation"));  // both rows in column 0
    EXPECT_TRUE(has(frame({{"_r", "3"}}), "not a rotation"));               // column 3
    EXPECT_TRUE(has(frame({{"_r", "200"}}), "not a rotation"));
    EXPECT_TRUE(has(frame({{"_r", "x"}}), "'_r' is 'x'"));
    EXPECT_TRUE(has(frame({{"_t", "16777217 0 0"}}), "beyond 16777216"));
    EXPECT_TRUE(has(frame({{"_t", "1 2"}}), "not three integers"));
    EXPECT_TRUE(has(frame({{"_t", "1 2 3 4"}}), "not three integers"));
    EXPECT_TRUE(has(frame({{"_f", "-1"}}), "'_f' is '-1'"));
    // Each translation within the limit, their sum beyond it.
    VoxWriter w;
    w.model({1, 1, 1}, {{0, 0, 0, 1}});
    w.transform(0, 1, {kMaxVoxTranslation, 0, 0}, VoxWriter::kIdentity, -1).group(1, {2});
    w.transform(2, 3, {1, 0, 0}).shape(3, 0);
    EXPECT_TRUE(has(refusal(w.bytes()), "16777217 voxels from the origin along x"));
}

TEST(VoxReadHostile, BadModels) {
    const std::string big = refusal(VoxWriter().model({257, 1, 1}, {{0, 0, 0, 1}}).bytes());
    EXPECT_TRUE(has(big, "chunk 'SIZE' at byte 20: model 0 is 257x1x1 voxels")) << big;
    EXPECT_TRUE(has(refusal(VoxWriter().model({0, 1, 1}, {}).bytes()), "0x1x1"));
    const std::string outside = refusal(VoxWriter().model({2, 2, 2}, {{1, 1, 1, 1}, {0, 2, 0, 1}}).bytes());
    EXPECT_TRUE(has(outside, "chunk 'XYZI' at byte 44: model 0's voxel 1 at (0, 2, 0) lies outside its size 2x2x2"))
        << outside;
    EXPECT_TRUE(has(refusal(VoxWriter().model({1, 1, 1}, {{0, 0, 0, 1}, {0, 0, 0, 2}}).bytes()), "more than its size"));
    EXPECT_TRUE(has(refusal(VoxWriter().chunk("XYZI", {0, 0, 0, 0}).bytes()), "without a SIZE chunk"));
    EXPECT_TRUE(has(refusal(VoxWriter().chunk("SIZE", {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}).bytes()),
                    "not followed by its XYZI"));
    EXPECT_TRUE(has(refusal(VoxWriter().bytes()), "holds no model"));
    EXPECT_TRUE(has(refusal(VoxWriter().model({1, 1, 1}, {}).chunk("RGBA", {1, 2, 3, 4}).bytes()), "1024"));
}

TEST(VoxReadHostile, NotAVoxFile) {
    std::vector<uint8_t> bytes = VoxWriter().model({1, 1, 1}, {{0, 0, 0, 1}}).bytes();
    bytes[4] = 151;
    EXPECT_TRUE(has(refusal(bytes), "version 151"));
    EXPECT_TRUE(has(refusal({'P', 'K', 3, 4, 0, 0, 0, 0}), "does not start with 'VOX '"));
    std::vector<uint8_t> notMain = VoxWriter().model({1, 1, 1}, {{0, 0, 0, 1}}).bytes();
    notMain[8] = 0x1B;  // an escape byte where MAIN's id is: printed harmlessly
    const std::string what = refusal(notMain);
    EXPECT_TRUE(has(what, "must be MAIN")) << what;
    EXPECT_EQ(what.find('\x1B'), std::string::npos);
}

TEST(VoxReadHostile, InstancingBombIsRefused) {
    // 4,097 instances of one full 16^3 model: 16,781,312 voxels from a file of a few hundred KiB.
    Voxels cube;
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) cube.push_back({uint8_t(x), uint8_t(y), uint8_t(z), 1});
    constexpr int kInstances = 4097;
    VoxWriter w;
    w.model({16, 16, 16}, cube);
    std::vector<int32_t> children;
    for (int i = 0; i < kInstances; ++i) children.push_back(3 + i);
    sceneRoot(w, children).shape(2, 0);
    for (int i = 0; i < kInstances; ++i) w.transform(3 + i, 2, {i, 0, 0});
    const std::vector<uint8_t> bytes = w.bytes();
    EXPECT_LT(bytes.size(), size_t(300) << 10);
    const auto start = std::chrono::steady_clock::now();
    const std::string what = refusal(bytes);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
    EXPECT_TRUE(has(what, kFile + ": places 16781312 voxels, more than the 16777216")) << what;
}

TEST(VoxReadHostile, OneMiBParsesFast) {
    Voxels slab;
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 256; ++y)
            for (int x = 0; x < 256; ++x)
                slab.push_back({uint8_t(x), uint8_t(y), uint8_t(z), uint8_t(1 + (x ^ y) % 255)});
    const std::vector<uint8_t> bytes = VoxWriter().model({256, 256, 4}, slab).bytes();
    EXPECT_GE(bytes.size(), size_t(1) << 20);
    const auto start = std::chrono::steady_clock::now();
    const VoxScene s = parse(bytes);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
    EXPECT_EQ(s.placedVoxels(), slab.size());
}

TEST(VoxReadFile, ReadsAndRefusesBeforeReading) {
    const fs::path dir = fs::temp_directory_path() / ("grotto_vox_read_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::vector<uint8_t> bytes = smallScene(true);
    {
        std::ofstream(dir / "small.vox", std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                                  std::streamsize(bytes.size()));
    }
    EXPECT_EQ(readVoxFile(dir / "small.vox").instances.size(), 2u);
    // A sparse file one byte over the limit: refused by its size, never read.
    { std::ofstream(dir / "huge.vox", std::ios::binary).write("VOX ", 4); }
    fs::resize_file(dir / "huge.vox", kMaxVoxFileBytes + 1);
    try {
        readVoxFile(dir / "huge.vox");
        ADD_FAILURE() << "read";
    } catch (const Error& e) {
        EXPECT_TRUE(has(e.what(), "huge.vox: is 536870913 bytes, more than the 512 MiB")) << e.what();
    }
    EXPECT_THROW(readVoxFile(dir / "missing.vox"), Error);
    EXPECT_THROW(readVoxFile(dir), Error);  // a directory
    fs::remove_all(dir);
}

}  // namespace
}  // namespace grotto::voxel
