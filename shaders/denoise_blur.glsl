// The edge-aware 3x3 blur of half-res AO, shared by the denoise passes and the
// temporal pass (which runs the final blur itself, so the spatial AO is never
// stored and read back between them). A neighbour counts only as far as both its
// own and the centre's edge weights agree they lie on one surface; diagonals
// through both of their paths. The includer declares `denoiseSource` (AO, packed
// edges, depth, face + 1) and includes shared/gtao_kernel.h first.

// The centre's weight: earlier passes of several blur harder than the final one.
float denoiseBeta(bool finalPass) { return finalPass ? gtao.settings.denoiseBlurBeta : gtao.settings.denoiseBlurBeta / 5.0; }

vec2 denoiseFetch(ivec2 p) { return imageLoad(denoiseSource, clamp(p, ivec2(0), ivec2(gtao.halfSize) - 1)).rg; }

// The blurred AO at p with centre weight beta; `range` gets the lowest and highest
// AO among the nine pixels read (the temporal clamp's range when they are raw).
float denoiseBlur(ivec2 p, float beta, out vec2 range) {
    vec2 c = denoiseFetch(p);
    vec2 l = denoiseFetch(p + ivec2(-1, 0)), r = denoiseFetch(p + ivec2(1, 0));
    vec2 t = denoiseFetch(p + ivec2(0, -1)), b = denoiseFetch(p + ivec2(0, 1));
    vec2 tl = denoiseFetch(p + ivec2(-1, -1)), tr = denoiseFetch(p + ivec2(1, -1));
    vec2 bl = denoiseFetch(p + ivec2(-1, 1)), br = denoiseFetch(p + ivec2(1, 1));
    range = vec2(min(min(min(c.x, l.x), min(r.x, t.x)), min(min(b.x, tl.x), min(min(tr.x, bl.x), br.x))),
                 max(max(max(c.x, l.x), max(r.x, t.x)), max(max(b.x, tl.x), max(max(tr.x, bl.x), br.x))));
    vec4 ec = gtaoUnpackEdges(c.y);
    vec4 el = gtaoUnpackEdges(l.y), er = gtaoUnpackEdges(r.y), et = gtaoUnpackEdges(t.y), eb = gtaoUnpackEdges(b.y);
    // Symmetric: the neighbour's edge back towards the centre must agree.
    float wl = ec.x * el.y, wr = ec.y * er.x, wt = ec.z * et.w, wb = ec.w * eb.z;
    // A corner counts through either side neighbour, and that neighbour's own edge
    // towards the corner, so nothing leaks round a silhouette's corner.
    const float diagonal = 0.425;
    float wtl = diagonal * (wl * el.z + wt * et.x);
    float wtr = diagonal * (wt * et.y + wr * er.z);
    float wbl = diagonal * (wb * eb.x + wl * el.w);
    float wbr = diagonal * (wr * er.w + wb * eb.y);
    float sum = beta * c.x + wl * l.x + wr * r.x + wt * t.x + wb * b.x + wtl * tl.x + wtr * tr.x + wbl * bl.x + wbr * br.x;
    float weight = beta + wl + wr + wt + wb + wtl + wtr + wbl + wbr;
    // A weighted mean of fractions is a fraction, but its division can round one
    // ulp above 1 (NVIDIA's does): clamped, so AO stays in [0, 1].
    return weight > 0.0 ? clamp(sum / weight, 0.0, 1.0) : c.x;
}
