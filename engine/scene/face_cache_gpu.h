#pragma once
// A face cache on the GPU: the three arrays of shaders/shared/face_cache.h in
// storage buffers (voxel/face_cache_layout.h lays them out), what a pass that
// reads it binds after its own inputs (shaders/face_cache.glsl), and what its
// tracer keeps (shaders/shared/face_trace.h): each face's level, the faces asked
// for this frame and the queue of them.
#include "engine/vk/pipeline.h"
#include "engine/vk/resources.h"
#include "voxel/daylight.h"
#include "voxel/face_cache_layout.h"

#include <optional>
#include <span>
#include <vector>

namespace grotto {

// The sun a cache's sun visibility was traced for.
struct FaceCacheSun {
    glm::vec3 direction{0.0f, 1.0f, 0.0f};
    float angleDegrees = 0.0f;
    // The day's sun: the path whose positions each texel holds a bit for
    // (voxel::FaceTexel::daySun) instead of one sun's visibility.
    std::optional<voxel::SunPath> day;
};

// With full light: the sky a texel traced on the GPU (without the bake) is lit
// by alone, its colours times its intensity.
struct FaceCacheSky {
    bool fullLight = false;
    glm::vec3 zenith{0.0f}, horizon{0.0f};
};

// The rays a converged texel holds, for the GPU's tracer to match.
struct FaceCacheRays {
    uint32_t rays = 64, sunRays = 16;
    float radiusVoxels = 4.0f;  // AO's R
};

// Face g (in the arrays' face order) of `cell`, looking `dir`, as the tracer's
// queue and backlog list it.
inline glm::uvec4 faceBacklogEntry(glm::ivec3 cell, uint32_t dir, uint32_t g) {
    return glm::uvec4(glm::uvec3(cell), dir | (g << 3));
}

class GpuFaceCache {
public:
    using Sun = FaceCacheSun;
    // `levels`: each face's (shared/face_trace.h), in the arrays' face order
    // (FaceCacheArrays::faceOrder); empty: all converged. `backlog`: the faces not
    // converged, as the tracer's queue lists them (faceBacklogEntry), in view or not.
    GpuFaceCache(vk::Context& ctx, const voxel::FaceCacheArrays& arrays, Sun sun = {}, FaceCacheRays rays = {},
                 std::span<const uint8_t> levels = {}, FaceCacheSky sky = {}, std::span<const glm::uvec4> backlog = {});
    ~GpuFaceCache();
    GpuFaceCache(const GpuFaceCache&) = delete;
    GpuFaceCache& operator=(const GpuFaceCache&) = delete;

    uint32_t table() const { return table_; }
    uint32_t texelsPerSide() const { return texelsPerSide_; }
    uint32_t faceCount() const { return faceCount_; }
    uint32_t materialsFirst() const { return materialsFirst_; }  // FaceCacheArrays::materialsFirst
    uint32_t daySunFirst() const { return daySunFirst_; }        // FaceCacheArrays::daySunFirst
    uint32_t dayLightFirst() const { return dayLightFirst_; }    // FaceCacheArrays::dayLightFirst
    uint32_t dayFacesFirst() const { return dayFacesFirst_; }    // FaceCacheArrays::dayFacesFirst
    const Sun& sun() const { return sun_; }
    const FaceCacheSky& sky() const { return sky_; }
    const FaceCacheRays& rays() const { return rays_; }
    // This copy, among all copies made in the process: a pass tells a new one from
    // the one it traced last frame, even at the same address.
    uint64_t id() const { return id_; }
    // Made by an edit: its first frame gives the faces the edit reached in view
    // their first look alone (face_cache_trace_pass.h).
    bool afterEdit() const { return afterEdit_; }
    void setAfterEdit() { afterEdit_ = true; }
    // The cache's own arrays and levels (what `info` and `bench` report); the
    // tracer's queue, backlog and request bits come on top.
    size_t gpuBytes() const { return size_t(bricks_.size + records_.size + texels_.size + levels_.size); }
    // Of those, the day's sun bits' (0 without).
    size_t daySunBytes() const { return daySunFirst_ ? size_t(faceCount_) * texelsPerSide_ * texelsPerSide_ * 4 : 0; }
    // And full light over the day's: the texels' sky weights and the faces' day words.
    size_t dayLightBytes() const {
        return dayLightFirst_ ? size_t(faceCount_) * (texelsPerSide_ * texelsPerSide_ + voxel::kDayLightWords) * 4 : 0;
    }

    // Appends the three buffers' bindings (bricks, records, texels) to a pass's own.
    static std::vector<VkDescriptorType> withBindings(std::vector<VkDescriptorType> own);
    std::vector<vk::Binding> withBindings(std::vector<vk::Binding> own) const;

    // Appends the levels' buffer (shaders/face_cache_levels.glsl) to a pass's own.
    static std::vector<VkDescriptorType> withLevelsBinding(std::vector<VkDescriptorType> own);
    std::vector<vk::Binding> withLevelsBinding(std::vector<vk::Binding> own) const;

    // Appends the buffers a pass that asks for faces binds (levels, request bits,
    // queue, header: shaders/face_cache_requests.glsl) to a pass's own.
    static std::vector<VkDescriptorType> withRequestBindings(std::vector<VkDescriptorType> own);
    std::vector<vk::Binding> withRequestBindings(std::vector<vk::Binding> own) const;

    // The tracer's buffers (face_cache_trace_pass.h).
    const vk::Buffer& texels() const { return texels_; }
    const vk::Buffer& dayPositions() const { return dayPositions_; }  // toward the sun at each, a vec4 each
    const vk::Buffer& levels() const { return levels_; }
    const vk::Buffer& requested() const { return requested_; }
    const vk::Buffer& queue() const { return queue_; }
    const vk::Buffer& backlog() const { return backlog_; }
    const vk::Buffer& header() const { return header_; }  // host-visible
    // The last finished frame's header words (shared/face_trace.h).
    std::vector<uint32_t> lastHeader() const;

    // Each face's level (in the arrays' face order) and the texels' packed words, as
    // the GPU holds them now: each waits for the device. The levels are a 32nd of
    // the words' size: read first, they tell whether the words are needed.
    std::vector<uint8_t> readLevels() const;
    std::vector<uint32_t> readTexelWords() const;

private:
    vk::Context& ctx_;
    vk::Buffer bricks_, records_, texels_, levels_, requested_, queue_, backlog_, header_, dayPositions_;
    uint32_t table_, texelsPerSide_, faceCount_, materialsFirst_, daySunFirst_, dayLightFirst_, dayFacesFirst_;
    Sun sun_;
    FaceCacheRays rays_;
    FaceCacheSky sky_;
    uint64_t id_;
    bool afterEdit_ = false;
};

}  // namespace grotto
