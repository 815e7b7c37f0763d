#include "engine/session_setup.h"

#include "engine/frame/frame_plan.h"
#include "engine/frame/render_memory.h"

namespace grotto {

std::unique_ptr<RenderSession> openSession(vk::Context& ctx, voxel::World world, const SessionSetup& setup,
                                           const std::string& sizeName) {
    requireRenderFits(ctx, planWorldFrame(world.desc(), setup.width, setup.height, setup.ao), sizeName);
    return std::make_unique<RenderSession>(ctx, std::move(world), setup.ao, setup.detail, setup.width, setup.height,
                                           setup.objectsMayMove);
}

bool bakesHere(const RenderSession& session, const FaceCacheSource& source) {
    return source.bake.empty() && !source.progressive && faceCached(session.ao());
}

void readyFaceCache(RenderSession& session, const FaceCacheSource& source) {
    session.setProgressiveFaceCache(source.progressive);
    if (!source.bake.empty()) session.loadFaceCache(source.bake);
    else if (!faceCached(session.ao())) return;
    else if (source.progressive) session.startFaceCache();
    else session.bakeFaceCache();
}

}  // namespace grotto
