// Reading MagicaVoxel .vox files (ephtracy/voxel-model: MagicaVoxel-file-format-vox.txt
// and MagicaVoxel-file-format-vox-extension.txt): a RIFF-style tree of chunks,
// id(4) + content size(4) + children size(4) + content + children, all little-endian.
#include "voxel/vox_read.h"

#include "common/file_kind.h"
#include "common/printable.h"
#include "grotto/error.h"
#include "voxel/vox_chunk.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string_view>
#include <unordered_map>
#include <utility>

namespace grotto::voxel {
namespace {

// MagicaVoxel's palette for files without an RGBA chunk, from its format
// description (section 8): entry c is colour index c, as 0xAABBGGRR.
constexpr uint32_t kDefaultPalette[256] = {
    0x00000000, 0xffffffff, 0xffccffff, 0xff99ffff, 0xff66ffff, 0xff33ffff, 0xff00ffff, 0xffffccff,
    0xffccccff, 0xff99ccff, 0xff66ccff, 0xff33ccff, 0xff00ccff, 0xffff99ff, 0xffcc99ff, 0xff9999ff,
    0xff6699ff, 0xff3399ff, 0xff0099ff, 0xffff66ff, 0xffcc66ff, 0xff9966ff, 0xff6666ff, 0xff3366ff,
    0xff0066ff, 0xffff33ff, 0xffcc33ff, 0xff9933ff, 0xff6633ff, 0xff3333ff, 0xff0033ff, 0xffff00ff,
    0xffcc00ff, 0xff9900ff, 0xff6600ff, 0xff3300ff, 0xff0000ff, 0xffffffcc, 0xffccffcc, 0xff99ffcc,
    0xff66ffcc, 0xff33ffcc, 0xff00ffcc, 0xffffcccc, 0xffcccccc, 0xff99cccc, 0xff66cccc, 0xff33cccc,
    0xff00cccc, 0xffff99cc, 0xffcc99cc, 0xff9999cc, 0xff6699cc, 0xff3399cc, 0xff0099cc, 0xffff66cc,
    0xffcc66cc, 0xff9966cc, 0xff6666cc, 0xff3366cc, 0xff0066cc, 0xffff33cc, 0xffcc33cc, 0xff9933cc,
    0xff6633cc, 0xff3333cc, 0xff0033cc, 0xffff00cc, 0xffcc00cc, 0xff9900cc, 0xff6600cc, 0xff3300cc,
    0xff0000cc, 0xffffff99, 0xffccff99, 0xff99ff99, 0xff66ff99, 0xff33ff99, 0xff00ff99, 0xffffcc99,
    0xffcccc99, 0xff99cc99, 0xff66cc99, 0xff33cc99, 0xff00cc99, 0xffff9999, 0xffcc9999, 0xff999999,
    0xff669999, 0xff339999, 0xff009999, 0xffff6699, 0xffcc6699, 0xff996699, 0xff666699, 0xff336699,
    0xff006699, 0xffff3399, 0xffcc3399, 0xff993399, 0xff663399, 0xff333399, 0xff003399, 0xffff0099,
    0xffcc0099, 0xff990099, 0xff660099, 0xff330099, 0xff000099, 0xffffff66, 0xffccff66, 0xff99ff66,
    0xff66ff66, 0xff33ff66, 0xff00ff66, 0xffffcc66, 0xffcccc66, 0xff99cc66, 0xff66cc66, 0xff33cc66,
    0xff00cc66, 0xffff9966, 0xffcc9966, 0xff999966, 0xff669966, 0xff339966, 0xff009966, 0xffff6666,
    0xffcc6666, 0xff996666, 0xff666666, 0xff336666, 0xff006666, 0xffff3366, 0xffcc3366, 0xff993366,
    0xff663366, 0xff333366, 0xff003366, 0xffff0066, 0xffcc0066, 0xff990066, 0xff660066, 0xff330066,
    0xff000066, 0xffffff33, 0xffccff33, 0xff99ff33, 0xff66ff33, 0xff33ff33, 0xff00ff33, 0xffffcc33,
    0xffcccc33, 0xff99cc33, 0xff66cc33, 0xff33cc33, 0xff00cc33, 0xffff9933, 0xffcc9933, 0xff999933,
    0xff669933, 0xff339933, 0xff009933, 0xffff6633, 0xffcc6633, 0xff996633, 0xff666633, 0xff336633,
    0xff006633, 0xffff3333, 0xffcc3333, 0xff993333, 0xff663333, 0xff333333, 0xff003333, 0xffff0033,
    0xffcc0033, 0xff990033, 0xff660033, 0xff330033, 0xff000033, 0xffffff00, 0xffccff00, 0xff99ff00,
    0xff66ff00, 0xff33ff00, 0xff00ff00, 0xffffcc00, 0xffcccc00, 0xff99cc00, 0xff66cc00, 0xff33cc00,
    0xff00cc00, 0xffff9900, 0xffcc9900, 0xff999900, 0xff669900, 0xff339900, 0xff009900, 0xffff6600,
    0xffcc6600, 0xff996600, 0xff666600, 0xff336600, 0xff006600, 0xffff3300, 0xffcc3300, 0xff993300,
    0xff663300, 0xff333300, 0xff003300, 0xffff0000, 0xffcc0000, 0xff990000, 0xff660000, 0xff330000,
    0xff0000ee, 0xff0000dd, 0xff0000bb, 0xff0000aa, 0xff000088, 0xff000077, 0xff000055, 0xff000044,
    0xff000022, 0xff000011, 0xff00ee00, 0xff00dd00, 0xff00bb00, 0xff00aa00, 0xff008800, 0xff007700,
    0xff005500, 0xff004400, 0xff002200, 0xff001100, 0xffee0000, 0xffdd0000, 0xffbb0000, 0xffaa0000,
    0xff880000, 0xff770000, 0xff550000, 0xff440000, 0xff220000, 0xff110000, 0xffeeeeee, 0xffdddddd,
    0xffbbbbbb, 0xffaaaaaa, 0xff888888, 0xff777777, 0xff555555, 0xff444444, 0xff222222, 0xff111111,
};

using namespace vox;

constexpr size_t kPaletteBytes = 256 * 4;
constexpr size_t kMaxMaterialTypeBytes = 32;
const char* const kGiveVox = "give a MagicaVoxel .vox file";

// A transform node's frame 0 among its keyframes: the one whose `_f` is 0, else the first.
template <class Item>
void keepFrameZero(std::optional<Item>& kept, bool& keptIsZero, Item item, bool isZero) {
    if (!kept || (isZero && !keptIsZero)) {
        kept = std::move(item);
        keptIsZero = isZero;
    }
}

enum class NodeKind { Transform, Group, Shape };

const char* chunkOf(NodeKind kind) {
    return kind == NodeKind::Transform ? "nTRN" : kind == NodeKind::Group ? "nGRP" : "nSHP";
}

struct Node {
    NodeKind kind = NodeKind::Transform;
    size_t at = 0;                  // its chunk's offset, for errors found while walking the graph
    bool hidden = false;            // nTRN `_hidden`
    int32_t layer = -1;             // nTRN; -1 = none
    glm::imat3 rotation{1};         // nTRN, frame 0
    glm::ivec3 translation{0};      // nTRN, frame 0
    std::vector<int32_t> children;  // nTRN: its one child; nGRP: its children
    int32_t model = -1;             // nSHP, frame 0
    bool visited = false, onPath = false;
};

// Where a node's content goes: the transforms above it, composed.
struct Pose {
    glm::imat3 rotation{1};
    glm::ivec3 translation{0};
};

// Collects what the chunks say, then flattens the scene graph into instances.
class Builder {
public:
    Builder(const std::string& file, uint32_t version) : file_(file) {
        scene_.version = version;
        for (size_t c = 0; c < 256; ++c) {
            const uint32_t v = kDefaultPalette[c];
            scene_.palette[c] = {uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)};
        }
    }

