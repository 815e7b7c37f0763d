// Rectangles cut at the corners of others that lie on their edges (watertight.h).
#include "voxel/watertight.h"

#include <glm/vec2.hpp>

#include <vector>

namespace grotto::voxel {
namespace {

constexpr int kSide = kChunkEdge + 1;  // lattice points per axis of a chunk's closed cube

// Lattice points of a chunk's closed cube, 0..kChunkEdge on each axis.
class PointSet {
public:
    void add(glm::ivec3 p) {
        if (inside(p)) bits_[size_t(index(p)) >> 6] |= uint64_t(1) << (index(p) & 63);
    }
    bool has(glm::ivec3 p) const { return inside(p) && (bits_[size_t(index(p)) >> 6] >> (index(p) & 63) & 1u); }

private:
    static bool inside(glm::ivec3 p) {
        return p.x >= 0 && p.y >= 0 && p.z >= 0 && p.x <= kChunkEdge && p.y <= kChunkEdge && p.z <= kChunkEdge;
    }
    static int index(glm::ivec3 p) { return (p.x * kSide + p.y) * kSide + p.z; }
    std::vector<uint64_t> bits_ = std::vector<uint64_t>((kSide * kSide * kSide + 63) / 64, 0);
};

bool onBoundary(int c) { return c == 0 || c == kChunkEdge; }

// Twice the signed area of triangle abc: > 0 when it turns counter-clockwise, 0 when flat.
int turn(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) { return (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x); }

int twiceArea(const std::vector<glm::ivec2>& p) {
    int s = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        const glm::ivec2 a = p[i], b = p[(i + 1) % p.size()];
        s += a.x * b.y - a.y * b.x;
    }
    return s;
}

template <typename T>
std::vector<T> without(std::vector<T> v, size_t first, size_t count) {  // minus `count` entries from first, cyclic
    for (size_t k = 0; k < count; ++k) v.erase(v.begin() + long(first < v.size() ? first : 0));
    return v;
}

// Cuts a convex counter-clockwise polygon (with points along its sides) into convex
// quads and triangles whose corners are its points, none lying inside another's
// side; `emit` gets each piece's corner indices (a triangle repeats its last).
template <typename Emit>
void cutConvex(std::vector<glm::ivec2> p, std::vector<int> id, Emit emit) {
    auto at = [&](size_t i) { return p[i % p.size()]; };
    // Cuts off the piece of p[i], the `count` points after it and the next, if what
    // is left still has area.
    auto cutAt = [&](size_t i, size_t count) {
        const size_t n = p.size();
        std::vector<glm::ivec2> rest = without(p, (i + 1) % n, count);
        if (twiceArea(rest) <= 0) return false;
        emit(id[i], id[(i + 1) % n], id[(i + 2) % n], id[(i + count + 1) % n]);
        id = without(id, (i + 1) % n, count);
        p = std::move(rest);
        return true;
    };
    while (p.size() > 4) {
        const size_t n = p.size();
        bool cut = false;
        for (size_t i = 0; i < n && !cut; ++i)  // a quad of four points in a row, convex at every corner
            cut = turn(at(i), at(i + 1), at(i + 2)) > 0 && turn(at(i + 1), at(i + 2), at(i + 3)) > 0 &&
                  turn(at(i + 2), at(i + 3), at(i)) > 0 && turn(at(i + 3), at(i), at(i + 1)) > 0 && cutAt(i, 2);
        for (size_t i = 0; i < n && !cut; ++i)  // else a triangle of three
            cut = turn(at(i), at(i + 1), at(i + 2)) > 0 && cutAt(i, 1);
        if (!cut) return;  // cannot happen for a convex polygon with area
    }
    if (p.size() == 3) {
        emit(id[0], id[1], id[2], id[2]);
        return;
    }
    for (size_t j = 0; j < 4; ++j)  // a triangle with a point along one side: two triangles
        if (turn(at(j + 3), at(j), at(j + 1)) == 0) {
            emit(id[(j + 3) % 4], id[j], id[(j + 2) % 4], id[(j + 2) % 4]);
            emit(id[j], id[(j + 1) % 4], id[(j + 2) % 4], id[(j + 2) % 4]);
            return;
        }
    emit(id[0], id[1], id[2], id[3]);
}

// One level's rectangles cut into quads. `own`: the level's rectangle corners;
// `boundary`: those on the chunk's boundary from every level of it and its neighbours.
void weldLevel(const std::vector<gpu::PackedQuad>& rects, const PointSet& own, const PointSet& boundary,
               std::array<uint32_t, 6>& faceCount, std::vector<MeshQuad>& quads) {
    faceCount = {};
    quads.clear();
    quads.reserve(rects.size());
    std::vector<glm::ivec3> corners;
    std::vector<glm::ivec2> flat;
    std::vector<int> ids;
    for (const gpu::PackedQuad& r : rects) {
        const uint32_t f = gpu::quadFace(r.bits), ua = gpu::faceUAxis(f), va = gpu::faceVAxis(f);
        const std::array<glm::ivec3, 4> c = rectCorners(r);
        corners.clear();
        for (int e = 0; e < 4; ++e) {
            const glm::ivec3 a = c[size_t(e)], b = c[size_t(e + 1) % 4], step = glm::sign(b - a);
            corners.push_back(a);
            // The points inside the edge: a line on the chunk's boundary meets the
            // neighbours' quads, any other only this level's own.
            int along = step.x != 0 ? 0 : step.y != 0 ? 1 : 2;
            const bool border = onBoundary(a[(along + 1) % 3]) || onBoundary(a[(along + 2) % 3]);
            const PointSet& points = border ? boundary : own;
            for (glm::ivec3 q = a + step; q != b; q += step)
                if (points.has(q)) corners.push_back(q);
        }
        const uint32_t m = r.material;
        auto vertex = [&](int i) {
            const glm::ivec3 q = corners[size_t(i)];
            return gpu::packVertex(uint32_t(q.x), uint32_t(q.y), uint32_t(q.z), f, m);
        };
        const size_t before = quads.size();
        if (corners.size() == 4) {
            quads.push_back({{vertex(0), vertex(1), vertex(2), vertex(3)}});
        } else {
            flat.clear();
            ids.clear();
            for (size_t i = 0; i < corners.size(); ++i) {
                flat.push_back({corners[i][int(ua)], corners[i][int(va)]});
                ids.push_back(int(i));
            }
            cutConvex(flat, ids, [&](int a, int b, int c2, int d) {
                quads.push_back({{vertex(a), vertex(b), vertex(c2), vertex(d)}});
            });
        }
        faceCount[f] += uint32_t(quads.size() - before);
    }
}

}  // namespace

