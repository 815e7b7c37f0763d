#include "engine/image_output.h"

#include "common/atomic_file.h"
#include "engine/image_codec/codec_library.h"
#include "engine/image_input.h"
#include "grotto/error.h"
#include "shaders/shared/tone_map.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace grotto {

ImageFormat imageFormatFor(const std::filesystem::path& path) {
    const std::string ext = path.extension().string();
    if (ext == ".png") return ImageFormat::Png;
    if (ext == ".exr") return ImageFormat::Exr;
    throw Error(path.string(), "unsupported image extension '" + ext + "'", "use .png or .exr");
}

namespace {

// The sRGB transfer function, rounded to 8 bits: the definition toSrgb8 follows.
uint8_t srgb8ByFormula(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(s * 255.0f));
}

// The formula is monotone, so 255 thresholds decide it: thresholds[k] is the least
// float it takes to k + 1 or more, found by bisection on the bit patterns (which
// order non-negative floats as their values). bucketStart[b] is the formula's value
// at the least float whose top bits are b. A bucket (2^16 floats) is narrower than
// the formula's steps anywhere in [0, 1], so it holds at most one threshold and
// one comparison finds the answer, without a branch: the same bytes as the
// formula, four times as fast as walking up the thresholds.
struct Srgb8Table {
    static constexpr int kShift = 16;
    std::array<float, 256> thresholds;  // [255]: above 1, so 255 never steps further
    std::vector<uint8_t> bucketStart;
    Srgb8Table() {
        const uint32_t one = std::bit_cast<uint32_t>(1.0f);
        for (int k = 0; k < 255; ++k) {
            uint32_t lo = 0, hi = one;  // formula(lo) <= k < formula(hi)
            while (hi - lo > 1) {
                const uint32_t mid = lo + (hi - lo) / 2;
                (srgb8ByFormula(std::bit_cast<float>(mid)) > k ? hi : lo) = mid;
            }
            thresholds[k] = std::bit_cast<float>(hi);
        }
        thresholds[255] = 2.0f;
        bucketStart.resize((one >> kShift) + 1);
        for (uint32_t b = 0; b < bucketStart.size(); ++b) bucketStart[b] = srgb8ByFormula(std::bit_cast<float>(b << kShift));
    }
};

const Srgb8Table& srgb8Table() {
    static const Srgb8Table table;
    return table;
}

uint8_t srgb8(const Srgb8Table& table, float v) {
    v = v > 0.0f ? std::min(v, 1.0f) : 0.0f;  // NaN too goes to 0
    const int k = table.bucketStart[std::bit_cast<uint32_t>(v) >> Srgb8Table::kShift];
    return uint8_t(k + (v >= table.thresholds[k]));
}

}  // namespace

uint8_t toSrgb8(float v) { return srgb8(srgb8Table(), v); }

float srgbToLinear(float s) { return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f); }

std::vector<float> aovDisplay(const FrameImages& f, const std::string& which) {
    auto valueOr = [](const std::vector<float>& v, size_t i, float none) { return v.empty() ? none : v[i]; };
    const size_t n = size_t(f.width) * f.height;
    float zMin = std::numeric_limits<float>::max(), zMax = 0.0f;
    for (float z : f.depth)
        if (std::isfinite(z)) zMin = std::min(zMin, z), zMax = std::max(zMax, z);
    const float logRange = std::max(std::log(std::max(zMax, 1e-30f) / std::max(zMin, 1e-30f)), 1e-6f);
    std::vector<float> out(4 * n, 1.0f);
    for (size_t i = 0; i < n; ++i) {
        glm::vec3 v(0.0f);
        const bool sky = !std::isfinite(f.depth[i]);
        if (which == "ao") v = glm::vec3(f.ao[i]);
        else if (which == "edges") v = glm::vec3(f.edges[i]);
        else if (which == "shadow") v = glm::vec3(f.shadow.empty() ? 1.0f : f.shadow[i]);
        else if (which == "normal") v = sky ? v : glm::vec3(f.normal[3 * i], f.normal[3 * i + 1], f.normal[3 * i + 2]) * 0.5f + 0.5f;
        else if (which == "depth") v = sky ? v : glm::vec3(1.0f - 0.9f * std::log(f.depth[i] / zMin) / logRange);
        else if (which == "raw") v = glm::vec3(valueOr(f.aoRaw, i, 1.0f));
        else if (which == "spatial") v = glm::vec3(valueOr(f.aoSpatial, i, 1.0f));
        else if (which == "temporal") v = glm::vec3(valueOr(f.aoTemporal, i, 1.0f));
        else if (which == "history") v = glm::vec3(valueOr(f.aoHistory, i, 1.0f) / 64.0f);  // the longest history is 64
        else if (which == kCacheLightAov) {
            if (f.light.empty()) throw Error("AOV", "light is the face cache's", "render with AO method cache");
            for (int c = 0; c < 3; ++c) v[c] = gpu::toneMap(f.light[3 * i + c], f.toneMap);
        }
        else if (which == kBentNormalAov) {
            if (f.bentNormal.empty()) throw Error("AOV", "bent_normal is VBAO's", "render with AO method vbao");
            v = sky ? v : glm::vec3(f.bentNormal[3 * i], f.bentNormal[3 * i + 1], f.bentNormal[3 * i + 2]) * 0.5f + 0.5f;
        }
        else throw Error("AOV", "unknown AOV '" + which + "'", "accepted: " + std::string(kShownAovs));
        for (int c = 0; c < 3; ++c) out[4 * i + c] = srgbToLinear(std::clamp(v[c], 0.0f, 1.0f));
    }
    return out;
}

