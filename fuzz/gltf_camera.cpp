// Fuzzes reading a glTF camera animation as a path (tinygltf's parse, then our
// checks of every accessor, node and sampler, then the path's keys). Bad input
// must end in grotto::Error of kind Input; any other exception, crash or
// sanitizer report is a bug.
#include "grotto/error.h"
#include "fuzz/input_file.h"
#include "voxel/gltf/gltf_camera.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto file = grotto::fuzz::writeInput(data, size, "shot.glb");
    try {
        (void)grotto::voxel::importGltfCameraPath(file);
    } catch (const grotto::Error& e) {
        if (e.kind() != grotto::Error::Kind::Input) throw;
    }
    return 0;
}
