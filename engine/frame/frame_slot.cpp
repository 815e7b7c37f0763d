#include "engine/frame/frame_slot.h"

#include "shaders/shared/frame.h"
#include "shaders/shared/gtao.h"
#include "shaders/shared/objects.h"
#include "shaders/shared/temporal.h"
#include "shaders/shared/trace.h"

namespace grotto {
namespace {

constexpr uint32_t kMaxTimedPasses = 16;

}  // namespace

FrameSlot::FrameSlot(vk::Context& context) : ctx(context), timestamps(context, kMaxTimedPasses) {
    try {
        frame = vk::createBuffer(ctx, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
        aoConstants = vk::createBuffer(ctx, sizeof(gpu::GtaoConstants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
        temporalConstants =
            vk::createBuffer(ctx, sizeof(gpu::TemporalConstants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
        traceConstants = vk::createBuffer(ctx, sizeof(gpu::TraceConstants), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        // The objects' normal tables: the composite reads them whether or not there are objects.
        objectUniforms = vk::createBuffer(ctx, sizeof(gpu::ObjectUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
        cmd = vk::allocateCommandBuffer(ctx);
    } catch (...) {
        release();
        throw;
    }
}

FrameSlot::~FrameSlot() { release(); }

void FrameSlot::release() {
    if (cmd) vkFreeCommandBuffers(ctx.device, ctx.commandPool, 1, &cmd);
    cmd = VK_NULL_HANDLE;
    for (vk::Buffer* b : {&frame, &aoConstants, &temporalConstants, &traceConstants, &objectUniforms, &staging, &hiz.buffer})
        vk::destroy(ctx, *b);
}

}  // namespace grotto
