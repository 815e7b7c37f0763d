#pragma once
// 8-bit PNGs, the commonest image Grotto writes (every frame of `render` and
// `flythrough`), encoded with libpng in the program itself: loading the codec
// module for them (OpenImageIO and some 250 libraries behind it) cost 0.55 s of
// CPU, 40% of a small render's run. Everything else goes through the module.
#include "engine/image_codec/image_codec_abi.h"

#include <string>

namespace grotto {

// Whether writePng8 takes `image`: a .png target, bytes in and stored, 1 to 4
// channels under the format's own names.
bool isPng8(const grotto_image_to_encode& image);

// `image` as PNG bytes in `out`, as the module writes them: the sRGB, gAMA and
// cHRM chunks, "oiio:ColorSpace" and "Software" in tEXt chunks, every row
// filtered by the one above. False with `error` filled when libpng fails.
bool writePng8(const grotto_image_to_encode& image, std::string& out, char (&error)[GROTTO_IMAGE_ERROR_SIZE]);

}  // namespace grotto
