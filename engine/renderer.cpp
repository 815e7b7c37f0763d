// The whole frame on one screen: G-buffer, then composite, with their barriers.
#include "engine/renderer.h"

#include "engine/vk/readback.h"
#include "shaders/shared/frame.h"
#include "shaders/shared/quad.h"

#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

namespace grotto {
namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

gpu::FrameUniforms frameUniforms(const Camera& camera, const voxel::Lighting& l) {
    gpu::FrameUniforms u{};
    u.viewProj = camera.viewProjRelative();
    u.invViewProj = glm::mat4(glm::inverse(glm::dmat4(u.viewProj)));
    u.sunDirection = glm::vec4(l.sunDirection, 0.0f);
    u.sunRadiance = glm::vec4(l.sunColor * l.sunIntensity, 0.0f);
    u.ambient = glm::vec4(l.ambientColor * l.ambientIntensity, 0.0f);
    u.skyZenith = glm::vec4(l.skyZenith, 0.0f);
    u.skyHorizon = glm::vec4(l.skyHorizon, 0.0f);
    // rayDirection() is linear in the pixel position before normalising.
    const double t = std::tan(camera.fovY * 0.5);
    const glm::dvec3 right = camera.basis[0] * (2.0 * t * camera.aspect() / camera.width);
    const glm::dvec3 down = -camera.basis[1] * (2.0 * t / camera.height);
    const glm::dvec3 corner = -camera.basis[2] - camera.basis[0] * (t * camera.aspect()) + camera.basis[1] * t;
    u.rayOrigin = glm::vec4(glm::vec3(corner), 0.0f);
    u.rayStepX = glm::vec4(glm::vec3(right), 0.0f);
    u.rayStepY = glm::vec4(glm::vec3(down), 0.0f);
    u.size = {camera.width, camera.height};
    return u;
}

}  // namespace

Renderer::Renderer(vk::Context& ctx, const GpuScene& scene, const voxel::Lighting& lighting, uint32_t width,
                   uint32_t height)
    : ctx_(ctx), scene_(scene), lighting_(lighting), timestamps_(ctx, 8) {
    const VkExtent2D extent{width, height};
    const VkImageUsageFlags read = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    gbuffer_.depth = vk::createImage(ctx, extent, VK_FORMAT_D32_SFLOAT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | read);
    gbuffer_.surface = vk::createImage(ctx, extent, kSurfaceFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | read);
    color_ = vk::createImage(ctx, extent, kColorFormat, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    frame_ = vk::createBuffer(ctx, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
    gbufferPass_ = std::make_unique<GBufferPass>(ctx);
    compositePass_ = std::make_unique<CompositePass>(ctx);

    VkCommandBufferAllocateInfo ai{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                   .commandPool = ctx.commandPool,
                                   .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                   .commandBufferCount = 1};
    VK_CHECK(vkAllocateCommandBuffers(ctx.device, &ai, &cmd_));
    VkFenceCreateInfo fci{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(ctx.device, &fci, nullptr, &fence_));
}

Renderer::~Renderer() {
    vkDeviceWaitIdle(ctx_.device);
    vkDestroyFence(ctx_.device, fence_, nullptr);
    vkFreeCommandBuffers(ctx_.device, ctx_.commandPool, 1, &cmd_);
    gbufferPass_.reset();
    compositePass_.reset();
    for (vk::Image* i : {&gbuffer_.depth, &gbuffer_.surface, &color_}) vk::destroy(ctx_, *i);
    vk::destroy(ctx_, frame_);
}

size_t Renderer::targetBytes() const {
    size_t n = 0;
    for (const vk::Image* i : {&gbuffer_.depth, &gbuffer_.surface, &color_}) n += i->memory.size;
    return n;
}

FrameStats Renderer::render(const Camera& camera) {
    const auto start = std::chrono::steady_clock::now();
    const gpu::FrameUniforms uniforms = frameUniforms(camera, lighting_);
    std::memcpy(frame_.mapped(), &uniforms, sizeof uniforms);

    VkCommandBuffer cmd = cmd_;
    VK_CHECK(vkResetCommandBuffer(cmd, 0));
    VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
    timestamps_.reset(cmd);

    const auto top = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
    const auto fragmentTests = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    const auto colorOut = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    const auto compute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    const auto readOnly = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const auto depthWrite = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

    // G-buffer: previous contents are not needed (cleared), so start from UNDEFINED.
    vk::transition(cmd, gbuffer_.depth, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, top, 0,
                   fragmentTests, depthWrite);
    vk::transition(cmd, gbuffer_.surface, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, top, 0,
                   colorOut, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    timestamps_.begin(cmd, "gbuffer");
    FrameStats stats;
    stats.quadsDrawn = gbufferPass_->record(cmd, gbuffer_, scene_, frame_, camera);
    timestamps_.end(cmd);

    // Composite reads the G-buffer and overwrites all of the colour target.
    vk::transition(cmd, gbuffer_.depth, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, readOnly, fragmentTests,
                   VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, compute, VK_ACCESS_SHADER_READ_BIT);
    vk::transition(cmd, gbuffer_.surface, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, readOnly, colorOut,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, compute, VK_ACCESS_SHADER_READ_BIT);
    vk::transition(cmd, color_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, top, 0, compute,
                   VK_ACCESS_SHADER_WRITE_BIT);
    timestamps_.begin(cmd, "composite");
    compositePass_->record(cmd, gbuffer_, color_, frame_, scene_.palette);
    timestamps_.end(cmd);

    VK_CHECK(vkEndCommandBuffer(cmd));
    VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
    VK_CHECK(vkResetFences(ctx_.device, 1, &fence_));
    VK_CHECK(vkQueueSubmit(ctx_.queue, 1, &si, fence_));
    VK_CHECK(vkWaitForFences(ctx_.device, 1, &fence_, VK_TRUE, UINT64_MAX));
    stats.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats.passMs = timestamps_.read();
    return stats;
}

FrameImages Renderer::readback(const Camera& camera, bool aovs) {
    FrameImages f;
    f.width = color_.extent.width;
    f.height = color_.extent.height;
    const size_t n = size_t(f.width) * f.height;
    const auto color = vk::readImage(ctx_, color_, VK_IMAGE_LAYOUT_GENERAL, 16);
    f.color.resize(4 * n);
    std::memcpy(f.color.data(), color.data(), color.size());
    if (!aovs) return f;

    const auto ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const auto depth = vk::readImage(ctx_, gbuffer_.depth, ro, 4);
    const auto surface = vk::readImage(ctx_, gbuffer_.surface, ro, 2);
    f.depth.resize(n);
    f.normal.assign(3 * n, 0.0f);
    f.albedo.assign(3 * n, 0.0f);
    for (size_t i = 0; i < n; ++i) {
        float d;
        std::memcpy(&d, depth.data() + 4 * i, 4);
        f.depth[i] = d > 0.0f ? float(camera.linearDepth(d)) : std::numeric_limits<float>::infinity();
        uint16_t id;
        std::memcpy(&id, surface.data() + 2 * i, 2);
        if (id == 0) continue;  // sky
        const uint32_t face = gpu::surfaceFace(id), material = gpu::surfaceMaterial(id);
        f.normal[3 * i + gpu::faceAxis(face)] = gpu::facePositive(face) ? 1.0f : -1.0f;
        if (material >= 1 && material <= scene_.albedo.size())
            for (int c = 0; c < 3; ++c) f.albedo[3 * i + c] = scene_.albedo[material - 1][c];
    }
    return f;
}

}  // namespace grotto
