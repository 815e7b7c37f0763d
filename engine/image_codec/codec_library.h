#pragma once
// The image codec module (image_codec_abi.h), loaded on the first image encoded or
// decoded, once, so that a process that never touches an image never maps
// OpenImageIO and the libraries behind it.
#include "engine/image_codec/image_codec_abi.h"

#include <functional>
#include <string_view>

namespace grotto {

struct ImageCodec {
    grotto_image_encode_fn encode;
    grotto_image_decode_fn decode;
    grotto_image_free_encoded_fn freeEncoded;
    grotto_image_free_decoded_fn freeDecoded;
};

// The module's functions, loading it on the first call (thread-safe). Throws
// grotto::Error (internal) naming the module and where it was looked for when it
// cannot be loaded; a later call tries again.
const ImageCodec& imageCodec();

// Encodes `image` in memory and hands its bytes to `use`; throws grotto::Error
// (internal) naming the target when it cannot be encoded.
void encodeImage(const grotto_image_to_encode& image, const std::function<void(std::string_view bytes)>& use);

}  // namespace grotto
