#pragma once
// The C interface of the image codec module (grotto_image_codec, the one place
// OpenImageIO is linked). It is a module loaded on first use, not a library every
// program links, because OpenImageIO pulls in some 250 shared libraries (OpenCV,
// ffmpeg, GDAL...) whose relocation costs about 0.3 s of CPU at every start: most
// runs (info, bake, refusals of bad input) never touch an image. Plain C types
// only, so nothing of either side's C++ library crosses; no call throws.
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

// Raised whenever a struct below changes: a module built from other sources is refused.
#define GROTTO_IMAGE_CODEC_ABI 1

// A channel's type in the file, or the type pixels are handed over in.
enum grotto_pixel_type { GROTTO_PIXEL_NONE = -1, GROTTO_PIXEL_NATIVE = 0, GROTTO_PIXEL_UINT8 = 1, GROTTO_PIXEL_HALF = 2, GROTTO_PIXEL_FLOAT = 3,
                         GROTTO_PIXEL_OTHER = 4 };

// Room for one bounded line saying why a call failed.
#define GROTTO_IMAGE_ERROR_SIZE 512

// An image to encode: the target's extension (.png, .exr) picks the format; the
// file itself is not written, its bytes are handed back.
struct grotto_image_to_encode {
    const char* target;
    int width, height, channels;
    const char* const* channel_names;  // `channels` names, or NULL for the format's defaults
    const int* channel_types;          // `channels` grotto_pixel_type the file stores
    int pixel_type;                    // of `pixels`, interleaved, row 0 on top
    const void* pixels;
    int alpha_channel, z_channel;      // -1: the format's default (RGBA's A; no Z)
    const float* world_to_camera;      // 16 floats (glm's column-major layout), or NULL
    const float* world_to_screen;      // likewise
    const float* chromaticities;       // 8 floats (red, green, blue, white xy), or NULL
    const char* color_space;           // "oiio:ColorSpace", or NULL
    int png_level;                     // zlib level 0 to 9
};

struct grotto_encoded_image {
    unsigned char* bytes;  // owned by the module: grotto_image_free_encoded
    size_t size;
    void* owner;
    char error[GROTTO_IMAGE_ERROR_SIZE];
};

// A decoded file: what it says of itself, and its pixels in the type asked for
// (GROTTO_PIXEL_NATIVE: each channel's own; GROTTO_PIXEL_NONE: the header alone,
// no pixels read).
struct grotto_decoded_image {
    int width, height, depth, channels;
    char** channel_names;  // `channels` of them
    int* channel_types;    // `channels` grotto_pixel_type
    int z_channel;         // -1: none
    int has_world_to_camera, has_world_to_screen, has_chromaticities;
    float world_to_camera[16], world_to_screen[16], chromaticities[8];
    char color_space[64];
    void* pixels;  // owned by the module: grotto_image_free_decoded
    size_t pixel_bytes;
    char error[GROTTO_IMAGE_ERROR_SIZE];
};

// Each returns 1 on success; on failure 0 with `error` filled (and nothing to free
// but what the free functions accept anyway).
typedef int (*grotto_image_codec_abi_fn)(void);
typedef int (*grotto_image_encode_fn)(const struct grotto_image_to_encode* image, struct grotto_encoded_image* out);
typedef int (*grotto_image_decode_fn)(const char* path, int pixel_type, struct grotto_decoded_image* out);
typedef void (*grotto_image_free_encoded_fn)(struct grotto_encoded_image* image);
typedef void (*grotto_image_free_decoded_fn)(struct grotto_decoded_image* image);

int grotto_image_codec_abi(void);
int grotto_image_encode(const struct grotto_image_to_encode* image, struct grotto_encoded_image* out);
int grotto_image_decode(const char* path, int pixel_type, struct grotto_decoded_image* out);
void grotto_image_free_encoded(struct grotto_encoded_image* image);
void grotto_image_free_decoded(struct grotto_decoded_image* image);

#ifdef __cplusplus
}
#endif