    void chunk(const ChunkRef& ref, std::span<const uint8_t> content) {
        Cursor c(content, file_, ref);
        const std::string& id = ref.id;
        if (id == "SIZE") size(c);
        else if (id == "XYZI") voxels(c);
        else if (id == "RGBA") palette(c);
        else if (id == "PACK") pack_ = {c.u32("the model count"), ref};
        else if (id == "nTRN") transform(c);
        else if (id == "nGRP") group(c);
        else if (id == "nSHP") shape(c);
        else if (id == "LAYR") layer(c);
        else if (id == "MATL") material(c);
        // Others (MATT, IMAP, NOTE, rOBJ, rCAM, META, ...) say nothing about where voxels
        // are or their colours: IMAP only orders the palette as the editor shows it.
    }

    VoxScene finish() {
        if (pending_) fail(file_, pending_->second, "is not followed by its XYZI chunk");
        if (scene_.models.empty()) throw Error(file_, "holds no model (no SIZE and XYZI chunks)", kGiveVox);
        if (pack_ && pack_->first != scene_.models.size())
            fail(file_, pack_->second,
                 "says the file holds " + str(pack_->first) + " models, it holds " + str(scene_.models.size()));
        if (nodes_.empty()) {  // no scene graph: model 0 at the origin (see vox_read.h)
            scene_.instances.push_back({0, glm::imat3(1), glm::ivec3(0)});
            placed_ = scene_.models[0].voxels.size();
        } else {
            walk(0, nullptr, Pose{}, false, 1);
        }
        if (placed_ > kMaxVoxPlacedVoxels)
            throw Error(file_, "places " + str(placed_) + " voxels, more than the " + str(kMaxVoxPlacedVoxels) +
                                   " a .vox file may place here",
                        "instances each place their model's voxels: hide layers or remove instances in MagicaVoxel");
        return std::move(scene_);
    }

private:
    void size(Cursor& c) {
        if (pending_) fail(file_, pending_->second, "is not followed by its XYZI chunk");
        if (c.left() != 12) c.fail("holds " + str(c.left()) + " bytes, a SIZE chunk 12");
        if (scene_.models.size() >= kMaxVoxModels)
            c.fail("the file holds more than " + str(kMaxVoxModels) + " models", "split the scene into several files");
        const uint32_t x = c.u32("size x"), y = c.u32("size y"), z = c.u32("size z");
        for (uint32_t n : {x, y, z})
            if (n < 1 || n > uint32_t(kMaxVoxModelSize))
                c.fail("model " + str(scene_.models.size()) + " is " + str(x) + "x" + str(y) + "x" + str(z) +
                           " voxels: each axis holds 1 to " + str(kMaxVoxModelSize),
                       "MagicaVoxel models are at most 256 voxels along each axis");
        pending_ = {glm::ivec3(int(x), int(y), int(z)), c.chunk()};
    }

