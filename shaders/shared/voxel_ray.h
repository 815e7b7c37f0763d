// Exact rays through voxels, written once for GLSL and C++ (GLM): the GPU's sun
// shadows (shaders/trace.glsl) and the CPU's World::raycast run this same code, in
// the same float arithmetic, so they agree ray for ray. The includer provides
//   int voxelRayBlock(ivec3 voxel);   -1 when the voxel is solid; else k: the
//                                     aligned block of 2^k voxels a side holding
//                                     it is empty (0: only the voxel is known to be)
// and, in C++, `using namespace glm` around it. Float literals carry an f so both
// languages read them the same way.
//
// The rule. A ray starts at `fraction` (0..1 on each axis) within voxel `voxel`
// and visits the voxels it passes through one face crossing at a time. A crossing
// happens at t = (distance to the boundary along its axis) * (1 / |d| on that
// axis): products and differences of floats, rounded alike on every IEEE device.
// Where two or three crossings fall on the same t (the ray goes exactly through an
// edge or a corner) they are taken one after another, z first, then y, then x: the
// ray enters one of the voxels beside the edge or corner, so it cannot slip
// between two solid voxels that meet there. An empty block is crossed in one step,
// to the voxel that crossing its boundaries one by one would reach, so the answer
// does not depend on how each side groups empty space (64^3 tiles on the GPU,
// OpenVDB's nodes on the CPU).
#ifndef GROTTO_SHARED_VOXEL_RAY_H
#define GROTTO_SHARED_VOXEL_RAY_H

#define kVoxelRayNever 3.0e38f  // the t of an axis the ray runs parallel to

struct VoxelRayStart {
    ivec3 voxel;
    vec3 fraction;
};

struct VoxelRayHit {
    float t;      // distance (voxels) to where the ray enters a solid voxel; -1: it enters none
    ivec3 voxel;  // that voxel
    int face;     // the face it enters through (0..5: +X -X +Y -Y +Z -Z); -1: it starts in it
};

// Does the crossing at ta on axis a come before the one at tb on axis b?
bool voxelRayBefore(float ta, int a, float tb, int b) { return ta < tb || (ta == tb && a > b); }

// Where the ray leaves cell c (relative to the start voxel) along axis a.
float voxelRayLeave(vec3 fraction, vec3 inv, ivec3 sgn, int a, int c) {
    if (inv[a] == 0.0f) return kVoxelRayNever;
    float distance = sgn[a] > 0 ? float(c + 1) - fraction[a] : fraction[a] - float(c);
    return distance * inv[a];
}

