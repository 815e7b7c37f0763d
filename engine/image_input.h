#pragma once
// Reads an image file (PNG, EXR) whole through the image codec module, loaded on
// first use: what the file says of itself (size, channels and their types, the
// camera and colour attributes writeFrame writes) and its pixels.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grotto {

// A channel's type in the file.
enum class ChannelType { UInt8, Half, Float, Other };

// What the pixels are handed back as: floats, 8-bit values (as OpenImageIO
// converts), or nothing: Check decodes them whole in their own types and drops
// them, Header reads none.
enum class ReadAs { Float, UInt8, Check, Header };

struct ImageFile {
    int width = 0, height = 0, depth = 1;
    std::vector<std::string> channelNames;
    std::vector<ChannelType> channelTypes;
    int zChannel = -1;
    std::optional<std::array<float, 16>> worldToCamera, worldToScreen;  // glm's column-major layout
    std::vector<float> chromaticities;  // red, green, blue and white xy, or none
    std::string colorSpace;             // "oiio:ColorSpace"
    std::vector<float> floats;          // ReadAs::Float: every channel interleaved, row 0 on top
    std::vector<uint8_t> bytes;         // ReadAs::UInt8: likewise

    int channels() const { return int(channelNames.size()); }
    // The channel's index, or -1.
    int channelIndex(std::string_view name) const;
    // One channel's floats, width * height of them (ReadAs::Float).
    std::vector<float> channel(std::string_view name) const;
};

// The file decoded whole, or nothing (with `why` set, when given) when it cannot
// be. Throws grotto::Error (internal) only when the codec module cannot be loaded.
std::optional<ImageFile> readImage(const std::filesystem::path& path, ReadAs as = ReadAs::Float, std::string* why = nullptr);

}  // namespace grotto
