#include "voxel/gltf/gltf_file.h"

#include "common/file_kind.h"
#include "common/json_text.h"
#include "grotto/error.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace grotto::voxel {
namespace fs = std::filesystem;

namespace {

// Images stay undecoded: a camera or a mesh read back needs none, and a hostile
// one must not reach an image decoder.
bool keepImageUndecoded(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                        void*) {
    return true;
}

// Files a .gltf names (its buffers) are read only when they are regular files,
// and at most kMaxGltfFileBytes of them in all: a URI naming /dev/zero, a FIFO,
// /proc's endless files or one file a million times must not hang a run.
bool isRegularFile(const std::string& path, void*) {
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}
std::string asGiven(const std::string& path, void*) { return path; }
bool readBoundedFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* budget) {
    uintmax_t& left = *static_cast<uintmax_t*>(budget);
    std::error_code ec;
    std::ifstream in;
    if (fs::is_regular_file(path, ec)) in.open(path, std::ios::binary);
    out->clear();
    char chunk[1 << 16];
    while (in && (in.read(chunk, sizeof chunk) || in.gcount() > 0)) {
        const auto got = uintmax_t(in.gcount());
        if (got > left) {
            if (err) *err += "buffer files reach past 256 MiB in all ('" + path + "')\n";
            return false;
        }
        left -= got;
        out->insert(out->end(), chunk, chunk + got);
    }
    if (!in.eof()) {
        if (err) *err += "buffer file '" + path + "' is not a readable regular file\n";
        return false;
    }
    return true;
}
bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not done here\n";
    return false;
}

// The JSON tinygltf will parse (all of a .gltf, a .glb's first chunk), checked
// for depth first: its parser recurses once per level of extras.
std::string_view jsonOf(const std::vector<unsigned char>& bytes, bool binary) {
    const auto* text = reinterpret_cast<const char*>(bytes.data());
    if (!binary) return {text, bytes.size()};
    if (bytes.size() < 20) return {};
    uint32_t length = 0;
    std::memcpy(&length, text + 12, 4);
    return {text + 20, std::min<size_t>(length, bytes.size() - 20)};
}

std::string firstLine(const std::string& text) {
    const std::string line = text.substr(0, text.find('\n'));
    return line.empty() ? "not a glTF 2.0 file" : line;
}

}  // namespace

tinygltf::Model readGltf(const fs::path& path) {
    const std::string file = path.string();
    requireInputFile(path, "give a glTF 2.0 file: .glb, or .gltf with its buffers");
    std::error_code ec;
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) throw Error(file, "cannot be read: " + ec.message());
    if (size > kMaxGltfFileBytes)
        throw Error(file, "is " + std::to_string(size >> 20) + " MiB, more than the " +
                              std::to_string(kMaxGltfFileBytes >> 20) + " MiB a glTF file may be here");
    std::ifstream in(path, std::ios::binary);
    const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.eof() && in.fail()) throw Error(file, "cannot be read");
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    requireShallowJson(jsonOf(bytes, binary), file);
    uintmax_t bufferBudget = kMaxGltfFileBytes;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keepImageUndecoded, nullptr);
    loader.SetFsCallbacks({isRegularFile, asGiven, readBoundedFile, refuseWrite, &bufferBudget});
    tinygltf::Model model;
    std::string err, warn;
    const std::string dir = path.parent_path().empty() ? "." : path.parent_path().string();
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), dir)
                           : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                        unsigned(bytes.size()), dir);
    if (!ok) throw Error(file, firstLine(err), "give a glTF 2.0 file: .glb, or .gltf with its buffers");
    return model;
}

std::vector<float> gltfFloats(const tinygltf::Model& model, int index, int components, const std::string& file,
                              const std::string& field) {
    auto fail = [&](const std::string& what) -> Error {
        return Error(file, "accessor " + std::to_string(index) + " (" + field + "): " + what);
    };
    if (index < 0 || size_t(index) >= model.accessors.size()) throw fail("does not exist");
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    const int have = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (have != components)
        throw fail("has " + std::to_string(std::max(have, 0)) + " components, expected " + std::to_string(components));
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) throw fail("is not of FLOAT components");
    if (a.sparse.isSparse) throw fail("is sparse, which is not supported here");
    if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size()) throw fail("has no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) throw fail("its buffer view has no buffer");
    const std::vector<unsigned char>& buffer = model.buffers[size_t(view.buffer)].data;
    const uint64_t element = uint64_t(components) * sizeof(float);
    const uint64_t stride = view.byteStride ? uint64_t(view.byteStride) : element;
    const uint64_t count = uint64_t(a.count);
    if (stride < element) throw fail("its buffer view's stride is smaller than an element");
    // Each bound first, so no sum below can wrap.
    if (count > buffer.size() || stride > 256 || view.byteOffset > buffer.size() || view.byteLength > buffer.size() ||
        a.byteOffset > buffer.size())
        throw fail("reaches past its buffer");
    const uint64_t viewEnd = uint64_t(view.byteOffset) + uint64_t(view.byteLength);
    const uint64_t need = count == 0 ? 0 : uint64_t(a.byteOffset) + stride * (count - 1) + element;
    if (viewEnd > buffer.size() || need > uint64_t(view.byteLength)) throw fail("reaches past its buffer");
    std::vector<float> out(size_t(count) * size_t(components));
    for (uint64_t i = 0; i < count; ++i)
        std::memcpy(&out[size_t(i) * size_t(components)],
                    buffer.data() + view.byteOffset + a.byteOffset + i * stride, size_t(element));
    for (float v : out)
        if (!std::isfinite(v)) throw fail("holds a value that is not finite");
    return out;
}

}  // namespace grotto::voxel
