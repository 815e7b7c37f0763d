#include "engine/frame/frame_copy.h"

#include "engine/frame/object_frame.h"
#include "shaders/shared/quad.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cstring>
#include <limits>

namespace grotto {

FrameCopy::FrameCopy(vk::Context& ctx, bool aovs) : ctx_(ctx), aovs_(aovs) {}

FrameCopy::~FrameCopy() {
    for (vk::Buffer& b : buffers_) vk::destroy(ctx_, b);
}

void FrameCopy::begin(Layout layout) {
    layout_ = std::move(layout);
    std::fill(std::begin(copied_), std::end(copied_), VkDeviceSize(0));
}

const vk::Buffer& FrameCopy::reserve(Part part, VkDeviceSize bytes) {
    vk::Buffer& b = buffers_[part];
    if (b.size < bytes) {
        vk::destroy(ctx_, b);
        b = vk::createBuffer(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    }
    copied_[part] = bytes;
    return b;
}

namespace {

template <class T>
std::vector<T> values(const vk::Buffer& buffer, VkDeviceSize bytes) {
    std::vector<T> out(bytes / sizeof(T));
    std::memcpy(out.data(), buffer.mapped(), out.size() * sizeof(T));
    return out;
}

// Channel `c` of a `channels`-wide half-res image, stored at full size by nearest.
std::vector<float> halfToFull(const std::vector<float>& half, VkExtent2D h, uint32_t channels, uint32_t c,
                              uint32_t scale, uint32_t width, uint32_t height) {
    std::vector<float> out(size_t(width) * height);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            out[size_t(y) * width + x] = half[(size_t(y / scale) * h.width + x / scale) * channels + c];
    return out;
}

}  // namespace

FrameImages FrameCopy::decode() const {
    const Layout& l = layout_;
    auto part = [&](Part p) { return values<float>(buffers_[p], copied_[p]); };
    FrameImages f;
    f.width = l.width;
    f.height = l.height;
    f.toneMap = l.toneMap;
    const size_t n = size_t(f.width) * f.height;
    f.color = part(Color);
    if (!aovs_) return f;
    f.shadow = copied_[Shadow] ? part(Shadow) : std::vector<float>(n, 1.0f);
    f.depthBuffer = part(Depth);
    f.surfaceIds = values<uint16_t>(buffers_[Surface], copied_[Surface]);
    if (copied_[Motion]) f.motion = part(Motion);
    if (copied_[CacheLight]) {  // RGBA32F
        const std::vector<float> light = part(CacheLight);
        f.light.resize(3 * n);
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) f.light[3 * i + c] = light[4 * i + c];
    }
    f.depth.resize(n);
    f.normal.assign(3 * n, 0.0f);
    f.albedo.assign(3 * n, 0.0f);
    for (size_t i = 0; i < n; ++i) {
        const float d = f.depthBuffer[i];
        f.depth[i] = d > 0.0f ? float(l.camera->linearDepth(d)) : std::numeric_limits<float>::infinity();
        const uint16_t id = f.surfaceIds[i];
        if (id == 0) continue;  // sky
        const uint32_t material = gpu::surfaceMaterial(id);
        const glm::dvec3 normal = surfaceNormal(id, l.poses);  // an axis, or an object's face turned with it
        for (int c = 0; c < 3; ++c) f.normal[3 * i + c] = float(normal[c]);
        if (material >= 1 && material <= l.albedo.size())
            for (int c = 0; c < 3; ++c) f.albedo[3 * i + c] = l.albedo[material - 1][c];
    }
    if (!l.ao) {
        f.ao = f.aoRaw = f.aoSpatial = f.aoTemporal = f.aoHistory = f.edges = std::vector<float>(n, 1.0f);
        return f;
    }
    f.ao = part(AoFull);
    if (!l.chain) {  // the face cache's AO: full resolution, no chain behind it
        f.aoRaw = f.aoSpatial = f.aoTemporal = f.ao;
        f.aoHistory = f.edges = std::vector<float>(n, 1.0f);
        return f;
    }
    const std::vector<float> raw = part(Raw);
    const std::vector<float> spatial = part(Spatial);
    f.aoRawHalf.resize(raw.size() / 2);
    for (size_t i = 0; i < raw.size() / 4; ++i) f.aoRawHalf[2 * i] = raw[4 * i], f.aoRawHalf[2 * i + 1] = raw[4 * i + 1];
    f.aoRaw = halfToFull(raw, l.half, 4, 0, l.scale, f.width, f.height);
    f.aoSpatial = halfToFull(spatial, l.half, 4, 0, l.scale, f.width, f.height);
    if (copied_[History]) {
        const std::vector<float> history = part(History);
        f.aoTemporal = halfToFull(history, l.half, 4, 0, l.scale, f.width, f.height);
        f.aoHistory = halfToFull(history, l.half, 4, 1, l.scale, f.width, f.height);
    } else {
        f.aoTemporal = f.aoSpatial;
        f.aoHistory.assign(n, 1.0f);
    }
    if (copied_[BentNormal]) {  // RGBA16F at AO resolution
        const std::vector<uint16_t> halves = values<uint16_t>(buffers_[BentNormal], copied_[BentNormal]);
        std::vector<float> bent(halves.size());
        for (size_t i = 0; i < halves.size(); ++i) bent[i] = glm::unpackHalf1x16(halves[i]);
        f.bentNormal.resize(3 * n);
        for (uint32_t c = 0; c < 3; ++c) {
            const std::vector<float> channel = halfToFull(bent, l.half, 4, c, l.scale, f.width, f.height);
            for (size_t i = 0; i < n; ++i) f.bentNormal[3 * i + c] = channel[i];
        }
    }
    const std::vector<float> packed = halfToFull(raw, l.half, 4, 1, l.scale, f.width, f.height);
    f.edges.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const uint32_t v = uint32_t(packed[i] * 255.0f + 0.5f);
        float e = 1.0f;
        for (int k = 0; k < 4; ++k) e = std::min(e, float((v >> (2 * k)) & 3u) / 3.0f);
        f.edges[i] = e;
    }
    return f;
}

}  // namespace grotto
