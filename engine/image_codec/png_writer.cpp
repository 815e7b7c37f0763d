#include "engine/image_codec/png_writer.h"

#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstring>

namespace grotto {
namespace {

// Where libpng's callbacks report: its error message, and the bytes written.
struct Sink {
    std::string* bytes;
    char* error;
    size_t errorSize;
};

[[noreturn]] void onError(png_structp png, png_const_charp message) {
    const Sink* sink = static_cast<const Sink*>(png_get_error_ptr(png));
    std::snprintf(sink->error, sink->errorSize, "libpng: %s", message);
    png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}

void append(png_structp png, png_bytep data, png_size_t size) {
    bool failed = false;
    try {
        static_cast<Sink*>(png_get_io_ptr(png))->bytes->append(reinterpret_cast<const char*>(data), size);
    } catch (...) {  // no exception may cross libpng's C frames
        failed = true;  // png_error leaves by longjmp: not from inside the handler
    }
    if (failed) png_error(png, "no memory left for the encoded image");
}

void flush(png_structp) {}

int colourType(int channels) {
    switch (channels) {
        case 1: return PNG_COLOR_TYPE_GRAY;
        case 2: return PNG_COLOR_TYPE_GRAY_ALPHA;
        case 3: return PNG_COLOR_TYPE_RGB;
        default: return PNG_COLOR_TYPE_RGB_ALPHA;
    }
}

// No C++ object lives between setjmp and a longjmp back to it: `sink` and the
// text chunks are plain data the caller or this frame owns throughout.
bool encode(const grotto_image_to_encode& image, Sink& sink) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, onError, onWarning);
    if (!png) return std::snprintf(sink.error, sink.errorSize, "libpng: cannot start a PNG"), false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        if (!info) std::snprintf(sink.error, sink.errorSize, "libpng: cannot start a PNG");
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, &sink, append, flush);
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, colourType(image.channels),
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, std::clamp(image.png_level, 0, 9));
    // Every row predicted from the one above: as small as trying all five
    // filters on each row, in about half the time.
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
    if (image.color_space && std::strcmp(image.color_space, "sRGB") == 0)
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
    char colourKey[] = "oiio:ColorSpace", softwareKey[] = "Software", software[] = "grotto";
    char colourSpace[64] = "";
    if (image.color_space) std::snprintf(colourSpace, sizeof colourSpace, "%s", image.color_space);
    png_text text[2] = {};
    text[0] = {.compression = PNG_TEXT_COMPRESSION_NONE, .key = softwareKey, .text = software};
    text[1] = {.compression = PNG_TEXT_COMPRESSION_NONE, .key = colourKey, .text = colourSpace};
    png_set_text(png, info, text, image.color_space ? 2 : 1);
    png_write_info(png, info);
    const size_t stride = size_t(image.width) * size_t(image.channels);
    const auto* pixels = static_cast<const png_byte*>(image.pixels);
    for (int y = 0; y < image.height; ++y) png_write_row(png, pixels + stride * size_t(y));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

bool isPng8(const grotto_image_to_encode& image) {
    const size_t n = std::strlen(image.target);
    if (n < 4 || std::strcmp(image.target + n - 4, ".png") != 0) return false;
    if (image.channels < 1 || image.channels > 4 || image.pixel_type != GROTTO_PIXEL_UINT8 || image.channel_names) return false;
    if (!std::all_of(image.channel_types, image.channel_types + image.channels, [](int t) { return t == GROTTO_PIXEL_UINT8; }))
        return false;
    const bool alphaAsFormat = image.alpha_channel < 0 || image.alpha_channel == image.channels - 1;
    return alphaAsFormat && image.z_channel < 0 && image.width > 0 && image.height > 0;
}

bool writePng8(const grotto_image_to_encode& image, std::string& out, char (&error)[GROTTO_IMAGE_ERROR_SIZE]) {
    out.clear();
    Sink sink{.bytes = &out, .error = error, .errorSize = sizeof error};
    return encode(image, sink);
}

}  // namespace grotto
