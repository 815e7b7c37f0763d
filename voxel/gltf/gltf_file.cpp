#include "voxel/gltf/gltf_file.h"

#include "common/file_kind.h"
#include "common/json_text.h"
#include "common/printable.h"
#include "grotto/error.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>

namespace grotto::voxel {
namespace fs = std::filesystem;

namespace {

// Images stay undecoded: a camera or a mesh read back needs none, and a hostile
// one must not reach an image decoder.
bool keepImageUndecoded(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                        void*) {
    return true;
}

// Up to `limit` bytes of a regular file. Read by istream::read, which turns a
// failing read (/proc/self/mem) into a state, not an exception.
enum class Read { Whole, Unreadable, TooLarge };
Read readUpTo(const std::string& path, uintmax_t limit, std::vector<unsigned char>& out) {
    out.clear();
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return Read::Unreadable;
    std::ifstream in(path, std::ios::binary);
    char chunk[1 << 16];
    while (in && (in.read(chunk, sizeof chunk) || in.gcount() > 0)) {
        const auto got = uintmax_t(in.gcount());
        if (got > limit - out.size()) return Read::TooLarge;
        out.insert(out.end(), chunk, chunk + got);
    }
    return in.eof() && !in.bad() ? Read::Whole : Read::Unreadable;
}

// What tinygltf's file callbacks share: the .gltf's folder (resolved), what its
// files may still take, and why a URI was refused (tinygltf would only say
// "File not found").
struct Files {
    fs::path folder;
    uintmax_t left = kMaxGltfFileBytes;
    std::string refused;
};

// A URI that starts with a scheme ("file:", "http:") names no file in the folder.
bool hasScheme(const std::string& uri) {
    const size_t colon = uri.find(':');
    if (colon == std::string::npos || colon == 0 || !std::isalpha((unsigned char)uri[0])) return false;
    return std::all_of(uri.begin(), uri.begin() + long(colon),
                       [](char c) { return std::isalnum((unsigned char)c) || c == '+' || c == '-' || c == '.'; });
}

// tinygltf asks for a buffer's or image's (URL-decoded) URI here. It resolves
// against the file's folder, `..` and symbolic links followed, and must stay in
// it: a URI must not read /etc/shadow, not even to learn its size. Refused: "".
std::string resolveInFolder(const std::string& uri, void* files) {
    Files& f = *static_cast<Files*>(files);
    std::string why;
    std::error_code ec;
    if (hasScheme(uri) || uri.find('\0') != std::string::npos) {
        why = "is not a relative file name";
    } else if (fs::path(uri).is_absolute()) {
        why = "is an absolute path";
    } else if (const fs::path full = fs::weakly_canonical(f.folder / uri, ec); ec) {
        why = "cannot be resolved (" + ec.message() + ")";
    } else if (const fs::path rel = full.lexically_relative(f.folder); rel.empty() || *rel.begin() == "..") {
        why = "leads outside the file's folder";
    } else {
        return full.string();
    }
    if (f.refused.empty()) f.refused = "URI '" + printableExcerpt(uri, 80) + "' " + why;
    return {};
}
bool isRegularFile(const std::string& path, void*) {
    std::error_code ec;
    return !path.empty() && fs::is_regular_file(path, ec);
}
// At most kMaxGltfFileBytes in all: one file named a thousand times must not fill memory.
bool readInBudget(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* files) {
    Files& f = *static_cast<Files*>(files);
    const Read read = readUpTo(path, f.left, *out);
    if (read == Read::Whole) f.left -= out->size();
    else if (err) *err += read == Read::TooLarge ? "buffer files reach past 256 MiB in all\n" : "a buffer file cannot be read\n";
    return read == Read::Whole;
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

// tinygltf's first complaint, which may quote a whole data URI: bounded.
std::string firstLine(std::string_view text) {
    const std::string_view line = text.substr(0, text.find('\n'));
    return line.empty() ? "not a glTF 2.0 file" : printableExcerpt(line, 200);
}

// A GLB's header version: 2 (glTF 1.0's binary extension wrote 1).
void requireGlbVersion2(const std::vector<unsigned char>& bytes, const std::string& file) {
    uint32_t version = 0;
    if (bytes.size() >= 8) std::memcpy(&version, bytes.data() + 4, 4);
    if (version != 2) throw Error(file, "is a GLB of version " + std::to_string(version), "accepted: glTF 2.0 (GLB version 2)");
}

// What tinygltf reads without checking: the asset's version, and the nodes and
// samplers animation channels name (an unknown node would be skipped silently).
void requireGltf2(const tinygltf::Model& m, const std::string& file) {
    const std::string& v = m.asset.version;
    if (v.size() < 3 || v.compare(0, 2, "2.") != 0 ||
        !std::all_of(v.begin() + 2, v.end(), [](char c) { return std::isdigit((unsigned char)c); }))
        throw Error(file, "'asset.version' is '" + printableExcerpt(v, 40) + "'", "accepted: glTF 2.x, such as \"2.0\"");
    for (size_t a = 0; a < m.animations.size(); ++a)
        for (size_t c = 0; c < m.animations[a].channels.size(); ++c) {
            const tinygltf::AnimationChannel& ch = m.animations[a].channels[c];
            const std::string where = "animation " + std::to_string(a) + " channel " + std::to_string(c);
            if (ch.target_node < -1 || ch.target_node >= int(m.nodes.size()))
                throw Error(file, where + " targets node " + std::to_string(ch.target_node) + ", which does not exist",
                            "the file has " + std::to_string(m.nodes.size()) + " nodes");
            if (ch.sampler < 0 || size_t(ch.sampler) >= m.animations[a].samplers.size())
                throw Error(file, where + " names sampler " + std::to_string(ch.sampler) + ", which does not exist");
        }
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
    std::vector<unsigned char> bytes;
    const Read read = readUpTo(file, kMaxGltfFileBytes, bytes);
    if (read == Read::TooLarge) throw Error(file, "holds more than " + std::to_string(kMaxGltfFileBytes >> 20) + " MiB");
    if (read == Read::Unreadable) throw Error(file, "cannot be read", "give a glTF 2.0 file: .glb, or .gltf with its buffers");
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    if (binary) requireGlbVersion2(bytes, file);
    requireShallowJson(jsonOf(bytes, binary), file);
    Files files;
    files.folder = fs::canonical(fs::absolute(path, ec).parent_path(), ec);
    if (ec) throw Error(file, "its folder cannot be resolved: " + ec.message());
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keepImageUndecoded, nullptr);
    loader.SetFsCallbacks({isRegularFile, resolveInFolder, readInBudget, refuseWrite, &files});
    tinygltf::Model model;
    std::string err, warn;
    // No base folder: resolveInFolder resolves each URI against files.folder itself.
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), "")
                           : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                        unsigned(bytes.size()), "");
    if (!files.refused.empty())
        throw Error(file, files.refused, "accepted: embedded data, or a relative URI naming a file in the .gltf's folder or below it");
    if (!ok) throw Error(file, firstLine(err), "give a glTF 2.0 file: .glb, or .gltf with its buffers");
    requireGltf2(model, file);
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