    void voxels(Cursor& c) {
        if (!pending_) c.fail("comes without a SIZE chunk before it");
        const glm::ivec3 size = pending_->first;
        pending_.reset();
        const std::string model = "model " + str(scene_.models.size());
        const uint32_t n = c.count("the voxel count", 4);
        if (c.left() != size_t(n) * 4)
            c.fail("holds " + str(c.left() - size_t(n) * 4) + " bytes past its " + str(n) + " voxels");
        if (uint64_t(n) > uint64_t(size.x) * uint64_t(size.y) * uint64_t(size.z))
            c.fail(model + " lists " + str(n) + " voxels, more than its size " + str(size.x) + "x" + str(size.y) + "x" +
                   str(size.z) + " holds");
        const auto data = c.take(size_t(n) * 4, "the voxels");
        VoxModel m;
        m.size = size;
        m.voxels.reserve(n);
        for (size_t i = 0; i < n; ++i) {
            const uint8_t* v = data.data() + 4 * i;
            if (v[0] >= size.x || v[1] >= size.y || v[2] >= size.z)
                c.fail(model + "'s voxel " + str(i) + " at (" + str(v[0]) + ", " + str(v[1]) + ", " + str(v[2]) +
                       ") lies outside its size " + str(size.x) + "x" + str(size.y) + "x" + str(size.z));
            if (v[3] == 0) continue;  // colour index 0 is no colour: MagicaVoxel never writes it; skipped as empty
            m.voxels.push_back({v[0], v[1], v[2], v[3]});
        }
        scene_.models.push_back(std::move(m));
    }

