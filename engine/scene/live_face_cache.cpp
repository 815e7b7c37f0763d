#include "engine/scene/live_face_cache.h"

#include "shaders/shared/face_trace.h"
#include "voxel/daylight.h"
#include "voxel/face_cache_layout.h"
#include "voxel/light_bake.h"

#include <algorithm>
#include <utility>

namespace grotto {

voxel::FaceBakeSettings lightingBakeSettings(const voxel::Lighting& lighting, double radius, uint32_t texelsPerSide) {
    const voxel::Lighting light = voxel::lightingInEffect(lighting);
    const double sky = light.ambientIntensity;
    return {.radius = radius, .texelsPerSide = texelsPerSide, .sunDirection = glm::dvec3(light.sunDirection),
            .sunAngleDegrees = double(light.sunAngle), .fullLight = light.ambientFrom == voxel::AmbientSource::Full,
            .skyZenith = glm::dvec3(light.skyZenith) * sky, .skyHorizon = glm::dvec3(light.skyHorizon) * sky,
            .day = lighting.sunFrom == voxel::SunSource::Day ? std::optional(voxel::sunPathOf(lighting)) : std::nullopt};
}

namespace {
// A face's level from its texels' rays: converged once they hold the settings'.
uint8_t levelOf(std::span<const voxel::FaceTexel> texels, const voxel::FaceBakeSettings& s) {
    uint32_t least = ~0u;
    for (const voxel::FaceTexel& t : texels) least = std::min(least, t.samples);
    return least == 0 ? 0 : least < s.rays ? 1 : GROTTO_FACE_LEVEL_CONVERGED;
}
}  // namespace

LiveFaceCache::LiveFaceCache(GpuScene& scene, const voxel::World& world, std::vector<voxel::ExposedFace> faces,
                             std::vector<voxel::FaceTexel> texels, const voxel::FaceBakeSettings& settings,
                             std::vector<glm::vec3> dayLight)
    : scene_(scene), faces_(std::move(faces)), texels_(std::move(texels)), dayLight_(std::move(dayLight)), settings_(settings),
      voxelSize_(world.voxelSize()) {
    if (settings_.fullLight) glowing_ = voxel::glowingFaces(world, faces_);
    // Room for edits to add faces in place (voxel::updateAfterEdit): a fresh copy
    // of tens of megabytes would cost an edit more than the rest of its work.
    texels_.reserve(texels_.size() + texels_.size() / 8);
    levelsFromTexels();
    upload(world);
}

void LiveFaceCache::levelsFromTexels() {
    const uint32_t perFace = settings_.texelsPerSide * settings_.texelsPerSide;
    levels_.resize(faces_.size());
    for (size_t f = 0; f < faces_.size(); ++f)
        levels_[f] = levelOf(std::span(texels_).subspan(f * perFace, perFace), settings_);
}

LiveFaceCache LiveFaceCache::load(GpuScene& scene, const voxel::BrickTable& table, const voxel::World& world,
                                  double radius, const std::filesystem::path& bake) {
    std::vector<voxel::ExposedFace> faces = voxel::exposedFaces(table, world);
    // The header first: another world's file costs nothing more.
    const voxel::FaceCacheHeader header = voxel::requireBakeOf(world, radius, faces.size(), bake);
    std::vector<voxel::FaceTexel> texels(header.texelCount());
    voxel::readFaceCacheTexels(bake, header, texels);
    std::vector<glm::vec3> dayLight(voxel::hasDayLight(header) ? header.faceCount * voxel::kDayLightWords : 0);
    voxel::readFaceCacheDayLight(bake, header, dayLight);
    voxel::FaceBakeSettings settings = worldBakeSettings(world, radius, header.key.texelsPerSide);
    // Faces traced after an edit get as many rays as the bake gave its texels.
    settings.rays = header.rays, settings.sunRays = header.sunRays;
    return LiveFaceCache(scene, world, std::move(faces), std::move(texels), settings, std::move(dayLight));
}

LiveFaceCache LiveFaceCache::bake(GpuScene& scene, const voxel::BrickTable& table, const voxel::World& world,
                                  const voxel::FaceBakeSettings& settings) {
    std::vector<voxel::ExposedFace> faces = voxel::exposedFaces(table, world);
    const voxel::LightSources lights = voxel::lightSources(world.desc().lighting);
    if (settings.fullLight)
        voxel::requireLightBakeFits(world, faces.size(), settings.texelsPerSide, {}, lights.day.has_value());
    std::vector<voxel::FaceTexel> texels(faces.size() * settings.texelsPerSide * settings.texelsPerSide);
    voxel::bakeFaces(table, world, faces, settings, texels);
    std::vector<glm::vec3> dayLight(settings.fullLight && lights.day ? faces.size() * voxel::kDayLightWords : 0);
    if (settings.fullLight) voxel::bakeLight(table, world, faces, settings.texelsPerSide, lights, {}, texels, {}, dayLight);
    return LiveFaceCache(scene, world, std::move(faces), std::move(texels), settings, std::move(dayLight));
}

LiveFaceCache LiveFaceCache::progressive(GpuScene& scene, const voxel::BrickTable& table, const voxel::World& world,
                                         const voxel::FaceBakeSettings& settings) {
    std::vector<voxel::ExposedFace> faces = voxel::exposedFaces(table, world);
    std::vector<voxel::FaceTexel> texels(faces.size() * settings.texelsPerSide * settings.texelsPerSide);
    LiveFaceCache cache(scene, world, std::move(faces), std::move(texels), settings);
    if (settings.fullLight) cache.lightBake_ = std::make_unique<voxel::LightBakeThread>(world, settings);
    return cache;
}

bool LiveFaceCache::takeBakedLight(const voxel::BrickTable& table, const voxel::World& world) {
    if (!lightBake_ || !lightBake_->finished()) return false;
    voxel::BakedLight baked;
    try {
        baked = lightBake_->take();
    } catch (const Error& e) {
        lightError_ = e;
        lightBake_.reset();
        return false;
    }
    lightBake_.reset();
    faces_ = std::move(baked.faces);
    texels_ = std::move(baked.texels);
    glowing_ = std::move(baked.glowing);
    dayLight_ = std::move(baked.dayLight);
    if (const std::optional<IndexBox> changed = std::exchange(editedSinceBake_, std::nullopt))
        editWithFullLight(table, world, *changed, nullptr);
    else {
        levelsFromTexels();
        upload(world);
    }
    return true;
}

double LiveFaceCache::lightBaked() const { return lightBake_ ? std::min(lightBake_->done(), 0.999) : 1.0; }  // 1 once taken

void LiveFaceCache::waitForLight() {
    if (lightBake_) lightBake_->wait();
}

void LiveFaceCache::sync() {
    if (!scene_.faceCache_) return;
    const std::vector<uint8_t> levels = scene_.faceCache_->readLevels();
    bool traced = false;  // the tracer touched a face since the last sync
    for (size_t g = 0; g < order_.size() && !traced; ++g) traced = levels[g] != levels_[order_[g]];
    if (!traced) return;
    const std::vector<uint32_t> words = scene_.faceCache_->readTexelWords();
    const uint32_t perFace = settings_.texelsPerSide * settings_.texelsPerSide;
    const uint32_t sunRays = voxel::sunRaysPerTexel(settings_);
    for (size_t g = 0; g < order_.size(); ++g) {
        const uint32_t f = order_[g];
        if (levels[g] == levels_[f]) continue;  // the tracer did not touch it
        levels_[f] = levels[g];
        const bool full = levels_[f] >= 2;
        const uint32_t rays = full ? settings_.rays : std::min<uint32_t>(GROTTO_FACE_COARSE_RAYS, settings_.rays);
        const uint32_t sun = full ? sunRays : std::min<uint32_t>(GROTTO_FACE_COARSE_SUN_RAYS, sunRays);
        for (uint32_t t = 0; t < perFace; ++t) {
            voxel::FaceTexel& texel = texels_[size_t(f) * perFace + t];
            texel = voxel::unpackFaceTexel(voxel::packedTexel(words, g * perFace + t), rays, sun, settings_.fullLight);
            if (daySunFirst_) texel.daySun = words[daySunFirst_ + g * perFace + t], texel.dayPositions = voxel::kDaySunPositions;
        }
    }
}

size_t LiveFaceCache::unconverged() const {
    return size_t(std::count_if(levels_.begin(), levels_.end(), [](uint8_t l) { return l != GROTTO_FACE_LEVEL_CONVERGED; }));
}

void LiveFaceCache::edited(const voxel::BrickTable& table, const voxel::World& world, const IndexBox& changed,
                           voxel::CacheEditStats* stats) {
    sync();  // what the GPU traced since the last edit is carried over with the rest
    // Full light is traced here: the GPU's tracer knows the sky's light alone.
    // While the world's light is still baking, the faces hold the sky's light
    // alone; the bake is brought up to this edit when it is taken.
    if (settings_.fullLight && !lightBake_) return editWithFullLight(table, world, changed, stats);
    if (lightBake_)
        editedSinceBake_ = editedSinceBake_ ? editedSinceBake_->merged(changed) : changed;
    const std::vector<voxel::ExposedFace> before = faces_;
    std::vector<voxel::FaceReach> reach;
    voxel::updateAfterEdit(table, world, changed, settings_, faces_, texels_, stats, false, &reach);
    std::vector<uint8_t> levels(faces_.size(), 0);
    size_t was = 0;  // both lists are in order: walk them together
    for (size_t f = 0; f < faces_.size(); ++f) {
        while (was < before.size() && before[was] < faces_[f]) ++was;
        if (reach[f] == voxel::FaceReach::Stale) continue;  // traced again, coarse first, in view from the next frame
        const uint8_t old = levels_[was];
        // Only the sky moved: the old texels stand until the budget's rays reach them.
        levels[f] = reach[f] == voxel::FaceReach::Untouched ? old : std::min<uint8_t>(old, 2);
    }
    levels_ = std::move(levels);
    upload(world, true);
}

void LiveFaceCache::editWithFullLight(const voxel::BrickTable& table, const voxel::World& world,
                                      const IndexBox& changed, voxel::CacheEditStats* stats) {
    const std::vector<voxel::ExposedFace> before = faces_;
    std::vector<voxel::FaceReach> reach;
    const std::vector<glm::vec3> sentBefore = voxel::sentLight(world, faces_, texels_, settings_.texelsPerSide, dayLight_);
    voxel::updateAfterEdit(table, world, changed, settings_, faces_, texels_, stats, true, &reach);
    if (!dayLight_.empty()) dayLight_ = voxel::carriedDayLight(before, faces_, dayLight_);
    const voxel::RelightStats relit = voxel::relightAfterEdit(table, world, faces_, settings_.texelsPerSide, texels_,
                                                              reach, changed, before, sentBefore, glowing_, dayLight_);
    glowing_ = voxel::glowingFaces(world, faces_);
    if (stats) stats->relit = relit.faces;
    levelsFromTexels();
    upload(world, true);
}

void LiveFaceCache::upload(const voxel::World& world, bool afterEdit) {
    voxel::FaceCacheArrays arrays =
        voxel::layFaceCache(faces_, texels_, settings_.texelsPerSide, settings_.fullLight, std::move(wordStorage_));
    // With full light, what objects read of the light world faces send.
    if (settings_.fullLight) voxel::appendFaceMaterials(arrays, faces_, world);
    if (voxel::daySunPositions(settings_)) voxel::appendDaySun(arrays, texels_);
    if (!dayLight_.empty()) voxel::appendDayLight(arrays, texels_, dayLight_);
    std::vector<uint8_t> gpuLevels(arrays.faceOrder.size());
    for (size_t g = 0; g < gpuLevels.size(); ++g) gpuLevels[g] = levels_[arrays.faceOrder[g]];
    // The faces not converged, for the tracer to reach in view or not: those never
    // traced since their edit first (levels 0 and 1), then those whose sky alone is left.
    std::vector<glm::uvec4> backlog;
    size_t rough = 0;
    for (uint8_t from : {0, 2})
        for (size_t g = 0; g < gpuLevels.size(); ++g) {
            const uint8_t level = gpuLevels[g] & 3u;
            if (level == GROTTO_FACE_LEVEL_CONVERGED || (level < 2) != (from == 0)) continue;
            const voxel::ExposedFace& face = faces_[arrays.faceOrder[g]];
            backlog.push_back(faceBacklogEntry(face.cell, face.dir, uint32_t(g)));
            rough += from == 0;
        }
    auto gpu = std::make_unique<GpuFaceCache>(
        scene_.ctx, arrays,
        GpuFaceCache::Sun{glm::vec3(settings_.sunDirection), float(settings_.sunAngleDegrees),
                          voxel::daySunPositions(settings_) ? settings_.day : std::nullopt},
        FaceCacheRays{settings_.rays, voxel::sunRaysPerTexel(settings_), float(settings_.radius / voxelSize_)}, gpuLevels,
        FaceCacheSky{settings_.fullLight, glm::vec3(settings_.skyZenith), glm::vec3(settings_.skyHorizon)}, backlog);
    if (afterEdit) gpu->setAfterEdit();
    vkDeviceWaitIdle(scene_.ctx.device);  // no frame in flight may still read the old copy
    scene_.faceCache_ = std::move(gpu);
    // The atlas holds texels as they are now: what the GPU's tracer changes later
    // is not in it. It is filled once no face is left that was never traced since
    // its edit (here, or when the tracer has traced them: catchUpAtlas), and again
    // once the faces whose sky alone was left have converged too.
    atlasWaits_ = rough ? AtlasWaits::Rough : backlog.empty() ? AtlasWaits::Nothing : AtlasWaits::Converged;
    if (rough)
        scene_.staleFaceAtlas();
    else
        scene_.fillFaceAtlas(arrays);
    order_ = std::move(arrays.faceOrder);
    daySunFirst_ = arrays.daySunFirst;
    wordStorage_ = std::move(arrays.texels);
}

bool LiveFaceCache::catchUpAtlas() {
    if (atlasWaits_ == AtlasWaits::Nothing || lightBake_ || !scene_.faceCache_) return false;
    // The header as the last frame to finish left it.
    const std::vector<uint32_t> header = scene_.faceCache_->lastHeader();
    if (header[atlasWaits_ == AtlasWaits::Rough ? GROTTO_FACE_ROUGH : GROTTO_FACE_UNCONVERGED] != 0) return false;
    atlasWaits_ = header[GROTTO_FACE_UNCONVERGED] == 0 ? AtlasWaits::Nothing : AtlasWaits::Converged;
    sync();
    voxel::FaceCacheArrays arrays =
        voxel::layFaceCache(faces_, texels_, settings_.texelsPerSide, settings_.fullLight, std::move(wordStorage_));
    vkDeviceWaitIdle(scene_.ctx.device);  // no frame in flight may still bind the atlas's old buffers
    scene_.fillFaceAtlas(arrays);
    wordStorage_ = std::move(arrays.texels);
    return true;
}

}  // namespace grotto
