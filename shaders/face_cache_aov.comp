#version 460
#extension GL_GOOGLE_include_directive : require
// --ao cache's AOVs for a read-back: the face cache's AO at each full-res pixel,
// less what objects take (1 for the sky and faces it lacks; an object's own on its
// faces with the object light pass, else 1) and, while its sun is the frame's,
// its sun visibility into the shadow image: over the world pixels it has, times
// the objects' shadow there where the shadow pass ran (which the other pixels
// keep), 1 on the others where it did not. And the light the cache holds there,
// irradiance over pi: the full light, or with sky weights the sky's light from
// them (0 where the cache has none, and with the constant ambient). Exactly what
// the composite (composite.comp's shadeCached) lit each pixel with.
#include "shared/frame.h"
#include "shared/objects.h"
#include "shared/quad.h"

layout(constant_id = 0) const bool cachedSun = false;
layout(constant_id = 1) const bool tracedShadows = false;
layout(constant_id = 2) const bool objectLight = false;
layout(local_size_x = 16, local_size_y = 16) in;
layout(set = 0, binding = 0, std140) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1) uniform usampler2D surfaceTex;
layout(set = 0, binding = 2) uniform sampler2D depthBuffer;
layout(set = 0, binding = 3, r32f) uniform writeonly image2D aoOut;
layout(set = 0, binding = 4, r32f) uniform image2D sunOut;  // 1x1 without sun shadows; the objects' shadow with
uint faceCacheTable() { return frame.faceCache.x; }
uint faceCacheK() { return frame.faceCache.y; }
layout(set = 0, binding = 5, rgba16f) uniform readonly image2D objectLightImage;  // object_light.comp's
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D lightOut;
#define GROTTO_FACE_CACHE_BINDING 7
#include "face_cache.glsl"
#include "face_cache_surface.glsl"
// The faces' levels: taps on faces never traced are left out, as the composite leaves them.
#define GROTTO_FACE_LEVELS_BINDING 10
#include "face_cache_levels.glsl"

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(q), frame.size))) return;
    uint surface = texelFetch(surfaceTex, q, 0).r;
    vec4 c = vec4(1.0);
    bool found = false;
    // With full light the object light pass gives light (rgb), not AO and sky weights.
    bool fullLight = frame.ambient.w >= 1.5;
    vec4 objectPart = objectLight && surface != 0u ? imageLoad(objectLightImage, q) : vec4(0.0);
    vec3 light = vec3(0.0);
    if (surface != 0u && surfaceObject(surface) == 0u) {
        FaceCacheTaps faces;
        FaceCacheTaps t = cachedTapsAt(q, surfaceFace(surface), faces);
        dropUntraced(t);
        vec2 sunRange;
        bool edge;
        c = faceCacheBlend(t, found, sunRange);
        if (cachedSun) c.y = cachedSunAt(t, c, sunRange, faceAxisNormal(surfaceFace(surface)), edge);
        if (found && fullLight) light = max(cachedFullLightAt(t, faces) + objectPart.rgb, vec3(0.0));
        else if (found && frame.ambient.w >= 0.5)
            light = frame.ambient.rgb * (c.z * frame.skyHorizon.rgb + c.w * frame.skyZenith.rgb);
    } else if (surface != 0u && objectLight && fullLight)
        light = objectPart.rgb;
    imageStore(lightOut, q, vec4(light, 1.0));
    float aoTaken = fullLight ? 0.0 : objectPart.x;
    float ao = found ? max(c.x - aoTaken, 0.0) : c.x;
    if (objectLight && !fullLight && surface != 0u && surfaceObject(surface) != 0u) ao = objectPart.x;
    imageStore(aoOut, q, vec4(ao));
    if (cachedSun && (found || !tracedShadows) && all(lessThan(q, imageSize(sunOut))))
        imageStore(sunOut, q, vec4(found ? c.y * (tracedShadows ? imageLoad(sunOut, q).r : 1.0) : 1.0));
}
