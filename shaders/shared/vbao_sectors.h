// The visibility bitmask of one slice (VBAO): 32 sectors splitting the slice's
// half-disc around the projected normal into parts of equal cosine-weighted
// measure, so the share of sectors left open is the share of the slice's
// cosine-weighted visibility, the quantity GTAO integrates between its two
// horizons. An occluder of finite thickness covers only the sectors between its
// front and its back, so light passes behind it. Written once for GLSL and C++
// (GLM, with `using namespace glm` around it and <bit> included before it).
//
// Angles lie in the slice, measured from the direction to the camera, positive
// toward the slice's direction; n is the projected normal's angle (|n| < pi/2).
// Angle t weighs w(t) = cos(t - n) |sin t|: the cosine to the normal times the
// slice's share of the sphere there. The signed integral of w from 0 to t is
//   a(t) = (cos n + 2 t sin n - cos(2t - n)) / 4
// (GTAO's arc per horizon), so the measure below t, from the hemisphere's edge
// n - pi/2, is a(n - pi/2) + sign(t) a(t), out of cos n + n sin n in all.
#define kVbaoSectors 32
#define kVbaoHalfPi 1.57079632679490f

float vbaoArc(float t, float n) { return (cos(n) + 2.0f * t * sin(n) - cos(2.0f * t - n)) * 0.25f; }

// The whole slice's measure: both horizons at the hemisphere's edges.
float vbaoSliceTotal(float n) { return cos(n) + n * sin(n); }

// The share of the slice's measure below angle t: 0 at n - pi/2, 1 at n + pi/2.
float vbaoCdf(float t, float n) {
    float lo = n - kVbaoHalfPi;
    t = clamp(t, lo, n + kVbaoHalfPi);
    return clamp((vbaoArc(lo, n) + sign(t) * vbaoArc(t, n)) / vbaoSliceTotal(n), 0.0f, 1.0f);
}

// Bits lo .. hi - 1 of a sector mask, both clamped to 0 .. 32 first: a shift by
// 32 is undefined in both languages.
uint vbaoBits(int lo, int hi) {
    lo = clamp(lo, 0, kVbaoSectors);
    hi = clamp(hi, lo, kVbaoSectors);
    uint below = hi == kVbaoSectors ? 0xFFFFFFFFu : (1u << uint(hi)) - 1u;
    uint under = lo == kVbaoSectors ? 0xFFFFFFFFu : (1u << uint(lo)) - 1u;
    return below & ~under;
}

// The sectors an occluder seen between angles a and b (either order) covers:
// those it covers more than half of, so the error is at most half a sector at
// each end and has no bias.
uint vbaoOccluded(float a, float b, float n) {
    float lo = vbaoCdf(min(a, b), n) * float(kVbaoSectors), hi = vbaoCdf(max(a, b), n) * float(kVbaoSectors);
    return vbaoBits(int(floor(lo + 0.5f)), int(floor(hi + 0.5f)));
}

// acos to within 7e-5 radians (Abramowitz and Stegun 4.4.45), far inside a
// sector, for the kernel's two angles per sample.
float vbaoAcos(float x) {
    float a = abs(x);
    float r = sqrt(1.0f - a) * (1.5707288f + a * (-0.2121144f + a * (0.0742610f - 0.0187293f * a)));
    return x < 0.0f ? 3.14159265358979f - r : r;
}

// One slice's terms of vbaoCdf, computed once per slice rather than per sample.
struct VbaoSlice {
    float n, cosN, sinN, arcLo, total;
};

VbaoSlice vbaoSlice(float n, float cosN, float sinN) {
    VbaoSlice s;
    s.n = n;
    s.cosN = cosN;
    s.sinN = sinN;
    s.total = cosN + n * sinN;
    s.arcLo = vbaoArc(n - kVbaoHalfPi, n);
    return s;
}

// vbaoCdf at the angle whose cosine to the view direction is c, on the side
// side (+1: toward the slice's direction, -1: against): cos(2t - n) from c by the
// double-angle formulas, so the only transcendental is the angle itself.
float vbaoSliceCdf(VbaoSlice s, float c, float side) {
    c = clamp(c, -1.0f, 1.0f);
    float t = side * vbaoAcos(c);
    if (t <= s.n - kVbaoHalfPi) return 0.0f;
    if (t >= s.n + kVbaoHalfPi) return 1.0f;
    float sinT = side * sqrt(max(1.0f - c * c, 0.0f));
    float cos2tn = (2.0f * c * c - 1.0f) * s.cosN + 2.0f * sinT * c * s.sinN;
    float a = (s.cosN + 2.0f * t * s.sinN - cos2tn) * 0.25f;
    return clamp((s.arcLo + sign(t) * a) / s.total, 0.0f, 1.0f);
}

