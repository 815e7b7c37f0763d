#include "engine/image_input.h"

#include "engine/image_codec/codec_library.h"

#include <algorithm>
#include <cstring>
#include <memory>

namespace grotto {

int ImageFile::channelIndex(std::string_view name) const {
    const auto it = std::find(channelNames.begin(), channelNames.end(), name);
    return it == channelNames.end() ? -1 : int(it - channelNames.begin());
}

std::vector<float> ImageFile::channel(std::string_view name) const {
    const int c = channelIndex(name);
    if (c < 0 || floats.empty()) return {};
    const size_t n = size_t(width) * size_t(height) * size_t(depth), stride = size_t(channels());
    std::vector<float> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = floats[i * stride + size_t(c)];
    return v;
}

namespace {

ChannelType channelType(int code) {
    switch (code) {
        case GROTTO_PIXEL_UINT8: return ChannelType::UInt8;
        case GROTTO_PIXEL_HALF: return ChannelType::Half;
        case GROTTO_PIXEL_FLOAT: return ChannelType::Float;
        default: return ChannelType::Other;
    }
}

std::array<float, 16> matrix(const float (&m)[16]) {
    std::array<float, 16> a;
    std::copy(m, m + 16, a.begin());
    return a;
}

}  // namespace

std::optional<ImageFile> readImage(const std::filesystem::path& path, ReadAs as, std::string* why) {
    const ImageCodec& codec = imageCodec();
    const int type = as == ReadAs::Float   ? GROTTO_PIXEL_FLOAT
                     : as == ReadAs::UInt8 ? GROTTO_PIXEL_UINT8
                     : as == ReadAs::Check ? GROTTO_PIXEL_NATIVE
                                           : GROTTO_PIXEL_NONE;
    grotto_decoded_image d;
    const bool decoded = codec.decode(path.c_str(), type, &d);
    const std::unique_ptr<grotto_decoded_image, grotto_image_free_decoded_fn> owned(&d, codec.freeDecoded);
    if (!decoded) {
        if (why) *why = d.error;
        return std::nullopt;
    }
    ImageFile image{.width = d.width, .height = d.height, .depth = d.depth, .zChannel = d.z_channel, .colorSpace = d.color_space};
    for (int c = 0; c < d.channels; ++c) {
        image.channelNames.emplace_back(d.channel_names[c]);
        image.channelTypes.push_back(channelType(d.channel_types[c]));
    }
    if (d.has_world_to_camera) image.worldToCamera = matrix(d.world_to_camera);
    if (d.has_world_to_screen) image.worldToScreen = matrix(d.world_to_screen);
    if (d.has_chromaticities) image.chromaticities.assign(d.chromaticities, d.chromaticities + 8);
    const auto* pixels = static_cast<const uint8_t*>(d.pixels);
    if (as == ReadAs::Float) {
        image.floats.resize(d.pixel_bytes / sizeof(float));
        std::memcpy(image.floats.data(), pixels, image.floats.size() * sizeof(float));
    } else if (as == ReadAs::UInt8) {
        image.bytes.assign(pixels, pixels + d.pixel_bytes);
    }
    return image;
}

}  // namespace grotto
