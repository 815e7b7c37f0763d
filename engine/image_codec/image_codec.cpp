// The image codec module: image_codec_abi.h's functions over OpenImageIO, the one
// file that includes it. Loaded on first use (codec_library.cpp); no exception
// leaves it.
#include "engine/image_codec/image_codec_abi.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace {
namespace OIIO = OIIO_NAMESPACE;

// One bounded line: OpenImageIO's messages may hold newlines.
void setError(char (&error)[GROTTO_IMAGE_ERROR_SIZE], std::string message) {
    std::replace(message.begin(), message.end(), '\n', ' ');
    while (!message.empty() && message.back() == ' ') message.pop_back();
    if (message.empty()) message = "unknown error";
    std::snprintf(error, sizeof error, "%s", message.c_str());
}

OIIO::TypeDesc typeOf(int type) {
    switch (type) {
        case GROTTO_PIXEL_UINT8: return OIIO::TypeDesc::UINT8;
        case GROTTO_PIXEL_HALF: return OIIO::TypeDesc::HALF;
        case GROTTO_PIXEL_FLOAT: return OIIO::TypeDesc::FLOAT;
        default: return OIIO::TypeUnknown;
    }
}

int typeCode(OIIO::TypeDesc type) {
    if (type == OIIO::TypeDesc::UINT8) return GROTTO_PIXEL_UINT8;
    if (type == OIIO::TypeDesc::HALF) return GROTTO_PIXEL_HALF;
    if (type == OIIO::TypeDesc::FLOAT) return GROTTO_PIXEL_FLOAT;
    return GROTTO_PIXEL_OTHER;
}

bool isPng(const char* target) {
    const size_t n = std::strlen(target);
    return n >= 4 && std::strcmp(target + n - 4, ".png") == 0;
}

OIIO::ImageSpec specOf(const grotto_image_to_encode& image) {
    const std::vector<int> types(image.channel_types, image.channel_types + image.channels);
    OIIO::ImageSpec spec(image.width, image.height, image.channels, typeOf(types[0]));
    if (image.channel_names) spec.channelnames.assign(image.channel_names, image.channel_names + image.channels);
    if (image.alpha_channel >= 0) spec.alpha_channel = image.alpha_channel;
    if (image.z_channel >= 0) spec.z_channel = image.z_channel;
    if (std::any_of(types.begin(), types.end(), [&](int t) { return t != types[0]; }))
        for (int t : types) spec.channelformats.push_back(typeOf(t));
    if (image.color_space) spec.attribute("oiio:ColorSpace", image.color_space);
    if (isPng(image.target)) {
        spec.attribute("png:compressionLevel", std::clamp(image.png_level, 0, 9));
        // Every row predicted from the one above (PNG_FILTER_UP): as small as
        // libpng's default of trying all five filters on each row, in about half the time.
        spec.attribute("png:filter", 0x20);
    } else {
        if (image.chromaticities) spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), image.chromaticities);
        spec.attribute("compression", "zip");
    }
    // Imath (row-vector) matrices share their memory layout with glm's column-major ones.
    if (image.world_to_camera) spec.attribute("worldtocamera", OIIO::TypeMatrix44, image.world_to_camera);
    if (image.world_to_screen) spec.attribute("worldtoscreen", OIIO::TypeMatrix44, image.world_to_screen);
    spec.attribute("Software", "grotto");
    return spec;
}

void copyAttribute(const OIIO::ImageSpec& spec, const char* name, OIIO::TypeDesc type, int& has, float* to, size_t n) {
    const OIIO::ParamValue* p = spec.find_attribute(name, type);
    has = p != nullptr;
    if (p) std::memcpy(to, p->data(), n * sizeof(float));
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) int grotto_image_codec_abi(void) { return GROTTO_IMAGE_CODEC_ABI; }

