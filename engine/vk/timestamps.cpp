#include "engine/vk/timestamps.h"

namespace grotto::vk {

Timestamps::Timestamps(Context& ctx, uint32_t maxPasses) : ctx_(ctx), max_(maxPasses) {
    VkQueryPoolCreateInfo ci{.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                             .queryType = VK_QUERY_TYPE_TIMESTAMP,
                             .queryCount = 2 * maxPasses};
    VK_CHECK(vkCreateQueryPool(ctx.device, &ci, nullptr, &pool_));
    uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physical, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physical, &n, families.data());
    validBits_ = families[ctx.queueFamily].timestampValidBits;
}

Timestamps::~Timestamps() { vkDestroyQueryPool(ctx_.device, pool_, nullptr); }

void Timestamps::reset(VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, pool_, 0, 2 * max_);
    names_.clear();
    open_ = false;
}

void Timestamps::begin(VkCommandBuffer cmd, const std::string& pass) {
    if (names_.size() >= max_) throw Error::internal("timestamps", "more passes than query slots");
    // Stamped once all earlier work is done, so passes never overlap in the figures.
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, 2 * uint32_t(names_.size()));
    names_.push_back(pass);
    open_ = true;
}

void Timestamps::end(VkCommandBuffer cmd) {
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, 2 * uint32_t(names_.size()) - 1);
    open_ = false;
}

std::vector<std::pair<std::string, double>> Timestamps::read() {
    std::vector<std::pair<std::string, double>> out;
    if (names_.empty()) return out;
    std::vector<uint64_t> ticks(2 * names_.size());
    VK_CHECK(vkGetQueryPoolResults(ctx_.device, pool_, 0, uint32_t(ticks.size()), ticks.size() * sizeof(uint64_t),
                                   ticks.data(), sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const double msPerTick = double(ctx_.properties.limits.timestampPeriod) * 1e-6;
    const uint64_t mask = validBits_ >= 64 ? ~uint64_t(0) : (uint64_t(1) << validBits_) - 1;
    for (size_t i = 0; i < names_.size(); ++i)
        out.emplace_back(names_[i], double((ticks[2 * i + 1] - ticks[2 * i]) & mask) * msPerTick);
    return out;
}

}  // namespace grotto::vk
