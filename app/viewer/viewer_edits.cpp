// Picking and edits: a click digs, places or paints where the view ray first
// meets a voxel; undo takes the last edit back; the world is saved as edited.
#include "app/viewer/viewer_internal.h"

#include "common/atomic_file.h"
#include "common/printable.h"

#include <algorithm>
#include <cstdio>

namespace grotto::viewer {

// The view ray through a window pixel (the window may show the frame scaled)
// and the first voxel it hits.
Viewer::Pick Viewer::pick(glm::dvec2 pixel) const {
    const VkExtent2D window = presenter_->extent();
    const Camera camera = makeCamera(fly_->desc(), renderSize_.width, renderSize_.height);
    const glm::dvec2 p = pixel * glm::dvec2(double(renderSize_.width) / std::max(window.width, 1u),
                                            double(renderSize_.height) / std::max(window.height, 1u));
    Pick k{camera.position, camera.rayDirection(p.x, p.y), std::nullopt};
    k.hit = session_->world().raycast(k.origin, k.direction, 1e12);
    return k;
}

// The orbit's pivot: the surface under the pixel, else the point a second's flight ahead.
glm::dvec3 Viewer::pointUnder(glm::dvec2 pixel) const {
    const Pick k = pick(pixel);
    return k.origin + k.direction * (k.hit ? k.hit->distance : fly_->speed());
}

// The panel's edit at a window pixel: dig and paint at the voxel hit, place in
// front of the face it hit. `primary`: the left button; any other does nothing yet.
// While a path is being recorded, the edit joins its edits track at this frame's time.
// "light" places one voxel of the palette's first glowing material there.
void Viewer::click(glm::dvec2 pixel, bool primary) {
    if (!primary || panel_.editMode == "none") return;
    const voxel::World& world = session_->world();
    const std::optional<voxel::RayHit> hit = pick(pixel).hit;
    if (!hit) return;
    const bool light = panel_.editMode == "light";
    const std::vector<voxel::Material>& palette = world.desc().materials;
    const auto glowing = std::find_if(palette.begin(), palette.end(), [](const voxel::Material& m) { return m.emits(); });
    if (light && glowing == palette.end()) {
        panel_.message = "no material of this world glows: give one an emission (docs/worlds.md) to place lights";
        return;
    }
    glm::ivec3 voxel = hit->voxel;
    if ((panel_.editMode == "place" || light) && hit->face >= 0) voxel[hit->face / 2] += hit->face % 2 == 0 ? 1 : -1;
    const double vs = world.voxelSize();
    const glm::dvec3 centre = world.origin() + (glm::dvec3(voxel) + 0.5) * vs;
    const double radius = std::max(panel_.brushRadius, 0.5) * vs;
    const voxel::Edit edit = light ? voxel::Edit::fillBox({voxel, voxel}, int(glowing - palette.begin()) + 1)
                             : panel_.editMode == "dig"   ? voxel::Edit::carveSphere(centre, radius)
                             : panel_.editMode == "place" ? voxel::Edit::fillSphere(centre, radius, panel_.material)
                                                          : voxel::Edit::paintSphere(centre, radius, panel_.material);
    const voxel::EditResult r = session_->apply(edit);
    if (recordStart_ && !r.voxels.empty()) recorder_.addEdit(playClock_ - *recordStart_, edit);
    edited(r);
}

// While recording, the undone edit leaves the recorded track too.
void Viewer::undo() {
    const voxel::EditResult r = session_->undo();
    if (recordStart_ && !r.voxels.empty()) recorder_.dropLastEdit();
    edited(r);
}

void Viewer::edited(const voxel::EditResult& r) {
    if (r.voxels.empty()) return;
    panel_.quads = session_->scene().gpu().quadCount;
    panel_.activeVoxels = session_->world().stats().solidVoxels;
    panel_.message = std::to_string(r.changed) + " voxels changed";
}

void Viewer::saveWorld(const std::filesystem::path& file) {
    requireOutputPath(file);
    // With the settings as the panel has them.
    const voxel::World::SavedFiles saved = session_->world().save(file, desc_);
    panel_.message = "wrote " + saved.world.string() + " and " + saved.grid.string();
    std::printf("wrote %s and %s\n", printable(saved.world.string()).c_str(), printable(saved.grid.string()).c_str());
}

}  // namespace grotto::viewer
