// mesh: voxelises a triangle mesh (OBJ, or ASCII PLY) into a narrow-band level set.
// The mesh is scaled uniformly so its largest extent is options.size voxels, centred
// on x = z = 0 and standing on y = 0.
#include "common/file_kind.h"
#include "grotto/error.h"
#include "voxel/mkworld.h"

#include "voxel/openvdb_grids.h"
#include <openvdb/tools/MeshToVolume.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>

namespace grotto::voxel {
namespace {

namespace fs = std::filesystem;

struct TriangleFile {
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
};

// Reads a file line by line, keeping the line number for error messages.
class LineReader {
public:
    explicit LineReader(const fs::path& file) : file_(file), in_(file, std::ios::binary) {
        std::error_code ec;
        if (!in_ || fs::is_directory(file, ec))
            throw Error(file.string(), "cannot open the mesh file", "give a readable .obj or .ply");
    }
    bool next(std::string& line) {
        if (!std::getline(in_, line)) return false;
        ++number_;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        return true;
    }
    [[noreturn]] void fail(const std::string& what, const std::string& hint = {}) const {
        throw Error(file_.string() + ":" + std::to_string(number_), what, hint);
    }

private:
    fs::path file_;
    std::ifstream in_;
    int number_ = 0;
};

std::vector<std::string_view> split(std::string_view s) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < s.size()) {
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
        size_t j = i;
        while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
        if (j > i) out.push_back(s.substr(i, j - i));
        i = j;
    }
    return out;
}

// Locale-independent number parsing; the whole token must be consumed.
template <typename T>
bool parse(std::string_view token, T& value) {
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && end == token.data() + token.size();
}

float coordinate(LineReader& r, std::string_view token) {
    float v = 0;
    if (!parse(token, v) || !std::isfinite(v))
        r.fail("bad vertex coordinate '" + std::string(token) + "'");
    return v;
}

// Polygons become triangle fans around their first vertex.
void addPolygon(LineReader& r, TriangleFile& mesh, const std::vector<uint32_t>& poly) {
    if (poly.size() < 3) r.fail("a face needs at least 3 vertices");
    for (size_t i = 1; i + 1 < poly.size(); ++i)
        mesh.triangles.emplace_back(poly[0], poly[i], poly[i + 1]);
}

void readObj(LineReader& r, TriangleFile& mesh) {
    std::string line;
    std::vector<uint32_t> poly;
    while (r.next(line)) {
        const auto t = split(line);
        if (t.empty() || t[0][0] == '#') continue;
        if (t[0] == "v") {
            if (t.size() < 4) r.fail("a 'v' line needs x y z");
            mesh.points.emplace_back(coordinate(r, t[1]), coordinate(r, t[2]), coordinate(r, t[3]));
        } else if (t[0] == "f") {
            poly.clear();
            for (size_t i = 1; i < t.size(); ++i) {
                long idx = 0;  // "7", "7/1", "7//3", "7/1/3"; negative counts back from the end
                const std::string_view head = t[i].substr(0, t[i].find('/'));
                const long n = long(mesh.points.size());
                if (!parse(head, idx) || idx == 0 || idx > n || idx < -n)
                    r.fail("bad face index '" + std::string(t[i]) + "'",
                           "indices run 1.." + std::to_string(n) + " or -1..-" + std::to_string(n));
                poly.push_back(uint32_t(idx > 0 ? idx - 1 : n + idx));
            }
            addPolygon(r, mesh, poly);
        }  // vt, vn, o, g, s, usemtl, mtllib, ...: not needed for the shape
    }
}

struct PlyProperty {
    std::string name;
    bool list = false;
    int axis = -1;  // 0, 1, 2 for x, y, z
};

struct PlyElement {
    std::string name;
    long count = 0;
    std::vector<PlyProperty> properties;
};

std::vector<PlyElement> readPlyHeader(LineReader& r) {
    std::string line;
    std::vector<PlyElement> elements;
    bool ascii = false;
    while (r.next(line)) {
        const auto t = split(line);
        if (t.empty() || t[0] == "comment" || t[0] == "obj_info" || t[0] == "ply") continue;
        if (t[0] == "format") {
            if (t.size() < 2 || t[1] != "ascii")
                r.fail("only ASCII PLY is supported", "convert the mesh to ASCII PLY or OBJ");
            ascii = true;
        } else if (t[0] == "element") {
            PlyElement e{std::string(t.size() > 1 ? t[1] : ""), 0, {}};
            if (t.size() != 3 || !parse(t[2], e.count) || e.count < 0) r.fail("bad element line");
            elements.push_back(e);
        } else if (t[0] == "property") {
            const bool list = t.size() > 1 && t[1] == "list";
            if (elements.empty() || t.size() != (list ? 5u : 3u)) r.fail("bad property line");
            const std::string_view n = t.back();
            const int axis = n == "x" ? 0 : n == "y" ? 1 : n == "z" ? 2 : -1;
            elements.back().properties.push_back({std::string(n), list, list ? -1 : axis});
        } else if (t[0] == "end_header") {
            if (!ascii) r.fail("PLY header has no format line", "expected 'format ascii 1.0'");
            for (const PlyElement& e : elements)
                if (e.name == "vertex" &&
                    std::count_if(e.properties.begin(), e.properties.end(),
                                  [](const auto& p) { return p.axis >= 0; }) != 3)
                    r.fail("PLY vertices need x, y and z properties");
            return elements;
        } else {
            r.fail("unknown PLY header line '" + line + "'");
        }
    }
    r.fail("PLY header ends without 'end_header'");
}

