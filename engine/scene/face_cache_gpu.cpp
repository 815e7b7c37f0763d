#include "engine/scene/face_cache_gpu.h"

#include "engine/vk/readback.h"
#include "shaders/shared/face_trace.h"

#include <algorithm>
#include <atomic>
#include <cstring>

namespace grotto {

namespace {
constexpr VkBufferUsageFlags kCacheBufferUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
// Faces a list of the queue holds: a frame that asks for more leaves the rest to
// the next. Bounded too so the trace's dispatch stays within 65535 groups.
uint32_t capacityFor(uint32_t faces, uint32_t k) {
    return std::min({faces, 65536u, 65535u * GROTTO_FACE_TRACE_GROUP / (2u * std::max(k * k, 1u))});
}
uint64_t nextId() {
    static std::atomic<uint64_t> last{0};
    return ++last;
}
}  // namespace

GpuFaceCache::GpuFaceCache(vk::Context& ctx, const voxel::FaceCacheArrays& a, Sun sun, FaceCacheRays rays,
                           std::span<const uint8_t> levels, FaceCacheSky sky, std::span<const glm::uvec4> backlog)
    : ctx_(ctx), table_(a.table), texelsPerSide_(a.texelsPerSide), faceCount_(a.faceCount), materialsFirst_(a.materialsFirst),
      daySunFirst_(a.daySunFirst), dayLightFirst_(a.dayLightFirst), dayFacesFirst_(a.dayFacesFirst),
      sun_(sun), rays_(rays), sky_(sky), id_(nextId()) {
    const uint32_t capacity = capacityFor(a.faceCount, a.texelsPerSide);  // the queue's, kept in its header
    // Empty arrays (a world with no faces) still bind: one zero word each.
    const uint32_t zero[4] = {};
    auto upload = [&](const void* data, size_t bytes) {
        return bytes ? vk::uploadBuffer(ctx, data, bytes, kCacheBufferUsage) : vk::uploadBuffer(ctx, zero, sizeof zero, kCacheBufferUsage);
    };
    std::vector<uint32_t> levelWords((size_t(faceCount_) + 15) / 16, levels.empty() ? ~0u : 0u);
    for (size_t f = 0; f < levels.size(); ++f) levelWords[f / 16] |= uint32_t(levels[f] & 3u) << (2 * (f % 16));
    const std::vector<uint32_t> requested((size_t(faceCount_) + 31) / 32, 0u);
    const std::vector<glm::uvec4> queue(2 * size_t(capacity), glm::uvec4(0));
    std::vector<glm::vec4> positions(voxel::kDaySunPositions, glm::vec4(0.0f));
    if (sun_.day)
        for (uint32_t m = 0; const glm::dvec3& d : voxel::daySunDirections(*sun_.day)) positions[m++] = glm::vec4(glm::vec3(d), 0.0f);
    try {
        bricks_ = upload(a.bricks.data(), a.bricks.size() * sizeof(glm::uvec4));
        records_ = upload(a.records.data(), a.records.size() * sizeof(uint32_t));
        texels_ = upload(a.texels.data(), a.texels.size() * sizeof(uint32_t));
        levels_ = upload(levelWords.data(), levelWords.size() * sizeof(uint32_t));
        requested_ = upload(requested.data(), requested.size() * sizeof(uint32_t));
        queue_ = upload(queue.data(), queue.size() * sizeof(glm::uvec4));
        backlog_ = upload(backlog.data(), backlog.size_bytes());
        dayPositions_ = upload(positions.data(), positions.size() * sizeof(glm::vec4));
        header_ = vk::createBuffer(ctx, GROTTO_FACE_HEADER_WORDS * sizeof(uint32_t),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   true);
        std::memset(header_.mapped(), 0, header_.size);
        uint32_t* header = static_cast<uint32_t*>(header_.mapped());
        header[GROTTO_FACE_CAPACITY] = capacity;
        header[GROTTO_FACE_BACKLOG] = uint32_t(backlog.size());
        header[GROTTO_FACE_UNCONVERGED] = uint32_t(std::count_if(levels.begin(), levels.end(), [](uint8_t l) {
            return (l & 3u) != GROTTO_FACE_LEVEL_CONVERGED;
        }));
        header[GROTTO_FACE_ROUGH] = uint32_t(std::count_if(levels.begin(), levels.end(), [](uint8_t l) { return (l & 3u) < 2u; }));
    } catch (...) {
        for (vk::Buffer* b : {&bricks_, &records_, &texels_, &levels_, &requested_, &queue_, &backlog_, &header_, &dayPositions_}) vk::destroy(ctx_, *b);
        throw;
    }
}

GpuFaceCache::~GpuFaceCache() {
    for (vk::Buffer* b : {&bricks_, &records_, &texels_, &levels_, &requested_, &queue_, &backlog_, &header_, &dayPositions_})
        vk::destroy(ctx_, *b);
}

std::vector<VkDescriptorType> GpuFaceCache::withBindings(std::vector<VkDescriptorType> own) {
    own.insert(own.end(), 3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    return own;
}

std::vector<vk::Binding> GpuFaceCache::withBindings(std::vector<vk::Binding> own) const {
    own.push_back(vk::storageBuffer(bricks_.buffer));
    own.push_back(vk::storageBuffer(records_.buffer));
    own.push_back(vk::storageBuffer(texels_.buffer));
    return own;
}

std::vector<VkDescriptorType> GpuFaceCache::withLevelsBinding(std::vector<VkDescriptorType> own) {
    own.push_back(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    return own;
}

std::vector<vk::Binding> GpuFaceCache::withLevelsBinding(std::vector<vk::Binding> own) const {
    own.push_back(vk::storageBuffer(levels_.buffer));
    return own;
}

std::vector<VkDescriptorType> GpuFaceCache::withRequestBindings(std::vector<VkDescriptorType> own) {
    own.insert(own.end(), 4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    return own;
}

std::vector<vk::Binding> GpuFaceCache::withRequestBindings(std::vector<vk::Binding> own) const {
    for (const vk::Buffer* b : {&levels_, &requested_, &queue_, &header_}) own.push_back(vk::storageBuffer(b->buffer));
    return own;
}

std::vector<uint32_t> GpuFaceCache::lastHeader() const {
    std::vector<uint32_t> words(GROTTO_FACE_HEADER_WORDS);
    std::memcpy(words.data(), header_.mapped(), words.size() * sizeof(uint32_t));
    return words;
}

std::vector<uint8_t> GpuFaceCache::readLevels() const {
    const std::vector<uint8_t> bytes = vk::readBuffer(ctx_, levels_);
    std::vector<uint8_t> levels(faceCount_);
    for (size_t f = 0; f < faceCount_; ++f) levels[f] = (bytes[f / 4] >> (2 * (f % 4))) & 3u;
    return levels;
}

std::vector<uint32_t> GpuFaceCache::readTexelWords() const {
    const std::vector<uint8_t> bytes = vk::readBuffer(ctx_, texels_);
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}

}  // namespace grotto
