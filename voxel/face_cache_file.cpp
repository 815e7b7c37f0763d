#include "voxel/face_cache_file.h"

#include "common/atomic_file.h"
#include "grotto/error.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace grotto::voxel {

namespace {

constexpr char kMagic[8] = {'G', 'R', 'O', 'T', 'T', 'O', 'F', 'C'};
constexpr uint32_t kVersion = 1;
constexpr size_t kHeaderBytes = 88;
constexpr size_t kTexelBytes = 24;
constexpr uint32_t kMaxTexelsPerSide = 16;

uint64_t mix(uint64_t h, uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    return h ^ (h >> 31);
}

// Little-endian fields, as every machine Grotto builds for keeps them.
template <class T> void put(std::string& out, T v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); }
template <class T> T take(const std::string& in, size_t& at) {
    T v;
    std::memcpy(&v, in.data() + at, sizeof v);
    at += sizeof v;
    return v;
}

std::string fmt(glm::dvec3 v) {
    std::ostringstream s;
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

}  // namespace

uint64_t solidVoxelHash(const World& world) {
    std::vector<Brick> bricks = world.bricks();
    std::sort(bricks.begin(), bricks.end(), [](const Brick& a, const Brick& b) {
        return std::tie(a.origin.x, a.origin.y, a.origin.z) < std::tie(b.origin.x, b.origin.y, b.origin.z);
    });
    uint64_t h = 0x6772'6f74'746f'4643ull;
    for (const Brick& b : bricks) {
        h = mix(h, uint64_t(uint32_t(b.origin.x)) << 32 | uint32_t(b.origin.y));
        h = mix(h, uint32_t(b.origin.z));
        for (uint64_t word : b.occupancy) h = mix(h, word);
    }
    return h;
}

FaceCacheKey faceCacheKey(const World& world, double radius, uint32_t texelsPerSide) {
    const Lighting& l = world.desc().lighting;
    return {.voxelHash = solidVoxelHash(world),
            .radiusVoxels = radius / world.voxelSize(),
            .texelsPerSide = texelsPerSide,
            .sunDirection = glm::dvec3(l.sunDirection),
            .sunAngleDegrees = double(l.sunAngle)};
}

void saveFaceCache(const FaceCacheFile& c, const std::filesystem::path& path) {
    std::string out;
    out.reserve(kHeaderBytes + c.texels.size() * kTexelBytes);
    out.append(kMagic, sizeof kMagic);
    put(out, kVersion);
    put(out, c.key.texelsPerSide);
    put(out, c.key.voxelHash);
    put(out, c.key.radiusVoxels);
    for (int a = 0; a < 3; ++a) put(out, c.key.sunDirection[a]);
    put(out, c.key.sunAngleDegrees);
    put(out, c.totalFaces);
    put(out, c.firstFace);
    put(out, c.faceCount());
    for (const FaceTexel& t : c.texels) {
        put(out, t.samples), put(out, t.open), put(out, t.skyHorizon), put(out, t.skyZenith);
        put(out, t.sunSamples), put(out, t.sunOpen);
    }
    writeAtomically(path, out);
}