    void palette(Cursor& c) {
        if (c.left() != kPaletteBytes) c.fail("holds " + str(c.left()) + " bytes, an RGBA chunk 1024 (256 colours)");
        const auto data = c.take(kPaletteBytes, "the palette");
        // Entry i is colour index i + 1; the 256th entry has no index and is ignored.
        for (size_t i = 0; i < 255; ++i)
            scene_.palette[i + 1] = {data[4 * i], data[4 * i + 1], data[4 * i + 2], data[4 * i + 3]};
        scene_.palette[0] = {};
        scene_.hasPalette = true;
    }

    static Node newNode(NodeKind kind, const Cursor& c) {
        Node node;
        node.kind = kind;
        node.at = c.chunk().at;
        return node;
    }

    int32_t nodeId(Cursor& c, std::string_view what) {
        const int32_t id = c.i32(what);
        if (id < 0) c.fail(std::string(what) + " is " + std::to_string(id) + ": node ids are 0 or more");
        return id;
    }

    void transform(Cursor& c) {
        Node node = newNode(NodeKind::Transform, c);
        const int32_t id = nodeId(c, "the node id");
        node.hidden = flag(c, c.dict("the node attributes"), "_hidden");
        node.children.push_back(nodeId(c, "the child node id"));
        c.i32("the reserved id");  // -1; nothing depends on it
        node.layer = c.i32("the layer id");
        const uint32_t frames = c.count("the frame count", 4);
        if (frames == 0) c.fail("has no frames: a transform node holds one at least");
        std::optional<Dict> frame;
        bool frameIsZero = false;
        for (uint32_t i = 0; i < frames; ++i) {
            Dict d = c.dict("the frame attributes");
            const bool isZero = frameIndex(c, d) == 0;
            keepFrameZero(frame, frameIsZero, std::move(d), isZero);
        }
        if (const auto r = frame->get("_r")) {
            const auto m = voxRotation(int(integer(c, "_r", *r, 0, 255)));
            if (!m)
                c.fail("'_r' is " + quoted(*r) + ", not a rotation: its two column indices are equal or 3",
                       "bits 0-1 and 2-3 are the columns (0, 1 or 2, different) of rows 0 and 1");
            node.rotation = *m;
        }
        if (const auto t = frame->get("_t")) node.translation = translation(c, *t);
        addNode(c, id, std::move(node));
    }

    void group(Cursor& c) {
        Node node = newNode(NodeKind::Group, c);
        const int32_t id = nodeId(c, "the node id");
        c.dict("the node attributes");
        const uint32_t n = c.count("the child count", 4);
        node.children.reserve(n);
        for (uint32_t i = 0; i < n; ++i) node.children.push_back(nodeId(c, "a child node id"));
        addNode(c, id, std::move(node));
    }

