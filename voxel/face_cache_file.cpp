#include "voxel/face_cache_file.h"

#include "common/atomic_file.h"
#include "grotto/error.h"
#include "voxel/daylight.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>

namespace grotto::voxel {

namespace {

constexpr char kMagic[8] = {'G', 'R', 'O', 'T', 'T', 'O', 'F', 'C'};
// 2: the rays a texel recorded; 3: full light; 4: the day's sun; 5: full light over the day
constexpr uint32_t kVersion = 5;
constexpr size_t kHeaderBytes = 132;
// The light's three floats follow when it is baked, the day's sun bits with its path.
constexpr size_t kTexelBytes = 24, kLightBytes = 12, kDayBytes = 4;

size_t texelBytes(const FaceCacheHeader& h) {
    return kTexelBytes + (h.key.lightHash != 0 ? kLightBytes : 0) + (h.key.day ? kDayBytes : 0);
}
// Full light over the day: after the texels, each face's day words as three floats.
size_t faceBytes(const FaceCacheHeader& h) { return hasDayLight(h) ? kDayLightWords * 12 : 0; }
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

// A double in its shortest exact form: equal texts are equal values.
std::string exact(double v) {
    char text[32];
    return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}

std::string hex(uint64_t v) {
    char text[20];
    std::snprintf(text, sizeof text, "%016llx", (unsigned long long)v);
    return text;
}

// What two headers record differently, first of: the world (its voxels, its
// faces), then every setting the texels were baked with.
struct Difference {
    std::string setting, value, other;
};
std::optional<Difference> firstDifference(const FaceCacheHeader& a, const FaceCacheHeader& b) {
    auto settings = [](const FaceCacheHeader& h) -> std::vector<std::pair<std::string, std::string>> {
        const glm::dvec3 s = h.key.sunDirection;
        return {{"voxel hash", hex(h.key.voxelHash)},
                {"world's faces", std::to_string(h.totalFaces)},
                {"AO radius", exact(h.key.radiusVoxels) + " voxels"},
                {"texels per side", std::to_string(h.key.texelsPerSide)},
                {"day's sun", h.key.day ? "latitude " + exact(h.key.day->latitude) + ", day " + exact(h.key.day->day) +
                                              ", north " + exact(h.key.day->north)
                                        : std::string("none")},
                {"sun direction", "(" + exact(s.x) + ", " + exact(s.y) + ", " + exact(s.z) + ")"},
                {"sun angle", exact(h.key.sunAngleDegrees) + " degrees"},
                {"full light", h.key.lightHash == 0 ? std::string("none") : "for lighting and materials " + hex(h.key.lightHash)},
                {"rays", std::to_string(h.rays) + " a texel"},
                {"sun rays", std::to_string(h.sunRays) + " a texel"}};
    };
    const auto x = settings(a), y = settings(b);
    for (size_t k = 0; k < x.size(); ++k)
        if (x[k].second != y[k].second) return Difference{x[k].first, x[k].second, y[k].second};
    return std::nullopt;
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

uint64_t lightHash(const World& world) {
    const Lighting l = lightingInEffect(world.desc().lighting);
    uint64_t h = 0x6c69'6768'7466'756cull;
    auto add = [&h](float v) { h = mix(h, std::bit_cast<uint32_t>(v)); };
    auto addColor = [&add](glm::vec3 c) { add(c.r), add(c.g), add(c.b); };
    // Over the day the bake keeps each source's light apart, white: the sky and
    // the sun are the frame's to colour, at any hour.
    if (world.desc().lighting.sunFrom == SunSource::Day) h = mix(h, 0x646179);
    else {
        addColor(l.skyZenith), addColor(l.skyHorizon), add(l.ambientIntensity);
        addColor(l.sunColor * l.sunIntensity), addColor(l.sunDirection), add(l.sunAngle);
    }
    for (const Material& m : world.desc().materials) addColor(m.albedo), addColor(m.emission());
    return h != 0 ? h : 1;
}

FaceCacheKey faceCacheKey(const World& world, double radius, uint32_t texelsPerSide) {
    const Lighting l = lightingInEffect(world.desc().lighting);
    const bool day = world.desc().lighting.sunFrom == SunSource::Day;  // l: the hour's sun, fixed
    return {.voxelHash = solidVoxelHash(world),
            .radiusVoxels = radius / world.voxelSize(),
            .texelsPerSide = texelsPerSide,
            .sunDirection = day ? glm::dvec3(0.0) : glm::dvec3(l.sunDirection),
            .sunAngleDegrees = double(l.sunAngle),
            .day = day ? std::optional(sunPathOf(l)) : std::nullopt,
            .lightHash = l.ambientFrom == AmbientSource::Full ? lightHash(world) : 0};
}

void saveFaceCache(const FaceCacheFile& c, const std::filesystem::path& path) {
    const FaceCacheHeader& h = c.header;
    if (c.texels.size() != h.texelCount() || c.dayLight.size() != (hasDayLight(h) ? h.faceCount * kDayLightWords : 0))
        throw Error::internal(path.string(), "a face cache of " + std::to_string(c.texels.size()) + " texels where its header says " +
                                                 std::to_string(h.texelCount()) + ", or day's light not its header's");
    std::string out;
    out.reserve(kHeaderBytes + c.texels.size() * texelBytes(h));
    out.append(kMagic, sizeof kMagic);
    put(out, kVersion);
    put(out, h.key.texelsPerSide);
    put(out, h.key.voxelHash);
    put(out, h.key.radiusVoxels);
    for (int a = 0; a < 3; ++a) put(out, h.key.sunDirection[a]);
    put(out, h.key.sunAngleDegrees);
    put(out, h.key.lightHash);
    put(out, h.totalFaces);
    put(out, h.firstFace);
    put(out, h.faceCount);
    put(out, h.rays);
    put(out, h.sunRays);
    put(out, h.key.day ? kDaySunPositions : 0u);
    const SunPath day = h.key.day.value_or(SunPath{0.0, 0.0, 0.0});
    put(out, day.latitude), put(out, day.day), put(out, day.north);
    for (const FaceTexel& t : c.texels) {
        put(out, t.samples), put(out, t.open), put(out, t.skyHorizon), put(out, t.skyZenith);
        put(out, t.sunSamples), put(out, t.sunOpen);
        if (h.key.lightHash != 0) put(out, t.light.r), put(out, t.light.g), put(out, t.light.b);
        if (h.key.day) put(out, t.daySun);
    }
    for (const glm::vec3& v : c.dayLight) put(out, v.r), put(out, v.g), put(out, v.b);
    writeAtomically(path, out);
}

FaceCacheHeader readFaceCacheHeader(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw Error(name, "cannot read the face cache: " + ec.message());
    // The magic and version first: an older version's header is another size.
    constexpr size_t kLead = sizeof kMagic + sizeof kVersion;
    if (size < kLead) throw Error(name, "header: " + std::to_string(size) + " bytes, shorter than a face cache's header");
    std::ifstream in(path, std::ios::binary);
    std::string head(std::min<uintmax_t>(size, kHeaderBytes), '\0');
    if (!in.read(head.data(), std::streamsize(head.size()))) throw Error(name, "cannot read the face cache's header");
    if (std::memcmp(head.data(), kMagic, sizeof kMagic) != 0) throw Error(name, "magic: not a Grotto face cache (grotto bake writes them)");
    size_t at = sizeof kMagic;
    if (const uint32_t v = take<uint32_t>(head, at); v != kVersion)
        throw Error(name, "version " + std::to_string(v) + " is not this Grotto's", "accepted: " + std::to_string(kVersion) + "; bake it again");
    if (size < kHeaderBytes) throw Error(name, "header: " + std::to_string(size) + " bytes, shorter than a face cache's header");
    FaceCacheHeader h;
    h.key.texelsPerSide = take<uint32_t>(head, at);
    if (h.key.texelsPerSide == 0 || h.key.texelsPerSide > kMaxTexelsPerSide)
        throw Error(name, "texels per side " + std::to_string(h.key.texelsPerSide) + " is out of range", "accepted: 1 to 16");
    h.key.voxelHash = take<uint64_t>(head, at);
    h.key.radiusVoxels = take<double>(head, at);
    for (int a = 0; a < 3; ++a) h.key.sunDirection[a] = take<double>(head, at);
    h.key.sunAngleDegrees = take<double>(head, at);
    h.key.lightHash = take<uint64_t>(head, at);
    if (!(h.key.radiusVoxels > 0.0 && std::isfinite(h.key.radiusVoxels)))
        throw Error(name, "radius: not a positive number of voxels");
    if (!std::isfinite(h.key.sunDirection.x + h.key.sunDirection.y + h.key.sunDirection.z + h.key.sunAngleDegrees))
        throw Error(name, "sun: not finite");
    h.totalFaces = take<uint64_t>(head, at);
    h.firstFace = take<uint64_t>(head, at);
    h.faceCount = take<uint64_t>(head, at);
    if (h.firstFace > h.totalFaces || h.faceCount > h.totalFaces - h.firstFace)
        throw Error(name, "faces: the run " + std::to_string(h.firstFace) + " + " + std::to_string(h.faceCount) +
                              " lies outside the world's " + std::to_string(h.totalFaces));
    h.rays = take<uint32_t>(head, at);
    h.sunRays = take<uint32_t>(head, at);
    const uint32_t positions = take<uint32_t>(head, at);
    SunPath day;
    day.latitude = take<double>(head, at), day.day = take<double>(head, at), day.north = take<double>(head, at);
    if (positions != 0 && positions != kDaySunPositions)
        throw Error(name, "day's sun: " + std::to_string(positions) + " positions", "accepted: 0 or " + std::to_string(kDaySunPositions));
    if (positions != 0) {
        if (!(std::abs(day.latitude) <= 90.0 && day.day >= 1.0 && day.day <= 366.0 && std::isfinite(day.north)))
            throw Error(name, "day's sun: latitude, day of the year or north out of range");
        h.key.day = day;
    }
    // A fixed sun takes at least a ray; the day's sun takes its positions instead.
    if (h.rays == 0 || (h.sunRays == 0) != bool(h.key.day))
        throw Error(name, "rays: " + std::to_string(h.rays) + " a texel and " + std::to_string(h.sunRays) +
                              " over the sun's disc; a bake casts at least 1, and sun rays only for a fixed sun");
    const uint64_t perFace = uint64_t(h.key.texelsPerSide) * h.key.texelsPerSide * texelBytes(h) + faceBytes(h);
    // The texels must be exactly the rest of the file (checked without overflow).
    if (h.faceCount > (size - kHeaderBytes) / perFace || size - kHeaderBytes != h.faceCount * perFace)
        throw Error(name, "texels: the file holds " + std::to_string(size - kHeaderBytes) + " bytes after its header, " +
                              std::to_string(h.faceCount) + " faces need " + std::to_string(h.faceCount * perFace));
    return h;
}

void readFaceCacheTexels(const std::filesystem::path& path, const FaceCacheHeader& h, std::span<FaceTexel> texels) {
    const std::string name = path.string();
    if (texels.size() != h.texelCount())
        throw Error::internal(name, "room for " + std::to_string(texels.size()) + " texels, the header says " +
                                        std::to_string(h.texelCount()));
    std::ifstream in(path, std::ios::binary);
    in.seekg(std::streamoff(kHeaderBytes));
    constexpr size_t kBlock = size_t(1) << 16;  // texels a read: the file is never held whole beside them
    std::string block;
    for (size_t first = 0; first < texels.size(); first += kBlock) {
        const std::span<FaceTexel> run = texels.subspan(first, std::min(kBlock, texels.size() - first));
        block.resize(run.size() * texelBytes(h));
        if (!in.read(block.data(), std::streamsize(block.size()))) throw Error(name, "texels: cannot read them");
        size_t at = 0;
        for (FaceTexel& t : run) {
            t.samples = take<uint32_t>(block, at), t.open = take<uint32_t>(block, at);
            t.skyHorizon = take<float>(block, at), t.skyZenith = take<float>(block, at);
            t.sunSamples = take<uint32_t>(block, at), t.sunOpen = take<uint32_t>(block, at);
            if (h.key.lightHash != 0) {
                t.light.r = take<float>(block, at), t.light.g = take<float>(block, at), t.light.b = take<float>(block, at);
                if (!(t.light.r >= 0.0f && t.light.g >= 0.0f && t.light.b >= 0.0f) || !std::isfinite(t.light.r + t.light.g + t.light.b))
                    throw Error(name, "texel " + std::to_string(first + size_t(&t - run.data())) + ": light negative or not finite");
            }
            if (h.key.day) t.daySun = take<uint32_t>(block, at), t.dayPositions = kDaySunPositions;
            if (t.samples != h.rays || t.sunSamples != h.sunRays || t.open > t.samples || t.sunOpen > t.sunSamples ||
                !(t.skyHorizon >= 0.0f && t.skyZenith >= 0.0f) || !std::isfinite(t.skyHorizon + t.skyZenith) ||
                // A ray's weights sum to 1 at most; without full light only the
                // rays open within R go on to the sky, with it the light's own rays give the sky.
                t.skyHorizon + t.skyZenith > 1.0001f * float(h.key.lightHash != 0 ? t.samples : t.open))
                throw Error(name, "texel " + std::to_string(first + size_t(&t - run.data())) +
                                      ": counts or sky sums out of range, or rays other than the header's");
        }
    }
}

void readFaceCacheDayLight(const std::filesystem::path& path, const FaceCacheHeader& h, std::span<glm::vec3> dayLight) {
    const std::string name = path.string();
    if (dayLight.size() != (hasDayLight(h) ? h.faceCount * kDayLightWords : 0))
        throw Error::internal(name, "room for " + std::to_string(dayLight.size()) + " day's light words, the header says otherwise");
    if (dayLight.empty()) return;
    std::ifstream in(path, std::ios::binary);
    in.seekg(std::streamoff(kHeaderBytes + h.texelCount() * texelBytes(h)));
    std::string block(dayLight.size() * 12, '\0');
    if (!in.read(block.data(), std::streamsize(block.size()))) throw Error(name, "day's light: cannot read it");
    size_t at = 0;
    for (size_t w = 0; w < dayLight.size(); ++w) {
        glm::vec3& v = dayLight[w];
        v.r = take<float>(block, at), v.g = take<float>(block, at), v.b = take<float>(block, at);
        if (!(v.r >= 0.0f && v.g >= 0.0f && v.b >= 0.0f) || !std::isfinite(v.r + v.g + v.b))
            throw Error(name, "day's light of face " + std::to_string(h.firstFace + w / kDayLightWords) + ": negative or not finite");
    }
}

FaceCacheFile loadFaceCache(const std::filesystem::path& path) {
    FaceCacheFile c{.header = readFaceCacheHeader(path)};
    c.texels.resize(c.header.texelCount());
    readFaceCacheTexels(path, c.header, c.texels);
    c.dayLight.resize(hasDayLight(c.header) ? c.header.faceCount * kDayLightWords : 0);
    readFaceCacheDayLight(path, c.header, c.dayLight);
    return c;
}

void requireMatchingBake(const FaceCacheHeader& h, const FaceCacheKey& expected, uint64_t totalFaces,
                         const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::string again = "bake it again for this world and these settings";
    if (h.key.voxelHash != expected.voxelHash || h.totalFaces != totalFaces)
        throw Error(name, "baked for other voxels than this world's", again);
    FaceCacheHeader wanted = h;
    wanted.key = expected;
    if (const auto d = firstDifference(h, wanted))
        throw Error(name, d->setting + ": baked for " + d->value + ", the world asks " + d->other, again);
    if (h.firstFace != 0 || h.faceCount != totalFaces)
        throw Error(name, "a part of a bake (faces " + std::to_string(h.firstFace) + " to " +
                              std::to_string(h.firstFace + h.faceCount) + " of " + std::to_string(totalFaces) + ")",
                    "join the parts with grotto bake --merge");
}

FaceCacheHeader requireBakeOf(const World& world, double radius, uint64_t totalFaces, const std::filesystem::path& path) {
    const FaceCacheHeader h = readFaceCacheHeader(path);
    requireMatchingBake(h, faceCacheKey(world, radius, h.key.texelsPerSide), totalFaces, path);
    return h;
}

FaceCacheFile mergeFaceCaches(const std::vector<std::filesystem::path>& paths) {
    if (paths.empty()) throw Error("bake --merge", "no parts to join");
    std::vector<FaceCacheHeader> parts;
    for (const std::filesystem::path& p : paths) parts.push_back(readFaceCacheHeader(p));
    // The others are compared with the part most of them agree with (the first
    // given of those), so the one unlike the rest is named, whatever its place.
    size_t ref = 0, most = 0;
    for (size_t a = 0; a < parts.size(); ++a) {
        const size_t alike = size_t(std::count_if(parts.begin(), parts.end(), [&](const FaceCacheHeader& b) {
            return !firstDifference(parts[a], b);
        }));
        if (alike > most) most = alike, ref = a;
    }
    for (size_t k = 0; k < parts.size(); ++k)
        if (const auto d = firstDifference(parts[k], parts[ref]))
            throw Error(paths[k].string(), d->setting + " " + d->value + ", where " + paths[ref].string() + " has " + d->other,
                        "bake every part of one world with the same settings");
    std::vector<size_t> order(parts.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return parts[a].firstFace < parts[b].firstFace; });
    uint64_t next = 0;
    for (size_t k : order) {
        const FaceCacheHeader& p = parts[k];
        if (p.firstFace != next)
            throw Error(paths[k].string(), "faces " + std::to_string(p.firstFace) + " to " + std::to_string(p.firstFace + p.faceCount) +
                                               (p.firstFace < next ? " overlap the part before" : " leave a gap after face " + std::to_string(next)));
        next += p.faceCount;
    }
    if (next != parts[ref].totalFaces)
        throw Error(paths[order.back()].string(), "the parts end at face " + std::to_string(next) + " of " +
                                                      std::to_string(parts[ref].totalFaces), "a part is missing");
    // Every header agrees and the runs tile the world: the texels, read into place.
    FaceCacheFile out{.header = parts[ref]};
    out.header.firstFace = 0, out.header.faceCount = out.header.totalFaces;
    out.texels.resize(out.header.texelCount());
    const size_t words = hasDayLight(out.header) ? kDayLightWords : 0;
    out.dayLight.resize(out.header.faceCount * words);
    size_t at = 0, face = 0;
    for (size_t k : order) {
        readFaceCacheTexels(paths[k], parts[k], std::span(out.texels).subspan(at, parts[k].texelCount()));
        readFaceCacheDayLight(paths[k], parts[k], std::span(out.dayLight).subspan(face * words, parts[k].faceCount * words));
        at += parts[k].texelCount(), face += parts[k].faceCount;
    }
    return out;
}

}  // namespace grotto::voxel
