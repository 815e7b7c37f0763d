#include "engine/image_codec/codec_library.h"
#include "engine/image_codec/png_writer.h"

#include "grotto/error.h"

#include <dlfcn.h>

#include <memory>
#include <string>
#include <vector>

namespace grotto {
namespace {

constexpr const char* kModule = "libgrotto_image_codec.so";

struct Candidate {
    std::string path;   // what dlopen is given
    std::string where;  // how the message names it
};

// The directories the loader searches for the program's own libraries, its run
// path first ($ORIGIN expanded): asked of the loader rather than left to dlopen
// by name, which searches the run path of whoever calls it, and under
// AddressSanitizer that is the sanitizer's runtime, not the program.
std::vector<std::string> programSearchPath() {
    std::vector<std::string> dirs;
    void* self = dlopen(nullptr, RTLD_NOW);
    Dl_serinfo size;
    if (!self || dlinfo(self, RTLD_DI_SERINFOSIZE, &size) != 0) return dirs;
    std::vector<char> buffer(size.dls_size);
    auto* info = reinterpret_cast<Dl_serinfo*>(buffer.data());
    if (dlinfo(self, RTLD_DI_SERINFOSIZE, info) != 0 || dlinfo(self, RTLD_DI_SERINFO, info) != 0) return dirs;
    for (unsigned i = 0; i < info->dls_cnt; ++i) dirs.emplace_back(info->dls_serpath[i].dls_name);
    return dirs;
}

// Where the module is looked for, in order: the program's run path (an installed
// grotto's $ORIGIN/../lib/grotto, a game's through the installed package), so an
// installed or relocated copy finds its own; then this build tree's; then where
// `cmake --install` puts it.
std::vector<Candidate> candidates() {
    std::vector<Candidate> out;
    for (const std::string& dir : programSearchPath()) out.push_back({dir + "/" + kModule, dir});
    out.push_back({GROTTO_IMAGE_CODEC_BUILD_PATH, GROTTO_IMAGE_CODEC_BUILD_PATH});
    out.push_back({GROTTO_IMAGE_CODEC_INSTALL_PATH, GROTTO_IMAGE_CODEC_INSTALL_PATH});
    return out;
}

template <typename F>
F symbol(void* module, const char* name) {
    return reinterpret_cast<F>(dlsym(module, name));
}

ImageCodec load() {
    std::string looked, why;
    for (const Candidate& c : candidates()) {
        looked += (looked.empty() ? "" : ", ") + c.where;
        // The module stays loaded for the life of the process: never dlclose'd.
        void* module = dlopen(c.path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!module) {
            // Why a module that is there did not load (a library it needs is
            // missing) says more than "not found" at the places it is not.
            const std::string error = dlerror();
            if (why.empty() && error.find("No such file") == std::string::npos) why = error;
            continue;
        }
        const auto abi = symbol<grotto_image_codec_abi_fn>(module, "grotto_image_codec_abi");
        const ImageCodec codec{
            .encode = symbol<grotto_image_encode_fn>(module, "grotto_image_encode"),
            .decode = symbol<grotto_image_decode_fn>(module, "grotto_image_decode"),
            .freeEncoded = symbol<grotto_image_free_encoded_fn>(module, "grotto_image_free_encoded"),
            .freeDecoded = symbol<grotto_image_free_decoded_fn>(module, "grotto_image_free_decoded"),
        };
        if (abi && abi() == GROTTO_IMAGE_CODEC_ABI && codec.encode && codec.decode && codec.freeEncoded && codec.freeDecoded)
            return codec;
        if (why.empty()) why = c.where + " holds a module of another version of Grotto";
    }
    throw Error::internal(kModule, "the image codec module cannot be loaded" + (why.empty() ? "" : ": " + why) +
                                       " (looked in " + looked + ")",
                          "build the grotto_image_codec target, or reinstall Grotto");
}

}  // namespace

const ImageCodec& imageCodec() {
    static const ImageCodec codec = load();
    return codec;
}

void encodeImage(const grotto_image_to_encode& image, const std::function<void(std::string_view bytes)>& use) {
    if (isPng8(image)) {  // without the module (png_writer.h)
        std::string bytes;
        char error[GROTTO_IMAGE_ERROR_SIZE] = "";
        if (!writePng8(image, bytes, error)) throw Error::internal(image.target, std::string("cannot be encoded: ") + error);
        use(bytes);
        return;
    }
    const ImageCodec& codec = imageCodec();
    grotto_encoded_image encoded;
    if (!codec.encode(&image, &encoded)) throw Error::internal(image.target, std::string("cannot be encoded: ") + encoded.error);
    const std::unique_ptr<grotto_encoded_image, grotto_image_free_encoded_fn> owned(&encoded, codec.freeEncoded);
    use(std::string_view(reinterpret_cast<const char*>(encoded.bytes), encoded.size));
}

}  // namespace grotto
