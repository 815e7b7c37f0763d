// The face cache's rays on the GPU (engine/passes/face_cache_trace_pass.h), shared
// by C++ and GLSL: each frame the faces in view whose texels have not converged
// are listed, and texels are traced, least converged first, within a ray budget.
//
// A face's level (2 bits each, 16 faces a word in the levels buffer):
//   0: never traced, or reached by an edit (its texels are stale or placeholders);
//   1: traced with the coarse rays only;
//   2: converged but for its sky light, which an edit far away may have moved by
//      at most voxel/face_cache_edit.h's kSkyStaleShare;
//   3: converged: traced with the full rays since the last edit that reached it.
// The queue: two lists of up to `capacity` faces in view (uvec4: cell xyz, dir |
// face index << 3), level 0 first at [0, capacity), levels 1 and 2 at
// [capacity, 2 capacity). The faces are asked for by the request pass, for the
// face under each pixel, and by the composite of the frame before, for every
// texel it read that had not converged. The backlog: every face not converged
// when the cache's GPU copy was made (uvec4s as the queue's), in view or not. A
// frame after one that found nothing in view to trace takes the next window of
// it, as many faces as a quarter of the budget traces at the full rays, so the faces an edit
// reached out of view, and a cache begun untraced, converge too (and the face
// atlas is filled again: LiveFaceCache::catchUpAtlas). The header's words:
#ifndef GROTTO_SHARED_FACE_TRACE_H
#define GROTTO_SHARED_FACE_TRACE_H
#include "common.h"

#define GROTTO_FACE_LEVEL_CONVERGED 3u
// The rays a face never traced gets at first, in the frame it comes into view, the
// face traced as one texel (face_cache_trace.comp): an estimate better than
// GTAO high's converged AO (docs/face-cache.md).
#define GROTTO_FACE_COARSE_RAYS 16u
#define GROTTO_FACE_COARSE_SUN_RAYS 4u
#define GROTTO_FACE_QUEUE_EMPTY 0u    // faces at level 0 asked for (may pass capacity)
#define GROTTO_FACE_QUEUE_PARTIAL 1u  // faces at levels 1 and 2 asked for
#define GROTTO_FACE_TRACED_EMPTY 2u   // of the first list, traced this frame
#define GROTTO_FACE_TRACED_PARTIAL 3u // of the second, traced this frame (the budget's share)
#define GROTTO_FACE_EMPTY_FULL 4u     // 1: the first list got the full rays, 0: the coarse
#define GROTTO_FACE_DISPATCH 5u       // three words: the trace's indirect dispatch
#define GROTTO_FACE_CAPACITY 8u       // the lists' length, set once
#define GROTTO_FACE_ASKED 9u          // faces asked for in view, this frame (for the host; the backlog's not counted)
#define GROTTO_FACE_UNCONVERGED 10u   // faces not at level 3, anywhere: none, and nothing is asked
#define GROTTO_FACE_REQUEST_DISPATCH 11u  // three words: the request pass's dispatch (none when all converged)
#define GROTTO_FACE_BACKLOG 14u      // faces in the backlog, set once
#define GROTTO_FACE_BACKLOG_NEXT 15u // where its next window starts
#define GROTTO_FACE_BACKLOG_DISPATCH 16u  // three words: the backlog pass's dispatch (none but when idle)
#define GROTTO_FACE_BACKLOG_START 19u     // this frame's window: its first entry ...
#define GROTTO_FACE_BACKLOG_TAKEN 20u     // ... and its length
#define GROTTO_FACE_BACKLOG_ADDED 21u     // of that window, the faces listed (not converged, not asked in view)
#define GROTTO_FACE_FRAMES 22u       // frames traced since the copy was made, up to 2 (the backlog waits for one)
#define GROTTO_FACE_ROUGH 23u        // faces at levels 0 and 1, anywhere: none, and every texel was traced since its edit
#define GROTTO_FACE_HEADER_WORDS 24u
// The backlog's share of a frame's budget, as a divisor: a still view's frames
// cost a quarter of a converging frame's rays more while the rest of the world
// converges (a progressive caves at 960x540: 1.03 s a frame at the whole budget,
// against 0.22 s with no backlog).
#define GROTTO_FACE_BACKLOG_SHARE 4u
#define GROTTO_FACE_TRACE_GROUP 64u
// The shadow edge list (shadow_edge.comp): its header's words, then the pixels.
#define GROTTO_EDGE_COUNT 0u     // pixels listed this frame (may pass capacity)
#define GROTTO_EDGE_CAPACITY 1u  // pixels it holds, set once
#define GROTTO_EDGE_DISPATCH 2u  // three words: the edge pass's indirect dispatch
#define GROTTO_EDGE_HEADER_WORDS 8u

GROTTO_NAMESPACE_BEGIN

struct FaceTraceConstants {
    vec4 sun;             // xyz: unit, toward the sun; w: cos of the disc's angular radius (1: a point)
    uint rays;            // cosine-weighted rays per texel, converged (AO and sky light)
    uint sunRays;         // rays per texel toward the sun, converged
    uint coarseRays;      // the same for a first look at a face never traced
    uint coarseSunRays;
    float radiusVoxels;   // AO's R, in voxels
    float epsilon;        // rays leave this far (voxels) in front of the face
    uint texelsPerSide;   // k
    uint budget;          // rays per frame for the second list (and for the first at full rays)
    uint width, height;   // the frame's, for the request pass's dispatch
    // The day's sun: its positions (0: none, one sun as `sun`), whose directions
    // the tracer's positions buffer holds, and the first word of the texels' bits.
    uint dayPositions, daySunFirst;
    // With full light (w of the first 1): the sky's two colours times its
    // intensity, for the light word of a texel traced here (the sky's light alone).
    vec4 skyZenith, skyHorizon;
};
GROTTO_STATIC_ASSERT(sizeof(FaceTraceConstants) == 96);

GROTTO_NAMESPACE_END
#endif
