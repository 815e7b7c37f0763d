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

// Where the ray leaves, on each axis, the voxel whose far boundary on it is at
// `far` (relative to the start voxel). `step`: the direction's sign over its size
// per axis (0 where it runs parallel to the axis); `never`: kVoxelRayNever there, 0
// elsewhere (adding 0 changes no bit, fused or not).
vec3 voxelRayLeave(VoxelRayStart start, vec3 step, vec3 never, ivec3 far) {
    return (vec3(far) - start.fraction) * step + never;
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
    bvec3 parallel = lessThanEqual(abs(d), vec3(1e-20f));
    bvec3 positive = greaterThanEqual(d, vec3(0.0f));
    vec3 sgn = mix(vec3(-1.0f), vec3(1.0f), positive);
    vec3 step = mix(sgn / max(abs(d), vec3(1e-20f)), vec3(0.0f), parallel);
    vec3 never = mix(vec3(0.0f), vec3(kVoxelRayNever), parallel);
    // Past `edge` on any axis (voxel times the direction's sign) the ray has left the
    // bounds for good; a ray parallel to an axis it is outside the bounds on never enters.
    ivec3 edge = mix(mix(-lo, hi, positive), ivec3(0x7fffffff), parallel);
    for (int a = 0; a < 3; ++a)
        if (parallel[a] && (start.voxel[a] < lo[a] || start.voxel[a] > hi[a])) return hit;
    ivec3 isgn = mix(ivec3(-1), ivec3(1), positive);
    // Integer selects below are products with 0 or 1: GLM leaves its vector mix
    // out of line, and it was a third of a CPU ray's time.
    ivec3 ahead = ivec3(positive);  // a voxel's far boundary, from the voxel
    ivec3 r = ivec3(0);  // the voxel the ray is in, relative to the start voxel
    float tIn = 0.0f;    // where it entered that voxel
    int axis = -1;       // across which axis
    for (int i = 0; i < maxSteps; ++i) {
        ivec3 voxel = start.voxel + r;
        if (any(greaterThan(voxel * isgn, edge))) return hit;
        int k = voxelRayBlock(voxel);
        if (k < 0 && (i > 0 || !openStart)) {
            hit.t = tIn;
            hit.voxel = voxel;
            if (axis >= 0) hit.face = 2 * axis + (positive[axis] ? 1 : 0);  // the face turned back toward the ray
            return hit;
        }
        if (k < 0) k = 0;
        int size = 1 << k;
        ivec3 blockLo = ((voxel >> k) << k) - start.voxel;
        // The first of the crossings out of the block: where the ray leaves the block
        // on each axis, ties to the later axis.
        ivec3 last = blockLo + (size - 1) * ahead;  // its last voxel on the way
        vec3 t = voxelRayLeave(start, step, never, last + ahead);
        int a = t.y <= t.x ? 1 : 0;
        float ta = min(t.x, t.y);
        if (t.z <= ta) {
            a = 2;
            ta = t.z;
        }
        if (ta > maxT) return hit;
        // Meanwhile each other axis reaches the first voxel whose own crossing does not
        // come before that one (the same voxel the crossings taken one by one reach):
        // guessed from where the ray is then, a little behind (more than rounding can
        // move it, for rays up to a million voxels), and moved on by one if its
        // crossing does come before. Across a single voxel that is the voxel itself.
        if (size > 1) {
            vec3 p = start.fraction + d * ta;
            vec3 behind = min(1e-5f * (1.0f + abs(p)), vec3(0.5f)) * sgn;
            ivec3 guess = ivec3(floor(p - behind));
            guess = clamp(guess, min(r, last), max(r, last));
            vec3 leave = voxelRayLeave(start, step, never, guess + ahead);
            ivec3 before = ivec3(lessThan(leave, vec3(ta))) |
                           (ivec3(equal(leave, vec3(ta))) & ivec3(greaterThan(ivec3(0, 1, 2), ivec3(a))));
            r = guess + isgn * (before & ivec3(notEqual(guess, last)));
        }
        // On axis a the ray steps out of the block: to blockLo + size, or blockLo - 1.
        r += (blockLo + (size + 1) * ahead - 1 - r) * ivec3(equal(ivec3(a), ivec3(0, 1, 2)));
        tIn = ta;
        axis = a;
    }
    return hit;
}

// How far the ray from `start`, in a solid voxel, runs through solid voxels before
// it enters an open one, in voxels; maxT when it is still in solid there. One
// voxel at a time (the runs are short), crossing as voxelRay does: on a tie
// z first, then y, then x.
float voxelRayExit(VoxelRayStart start, vec3 d, float maxT) {
    bvec3 parallel = lessThanEqual(abs(d), vec3(1e-20f));
    bvec3 positive = greaterThanEqual(d, vec3(0.0f));
    vec3 step = mix(mix(vec3(-1.0f), vec3(1.0f), positive) / max(abs(d), vec3(1e-20f)), vec3(0.0f), parallel);
    vec3 never = mix(vec3(0.0f), vec3(kVoxelRayNever), parallel);
    ivec3 isgn = mix(ivec3(-1), ivec3(1), positive), ahead = mix(ivec3(0), ivec3(1), positive);
    if (voxelRayBlock(start.voxel) >= 0) return 0.0f;
    ivec3 r = ivec3(0);
    for (int i = 0; i < 4096; ++i) {
        vec3 t = voxelRayLeave(start, step, never, r + ahead);
        int a = t.y <= t.x ? 1 : 0;
        float ta = min(t.x, t.y);
        if (t.z <= ta) {
            a = 2;
            ta = t.z;
        }
        if (ta >= maxT) return maxT;
        r += isgn * ivec3(equal(ivec3(a), ivec3(0, 1, 2)));
        if (voxelRayBlock(start.voxel + r) >= 0) return ta;
    }
    return maxT;
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
