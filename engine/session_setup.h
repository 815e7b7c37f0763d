#pragma once
// One set-up for every command, the viewer and grotto::Engine: a world, with its
// AO and detail resolved, at an image size becomes a session once its frame is
// known to fit the device; then --ao cache's light is readied on its faces.
#include "engine/session.h"

#include <filesystem>
#include <memory>
#include <string>

namespace grotto {

struct SessionSetup {
    AoOptions ao;
    voxel::Detail detail;  // the levels of detail and occlusion culling drawn with
    uint32_t width = 0, height = 0;
    bool objectsMayMove = false;  // every object gets motion vectors (a game poses objects itself)
};

// Refused with grotto::Error (input) naming `sizeName` (what set the image size)
// when the frame cannot fit the device's memory, before anything is uploaded.
std::unique_ptr<RenderSession> openSession(vk::Context& ctx, voxel::World world, const SessionSetup& setup,
                                           const std::string& sizeName);

// Where the face cache's light comes from before the first frame, for the face
// cache's AO method (nothing otherwise): `bake`, a bake of this world with the
// session's AO radius; else with `progressive` nothing traced yet (the GPU traces
// the faces in view as frames go, now and whenever the session needs a cache
// anew); else a bake made here on every core.
struct FaceCacheSource {
    std::filesystem::path bake;
    bool progressive = false;
};
// Would readyFaceCache bake here (minutes for a large world)?
bool bakesHere(const RenderSession& session, const FaceCacheSource& source);
// A bake that is not this world's or these settings' is refused with
// grotto::Error (input) naming the file and field.
void readyFaceCache(RenderSession& session, const FaceCacheSource& source);

}  // namespace grotto
