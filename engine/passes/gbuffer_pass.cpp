#include "engine/passes/gbuffer_pass.h"

#include "engine/frame/frustum.h"
#include "engine/vk/pipeline.h"
#include "shaders/shared/frame.h"
#include "shaders/shared/objects.h"

#include <algorithm>
#include <limits>

namespace grotto {
namespace {

// The second attachment, if any: the motion target, or the face atlas's records.
enum class Second { None, Motion, AtlasRecord };

VkPipeline createPipeline(vk::Context& ctx, VkPipelineLayout layout, const char* vertex = "gbuffer.vert",
                          const char* fragment = "gbuffer.frag", Second second = Second::None) {
    const bool motion = second == Second::Motion;
    const uint32_t attachments = second == Second::None ? 1u : 2u;
    const vk::ShaderModule vs = vk::loadShader(ctx, vertex);
    const vk::ShaderModule fs = vk::loadShader(ctx, fragment);
    VkPipelineShaderStageCreateInfo stages[2] = {
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, .stage = VK_SHADER_STAGE_VERTEX_BIT,
         .module = vs.handle(), .pName = "main"},
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, .stage = VK_SHADER_STAGE_FRAGMENT_BIT,
         .module = fs.handle(), .pName = "main"}};
    VkVertexInputBindingDescription vertexBinding{.binding = 0, .stride = 4, .inputRate = VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription vertexAttribute{.location = 0, .binding = 0, .format = VK_FORMAT_R32_UINT};
    VkPipelineVertexInputStateCreateInfo vertexInput{.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
                                                     .vertexBindingDescriptionCount = 1,
                                                     .pVertexBindingDescriptions = &vertexBinding,
                                                     .vertexAttributeDescriptionCount = 1,
                                                     .pVertexAttributeDescriptions = &vertexAttribute};
    VkPipelineInputAssemblyStateCreateInfo assembly{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
        .topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST};
    VkPipelineViewportStateCreateInfo viewport{.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                               .viewportCount = 1, .scissorCount = 1};
    // Counter-clockwise about the outward normal is front-facing (checked against the CPU ray cast).
    VkPipelineRasterizationStateCreateInfo raster{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
        .polygonMode = VK_POLYGON_MODE_FILL,
        .cullMode = VK_CULL_MODE_BACK_BIT,
        .frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE,
        .lineWidth = 1.0f};
    VkPipelineMultisampleStateCreateInfo multisample{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
        .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT};
    VkPipelineDepthStencilStateCreateInfo depth{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
        .depthTestEnable = VK_TRUE,
        .depthWriteEnable = VK_TRUE,
        .depthCompareOp = VK_COMPARE_OP_GREATER};  // reverse-Z: nearer is larger
    // Identical for both attachments (no independent blend): what a format lacks is not written.
    const VkColorComponentFlags mask = motion ? VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                                    VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT
                                       : second == Second::AtlasRecord ? VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT
                                                                      : VK_COLOR_COMPONENT_R_BIT;
    const VkPipelineColorBlendAttachmentState blendOff[2] = {{.colorWriteMask = mask}, {.colorWriteMask = mask}};
    VkPipelineColorBlendStateCreateInfo blend{.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
                                              .attachmentCount = attachments, .pAttachments = blendOff};
    VkDynamicState dynamicStates[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
                                             .dynamicStateCount = 2, .pDynamicStates = dynamicStates};
    const VkFormat formats[2] = {kSurfaceFormat, motion ? kMotionFormat : kAtlasRecordFormat};
    VkPipelineRenderingCreateInfo rendering{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                            .colorAttachmentCount = attachments,
                                            .pColorAttachmentFormats = formats,
                                            .depthAttachmentFormat = VK_FORMAT_D32_SFLOAT};
    VkGraphicsPipelineCreateInfo ci{.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                    .pNext = &rendering,
                                    .stageCount = 2,
                                    .pStages = stages,
                                    .pVertexInputState = &vertexInput,
                                    .pInputAssemblyState = &assembly,
                                    .pViewportState = &viewport,
                                    .pRasterizationState = &raster,
                                    .pMultisampleState = &multisample,
                                    .pDepthStencilState = &depth,
                                    .pColorBlendState = &blend,
                                    .pDynamicState = &dynamic,
                                    .layout = layout};
    VkPipeline pipeline;
    VK_CHECK(vkCreateGraphicsPipelines(ctx.device, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline));
    return pipeline;
}

}  // namespace

PassDecl GBufferPass::declare() const {
    PassDecl d{"gbuffer", {{TargetId::Depth, Access::DepthAttachment}, {TargetId::Surface, Access::ColorAttachment}}};
    if (mode_ == GBufferMode::Motion) d.uses.push_back({TargetId::Motion, Access::ColorAttachment});
    if (atlas_) d.uses.push_back({TargetId::AtlasRecord, Access::ColorAttachment});
    return d;
}

