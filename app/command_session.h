#pragma once
// The set-up every rendering command shares, its flags mapped onto the engine's
// (engine/session_setup.h): a command is then its own options and what it does
// with the frames.
#include "app/options.h"
#include "engine/session_setup.h"

#include <memory>

namespace grotto::app {

// --ao cache's light for the session's world: the --bake file (refused, naming the
// file and field, when it is not this world's or these settings'), with
// --progressive none (the GPU traces the faces in view as frames go), or else a
// bake made here on every core, announced on stderr. Nothing for other methods.
void prepareFaceCache(RenderSession& session, const AoFlags& flags);

// The session a command renders `world` with at `size`: refused naming --size when
// its frame cannot fit the device, with the detail of the world and `flags`, and,
// with `faceCache`, the face cache readied from the flags (prepareFaceCache).
std::unique_ptr<RenderSession> commandSession(vk::Context& ctx, voxel::World world, const AoOptions& ao,
                                              const AoFlags& flags, Size size, bool faceCache = true);

}  // namespace grotto::app
