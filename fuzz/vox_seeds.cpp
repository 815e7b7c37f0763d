// Writes small .vox seeds for fuzz_vox with the tests' own writer: one model, a
// scene graph with groups, rotations, a hidden layer and materials, and no palette.
//   fuzz_vox_seeds DIR
#include "tests/vox_writer.h"

#include <cstdio>
#include <fstream>

namespace {

void write(const std::filesystem::path& file, const std::vector<uint8_t>& bytes) {
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) return std::fprintf(stderr, "usage: fuzz_vox_seeds DIR\n"), 2;
    using grotto::voxel::test::VoxWriter;
    const std::filesystem::path dir = argv[1];
    std::array<grotto::voxel::VoxColor, 256> palette{};
    for (size_t i = 0; i < palette.size(); ++i) palette[i] = {uint8_t(i), uint8_t(255 - i), uint8_t(i * 7), 255};
    const std::vector<std::array<uint8_t, 4>> cube = {{0, 0, 0, 1}, {1, 0, 0, 2}, {0, 1, 0, 3}, {1, 1, 1, 4}};
    write(dir / "one.vox", VoxWriter(150).model({2, 2, 2}, cube).bytes());
    write(dir / "scene.vox", VoxWriter()
                                 .model({2, 2, 2}, cube).model({3, 1, 2}, {{0, 0, 0, 5}, {2, 0, 1, 6}}).palette(palette)
                                 .transform(0, 1).group(1, {2, 4, 6})
                                 .transform(2, 3, {4, 0, 1}, 0x11).shape(3, 0)
                                 .transform(4, 5, {-3, 2, 0}, 0x28).shape(5, 1)
                                 .transform(6, 3, {0, 9, 0}, VoxWriter::kIdentity, 1).layer(0, false).layer(1, true)
                                 .material(5, {{"_type", "_metal"}, {"_rough", "0.3"}, {"_metal", "1"}})
                                 .bytes());
    return 0;
}