// The sectors between two shares of the slice's measure (either order), each
// rounded to the nearest sector boundary as vbaoOccluded rounds.
uint vbaoSectorsBetween(float a, float b) {
    return vbaoBits(int(floor(min(a, b) * float(kVbaoSectors) + 0.5f)), int(floor(max(a, b) * float(kVbaoSectors) + 0.5f)));
}

#ifdef __cplusplus
int vbaoOpenSectors(uint mask) { return kVbaoSectors - std::popcount(mask); }
int vbaoLowestBit(uint mask) { return std::countr_zero(mask); }  // mask != 0
#else
int vbaoOpenSectors(uint mask) { return kVbaoSectors - bitCount(mask); }
int vbaoLowestBit(uint mask) { return findLSB(mask); }
#endif

// The slice's visibility from its mask, on GTAO's scale: projectedLength times the
// measure of the open sectors (GTAO's projectedLength * (arc0 + arc1)).
float vbaoVisibility(uint mask, float n, float projectedLength) {
    return projectedLength * vbaoSliceTotal(n) * float(vbaoOpenSectors(mask)) / float(kVbaoSectors);
}

// --- The bent normal: the mean open direction, cosine-weighted --------------

// vbaoCdf at angle t of the slice s.
float vbaoSliceCdfAt(VbaoSlice s, float t) {
    t = clamp(t, s.n - kVbaoHalfPi, s.n + kVbaoHalfPi);
    float a = (s.cosN + 2.0f * t * s.sinN - cos(2.0f * t - s.n)) * 0.25f;
    return clamp((s.arcLo + sign(t) * a) / s.total, 0.0f, 1.0f);
}

// The angle below which the slice holds share u of its measure (vbaoCdf's
// inverse): Newton's method inside a bracket that halves where a step would leave
// it (the weight vanishes toward the camera, where Newton alone would overshoot).
float vbaoAngleAt(VbaoSlice s, float u) {
    float lo = s.n - kVbaoHalfPi, hi = s.n + kVbaoHalfPi;
    float t = lo + u * (hi - lo);
    for (int i = 0; i < 8; ++i) {
        float f = vbaoSliceCdfAt(s, t) - u;
        if (f > 0.0f) hi = t; else lo = t;
        float slope = cos(t - s.n) * abs(sin(t)) / s.total;
        float next = t - f / max(slope, 1e-6f);
        t = next >= lo && next <= hi ? next : 0.5f * (lo + hi);
    }
    return t;
}

// The integral of the direction times the weight w from angle 0 to t: x toward
// the slice's direction, y toward the camera. With w = cos(t - n) |sin t| it is
// sign(t) (G(t) - G(0)) for
//   G_x = sin^3 t cos n / 3 + sin n (cos^3 t / 3 - cos t)
//   G_y = (sin^3 t sin n - cos^3 t cos n) / 3.
vec2 vbaoDirectionTo(VbaoSlice s, float t) {
    float c = cos(t), sn = sin(t);
    float c3 = c * c * c, s3 = sn * sn * sn;
    vec2 g = vec2(s3 * s.cosN / 3.0f + s.sinN * (c3 / 3.0f - c), (s3 * s.sinN - c3 * s.cosN) / 3.0f);
    vec2 g0 = vec2(-2.0f * s.sinN / 3.0f, -s.cosN / 3.0f);
    return sign(t) * (g - g0);
}

// The cosine-weighted integral of the directions the mask leaves open, in the
// slice (x toward its direction, y toward the camera): each run of open sectors
// integrated exactly between its ends' angles.
vec2 vbaoOpenDirection(VbaoSlice s, uint mask) {
    vec2 sum = vec2(0.0f);
    uint open = ~mask;
    while (open != 0u) {
        int lo = vbaoLowestBit(open);
        uint closedAbove = mask & ~vbaoBits(0, lo);
        int hi = closedAbove == 0u ? kVbaoSectors : vbaoLowestBit(closedAbove);
        open &= ~vbaoBits(lo, hi);
        float a = lo == 0 ? s.n - kVbaoHalfPi : vbaoAngleAt(s, float(lo) / float(kVbaoSectors));
        float b = hi == kVbaoSectors ? s.n + kVbaoHalfPi : vbaoAngleAt(s, float(hi) / float(kVbaoSectors));
        sum += vbaoDirectionTo(s, b) - vbaoDirectionTo(s, a);
    }
    return sum;
}