    void shape(Cursor& c) {
        Node node = newNode(NodeKind::Shape, c);
        const int32_t id = nodeId(c, "the node id");
        c.dict("the node attributes");
        const uint32_t n = c.count("the model count", 8);  // a model id and its dict's count
        if (n == 0) c.fail("has no model: a shape node holds one at least");
        std::optional<int32_t> model;
        bool modelIsZero = false;
        for (uint32_t i = 0; i < n; ++i) {
            const int32_t m = c.i32("a model id");
            if (m < 0) c.fail("a model id is " + std::to_string(m) + ": model ids are 0 or more");
            const bool isZero = frameIndex(c, c.dict("the model attributes")) == 0;
            keepFrameZero(model, modelIsZero, m, isZero);
        }
        node.model = *model;
        addNode(c, id, std::move(node));
    }

    void layer(Cursor& c) {
        const int32_t id = c.i32("the layer id");
        const bool hidden = flag(c, c.dict("the layer attributes"), "_hidden");
        if (hiddenLayers_.size() >= kMaxVoxNodes && !hiddenLayers_.count(id))
            c.fail("the file holds more than " + str(kMaxVoxNodes) + " layers");
        hiddenLayers_[id] = hidden;
    }

    void material(Cursor& c) {
        const int32_t id = c.i32("the material id");
        // The id is the colour index; MagicaVoxel writes 0..255 or 1..256, where 0 and 256 are index 0.
        if (id < 0 || id > 256)
            c.fail("the material id is " + std::to_string(id) + ": ids are colour indices, 0 to 256");
        const Dict d = c.dict("the material properties");
        VoxMaterial m;
        m.present = true;
        if (const auto type = d.get("_type")) {
            if (type->size() > kMaxMaterialTypeBytes) c.fail("'_type' is " + quoted(*type) + ", not a material type");
            m.type = printable(*type);
        }
        const std::pair<const char*, float VoxMaterial::*> fields[] = {
            {"_weight", &VoxMaterial::weight}, {"_rough", &VoxMaterial::rough}, {"_metal", &VoxMaterial::metal},
            {"_spec", &VoxMaterial::spec},     {"_emit", &VoxMaterial::emit},   {"_flux", &VoxMaterial::flux},
            {"_ldr", &VoxMaterial::ldr},       {"_trans", &VoxMaterial::trans}};
        for (const auto& [key, field] : fields)
            if (const auto v = d.get(key)) m.*field = number(c, key, *v);
        if (const auto alpha = d.get("_alpha"); alpha && !d.get("_trans")) m.trans = number(c, "_alpha", *alpha);
        if (const auto ri = d.get("_ri")) m.ior = number(c, "_ri", *ri);
        else if (const auto ior = d.get("_ior")) m.ior = 1.0f + number(c, "_ior", *ior);
        if (id != 0 && id != 256) scene_.materials[size_t(id)] = std::move(m);
    }

    void addNode(Cursor& c, int32_t id, Node node) {
        if (nodes_.size() >= kMaxVoxNodes)
            c.fail("the file holds more than " + str(kMaxVoxNodes) + " scene nodes",
                   "split the scene into several files");
        const auto [it, added] = nodes_.try_emplace(id, std::move(node));
        if (!added)
            c.fail("node " + str(uint32_t(id)) + " is defined twice: first by the " + chunkOf(it->second.kind) +
                   " chunk at byte " + str(it->second.at));
    }

    [[noreturn]] void failAt(const Node& node, const std::string& what, const std::string& hint = kDamaged) const {
        fail(file_, ChunkRef{chunkOf(node.kind), node.at}, what, hint);
    }

    bool layerHidden(int32_t id) const {
        const auto it = hiddenLayers_.find(id);
        return it != hiddenLayers_.end() && it->second;
    }