std::vector<float> displayColor(const FrameImages& f) {
    std::vector<float> out(f.color.size());
    for (size_t k = 0; k < out.size(); ++k) out[k] = k % 4 == 3 ? f.color[k] : gpu::toneMap(f.color[k], f.toneMap);
    return out;
}

namespace {

// The camera as the standard worldtocamera / worldtoscreen attributes.
struct CameraMatrices {
    glm::mat4 worldToCamera, worldToScreen;
    explicit CameraMatrices(const Camera& camera)
        : worldToCamera(camera.viewFromWorld()), worldToScreen(camera.projection(false) * camera.viewFromWorld()) {}
    void describe(grotto_image_to_encode& image) const {
        image.world_to_camera = &worldToCamera[0][0];
        image.world_to_screen = &worldToScreen[0][0];
    }
};

// Pixels of `channels` interleaved channels, each stored as `types` says, with
// the format's default names and neither alpha nor Z marked.
grotto_image_to_encode imageOf(const std::filesystem::path& target, uint32_t width, uint32_t height, int channels,
                               const int* types, int pixelType, const void* pixels) {
    return {.target = target.c_str(), .width = int(width), .height = int(height), .channels = channels,
            .channel_names = nullptr, .channel_types = types, .pixel_type = pixelType, .pixels = pixels,
            .alpha_channel = -1, .z_channel = -1, .world_to_camera = nullptr, .world_to_screen = nullptr,
            .chromaticities = nullptr, .color_space = nullptr, .png_level = FrameEncoding::kDefaultPngLevel};
}

// Encodes in memory and writes the bytes through writeAtomically, which checks
// every write: OpenImageIO's PNG writer ignores a failed fwrite, so a full disk
// would otherwise leave a truncated file that it reports as written.
void writeImage(const std::filesystem::path& target, const grotto_image_to_encode& image) {
    encodeImage(image, [&](std::string_view bytes) { writeAtomically(target, bytes); });
}

// Pointers to the names, as the codec takes them.
std::vector<const char*> namePointers(const std::vector<std::string>& names) {
    std::vector<const char*> p;
    for (const std::string& n : names) p.push_back(n.c_str());
    return p;
}

}  // namespace

std::vector<uint8_t> srgb8Pixels(const FrameImages& f) {
    const size_t w = f.width;
    std::vector<uint8_t> px(3 * w * f.height);
    // A row at a time: the tone map vectorises on its own, the table walk does not.
    std::vector<float> shown(4 * w);
    const Srgb8Table& table = srgb8Table();
    for (size_t y = 0; y < f.height; ++y) {
        const float* row = &f.color[4 * w * y];
        for (size_t k = 0; k < 4 * w; ++k) shown[k] = gpu::toneMap(row[k], f.toneMap);
        for (size_t x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) px[3 * (w * y + x) + c] = srgb8(table, shown[4 * x + c]);
    }
    return px;
}

std::vector<uint8_t> encodeSrgb8(std::span<const float> rgba) {
    std::vector<uint8_t> px(rgba.size() / 4 * 3);
    const Srgb8Table& table = srgb8Table();
    for (size_t i = 0; i < rgba.size() / 4; ++i)
        for (int c = 0; c < 3; ++c) px[3 * i + c] = srgb8(table, rgba[4 * i + c]);
    return px;
}

