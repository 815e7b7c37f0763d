// What the window shows besides the final colour: an AOV view read back and
// uploaded for the presenter, and screenshots of either.
#include "app/viewer/viewer_internal.h"

#include "common/printable.h"
#include "engine/image_output.h"

#include <cstdio>

namespace grotto::viewer {

std::filesystem::path Viewer::nextShotName() {
    for (;; ++shotCounter_) {
        char name[32];
        std::snprintf(name, sizeof name, "grotto-%03d.png", shotCounter_);
        if (!std::filesystem::exists(name)) return name;
    }
}

namespace {
std::vector<float> blackImage(uint32_t width, uint32_t height) {
    std::vector<float> rgba(size_t(width) * height * 4, 0.0f);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 1.0f;
    return rgba;
}
}  // namespace

// Reads the frame back for an AOV view or a screenshot.
void Viewer::readback(const Camera& camera) {
    const FrameImages f = renderer().readback(camera, true);
    const bool noLight = panel_.view == kCacheLightAov && f.light.empty();  // not lit from a face cache
    const std::vector<float> shown = panel_.view == "final" ? std::vector<float>()
                                     : noLight             ? blackImage(f.width, f.height)
                                                           : aovDisplay(f, panel_.view);
    if (pendingShot_) {
        writeShot(*pendingShot_, f, shown, camera);
        pendingShot_.reset();
    }
    if (panel_.view == "final") return;
    if (shown_.extent.width != f.width || shown_.extent.height != f.height) {
        vk::destroy(ctx_, shown_);
        shown_ = vk::createImage(ctx_, {f.width, f.height}, VK_FORMAT_R32G32B32A32_SFLOAT,
                                 VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                     VK_IMAGE_USAGE_SAMPLED_BIT);  // sampled: an image gets a view
    }
    vk::Buffer staging = vk::uploadBuffer(ctx_, shown.data(), shown.size() * sizeof(float), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        vk::transition(cmd, shown_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, .imageExtent = {f.width, f.height, 1}};
        vkCmdCopyBufferToImage(cmd, staging.buffer, shown_.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        vk::transition(cmd, shown_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_TRANSFER_READ_BIT);
    });
    vk::destroy(ctx_, staging);
}

// What the view shows: a PNG of the final view holds the tone-mapped colour as
// `render` writes it, of an AOV view that AOV as the window shows it (`shown`,
// aovDisplay). An EXR holds the scene-linear colour and every AOV, the shown one
// among them.
void Viewer::writeShot(const std::filesystem::path& path, const FrameImages& f, const std::vector<float>& shown,
                       const Camera& camera) {
    if (imageFormatFor(path) == ImageFormat::Exr) writeFrame(path, f, camera, true);
    else if (shown.empty()) writeFrame(path, f, camera, false);
    else writeSrgb8(path, f.width, f.height, encodeSrgb8(shown), &camera);
    panel_.message = "wrote " + path.string();
    std::printf("wrote %s (%ux%u)\n", printable(path.string()).c_str(), f.width, f.height);
}

// The last frame rendered, with the camera it was rendered from.
void Viewer::screenshot(const std::filesystem::path& path) {
    const bool aov = panel_.view != "final";
    const FrameImages f = renderer().readback(lastCamera_, aov || imageFormatFor(path) == ImageFormat::Exr);
    writeShot(path, f, aov ? aovDisplay(f, panel_.view) : std::vector<float>(), lastCamera_);
}

}  // namespace grotto::viewer