void readPlyData(LineReader& r, const std::vector<PlyElement>& elements, TriangleFile& mesh) {
    std::string line;
    std::vector<uint32_t> poly;
    for (const PlyElement& e : elements) {
        const bool vertex = e.name == "vertex", face = e.name == "face";
        for (long n = 0; n < e.count; ++n) {
            if (!r.next(line))
                r.fail("PLY data ends early", "the header promises " + std::to_string(e.count) +
                                                  " '" + e.name + "' lines");
            if (!vertex && !face) continue;  // edges, materials, ...: not needed
            const auto t = split(line);
            size_t at = 0;  // the next value on the line
            float xyz[3] = {0, 0, 0};
            for (const PlyProperty& p : e.properties) {
                if (at >= t.size()) r.fail("too few values for a '" + e.name + "'");
                if (!p.list) {
                    if (vertex && p.axis >= 0) xyz[p.axis] = coordinate(r, t[at]);
                    ++at;
                    continue;
                }
                long k = 0;
                if (!parse(t[at++], k) || k < 0 || at + size_t(k) > t.size())
                    r.fail("bad list for a '" + e.name + "'");
                if (face && (p.name == "vertex_indices" || p.name == "vertex_index")) {
                    poly.clear();
                    for (size_t j = at; j < at + size_t(k); ++j) {
                        long idx = -1;
                        if (!parse(t[j], idx) || idx < 0 || idx >= long(mesh.points.size()))
                            r.fail("bad face index '" + std::string(t[j]) + "'",
                                   "indices run 0.." +
                                       std::to_string(long(mesh.points.size()) - 1) +
                                       "; vertices must come before faces");
                        poly.push_back(uint32_t(idx));
                    }
                    addPolygon(r, mesh, poly);
                }
                at += size_t(k);
            }
            if (vertex) mesh.points.emplace_back(xyz[0], xyz[1], xyz[2]);
        }
    }
}

TriangleFile readMesh(const fs::path& file) {
    LineReader r(file);
    TriangleFile mesh;
    std::string first;
    const std::string ext = lowerExtension(file);
    const bool hasLine = r.next(first);
    if (hasLine && split(first).size() == 1 && split(first)[0] == "ply") {
        readPlyData(r, readPlyHeader(r), mesh);
    } else if (ext == ".obj") {
        LineReader again(file);  // the first line is data too
        readObj(again, mesh);
    } else {
        throw Error(file.string(), "not an OBJ or ASCII PLY mesh",
                    "accepted: .obj files, or files starting with a 'ply' header");
    }
    if (mesh.triangles.empty())
        throw Error(file.string(), "the mesh has no faces", "an OBJ needs 'v' and 'f' lines");
    return mesh;
}

}  // namespace

openvdb::GridBase::Ptr generateMesh(const GeneratorOptions& options) {
    TriangleFile mesh = readMesh(options.meshFile);

    openvdb::Vec3s lo = mesh.points[0], hi = mesh.points[0];
    for (const auto& p : mesh.points) {
        lo = openvdb::math::minComponent(lo, p);
        hi = openvdb::math::maxComponent(hi, p);
    }
    const openvdb::Vec3s extent = hi - lo;
    const float largest = std::max({extent.x(), extent.y(), extent.z()});
    if (!(largest > 0.0f))
        throw Error(options.meshFile, "the mesh has zero extent",
                    "all its vertices are at one point");

    // World units: centre x and z on 0, rest the lowest point on y = 0.
    const float scale = float(options.size * options.voxelSize) / largest;
    const openvdb::Vec3s shift(0.5f * (lo.x() + hi.x()), lo.y(), 0.5f * (lo.z() + hi.z()));
    for (auto& p : mesh.points) p = (p - shift) * scale;

    const auto xform = openvdb::math::Transform::createLinearTransform(options.voxelSize);
    auto grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*xform, mesh.points,
                                                                   mesh.triangles, 3.0f);
    grid->setName("surface");
    return grid;
}

}  // namespace grotto::voxel