FaceCacheFile loadFaceCache(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw Error(name, "cannot read the face cache: " + ec.message());
    if (size < kHeaderBytes) throw Error(name, "header: " + std::to_string(size) + " bytes, shorter than a face cache's header");
    std::ifstream in(path, std::ios::binary);
    std::string head(kHeaderBytes, '\0');
    if (!in.read(head.data(), std::streamsize(head.size()))) throw Error(name, "cannot read the face cache's header");
    if (std::memcmp(head.data(), kMagic, sizeof kMagic) != 0) throw Error(name, "magic: not a Grotto face cache (grotto bake writes them)");
    size_t at = sizeof kMagic;
    if (const uint32_t v = take<uint32_t>(head, at); v != kVersion)
        throw Error(name, "version " + std::to_string(v) + " is not this Grotto's", "accepted: " + std::to_string(kVersion) + "; bake it again");
    FaceCacheFile c;
    c.key.texelsPerSide = take<uint32_t>(head, at);
    if (c.key.texelsPerSide == 0 || c.key.texelsPerSide > kMaxTexelsPerSide)
        throw Error(name, "texels per side " + std::to_string(c.key.texelsPerSide) + " is out of range", "accepted: 1 to 16");
    c.key.voxelHash = take<uint64_t>(head, at);
    c.key.radiusVoxels = take<double>(head, at);
    for (int a = 0; a < 3; ++a) c.key.sunDirection[a] = take<double>(head, at);
    c.key.sunAngleDegrees = take<double>(head, at);
    if (!(c.key.radiusVoxels > 0.0 && std::isfinite(c.key.radiusVoxels)))
        throw Error(name, "radius: not a positive number of voxels");
    if (!std::isfinite(c.key.sunDirection.x + c.key.sunDirection.y + c.key.sunDirection.z + c.key.sunAngleDegrees))
        throw Error(name, "sun: not finite");
    c.totalFaces = take<uint64_t>(head, at);
    c.firstFace = take<uint64_t>(head, at);
    const uint64_t count = take<uint64_t>(head, at);
    if (c.firstFace > c.totalFaces || count > c.totalFaces - c.firstFace)
        throw Error(name, "faces: the run " + std::to_string(c.firstFace) + " + " + std::to_string(count) +
                              " lies outside the world's " + std::to_string(c.totalFaces));
    const uint64_t perFace = uint64_t(c.key.texelsPerSide) * c.key.texelsPerSide;
    // Checked before allocating: the texels must be exactly the rest of the file.
    if (count > (size - kHeaderBytes) / (perFace * kTexelBytes) || size - kHeaderBytes != count * perFace * kTexelBytes)
        throw Error(name, "texels: the file holds " + std::to_string(size - kHeaderBytes) + " bytes after its header, " +
                              std::to_string(count) + " faces need " + std::to_string(count * perFace * kTexelBytes));
    std::string body(size - kHeaderBytes, '\0');
    if (!in.read(body.data(), std::streamsize(body.size()))) throw Error(name, "texels: cannot read them");
    c.texels.resize(count * perFace);
    at = 0;
    for (FaceTexel& t : c.texels) {
        t.samples = take<uint32_t>(body, at), t.open = take<uint32_t>(body, at);
        t.skyHorizon = take<float>(body, at), t.skyZenith = take<float>(body, at);
        t.sunSamples = take<uint32_t>(body, at), t.sunOpen = take<uint32_t>(body, at);
        if (t.open > t.samples || t.sunOpen > t.sunSamples || !(t.skyHorizon >= 0.0f && t.skyZenith >= 0.0f) ||
            !std::isfinite(t.skyHorizon + t.skyZenith) || t.skyHorizon + t.skyZenith > 1.0001f * float(t.open))
            throw Error(name, "texel " + std::to_string(&t - c.texels.data()) + ": counts or sky sums out of range");
    }
    return c;
}

void requireMatchingBake(const FaceCacheFile& c, const FaceCacheKey& expected, uint64_t totalFaces,
                         const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::string again = "bake it again for this world and these settings";
    if (c.key.voxelHash != expected.voxelHash || c.totalFaces != totalFaces)
        throw Error(name, "baked for other voxels than this world's", again);
    if (c.key.radiusVoxels != expected.radiusVoxels)
        throw Error(name, "AO radius: baked for " + std::to_string(c.key.radiusVoxels) + " voxels, the world asks " +
                              std::to_string(expected.radiusVoxels), again);
    if (c.key.texelsPerSide != expected.texelsPerSide)
        throw Error(name, "texels per side: baked with " + std::to_string(c.key.texelsPerSide) + ", asked for " +
                              std::to_string(expected.texelsPerSide), again);
    if (c.key.sunDirection != expected.sunDirection || c.key.sunAngleDegrees != expected.sunAngleDegrees)
        throw Error(name, "sun: baked for " + fmt(c.key.sunDirection) + " at " + std::to_string(c.key.sunAngleDegrees) +
                              " degrees, the world's is " + fmt(expected.sunDirection) + " at " +
                              std::to_string(expected.sunAngleDegrees), again);
    if (c.firstFace != 0 || c.faceCount() != totalFaces)
        throw Error(name, "a part of a bake (faces " + std::to_string(c.firstFace) + " to " +
                              std::to_string(c.firstFace + c.faceCount()) + " of " + std::to_string(totalFaces) + ")",
                    "join the parts with grotto bake --merge");
}

FaceCacheFile mergeFaceCaches(std::vector<FaceCacheFile> parts, const std::vector<std::filesystem::path>& paths) {
    if (parts.empty()) throw Error("bake --merge", "no parts to join");
    std::vector<size_t> order(parts.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return parts[a].firstFace < parts[b].firstFace; });
    FaceCacheFile out;
    out.key = parts[order[0]].key;
    out.totalFaces = parts[order[0]].totalFaces;
    uint64_t next = 0;
    for (size_t k : order) {
        FaceCacheFile& p = parts[k];
        const std::string name = paths[k].string();
        if (!(p.key == out.key) || p.totalFaces != out.totalFaces)
            throw Error(name, "baked for another world or other settings than " + paths[order[0]].string());
        if (p.firstFace != next)
            throw Error(name, "faces " + std::to_string(p.firstFace) + " to " + std::to_string(p.firstFace + p.faceCount()) +
                                  (p.firstFace < next ? " overlap the part before" : " leave a gap after face " + std::to_string(next)));
        next += p.faceCount();
        out.texels.insert(out.texels.end(), p.texels.begin(), p.texels.end());
        p.texels = {};
    }
    if (next != out.totalFaces)
        throw Error(paths[order.back()].string(), "the parts end at face " + std::to_string(next) + " of " +
                                                      std::to_string(out.totalFaces), "a part is missing");
    return out;
}

}  // namespace grotto::voxel
