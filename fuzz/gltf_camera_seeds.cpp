// Writes small glTF camera animations for fuzz_gltf_camera, as the tests write
// them: LINEAR, CUBICSPLINE and STEP samplers, binary and text.
//   fuzz_gltf_camera_seeds DIR
#include "tests/gltf_camera_writer.h"

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) return std::fprintf(stderr, "usage: fuzz_gltf_camera_seeds DIR\n"), 2;
    const std::filesystem::path dir = argv[1];
    grotto::test::GltfCameraScene s;
    s.parentTranslation = {8, 0, 8};
    s.samplers = {{"translation", "LINEAR", {0, 1, 2}, {0, 5, 20, 4, 5, 20, 4, 8, 10}},
                  {"rotation", "STEP", {0, 2}, {0, 0, 0, 1, 0, 0.38f, 0, 0.92f}}};
    bool ok = grotto::test::writeGltfCamera(s, dir / "linear.glb") && grotto::test::writeGltfCamera(s, dir / "linear.gltf");
    s.samplers = {{"translation", "CUBICSPLINE", {0, 1}, {0, 0, 0, 0, 0, 0, 8, 0, 0, -4, 6, 0, 5, 2, 1, 0, 0, 0}},
                  {"scale", "LINEAR", {0, 1}, {1, 1, 1, 2, 2, 2}, 0}};
    ok = ok && grotto::test::writeGltfCamera(s, dir / "cubic.glb");
    return ok ? 0 : 1;
}
