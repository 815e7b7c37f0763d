// A session's objects coming and going at run time, and rays through the world
// and its objects at their poses (a game's pick).
#include "engine/session.h"

#include "engine/scene/scene_memory.h"
#include "grotto/error.h"
#include "shaders/shared/objects.h"

#include <glm/gtc/quaternion.hpp>

namespace grotto {

namespace {

// The outward normal of face 0..5 (+X -X +Y -Y +Z -Z): the ray entered through it.
glm::dvec3 faceNormal(int face) {
    glm::dvec3 n(0.0);
    if (face >= 0) n[face / 2] = face % 2 == 0 ? 1.0 : -1.0;
    return n;
}

}  // namespace

void RenderSession::addObject(voxel::World world, voxel::ObjectDesc desc) {
    if (!objectsMayMove_) throw Error::internal("RenderSession::addObject", "made without objectsMayMove");
    if (objectWorlds_.size() >= GROTTO_MAX_OBJECTS)
        throw Error("addObject", "the world already holds " + std::to_string(objectWorlds_.size()) + " objects",
                    "at most " + std::to_string(GROTTO_MAX_OBJECTS) + ": remove one first");
    if (desc.keys.empty()) desc.keys.emplace_back();
    ObjectGrid grid = objectGrid(world);
    requireGlowFits("addObject", objects_->grids, &grid);  // before anything changes
    objects_->scenes.push_back(uploadMeshWithinBudget(ctx_, world, world.desc()));
    objects_->descs.push_back(desc);
    objects_->grids.push_back(std::move(grid));
    ++objects_->gridsVersion;
    objectWorlds_.push_back(std::move(world));
    const voxel::ObjectPose pose = voxel::objectPose(desc, 0.0);
    if (renderer_) renderer_->objectAdded(pose);
    else unmade_->poses.push_back(pose);
}

void RenderSession::removeObject(size_t index) {
    if (index >= objectWorlds_.size())
        throw Error("removeObject", "object " + std::to_string(index) + " does not exist",
                    "the world has " + std::to_string(objectWorlds_.size()) + " objects");
    // The renderer lets go of the object's scene first: it drew it last frame.
    if (renderer_) renderer_->objectRemoved(index);
    objects_->scenes.erase(objects_->scenes.begin() + ptrdiff_t(index));
    objects_->descs.erase(objects_->descs.begin() + ptrdiff_t(index));
    objects_->grids.erase(objects_->grids.begin() + ptrdiff_t(index));
    ++objects_->gridsVersion;
    objectWorlds_.erase(objectWorlds_.begin() + ptrdiff_t(index));
    if (!renderer_) unmade_->poses.erase(unmade_->poses.begin() + ptrdiff_t(index));
}

std::optional<RenderSession::Hit> RenderSession::raycast(glm::dvec3 origin, glm::dvec3 direction,
                                                         double maxDistance) const {
    std::optional<Hit> best;
    if (const auto h = world().raycast(origin, direction, maxDistance))
        best = Hit{*h, faceNormal(h->face), world().material(h->voxel), -1};
    // Each object traced in its own space: the pose is rigid, so distances carry over.
    const std::vector<voxel::ObjectPose>& posed = poses();
    for (size_t k = 0; k < objectWorlds_.size() && k < posed.size(); ++k) {
        const voxel::ObjectPose& pose = posed[k];
        const double reach = best ? best->ray.distance : maxDistance;
        const auto h = objectWorlds_[k].raycast(pose.toLocal(origin), glm::conjugate(pose.rotation) * direction, reach);
        if (h && (!best || h->distance < best->ray.distance))
            best = Hit{*h, pose.rotation * faceNormal(h->face), objectWorlds_[k].material(h->voxel), int(k)};
    }
    return best;
}

}  // namespace grotto
