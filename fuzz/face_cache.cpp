// Fuzzes the baked face cache reader (.gfc, grotto bake): any input is either a
// cache whose counts are consistent or a grotto::Error of kind Input, and a cache
// it accepts reads back through the lookup without leaving its texels.
#include "fuzz/input_file.h"
#include "grotto/error.h"
#include "voxel/face_cache_file.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto file = grotto::fuzz::writeInput(data, size, "cache.gfc");
    grotto::voxel::FaceCacheFile cache;
    try {
        cache = grotto::voxel::loadFaceCache(file);
    } catch (const grotto::Error& e) {
        if (e.kind() != grotto::Error::Kind::Input) throw;
        return 0;
    }
    for (const grotto::voxel::FaceTexel& t : cache.texels)
        if (t.open > t.samples || t.sunOpen > t.sunSamples || !(t.ao() >= 0.0 && t.ao() <= 1.0)) {
            std::fprintf(stderr, "an accepted texel is inconsistent\n");
            std::abort();
        }
    const grotto::voxel::FaceCacheHeader& h = cache.header;
    if (h.firstFace + h.faceCount > h.totalFaces || cache.texels.size() != h.texelCount()) std::abort();
    return 0;
}
