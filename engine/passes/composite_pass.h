#pragma once
// Composite pass. Reads: the surface id, the palette, frame uniforms and, with AO,
// the AO chain's output, full-res depth and the AO constants (it upsamples the AO
// itself, see upsample.glsl) and, with shadows, the shadow image. Writes: RGBA32F
// scene-linear colour: sun Lambert x shadow + ambient x AO (multi-bounce from
// albedo), and the sky, times the exposure. No history. Object faces are lit with
// their turned normals (the objects' uniforms, shaders/shared/objects.h). The
// ambient is a constant or the sky's light (shared/sky.h), around VBAO's bent
// normals where the frame has them. With the face cache (--ao cache) there is no
// AO chain: world surfaces take AO, sky light and, while its sun is the frame's,
// sun visibility from the cache at each pixel's point (composite_cache.comp), less
// what objects take, and objects' own from the object light pass.
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/compute_pass.h"
#include "engine/passes/gbuffer_pass.h"
#include "engine/scene/face_cache_gpu.h"

#include <optional>
#include <tuple>

namespace grotto {

struct CompositeShape {
    bool withAo = true;            // an AO chain's output to upsample (never with the face cache)
    bool withShadow = false;       // the shadow pass's image
    bool withBentNormals = false;  // VBAO's bent normals light the sky's ambient
    bool faceCache = false;        // --ao cache: the face cache instead of an AO chain
    bool cachedSun = false;        // with it: world surfaces take the cache's sun visibility
    bool objectLight = false;      // with it: objects' AO and sky light from the object light pass
    bool shadowEdges = false;      // with the cache's sun: its shadow edges' pixels listed (shadow_edge_pass.h)
    bool askFaces = false;         // with it, while faces have not converged: the texels' faces asked for
    bool fullLight = false;        // with it: the plan's cacheFullLight, cacheDayLight and daySun
    bool dayLight = false;
    bool daySun = false;
    bool atlas = false;            // with it: the texels read through the atlas (FramePlan::faceAtlas)
    uint32_t listPixels = 0;       // with the atlas: the frame's pixels, what the chain's pass may be left
    bool operator==(const CompositeShape&) const = default;
};

class CompositePass {
public:
    CompositePass(vk::Context& ctx, const CompositeShape& shape);
    ~CompositePass();
    CompositePass(const CompositePass&) = delete;
    CompositePass& operator=(const CompositePass&) = delete;
    // Every frame has one; while the face cache has faces not converged, AskingCompositePass instead.
    static bool runs(const FramePlan&) { return true; }
    static std::tuple<CompositeShape> key(const FramePlan& plan) { return {shapeFor(plan, false)}; }
    static CompositeShape shapeFor(const FramePlan& plan, bool askFaces);
    // `ao`: the AO chain's output (or its 1x1 placeholder without AO).
    static PassDecl declare(TargetRef ao) {
        return {"composite", {{TargetId::Surface, Access::Sampled}, {TargetId::Color, Access::Write}, {ao, Access::Read},
                              {TargetId::Depth, Access::Sampled}, {TargetId::Shadow, Access::Read},
                              {TargetId::AoBentNormal, Access::Read}, {TargetId::ObjectLight, Access::Read},
                              {TargetId::AtlasRecord, Access::Sampled}}};
    }
    // Without AO, `aoHalf` and `gtaoConstants` are placeholders the shader ignores;
    // without shadows, so is `shadow`; without bent normals, so is `bentNormals`.
    // With the face cache, `faceCache`.
    struct Inputs {
        const vk::Image& aoHalf;
        const vk::Buffer& frame;
        const vk::Buffer& palette;
        const vk::Buffer& gtaoConstants;
        const vk::Buffer& objectUniforms;
        const vk::Image& shadow;
        const vk::Image& bentNormals;
        const GpuFaceCache* faceCache = nullptr;
        const vk::Image* objectLight = nullptr;  // with the face cache: the object light pass's (or a placeholder)
        const vk::Buffer* shadowEdges = nullptr;  // with shadowEdges: the list it appends to
        const vk::Image* atlasRecord = nullptr;   // with the atlas: the G-buffer's records and the scene's cells
        const vk::Buffer* atlasCells = nullptr;
    };
    void record(VkCommandBuffer cmd, const GBufferTargets& gbuffer, const vk::Image& color, const Inputs& in);

private:
    vk::Context& ctx_;
    CompositeShape shape_;
    ComputePass pass_;
    // With the atlas: the chain's read of the pixels whose quad has no region (a
    // coarser level), over the list the atlas's pass appends them to.
    std::optional<ComputePass> withoutRegion_;
    vk::Buffer chainList_;
};

// The composite while the face cache has faces in view not converged: it asks for
// the faces of the texels it reads (the frame picks it by the cache's last count).
class AskingCompositePass : public CompositePass {
public:
    using CompositePass::CompositePass;
    static bool runs(const FramePlan& plan) { return plan.cacheTracing; }
    static std::tuple<CompositeShape> key(const FramePlan& plan) { return {shapeFor(plan, true)}; }
};

}  // namespace grotto
