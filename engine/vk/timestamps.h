#pragma once
// GPU timestamps around named passes: begin/end per pass, read after the frame.
#include "engine/vk/context.h"

#include <string>
#include <utility>
#include <vector>

namespace grotto::vk {

class Timestamps {
public:
    Timestamps(Context& ctx, uint32_t maxPasses);
    ~Timestamps();

    void reset(VkCommandBuffer cmd);  // at the start of a frame
    void begin(VkCommandBuffer cmd, const std::string& pass);
    void end(VkCommandBuffer cmd);
    // The pass begun and not yet ended, if any: what work recorded now is timed under.
    const std::string* open() const { return open_ ? &names_.back() : nullptr; }
    // Milliseconds per pass of the last completed frame, in recording order.
    std::vector<std::pair<std::string, double>> read();

private:
    Context& ctx_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t max_;
    uint32_t validBits_ = 64;
    std::vector<std::string> names_;
    bool open_ = false;
};

}  // namespace grotto::vk
