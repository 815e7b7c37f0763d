#include "tests/vox_writer.h"

namespace grotto::voxel::test {

void appendU32(std::vector<uint8_t>& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
}

void appendString(std::vector<uint8_t>& out, std::string_view s) {
    appendU32(out, uint32_t(s.size()));
    out.insert(out.end(), s.begin(), s.end());
}

void appendDict(std::vector<uint8_t>& out, const VoxDict& dict) {
    appendU32(out, uint32_t(dict.size()));
    for (const auto& [key, value] : dict) {
        appendString(out, key);
        appendString(out, value);
    }
}

uint8_t voxRotationByte(const glm::imat3& m) {
    int byte = 0;
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) {
            if (m[col][row] == 0) continue;
            if (row < 2) byte |= col << (2 * row);
            if (m[col][row] < 0) byte |= 1 << (4 + row);
        }
    return uint8_t(byte);
}

VoxWriter& VoxWriter::chunk(std::string_view id, const std::vector<uint8_t>& content,
                            const std::vector<uint8_t>& children) {
    chunks_.insert(chunks_.end(), id.begin(), id.begin() + 4);
    appendU32(chunks_, uint32_t(content.size()));
    appendU32(chunks_, uint32_t(children.size()));
    chunks_.insert(chunks_.end(), content.begin(), content.end());
    chunks_.insert(chunks_.end(), children.begin(), children.end());
    return *this;
}

VoxWriter& VoxWriter::pack(uint32_t models) {
    std::vector<uint8_t> c;
    appendU32(c, models);
    return chunk("PACK", c);
}

VoxWriter& VoxWriter::model(glm::ivec3 size, const std::vector<std::array<uint8_t, 4>>& voxels) {
    std::vector<uint8_t> s;
    for (int a = 0; a < 3; ++a) appendU32(s, uint32_t(size[a]));
    chunk("SIZE", s);
    std::vector<uint8_t> v;
    appendU32(v, uint32_t(voxels.size()));
    for (const auto& voxel : voxels) v.insert(v.end(), voxel.begin(), voxel.end());
    return chunk("XYZI", v);
}

VoxWriter& VoxWriter::palette(const std::array<VoxColor, 256>& entries) {
    std::vector<uint8_t> c;
    for (const VoxColor& e : entries) c.insert(c.end(), {e.r, e.g, e.b, e.a});
    return chunk("RGBA", c);
}

VoxWriter& VoxWriter::transform(int32_t id, int32_t child, glm::ivec3 t, uint8_t r, int32_t layer, bool hidden) {
    VoxDict frame;
    if (r != kIdentity) frame.emplace_back("_r", std::to_string(r));
    if (t != glm::ivec3(0))
        frame.emplace_back("_t", std::to_string(t.x) + " " + std::to_string(t.y) + " " + std::to_string(t.z));
    VoxDict attributes;
    if (hidden) attributes.emplace_back("_hidden", "1");
    return transformFrames(id, child, attributes, layer, {frame});
}

VoxWriter& VoxWriter::transformFrames(int32_t id, int32_t child, const VoxDict& attributes, int32_t layer,
                                     const std::vector<VoxDict>& frames) {
    std::vector<uint8_t> c;
    appendU32(c, uint32_t(id));
    appendDict(c, attributes);
    appendU32(c, uint32_t(child));
    appendU32(c, uint32_t(-1));  // reserved
    appendU32(c, uint32_t(layer));
    appendU32(c, uint32_t(frames.size()));
    for (const VoxDict& frame : frames) appendDict(c, frame);
    return chunk("nTRN", c);
}

VoxWriter& VoxWriter::group(int32_t id, const std::vector<int32_t>& children) {
    std::vector<uint8_t> c;
    appendU32(c, uint32_t(id));
    appendDict(c, {});
    appendU32(c, uint32_t(children.size()));
    for (const int32_t child : children) appendU32(c, uint32_t(child));
    return chunk("nGRP", c);
}

VoxWriter& VoxWriter::shape(int32_t id, int32_t model) { return shapeFrames(id, {{model, {}}}); }

VoxWriter& VoxWriter::shapeFrames(int32_t id, const std::vector<std::pair<int32_t, VoxDict>>& models) {
    std::vector<uint8_t> c;
    appendU32(c, uint32_t(id));
    appendDict(c, {});
    appendU32(c, uint32_t(models.size()));
    for (const auto& [model, attributes] : models) {
        appendU32(c, uint32_t(model));
        appendDict(c, attributes);
    }
    return chunk("nSHP", c);
}

VoxWriter& VoxWriter::layer(int32_t id, bool hidden) {
    std::vector<uint8_t> c;
    appendU32(c, uint32_t(id));
    appendDict(c, {{"_name", "layer " + std::to_string(id)}, {"_hidden", hidden ? "1" : "0"}});
    appendU32(c, uint32_t(-1));  // reserved
    return chunk("LAYR", c);
}

VoxWriter& VoxWriter::material(int32_t id, const VoxDict& properties) {
    std::vector<uint8_t> c;
    appendU32(c, uint32_t(id));
    appendDict(c, properties);
    return chunk("MATL", c);
}

std::vector<uint8_t> VoxWriter::bytes() const {
    std::vector<uint8_t> out = {'V', 'O', 'X', ' '};
    appendU32(out, version_);
    out.insert(out.end(), {'M', 'A', 'I', 'N'});
    appendU32(out, 0);
    appendU32(out, uint32_t(chunks_.size()));
    out.insert(out.end(), chunks_.begin(), chunks_.end());
    return out;
}

}  // namespace grotto::voxel::test
