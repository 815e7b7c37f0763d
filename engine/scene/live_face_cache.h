#pragma once
// The face cache of a live world (--ao cache): every exposed face's texels on the
// host, laid out and uploaded into the scene's GpuScene::faceCache, from a bake
// loaded from disk, made here on every core, or left empty for the GPU's tracer to
// converge in view (engine/passes/face_cache_trace_pass.h; with full light, and
// the world's light baked on a thread meanwhile). After an edit the
// texels it reaches are left to that tracer too; with full light they are traced
// here at once, and every face whose light the edit moved is lit again
// (voxel/light_edit.h), before the next frame.
#include "engine/scene/scene.h"
#include "grotto/error.h"
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/face_cache_edit.h"
#include "voxel/face_cache_file.h"
#include "voxel/light_bake_thread.h"
#include "voxel/light_edit.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace grotto {

class LiveFaceCache {
public:
    // `texels`: k x k for each of `faces` (exposedFaces of `world`, in order),
    // traced with `settings`; `dayLight`: full light over the day's words
    // (kDayLightWords a face, voxel/light_bake.h) or none. Uploads them into `scene`.
    LiveFaceCache(GpuScene& scene, const voxel::World& world, std::vector<voxel::ExposedFace> faces,
                  std::vector<voxel::FaceTexel> texels, const voxel::FaceBakeSettings& settings,
                  std::vector<glm::vec3> dayLight = {});

    // A bake of the world (`grotto bake`) with AO radius `radius` (world units);
    // throws grotto::Error (input) naming the file and the first field that is not
    // this world's or these settings' (voxel::requireMatchingBake).
    static LiveFaceCache load(GpuScene& scene, const voxel::BrickTable& table, const voxel::World& world,
                              double radius, const std::filesystem::path& bake);
    // Baked here on every core, as `grotto bake` with `settings` would.
    static LiveFaceCache bake(GpuScene& scene, const voxel::BrickTable& table, const voxel::World& world,
                              const voxel::FaceBakeSettings& settings);
    // Nothing traced yet: the GPU's tracer converges the faces as they come into
    // view. With full light, which that tracer does not carry (it traces the sky's
    // light alone), the world's light is also baked on a thread of its own (below).
    static LiveFaceCache progressive(GpuScene& scene, const voxel::BrickTable& table, const voxel::World& world,
                                     const voxel::FaceBakeSettings& settings);

    // After an edit of `changed` (the world and table already edited): the faces
    // listed again, the rest carried over, and the GPU copy replaced; the faces
    // the edit reaches (voxel::updateAfterEdit) keep their old texels until the
    // GPU's tracer traces them again, in view, from the next frame on. With full
    // light they are traced here, and the faces whose light moved lit again.
    void edited(const voxel::BrickTable& table, const voxel::World& world, const IndexBox& changed,
                voxel::CacheEditStats* stats = nullptr);

    // The full light baked on its own thread, taken between frames: the faces as
    // that bake left them, then brought up to the edits made since, as one edit
    // of the box holding them all. False while it runs (and without one).
    // `table` and `world` as they are now.
    bool takeBakedLight(const voxel::BrickTable& table, const voxel::World& world);
    // Is that bake running, or finished and not taken yet? Its progress, 0 to 1;
    // 1 when there is none.
    bool lightPending() const { return lightBake_ != nullptr; }
    double lightBaked() const;
    void waitForLight();  // until that bake has finished (takeBakedLight then takes it)
    // What stopped that bake (the world too large for its memory budget, say), or
    // null: the faces keep the sky's light alone then.
    const Error* lightError() const { return lightError_ ? &*lightError_ : nullptr; }

    const voxel::FaceBakeSettings& settings() const { return settings_; }
    std::span<const voxel::ExposedFace> faces() const { return faces_; }
    // The texels and each face's level (shaders/shared/face_trace.h) as of the
    // last sync(): what the GPU's tracer traced since is on the GPU alone.
    std::span<const voxel::FaceTexel> texels() const { return texels_; }
    std::span<const glm::vec3> dayLight() const { return dayLight_; }
    std::span<const uint8_t> levels() const { return levels_; }
    // Brings the GPU tracer's texels into the host's copy (waits for the device);
    // their values come back as the GPU holds them, quantised (face_cache.h).
    void sync();
    // Faces not converged, of all.
    size_t unconverged() const;
    // Fills the face atlas again from the GPU's texels (GpuScene::fillFaceAtlas)
    // once its tracer has traced every face an edit reached, in view or not, or a
    // cache begun untraced: first when none is left that was never traced since
    // its edit (the frames read through the atlas from then on), then once those
    // whose sky light alone was left have converged too. Call between frames.
    // True when it filled (a sync and a fill: caves 0.43 s).
    bool catchUpAtlas();

private:
    // Replaces the scene's GPU copy; `afterEdit`: an edit's (GpuFaceCache::afterEdit).
    void upload(const voxel::World& world, bool afterEdit = false);
    void levelsFromTexels();  // each face's level from its texels' rays
    // An edit with full light: traced here, and the faces whose light moved lit again.
    void editWithFullLight(const voxel::BrickTable& table, const voxel::World& world, const IndexBox& changed,
                           voxel::CacheEditStats* stats);

    GpuScene& scene_;
    std::vector<voxel::ExposedFace> faces_;
    std::vector<voxel::FaceTexel> texels_;
    std::vector<glm::vec3> dayLight_;  // full light over the day: kDayLightWords a face, or none
    std::vector<uint8_t> levels_;  // per face
    std::vector<uint32_t> order_;  // the GPU's face g is faces_[order_[g]]
    uint32_t daySunFirst_ = 0;     // where the GPU's texel words hold the day's sun bits (0: none)
    // What the atlas waits for, the GPU's copy made with faces to trace:
    // nothing; no face at levels 0 and 1 (GROTTO_FACE_ROUGH); every face converged.
    enum class AtlasWaits { Nothing, Rough, Converged };
    AtlasWaits atlasWaits_ = AtlasWaits::Nothing;
    std::vector<uint32_t> wordStorage_;  // the last layout's texel words, whose memory the next takes
    std::vector<voxel::GlowingFace> glowing_;  // with full light: the faces that glow, as of the last edit
    voxel::FaceBakeSettings settings_;
    double voxelSize_;
    std::unique_ptr<voxel::LightBakeThread> lightBake_;  // progressive with full light, until taken
    std::optional<IndexBox> editedSinceBake_;            // what edits changed since it started
    std::optional<Error> lightError_;
};

// The settings a bake with AO radius `radius` (world units) and k texels a side
// traces with under `lighting`: `grotto bake`'s defaults otherwise, its sun, its
// sky and whether it asks for full light.
voxel::FaceBakeSettings lightingBakeSettings(const voxel::Lighting& lighting, double radius,
                                             uint32_t texelsPerSide = voxel::kDefaultBakeTexels);
// The same under the world's own lighting: what `grotto bake` traces.
inline voxel::FaceBakeSettings worldBakeSettings(const voxel::World& world, double radius,
                                                 uint32_t texelsPerSide = voxel::kDefaultBakeTexels) {
    return lightingBakeSettings(world.desc().lighting, radius, texelsPerSide);
}

}  // namespace grotto
