#include "engine/frame/pass_traffic.h"

namespace grotto {

uint64_t declaredImageBytes(const PassDecl& decl, const FrameTargets& targets) {
    uint64_t bytes = 0;
    for (const TargetUse& use : decl.uses) {
        const vk::Image& image = targets.image(use.target);
        const uint64_t whole = uint64_t(image.extent.width) * image.extent.height * vk::texelBytes(image.format);
        bytes += use.access == Access::DepthAttachment ? 2 * whole : whole;
    }
    return bytes;
}

}  // namespace grotto