// The first solid voxel the ray from `start` along the unit direction d enters
// within maxT voxels, among those in [lo, hi] (the world's solid bounds: once the
// ray has left them for good it stops). openStart: the start voxel counts as open
// and is not tested. Gives up (no hit) after maxSteps voxels or empty blocks.
VoxelRayHit voxelRay(VoxelRayStart start, vec3 d, float maxT, ivec3 lo, ivec3 hi, bool openStart, int maxSteps) {
    VoxelRayHit hit;
    hit.t = -1.0f;
    hit.voxel = start.voxel;
    hit.face = -1;
    vec3 inv = vec3(0.0f);  // 1 / |d| per axis, 0 where the ray runs parallel to it
    ivec3 sgn = ivec3(1);  // the direction's sign per axis
    for (int a = 0; a < 3; ++a) {
        if (abs(d[a]) > 1e-20f) inv[a] = 1.0f / abs(d[a]);
        if (d[a] < 0.0f) sgn[a] = -1;
    }
    ivec3 r = ivec3(0);  // the voxel the ray is in, relative to the start voxel
    float tIn = 0.0f;    // where it entered that voxel
    int face = -1;       // and through which face
    for (int i = 0; i < maxSteps; ++i) {
        ivec3 voxel = start.voxel + r;
        bool gone = false;
        for (int a = 0; a < 3; ++a) {
            bool before = voxel[a] < lo[a], after = voxel[a] > hi[a];
            gone = gone || (inv[a] == 0.0f ? before || after : sgn[a] > 0 ? after : before);
        }
        if (gone) return hit;
        int k = voxelRayBlock(voxel);
        if (k < 0 && (i > 0 || !openStart)) {
            hit.t = tIn;
            hit.voxel = voxel;
            hit.face = face;
            return hit;
        }
        if (k < 0) k = 0;
        int size = 1 << k;
        ivec3 blockLo = ((voxel >> k) << k) - start.voxel;
        // The first of the crossings out of the block.
        vec3 t;
        for (int a = 0; a < 3; ++a)
            t[a] = voxelRayLeave(start.fraction, inv, sgn, a, sgn[a] > 0 ? blockLo[a] + size - 1 : blockLo[a]);
        int a = 0;
        if (voxelRayBefore(t[1], 1, t[a], a)) a = 1;
        if (voxelRayBefore(t[2], 2, t[a], a)) a = 2;
        if (t[a] > maxT) return hit;
        // Across a block of several voxels, each other axis reaches the first voxel
        // whose own crossing does not come before that one.
        if (size > 1)
            for (int b = 0; b < 3; ++b) {
                if (b == a || inv[b] == 0.0f) continue;
                int last = sgn[b] > 0 ? blockLo[b] + size - 1 : blockLo[b];
                int guess = int(floor(start.fraction[b] + d[b] * t[a]));
                int c = sgn[b] > 0 ? clamp(guess, r[b], last) : clamp(guess, last, r[b]);
                while (c != last && voxelRayBefore(voxelRayLeave(start.fraction, inv, sgn, b, c), b, t[a], a))
                    c += sgn[b];
                while (c != r[b] && !voxelRayBefore(voxelRayLeave(start.fraction, inv, sgn, b, c - sgn[b]), b, t[a], a))
                    c -= sgn[b];
                r[b] = c;
            }
        r[a] = sgn[a] > 0 ? blockLo[a] + size : blockLo[a] - 1;
        tIn = t[a];
        face = 2 * a + (sgn[a] > 0 ? 1 : 0);  // entered through the face turned back toward the ray
    }
    return hit;
}

// The start of a ray leaving a point on a voxel face: the open voxel in front of
// the face (`start`, the point within it), the face's axis `normalAxis`. A point
// placed from float depth near a concave edge or corner may land a hair inside the
// solid voxel beside that one; it moves across the nearest boundaries along the
// face onto the open voxel's edge. A start with no open voxel near stays as it is.
VoxelRayStart voxelRayOpenStart(VoxelRayStart start, int normalAxis) {
    if (voxelRayBlock(start.voxel) >= 0) return start;
    int u = (normalAxis + 1) % 3, v = (normalAxis + 2) % 3;
    // Across the nearer boundary on each of the two axes along the face.
    int su = start.fraction[u] < 0.5f ? -1 : 1, sv = start.fraction[v] < 0.5f ? -1 : 1;
    float du = min(start.fraction[u], 1.0f - start.fraction[u]), dv = min(start.fraction[v], 1.0f - start.fraction[v]);
    // The nearer of the two first, then the other, then both.
    for (int attempt = 0; attempt < 3; ++attempt) {
        bool moveU = attempt == 2 || (attempt == 0) == (du <= dv);
        bool moveV = attempt == 2 || (attempt == 0) == (dv < du);
        VoxelRayStart s = start;
        if (moveU) {
            s.voxel[u] += su;
            s.fraction[u] = su > 0 ? 0.0f : 1.0f;
        }
        if (moveV) {
            s.voxel[v] += sv;
            s.fraction[v] = sv > 0 ? 0.0f : 1.0f;
        }
        if (voxelRayBlock(s.voxel) >= 0) return s;
    }
    return start;
}

#endif