GBufferPass::GBufferPass(vk::Context& ctx, GBufferMode mode, bool atlas) : ctx_(ctx), mode_(mode), atlas_(atlas) {
    std::vector<VkDescriptorType> bindings = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
    if (atlas) bindings.push_back(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);  // the quads' atlas records
    setLayout_ = vk::pushDescriptorLayout(ctx, bindings, VK_SHADER_STAGE_VERTEX_BIT);
    const Second record = atlas ? Second::AtlasRecord : Second::None;
    try {  // a shader that fails to load must not leak the layouts
        layout_ = vk::pipelineLayout(ctx, setLayout_, sizeof(gpu::ChunkPush), VK_SHADER_STAGE_VERTEX_BIT);
        if (mode != GBufferMode::Motion)
            pipeline_ = atlas ? createPipeline(ctx, layout_, "gbuffer_atlas.vert", "gbuffer_atlas.frag", record)
                              : createPipeline(ctx, layout_);
        if (mode != GBufferMode::World) {
            objectSetLayout_ = vk::pushDescriptorLayout(ctx, {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                                        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
            objectLayout_ = vk::pipelineLayout(ctx, objectSetLayout_, sizeof(gpu::ObjectPush), VK_SHADER_STAGE_VERTEX_BIT);
            const bool motion = mode == GBufferMode::Motion;
            // Objects have no records: theirs read (0, 0), and the composite reads no cache on them.
            objectPipeline_ = createPipeline(ctx, objectLayout_, motion ? "gbuffer_object.vert" : "gbuffer_still.vert",
                                             motion ? "gbuffer_motion.frag" : atlas ? "gbuffer_object_atlas.frag" : "gbuffer.frag",
                                             motion ? Second::Motion : record);
        }
    } catch (...) {
        release();
        throw;
    }
}

GBufferPass::~GBufferPass() { release(); }

void GBufferPass::release() {
    vkDestroyPipeline(ctx_.device, objectPipeline_, nullptr);
    vkDestroyPipelineLayout(ctx_.device, objectLayout_, nullptr);
    vkDestroyDescriptorSetLayout(ctx_.device, objectSetLayout_, nullptr);
    vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    vkDestroyDescriptorSetLayout(ctx_.device, setLayout_, nullptr);
}

namespace {

// A chunk's voxel coordinates to camera-relative world units: its corner and voxel size.
glm::dmat4 chunkMatrix(glm::dvec3 origin, double voxelSize) {
    glm::dmat4 m(voxelSize);
    m[3] = glm::dvec4(origin, 1.0);
    return m;
}

// The camera-relative bounds of a box after a transform (its eight corners).
void transformedBounds(const glm::dmat4& m, glm::vec3 lo, glm::vec3 hi, glm::vec3& outLo, glm::vec3& outHi) {
    outLo = glm::vec3(std::numeric_limits<float>::max());
    outHi = -outLo;
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 c(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
        const glm::vec3 w(m * glm::dvec4(c, 1.0));
        outLo = glm::min(outLo, w), outHi = glm::max(outHi, w);
    }
}

}  // namespace

uint64_t GBufferPass::record(VkCommandBuffer cmd, const GBufferTargets& t, const GpuScene& scene,
                             const vk::Buffer& frame, const Camera& camera, std::span<const QuadDraw> draws,
                             bool clear, const GBufferObjects* objects, bool drawObjects) {
    const VkExtent2D extent = t.depth.extent;
    const bool motion = mode_ == GBufferMode::Motion;
    auto attachment = [clear](const vk::Image& img, VkClearValue value) {
        return VkRenderingAttachmentInfo{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                         .imageView = img.view,
                                         .imageLayout = img.aspect == VK_IMAGE_ASPECT_DEPTH_BIT
                                                            ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL
                                                            : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                         .loadOp = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD,
                                         .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                         .clearValue = value};
    };
    VkRenderingAttachmentInfo color[2] = {attachment(t.surface, {}), {}};  // 0 = sky
    if (motion) color[1] = attachment(t.motion, {});                       // sky: no motion
    if (atlas_) color[1] = attachment(t.atlasRecord, {});                  // sky: no record
    VkRenderingAttachmentInfo depth = attachment(t.depth, {.depthStencil = {0.0f, 0}});
    VkRenderingInfo info{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                         .renderArea = {{0, 0}, extent},
                         .layerCount = 1,
                         .colorAttachmentCount = motion || atlas_ ? 2u : 1u,
                         .pColorAttachments = color,
                         .pDepthAttachment = &depth};
    ctx_.cmdBeginRendering(cmd, &info);
    VkViewport viewport{0, 0, float(extent.width), float(extent.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    auto bind = [&](VkPipeline pipeline, VkPipelineLayout layout, const GpuScene& s) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        if (atlas_ && layout == layout_)
            vk::pushBindings(ctx_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout,
                             {vk::uniformBuffer(frame.buffer), vk::storageBuffer(s.faceAtlasRecords().buffer)});
        else
            vk::pushBindings(ctx_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, {vk::uniformBuffer(frame.buffer)});
        const VkDeviceSize zero = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &s.vertices.buffer, &zero);
        vkCmdBindIndexBuffer(cmd, s.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    };
    if (motion)
        bind(objectPipeline_, objectLayout_, scene);
    else
        bind(pipeline_, layout_, scene);

    const Camera& previousCamera = objects && objects->previousCamera ? *objects->previousCamera : camera;
    const glm::dmat4 viewProj = camera.viewProjRelativeDouble();
    const glm::dmat4 previousViewProj = previousCamera.viewProjRelativeDouble();
    // The camera's voxel and its place in it, for chunks placed in whole voxels from it.
    const glm::dvec3 cameraIndex = (camera.position - scene.worldOrigin) / scene.voxelSize;
    const glm::dvec3 cameraVoxel = glm::floor(cameraIndex);
    const glm::vec4 cameraAndVoxelSize(glm::vec3(cameraIndex - cameraVoxel), float(scene.voxelSize));
    uint64_t drawn = 0;
    uint32_t pushed = UINT32_MAX;  // the chunk whose placement the push constants hold
    for (const QuadDraw& d : draws) {
        const GpuChunk& c = scene.chunks[d.chunk];
        if (d.chunk != pushed) {
            pushed = d.chunk;
            if (motion) {
                const gpu::ObjectPush push{
                    glm::mat4(viewProj * chunkMatrix(c.origin - camera.position, scene.voxelSize)),
                    glm::mat4(previousViewProj * chunkMatrix(c.origin - previousCamera.position, scene.voxelSize))};
                vkCmdPushConstants(cmd, objectLayout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
            } else {
                // Chunks beyond 2^30 voxels from the camera (never in view) are clamped there.
                const glm::dvec3 voxel = glm::clamp(glm::dvec3(c.index) - cameraVoxel, -1073741824.0, 1073741824.0);
                const gpu::ChunkPush push{glm::ivec4(glm::ivec3(voxel), 0), cameraAndVoxelSize};
                vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
            }
        }
        // Draws longer than the index buffer (merged clusters of one face range never are,
        // but runs across faces may be) go in pieces.
        for (uint32_t done = 0; done < d.count;) {
            const uint32_t n = std::min(d.count - done, scene.indexQuads);
            vkCmdDrawIndexed(cmd, 6 * n, 1, 0, int32_t(4 * (d.first + done)), 0);
            done += n;
        }
        drawn += d.count;
    }

    // Objects: each chunk through its object's pose, camera-relative in double
    // (exact far from the origin), culled by its transformed bounds; the object's
    // index (1, 2, ...) is the instance index, which the surface id carries.
    const Frustum frustum(camera);
    if (objects && drawObjects)
        for (size_t k = 0; k < objects->scenes.size(); ++k) {
            const GpuScene& s = *objects->scenes[k];
            if (s.chunks.empty()) continue;
            const voxel::ObjectPose& pose = objects->poses[k];
            const voxel::ObjectPose& before =
                objects->previousPoses.empty() ? pose : objects->previousPoses[k];
            const glm::dmat4 model = pose.worldFromLocal(camera.position);
            const glm::dmat4 previousModel = before.worldFromLocal(previousCamera.position);
            bind(objectPipeline_, objectLayout_, s);
            for (const GpuChunk& c : s.chunks) {
                const glm::dmat4 place = model * chunkMatrix(c.origin, 1.0);
                glm::vec3 lo, hi;
                transformedBounds(place, c.lo, c.hi, lo, hi);
                if (frustum.outside(lo, hi)) continue;
                const gpu::ObjectPush push{glm::mat4(viewProj * model * chunkMatrix(c.origin, s.voxelSize)),
                                           glm::mat4(previousViewProj * previousModel * chunkMatrix(c.origin, s.voxelSize))};
                vkCmdPushConstants(cmd, objectLayout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
                const GpuLevel& l = c.exact();
                for (int f = 0; f < 6; ++f) {
                    if (!l.faceCount[f]) continue;
                    vkCmdDrawIndexed(cmd, 6 * l.faceCount[f], 1, 0, int32_t(4 * l.faceFirst[f]), uint32_t(k + 1));
                    drawn += l.faceCount[f];
                }
            }
        }
    ctx_.cmdEndRendering(cmd);
    return drawn;
}

}  // namespace grotto
