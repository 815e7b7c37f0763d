#include "engine/scene/scene_objects.h"

#include "engine/scene/scene_memory.h"
#include "grotto/error.h"
#include "voxel/world.h"

namespace grotto {

std::vector<const GpuScene*> SceneObjects::list() const {
    std::vector<const GpuScene*> out;
    for (const auto& s : scenes) out.push_back(s.get());
    return out;
}

std::unique_ptr<SceneObjects> uploadObjects(vk::Context& ctx, std::span<const voxel::World> worlds,
                                            const voxel::WorldDesc& desc) {
    if (worlds.size() != desc.objects.size())
        throw Error::internal("uploadObjects", "the object worlds do not match the world file's objects");
    auto objects = std::make_unique<SceneObjects>();
    objects->descs = desc.objects;
    for (size_t k = 0; k < worlds.size(); ++k) {
        objects->scenes.push_back(uploadMeshWithinBudget(ctx, worlds[k], desc));
        objects->grids.push_back(objectGrid(worlds[k]));
        objects->moving |= desc.objects[k].moves();
    }
    requireGlowFits(desc.source.string() + ": field 'objects'", objects->grids);
    return objects;
}

}  // namespace grotto