__attribute__((visibility("default"))) int grotto_image_encode(const grotto_image_to_encode* image, grotto_encoded_image* out) {
    *out = {};
    try {
        auto bytes = std::make_unique<std::vector<unsigned char>>();
        OIIO::Filesystem::IOVecOutput memory(*bytes);
        const OIIO::ImageSpec spec = specOf(*image);
        auto encoder = OIIO::ImageOutput::create(image->target);
        if (!encoder || !encoder->set_ioproxy(&memory) || !encoder->open(image->target, spec) ||
            !encoder->write_image(typeOf(image->pixel_type), image->pixels) || !encoder->close()) {
            setError(out->error, encoder ? encoder->geterror() : OIIO::geterror());
            return 0;
        }
        out->bytes = bytes->data();
        out->size = bytes->size();
        out->owner = bytes.release();
        return 1;
    } catch (const std::exception& e) {
        setError(out->error, e.what());
        return 0;
    }
}

__attribute__((visibility("default"))) void grotto_image_free_encoded(grotto_encoded_image* image) {
    delete static_cast<std::vector<unsigned char>*>(image->owner);
    image->owner = nullptr;
    image->bytes = nullptr;
    image->size = 0;
}

__attribute__((visibility("default"))) int grotto_image_decode(const char* path, int pixelType, grotto_decoded_image* out) {
    *out = {};
    try {
        auto in = OIIO::ImageInput::open(path);
        if (!in) {
            setError(out->error, OIIO::geterror());  // taken, so OpenImageIO does not print it
            return 0;
        }
        const OIIO::ImageSpec& spec = in->spec();
        out->width = spec.width;
        out->height = spec.height;
        out->depth = spec.depth;
        out->channels = spec.nchannels;
        out->z_channel = spec.z_channel;
        out->channel_names = static_cast<char**>(std::calloc(size_t(spec.nchannels), sizeof(char*)));
        out->channel_types = static_cast<int*>(std::calloc(size_t(spec.nchannels), sizeof(int)));
        for (int c = 0; c < spec.nchannels; ++c) {
            out->channel_names[c] = strdup(spec.channelnames[size_t(c)].c_str());
            out->channel_types[c] = typeCode(spec.channelformat(c));
        }
        copyAttribute(spec, "worldtocamera", OIIO::TypeMatrix44, out->has_world_to_camera, out->world_to_camera, 16);
        copyAttribute(spec, "worldtoscreen", OIIO::TypeMatrix44, out->has_world_to_screen, out->world_to_screen, 16);
        copyAttribute(spec, "chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), out->has_chromaticities,
                      out->chromaticities, 8);
        std::snprintf(out->color_space, sizeof out->color_space, "%s", spec.get_string_attribute("oiio:ColorSpace").c_str());
        if (pixelType == GROTTO_PIXEL_NONE) {
            in->geterror();
            return 1;
        }
        const OIIO::TypeDesc type = typeOf(pixelType);
        out->pixel_bytes = type == OIIO::TypeUnknown ? spec.image_bytes(true)
                                                     : size_t(spec.image_pixels()) * size_t(spec.nchannels) * type.size();
        out->pixels = std::malloc(std::max<size_t>(out->pixel_bytes, 1));
        if (!out->pixels) {
            setError(out->error, "out of memory for " + std::to_string(out->pixel_bytes) + " bytes of pixels");
            return 0;
        }
        if (!in->read_image(0, 0, 0, spec.nchannels, type, out->pixels) || !in->close()) {
            setError(out->error, in->geterror());
            return 0;
        }
        in->geterror();  // any warning taken, so OpenImageIO does not print it
        return 1;
    } catch (const std::exception& e) {
        setError(out->error, e.what());
        return 0;
    }
}

__attribute__((visibility("default"))) void grotto_image_free_decoded(grotto_decoded_image* image) {
    for (int c = 0; image->channel_names && c < image->channels; ++c) std::free(image->channel_names[c]);
    std::free(image->channel_names);
    std::free(image->channel_types);
    std::free(image->pixels);
    *image = {};
}

}  // extern "C"