std::array<glm::ivec3, 4> rectCorners(const gpu::PackedQuad& rect) {
    const uint32_t f = gpu::quadFace(rect.bits);
    glm::ivec3 base;
    for (uint32_t i = 0; i < 3; ++i) base[int(i)] = int(gpu::quadCoord(rect.bits, i));
    if (gpu::facePositive(f)) base[int(gpu::faceAxis(f))] += 1;
    glm::ivec3 du(0), dv(0);
    du[int(gpu::faceUAxis(f))] = int(gpu::quadWidth(rect.bits));
    dv[int(gpu::faceVAxis(f))] = int(gpu::quadHeight(rect.bits));
    return {base, base + du, base + du + dv, base + dv};
}

std::vector<glm::ivec3> boundaryCorners(const MeshChunkQuads& chunk) {
    std::vector<glm::ivec3> corners;
    auto add = [&](const std::vector<gpu::PackedQuad>& rects) {
        for (const gpu::PackedQuad& r : rects)
            for (const glm::ivec3& p : rectCorners(r))
                if (onBoundary(p.x) || onBoundary(p.y) || onBoundary(p.z)) corners.push_back(p);
    };
    add(chunk.rects);
    for (const MeshLevel& l : chunk.coarser) add(l.rects);
    return corners;
}

void weld(MeshChunkQuads& chunk, std::span<const ChunkBoundary> around) {
    // A corner of another chunk in this one's closed cube lies on both boundaries.
    PointSet boundary;
    for (const ChunkBoundary& b : around) {
        const glm::ivec3 shift = b.origin - chunk.origin;
        for (const glm::ivec3& p : *b.corners) boundary.add(p + shift);
    }
    auto level = [&](const std::vector<gpu::PackedQuad>& rects, std::array<uint32_t, 6>& faceCount,
                     std::vector<MeshQuad>& quads) {
        PointSet own;
        for (const gpu::PackedQuad& r : rects)
            for (const glm::ivec3& p : rectCorners(r)) own.add(p);
        weldLevel(rects, own, boundary, faceCount, quads);
    };
    level(chunk.rects, chunk.faceCount, chunk.quads);
    for (MeshLevel& l : chunk.coarser) level(l.rects, l.faceCount, l.quads);
}

}  // namespace grotto::voxel
