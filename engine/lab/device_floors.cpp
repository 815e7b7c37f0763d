#include "engine/lab/device_floors.h"

#include "engine/passes/compute_pass.h"
#include "engine/vk/readback.h"
#include "engine/vk/resources.h"
#include "engine/vk/timestamps.h"
#include "grotto/error.h"

#include <algorithm>
#include <string>

namespace grotto {
namespace {

constexpr uint32_t kWidth = 1024;      // threads a row of the 2D grid
constexpr uint32_t kRepeats = 8;       // dispatches between the two timestamps
constexpr int kRuns = 3;               // the best of these
constexpr uint32_t kFmaRounds = 256;

// The best of kRuns: each records `dispatch` kRepeats times between two
// timestamps, a barrier between dispatches.
template <typename Dispatch>
double bestMs(vk::Context& ctx, const Dispatch& dispatch) {
    vk::Timestamps stamps(ctx, 1);
    double best = 0.0;
    for (int run = 0; run < kRuns; ++run) {
        ctx.submitAndWait([&](VkCommandBuffer cmd) {
            stamps.reset(cmd);
            stamps.begin(cmd, "floor");
            for (uint32_t k = 0; k < kRepeats; ++k) {
                dispatch(cmd);
                computeToCompute(cmd);
            }
            stamps.end(cmd);
        });
        const double ms = stamps.read().front().second;
        if (ms > 0.0 && (best == 0.0 || ms < best)) best = ms;
    }
    if (best <= 0.0) throw Error::internal("measureDeviceFloors", "the device's timestamps read no time");
    return best;
}

}  // namespace

// The pattern the copy's source holds: word i (of 32 bits).
uint32_t patternWord(uint64_t i) { return uint32_t(i * 2654435761u); }

DeviceFloors measureDeviceFloors(vk::Context& ctx, uint32_t copyMiB) {
    DeviceFloors floors;
    const uint64_t copyWords = (uint64_t(std::max(copyMiB, 1u)) << 20) / 16;  // 16-byte words, whole rows of kWidth
    const VkDeviceSize bytes = copyWords * 16;
    const uint32_t fmaThreads = uint32_t(copyWords / 16);  // 2^18 at the default: a GPU's every lane, many times
    // Device-local, as a frame's targets are: a discrete GPU's host-visible
    // memory lies across its bus.
    vk::Buffer source = vk::uploadBuffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, [&](void* to) {
        auto* words = static_cast<uint32_t*>(to);
        for (uint64_t i = 0; i < 4 * copyWords; ++i) words[i] = patternWord(i);
    });
    vk::Buffer target, check, sums;
    try {
        target = vk::createBuffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false);
        check = vk::createBuffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
        sums = vk::createBuffer(ctx, VkDeviceSize(fmaThreads) * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
        {
            ComputePass copy(ctx, "floor_copy.comp", {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                             2 * sizeof(uint32_t));
            const uint32_t push[2] = {uint32_t(copyWords), kWidth};
            const double ms = bestMs(ctx, [&](VkCommandBuffer cmd) {
                copy.dispatch(cmd, {vk::storageBuffer(source.buffer), vk::storageBuffer(target.buffer)},
                              VkExtent2D{kWidth, uint32_t(copyWords / kWidth)}, 8, push);
            });
            ctx.submitAndWait([&](VkCommandBuffer cmd) {
                const VkBufferCopy region{.size = bytes};
                vkCmdCopyBuffer(cmd, target.buffer, check.buffer, 1, &region);
                vk::recordHostRead(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
            });
            const auto* words = static_cast<const uint32_t*>(check.mapped());
            for (uint64_t i = 0; i < 4 * copyWords; ++i)
                if (words[i] != patternWord(i))
                    throw Error::internal("measureDeviceFloors", "the copy kernel's word " + std::to_string(i) +
                                                                     " differs from its source's");
            floors.copyBytesPerMs = double(2 * bytes * kRepeats) / ms;
        }
        {
            ComputePass fma(ctx, "floor_fma.comp", {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, 2 * sizeof(uint32_t));
            const uint32_t push[2] = {kFmaRounds, kWidth};
            const double ms = bestMs(ctx, [&](VkCommandBuffer cmd) {
                fma.dispatch(cmd, {vk::storageBuffer(sums.buffer)}, VkExtent2D{kWidth, fmaThreads / kWidth}, 8, push);
            });
            floors.fmaPerMs = double(uint64_t(fmaThreads) * kFmaRounds * 32 * kRepeats) / ms;  // 8 vec4s a round
        }
    } catch (...) {
        vk::destroy(ctx, source), vk::destroy(ctx, target), vk::destroy(ctx, check), vk::destroy(ctx, sums);
        throw;
    }
    vk::destroy(ctx, source), vk::destroy(ctx, target), vk::destroy(ctx, check), vk::destroy(ctx, sums);
    return floors;
}

}  // namespace grotto
