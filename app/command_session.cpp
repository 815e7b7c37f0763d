#include "app/command_session.h"

#include <chrono>
#include <cstdio>

namespace grotto::app {

void prepareFaceCache(RenderSession& session, const AoFlags& flags) {
    const FaceCacheSource source{.bake = flags.bake, .progressive = flags.progressive};
    if (!bakesHere(session, source)) {
        readyFaceCache(session, source);
        // The GPU's tracer carries the sky's light alone: a command's frames wait
        // for the world's full light, baked on its own thread, so they do not
        // depend on how fast that ran.
        const LiveFaceCache* cache = session.scene().faceCache();
        if (cache && cache->lightPending()) {
            std::fprintf(stderr, "baking the world's full light (the GPU traces the sky's light alone)...\n");
            session.waitForLight();
            if (const Error* error = cache->lightError()) throw *error;
        }
        return;
    }
    std::fprintf(stderr, "baking the face cache (no --bake given; grotto bake writes one for every run)...\n");
    const auto start = std::chrono::steady_clock::now();
    readyFaceCache(session, source);
    std::fprintf(stderr, "baked %zu faces in %.1f s\n", session.scene().faceCache()->faces().size(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

std::unique_ptr<RenderSession> commandSession(vk::Context& ctx, voxel::World world, const AoOptions& ao,
                                              const AoFlags& flags, Size size, bool faceCache) {
    const SessionSetup setup{.ao = ao, .detail = resolveDetail(world, flags), .width = size.width, .height = size.height};
    std::unique_ptr<RenderSession> session = openSession(ctx, std::move(world), setup, "--size");
    if (faceCache) prepareFaceCache(*session, flags);
    return session;
}

}  // namespace grotto::app