    // The tree from node 0, depth first with the depth bounded. Transform and group
    // nodes may appear once; shape nodes may be shared, as MagicaVoxel shares a
    // model's shape among its instances. Hidden subtrees are checked, not placed.
    void walk(int32_t id, const Node* parent, Pose pose, bool hidden, int depth) {
        const auto it = nodes_.find(id);
        if (it == nodes_.end()) {
            if (!parent) throw Error(file_, "has a scene graph without its root, node 0", kDamaged);
            failAt(*parent, "lists child node " + str(uint32_t(id)) + ", which no nTRN, nGRP or nSHP chunk defines");
        }
        Node& node = it->second;
        if (node.onPath)
            failAt(*parent, "lists child node " + str(uint32_t(id)) +
                                ", one of its own ancestors: the scene graph has a cycle");
        if (node.visited && node.kind != NodeKind::Shape)
            failAt(*parent, "lists child node " + str(uint32_t(id)) +
                                ", which another node lists too: only shape nodes (nSHP) may be shared");
        if (depth > kMaxVoxGraphDepth)
            failAt(node, "is nested more than " + str(kMaxVoxGraphDepth) + " nodes deep in the scene graph");
        node.visited = true;
        if (node.kind == NodeKind::Shape) return place(node, pose, hidden);
        if (node.kind == NodeKind::Transform) {
            hidden = hidden || node.hidden || layerHidden(node.layer);
            pose = compose(pose, node);
        }
        node.onPath = true;
        for (const int32_t child : node.children) walk(child, &node, pose, hidden, depth + 1);
        node.onPath = false;
    }

    // The parent's transform applied after the node's: R = Rp Rn, t = Rp tn + tp.
    Pose compose(const Pose& parent, const Node& node) const {
        Pose p;
        p.rotation = parent.rotation * node.rotation;
        for (int row = 0; row < 3; ++row) {
            int64_t t = parent.translation[row];
            for (int col = 0; col < 3; ++col) t += int64_t(parent.rotation[col][row]) * node.translation[col];
            if (t < -kMaxVoxTranslation || t > kMaxVoxTranslation)
                failAt(node, "places its content " + std::to_string(t) + " voxels from the origin along " +
                                 "xyz"[row] + ", beyond " + str(kMaxVoxTranslation),
                       "Grotto reads .vox content within 2^24 voxels of the origin: move it closer in MagicaVoxel");
            p.translation[row] = int(t);
        }
        return p;
    }

    void place(const Node& shape, const Pose& pose, bool hidden) {
        if (size_t(shape.model) >= scene_.models.size())
            failAt(shape, "refers to model " + str(uint32_t(shape.model)) + ", the file holds " +
                              str(scene_.models.size()));
        if (hidden) return;
        if (scene_.instances.size() >= kMaxVoxInstances)
            throw Error(file_, "places more than " + str(kMaxVoxInstances) + " instances",
                        "remove instances in MagicaVoxel or split the scene into several files");
        scene_.instances.push_back({uint32_t(shape.model), pose.rotation, pose.translation});
        placed_ += scene_.models[size_t(shape.model)].voxels.size();
    }

    const std::string& file_;
    VoxScene scene_;
    std::optional<std::pair<glm::ivec3, ChunkRef>> pending_;  // a SIZE waiting for its XYZI
    std::optional<std::pair<uint32_t, ChunkRef>> pack_;
    std::unordered_map<int32_t, Node> nodes_;
    std::unordered_map<int32_t, bool> hiddenLayers_;
    uint64_t placed_ = 0;
};

// One chunk's header at `at`, its content and children checked to lie before `end`
// (the end of the file for MAIN, of MAIN's children for the others).
struct ChunkSpan {
    ChunkRef ref;
    std::span<const uint8_t> content;
    size_t childrenAt = 0, end = 0;
};

ChunkSpan readChunk(std::span<const uint8_t> bytes, size_t at, size_t end, const std::string& file) {
    const size_t left = end - at;
    if (left < 4)
        throw Error(file,
                    "truncated: a chunk header at byte " + str(at) + " needs 12 bytes, " + str(left) + " are left",
                    kDamaged);
    const ChunkRef ref{chunkId(bytes, at), at};
    if (left < kChunkHeaderBytes) fail(file, ref, "truncated: its header needs 12 bytes, " + str(left) + " are left");
    const uint64_t content = le32(bytes.data() + at + 4), children = le32(bytes.data() + at + 8);
    const uint64_t room = left - kChunkHeaderBytes;
    if (content > room) fail(file, ref, "claims " + str(content) + " bytes of content, " + str(room) + " are left");
    if (children > room - content)
        fail(file, ref, "claims " + str(children) + " bytes of children, " + str(room - content) + " are left");
    const size_t contentAt = at + kChunkHeaderBytes;
    return {ref, bytes.subspan(contentAt, size_t(content)), contentAt + size_t(content),
            contentAt + size_t(content + children)};
}

}  // namespace