void writeSrgb8(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const uint8_t> rgb,
                const Camera* camera, int pngLevel) {
    if (rgb.size() != size_t(width) * height * 3) throw Error::internal(path.string(), "pixels of the wrong size");
    static constexpr int kTypes[3] = {GROTTO_PIXEL_UINT8, GROTTO_PIXEL_UINT8, GROTTO_PIXEL_UINT8};
    grotto_image_to_encode image = imageOf(path, width, height, 3, kTypes, GROTTO_PIXEL_UINT8, rgb.data());
    image.color_space = "sRGB";
    image.png_level = pngLevel;
    std::optional<CameraMatrices> matrices;
    if (camera) matrices.emplace(*camera).describe(image);
    writeImage(path, image);
}

void writeFrame(const std::filesystem::path& path, const FrameImages& f, const Camera& camera, bool aovs) {
    FrameEncoding encoding;
    if (aovs) encoding.exrAovs.assign(std::begin(kExrAovs), std::end(kExrAovs));
    if (aovs && !f.bentNormal.empty()) encoding.exrAovs.push_back(kBentNormalAov);
    if (aovs && !f.light.empty()) encoding.exrAovs.push_back(kCacheLightAov);
    writeFrame(path, f, camera, encoding);
}

namespace {

// One EXR layer: its channels, and channel c of pixel i.
struct Layer {
    const char* name;
    std::vector<std::string> channels;
    std::function<float(size_t i, int c)> value;
};

std::vector<Layer> exrLayers(const FrameImages& f) {
    auto one = [](const std::vector<float>& v) { return [p = v.data()](size_t i, int) { return p[i]; }; };
    auto three = [](const std::vector<float>& v) { return [p = v.data()](size_t i, int c) { return p[3 * i + c]; }; };
    return {
        // EXR readers expect a finite Z; sky gets the largest float.
        {"Z", {"Z"}, [&f](size_t i, int) { return std::isfinite(f.depth[i]) ? f.depth[i] : std::numeric_limits<float>::max(); }},
        {"N", {"N.x", "N.y", "N.z"}, three(f.normal)},
        {"albedo", {"albedo.R", "albedo.G", "albedo.B"}, three(f.albedo)},
        {"AO", {"AO"}, one(f.ao)},
        {"AO_raw", {"AO_raw"}, one(f.aoRaw)},
        {"AO_spatial", {"AO_spatial"}, one(f.aoSpatial)},
        {"AO_temporal", {"AO_temporal"}, one(f.aoTemporal)},
        {"AO_history", {"AO_history"}, one(f.aoHistory)},
        {"edges", {"edges"}, one(f.edges)},
        {"shadow", {"shadow"}, [&f](size_t i, int) { return f.shadow.empty() ? 1.0f : f.shadow[i]; }},
        {kBentNormalAov, {"bent_normal.x", "bent_normal.y", "bent_normal.z"}, three(f.bentNormal)},
        {kCacheLightAov, {"light.R", "light.G", "light.B"}, three(f.light)},
    };
}

void writeExr(const std::filesystem::path& path, const FrameImages& f, const Camera& camera, const FrameEncoding& e) {
    std::vector<Layer> layers;
    for (Layer& layer : exrLayers(f))
        if (std::find(e.exrAovs.begin(), e.exrAovs.end(), layer.name) != e.exrAovs.end()) layers.push_back(std::move(layer));
    if (layers.size() != e.exrAovs.size())
        throw Error::internal(path.string(), "an unknown or repeated EXR AOV layer was asked for");
    if (!layers.empty() && f.depth.empty()) throw Error::internal(path.string(), "AOV layers of a frame read back without AOVs");
    if (std::find(e.exrAovs.begin(), e.exrAovs.end(), kBentNormalAov) != e.exrAovs.end() && f.bentNormal.empty())
        throw Error(path.string(), "the bent_normal layer is VBAO's", "render with AO method vbao, or leave bent_normal out");
    if (std::find(e.exrAovs.begin(), e.exrAovs.end(), kCacheLightAov) != e.exrAovs.end() && f.light.empty())
        throw Error(path.string(), "the light layer is the face cache's", "render with AO method cache, or leave light out");
    std::vector<std::string> names = {"R", "G", "B", "A"};
    for (const Layer& layer : layers) names.insert(names.end(), layer.channels.begin(), layer.channels.end());
    const int channels = int(names.size());
    // Z stays float in a half EXR: half's 65504 range and 11-bit precision would garble depth.
    std::vector<int> types(size_t(channels), e.exrHalf ? GROTTO_PIXEL_HALF : GROTTO_PIXEL_FLOAT);
    const auto z = std::find(names.begin(), names.end(), "Z");
    if (z != names.end()) types[size_t(z - names.begin())] = GROTTO_PIXEL_FLOAT;
    // Scene-linear Rec. 709 / sRGB primaries with a D65 white (OpenEXR's chromaticities:
    // red, green, blue and white xy), as the composite lights them.
    static constexpr float kRec709[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
    const size_t n = size_t(f.width) * f.height;
    std::vector<float> px(size_t(channels) * n);
    for (size_t i = 0; i < n; ++i) {
        float* p = &px[size_t(channels) * i];
        for (int c = 0; c < 4; ++c) *p++ = f.color[4 * i + c];
        for (const Layer& layer : layers)
            for (int c = 0; c < int(layer.channels.size()); ++c) *p++ = layer.value(i, c);
    }
    const std::vector<const char*> namePtrs = namePointers(names);
    grotto_image_to_encode image = imageOf(path, f.width, f.height, channels, types.data(), GROTTO_PIXEL_FLOAT, px.data());
    image.channel_names = namePtrs.data();
    image.alpha_channel = 3;
    image.z_channel = z != names.end() ? int(z - names.begin()) : -1;
    image.chromaticities = kRec709;
    image.color_space = "Linear";
    const CameraMatrices matrices(camera);
    matrices.describe(image);
    writeImage(path, image);
}

}  // namespace

void writeFrame(const std::filesystem::path& path, const FrameImages& f, const Camera& camera,
                const FrameEncoding& encoding) {
    if (imageFormatFor(path) == ImageFormat::Png)
        writeSrgb8(path, f.width, f.height, srgb8Pixels(f), &camera, encoding.pngLevel);
    else
        writeExr(path, f, camera, encoding);
}

void writeChannels(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const Channel> channels,
                   const Camera& camera) {
    if (imageFormatFor(path) != ImageFormat::Exr)
        throw Error(path.string(), "named channels need an .exr output", "use .exr");
    const size_t n = size_t(width) * height, count = channels.size();
    for (const Channel& c : channels)
        if (c.values->size() != n) throw Error::internal(path.string(), "channel " + c.name + " has the wrong size");
    std::vector<float> px(count * n);
    for (size_t i = 0; i < n; ++i)
        for (size_t c = 0; c < count; ++c) px[count * i + c] = (*channels[c].values)[i];
    std::vector<std::string> names;
    for (const Channel& c : channels) names.push_back(c.name);
    const std::vector<const char*> namePtrs = namePointers(names);
    const std::vector<int> types(count, GROTTO_PIXEL_FLOAT);
    grotto_image_to_encode image = imageOf(path, width, height, int(count), types.data(), GROTTO_PIXEL_FLOAT, px.data());
    image.channel_names = namePtrs.data();
    const CameraMatrices matrices(camera);
    matrices.describe(image);
    writeImage(path, image);
}

namespace {

// Whether a PNG ends with its IEND chunk, as a whole one does and a truncated one
// does not: libpng prints its errors on stderr, so those are not handed to it.
bool endsWithPngEnd(const std::filesystem::path& path) {
    static constexpr char kEnd[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', char(0xAE), 0x42, 0x60, char(0x82)};
    std::ifstream in(path, std::ios::binary);
    char tail[12] = {};
    return in.seekg(-12, std::ios::end) && in.read(tail, 12) && std::equal(tail, tail + 12, kEnd);
}

}  // namespace

bool imageDecodes(const std::filesystem::path& path, uint32_t width, uint32_t height) {
    if (imageFormatFor(path) == ImageFormat::Png && !endsWithPngEnd(path)) return false;
    // The size first: a frame of another size is not decoded at all.
    const std::optional<ImageFile> header = readImage(path, ReadAs::Header);
    if (!header || header->width != int(width) || header->height != int(height) || header->depth != 1) return false;
    return readImage(path, ReadAs::Check).has_value();
}

}  // namespace grotto