uint64_t VoxScene::placedVoxels() const {
    uint64_t n = 0;
    for (const VoxInstance& instance : instances) n += models[instance.model].voxels.size();
    return n;
}

std::optional<glm::imat3> voxRotation(int byte) {
    if (byte < 0 || byte > 127) return std::nullopt;
    const int first = byte & 3, second = (byte >> 2) & 3;
    if (first == 3 || second == 3 || first == second) return std::nullopt;
    const int column[3] = {first, second, 3 - first - second};
    glm::imat3 m(0);
    for (int row = 0; row < 3; ++row) m[column[row]][row] = (byte >> (4 + row)) & 1 ? -1 : 1;  // glm: m[column][row]
    return m;
}

VoxScene parseVox(std::span<const uint8_t> bytes, const std::string& file) {
    if (bytes.size() < 8 || std::memcmp(bytes.data(), "VOX ", 4) != 0)
        throw Error(file, "is not a MagicaVoxel .vox file: it does not start with 'VOX '", kGiveVox);
    const uint32_t version = le32(bytes.data() + 4);
    if (version != 150 && version != 200)
        throw Error(file, "is .vox version " + str(version) + ", not 150 or 200",
                    "the versions MagicaVoxel writes (200 since 0.99.7): save it again from MagicaVoxel");
    const ChunkSpan main = readChunk(bytes, 8, bytes.size(), file);
    if (main.ref.id != "MAIN") fail(file, main.ref, "the first chunk must be MAIN");
    Builder builder(file, version);
    for (size_t at = main.childrenAt; at < main.end;) {
        const ChunkSpan chunk = readChunk(bytes, at, main.end, file);
        builder.chunk(chunk.ref, chunk.content);
        at = chunk.end;
    }
    // Bytes after MAIN are in no chunk MagicaVoxel reads: ignored.
    return builder.finish();
}

VoxScene readVoxFile(const std::filesystem::path& path) {
    const std::string file = path.string();
    requireInputFile(path, kGiveVox);
    std::error_code ec;
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw Error(file, "cannot be read: " + ec.message(), kGiveVox);
    if (size > kMaxVoxFileBytes)
        throw Error(file, "is " + str(size) + " bytes, more than the " + str(kMaxVoxFileBytes >> 20) +
                              " MiB a .vox file may be here", kGiveVox);
    std::ifstream in(path, std::ios::binary);
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size));
    if (!in || in.gcount() != std::streamsize(size))
        throw Error(file, "cannot be read (or it shrank while being read)", kGiveVox);
    return parseVox(bytes, file);
}

glm::ivec3 placeVoxel(const VoxScene& scene, const VoxInstance& instance, const std::array<uint8_t, 4>& voxel) {
    const glm::ivec3 pivot = scene.models[instance.model].size / 2;
    // Twice the voxel's centre relative to the pivot: odd on every axis, so exact in integers.
    const glm::ivec3 twice = 2 * (glm::ivec3(voxel[0], voxel[1], voxel[2]) - pivot) + 1;
    const glm::ivec3 turned = instance.rotation * twice;              // still odd: entries are -1, 0, 1, one a row
    const glm::ivec3 cell = (turned - 1) / 2 + instance.translation;  // floor(turned / 2), exact
    return {cell.x, cell.z, -cell.y - 1};                             // z-up to y-up
}

}  // namespace grotto::voxel
