#include "voxel/light_bake.h"

#include "grotto/error.h"
#include "shaders/shared/quad.h"
#include "shaders/shared/sky.h"
#include "voxel/bounce_guide.h"
#include "voxel/day_light_solve.h"
#include "voxel/brick_table.h"
#include "voxel/light_scene.h"
#include "voxel/luminance.h"
#include "voxel/ray_sampling.h"
#include "voxel/work_memory.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>

namespace grotto::voxel {

uint64_t lightBakeBytes(uint64_t texels, const LightBakeSettings& s, bool dayLight) {
    // The hits (the base rays', and extraShare of them more for the noisy texels),
    // the drawn rays' hits and the faces they were drawn toward, the sky's sums,
    // then glow, direct light, light, the next pass's and what each texel sends
    // as float RGB, and the extra rays' counts and offsets.
    const double hits = s.rays * (1.0 + (s.relativeError > 0.0 && s.maxExtraRays > 0 ? s.extraShare : 0.0));
    const uint64_t perTexel = uint64_t(std::ceil(hits)) * sizeof(uint32_t) + s.guidedRays * sizeof(GuidedHit) +
                              sizeof(Drawn) + 6 * sizeof(double) + 5 * sizeof(glm::vec3) + 2 * sizeof(uint32_t);
    // With the day's words: each face's row, 8 bytes a term, its rays' hits
    // merged by face (counted as a quarter of them: houses keeps a tenth), and
    // each face's words' sources, what it sends and the next pass's (a face of
    // at least 4 texels).
    const uint64_t day = dayLight ? uint64_t(std::ceil(hits) + s.guidedRays) * 8 / 4 +
                                        (kDayLightWords * (sizeof(float) + 2 * sizeof(glm::vec3)) + sizeof(glm::vec3)) / 4
                                  : 0;
    return texels * (perTexel + day);
}

void requireLightBakeFits(const World& world, uint64_t faces, uint32_t k, const LightBakeSettings& s, bool dayLight) {
    if (const uint64_t need = lightBakeBytes(faces * k * k, s, dayLight); need > budgetRoom(world))
        refuseOverBudget(world, "full light's bake of " + std::to_string(faces) + " faces needs " + mibText(need));
}

namespace {

// What a run of a texel's cosine rays saw of the sky.
struct SkySums {
    glm::dvec3 radiance{0.0};  // summed over the rays that left the world
    double squares = 0.0;      // their luminances squared, summed
    double horizon = 0.0, zenith = 0.0;
};

// Rays first .. first + n - 1 of a texel's sequence (R2 turned by `shift`) from
// `start` about `normal`: each one's hit texel written to `hits` (kMissed when it
// left the world), the sky summed.
SkySums traceTexelRays(const BrickTable& table, const LightScene& scene, const LightSources& lights, glm::dvec3 start,
                       glm::dvec3 normal, glm::dvec2 shift, uint32_t first, uint32_t n, uint32_t* hits) {
    SkySums sky;
    for (uint32_t ray = 0; ray < n; ++ray) {
        const glm::dvec2 u = r2(first + ray, shift);
        const glm::dvec3 d = cosineAbout(normal, u.x, u.y);
        const std::optional<BrickHit> hit = table.firstHit(start, d, std::numeric_limits<double>::infinity());
        hits[ray] = hit ? scene.texelAt(*hit, start + d * hit->t) : kMissed;
        if (hit) continue;
        const glm::dvec3 radiance(gpu::skyRadiance(float(d.y), glm::vec3(lights.skyZenith), glm::vec3(lights.skyHorizon)));
        sky.radiance += radiance;
        sky.squares += luminance(radiance) * luminance(radiance);
        const SkyWeights w = skyWeights(d.y);
        sky.horizon += w.horizon, sky.zenith += w.zenith;
    }
    return sky;
}

}  // namespace

LightBakeStats relightFaces(const BrickTable& table, const World& world, std::span<const ExposedFace> faces, uint32_t k,
                            const LightSources& lights, const LightBakeSettings& s, std::span<FaceTexel> texels,
                            std::span<const uint32_t> relit, const BakeProgress& progress, std::span<glm::vec3> dayLight) {
    const size_t perFace = size_t(k) * k, count = faces.size() * perFace, traced = relit.size() * perFace;
    if (texels.size() != count) throw Error::internal("relightFaces", "texels and faces differ in count");
    // Full light over the day: the texels keep the glowing faces' light alone,
    // and each face its day words (voxel/day_light_solve.h). Without room for
    // them, the hour's sun stands still.
    const bool day = lights.day && !dayLight.empty();
    if (day && dayLight.size() != faces.size() * kDayLightWords)
        throw Error::internal("relightFaces", "the day's light and faces differ in count");
    requireLightBakeFits(world, relit.size(), k, s, day);
    const LightScene scene(world, faces, k, texels, relit);
    const glm::dvec3 sunDirection = glm::normalize(lights.sunDirection);
    // With the day's sun the rays take a white sky of radiance 1: the sky's two
    // words' sum, what the noise of the light is judged by.
    LightSources rayLights = lights;
    if (day) rayLights.skyZenith = rayLights.skyHorizon = glm::dvec3(1.0), rayLights.skyIntensity = 1.0;
    const uint32_t baseRays = std::max(s.rays, 1u);
    // The texel of the m-th texel relit; where its rays start; how they are turned.
    auto texelOf = [&](size_t m) { return size_t(relit[m / perFace]) * perFace + m % perFace; };
    auto startOf = [&](size_t m) {
        const ExposedFace& face = faces[relit[m / perFace]];
        const uint32_t i = uint32_t(m % perFace) % k, j = uint32_t(m % perFace) / k;
        return texelPoint(face, k, i, j) + faceNormal(face.dir) * s.epsilon;
    };
    auto seedOf = [&](size_t m) {
        const uint32_t i = uint32_t(m % perFace) % k, j = uint32_t(m % perFace) / k;
        return splitmix64(texelSeed(faces[relit[m / perFace]], i, j) ^ 0x6c69676874ull);  // not the AO's rays
    };
    auto shiftOf = [&](uint64_t h) { return glm::dvec2(unitInterval(h), unitInterval(splitmix64(h))); };

    // The base rays: each relit texel's glowing faces' light, its sky, and the
    // texels its cosine rays hit.
    std::vector<uint32_t> hits(traced * baseRays, kMissed);
    std::vector<SkySums> sky(traced);
    std::vector<glm::vec3> glow(traced);
    std::vector<uint64_t> rays(relit.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, relit.size(), 16), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t n = r.begin(); n < r.end(); ++n) {
            const ExposedFace& face = faces[relit[n]];
            const glm::dvec3 normal = faceNormal(face.dir);
            for (size_t m = n * perFace; m < (n + 1) * perFace; ++m) {
                const uint64_t h = seedOf(m);
                const glm::dvec3 start = startOf(m);
                sky[m] = traceTexelRays(table, scene, rayLights, start, normal, shiftOf(h), 0, baseRays, &hits[m * baseRays]);
                rays[n] += baseRays;
                glow[m] = glm::vec3(scene.glowLight(table, face.cell, face.dir, start - normal * s.epsilon, normal,
                                                    s.emitterRays, splitmix64(h ^ 3), s.epsilon, rays[n]));
                // The sky's weights as sums over the texel's own ray count.
                const size_t t = texelOf(m);
                const double scale = double(texels[t].samples) / baseRays;
                texels[t].skyHorizon = float(sky[m].horizon * scale), texels[t].skyZenith = float(sky[m].zenith * scale);
            }
        }
    });

    // What each texel sends back to the rays that hit it: its albedo times its
    // light and its sun (with the day's sun, its glowing faces' light alone). The
    // texels not relit send what they hold throughout.
    std::vector<glm::vec3> sent(count);
    auto sends = [&](size_t t, glm::vec3 light) {
        const ExposedFace& face = faces[t / perFace];
        const double sun = day ? 0.0 : std::max(glm::dot(faceNormal(face.dir), sunDirection), 0.0) * texels[t].sun();
        return glm::vec3(scene.albedo(t / perFace)) * (light + glm::vec3(lights.sun * sun));
    };
    // The day's words: every face's white sources, and what the relit faces'
    // rays bring back, merged by face.
    DaySources sources;
    if (day) sources = daySources(faces, k, texels, *lights.day, [&](size_t f) { return glm::vec3(scene.albedo(f)); });
    // A texel's own light, or what it sends, with its face's day words: summed as
    // the noise and the bright faces are judged, the day's sun spread over its
    // positions. `part`: what of each word (its bounced light, with its source,
    // or what the face sends).
    enum class Part { Bounced, Light, Sent };
    auto summed = [&](size_t t, glm::vec3 own, Part part) {
        if (!day) return own;
        const size_t f = t / perFace;
        for (uint32_t w = 0; w < kDayLightWords; ++w) {
            const float share = w < 2 ? 1.0f : 1.0f / float(kDayBouncePositions);
            const glm::vec3 word = dayLight[f * kDayLightWords + w];
            own += share * (part == Part::Sent     ? daySent(sources, dayLight, f, w)
                            : part == Part::Light ? word + sources.direct[f * kDayLightWords + w]
                                                  : word);
        }
        return own;
    };
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t t = r.begin(); t < r.end(); ++t) sent[t] = sends(t, texels[t].light);
    });

    // More rays for the texels whose light is still noisy (after the passes
    // below): their hits, texel m's at [extraStart[m], extraStart[m + 1]).
    std::vector<uint32_t> extraStart(traced + 1, 0), extraHits;
    auto raysOf = [&](size_t m) { return baseRays + (extraStart[m + 1] - extraStart[m]); };
    // The rays drawn toward bright faces (below), none until the first passes have run.
    const uint32_t guidedRays = s.guidedFaces > 0 ? s.guidedRays : 0;
    std::vector<GuidedHit> guided(traced * guidedRays, GuidedHit{kMissed, 0.0f});
    std::vector<Drawn> drawn(traced);
    std::vector<glm::vec3> direct(traced);
    auto setDirect = [&](size_t m) {
        direct[m] = day ? glow[m] : glm::vec3(sky[m].radiance * (lights.skyIntensity / raysOf(m))) + glow[m];
    };
    for (size_t m = 0; m < traced; ++m) setDirect(m);

    // Bounce passes: light = direct + what the hits send back, from the pass before.
    std::vector<glm::vec3> light = direct, next(traced);
    LightBakeStats stats;
    if (progress) progress(0, s.maxPasses);
    // A texel's change counts against its own light, down to a floor far below
    // the mean: a room lit through a window converges too, not only the open
    // ground that holds most of the light.
    double mean = 0.0;
    for (const glm::vec3& d : direct) mean += luminance(glm::dvec3(d)) / double(std::max<size_t>(traced, 1));
    const double floor = std::max(mean, 1e-30) * 1e-4;
    auto bounce = [&](size_t m) {
        glm::vec3 back(0.0f);
        // kMissed, and the hits on faces drawn toward, have kHitOnDrawnFace set.
        for (const uint32_t* hit = &hits[m * baseRays]; hit != &hits[m * baseRays] + baseRays; ++hit)
            if (*hit < kHitOnDrawnFace) back += sent[*hit];
        for (uint32_t e = extraStart[m]; e < extraStart[m + 1]; ++e)
            if (extraHits[e] < kHitOnDrawnFace) back += sent[extraHits[e]];
        back /= float(raysOf(m));
        if (guidedRays == 0) return back;
        // The control variate holds the guide's light: with the day's sun, the
        // words summed, not this light; the drawn rays alone stay unbiased.
        if (!day) back += drawn[m].base(raysOf(m));
        for (const GuidedHit* g = &guided[m * guidedRays]; g != &guided[m * guidedRays] + guidedRays; ++g)
            if (g->reached()) back += g->weight * sent[g->texel];
        return back;
    };
    auto converge = [&] {
        for (uint32_t pass = 0; pass < s.maxPasses; ++pass) {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, traced, 4096), [&](const tbb::blocked_range<size_t>& r) {
                for (size_t m = r.begin(); m < r.end(); ++m) sent[texelOf(m)] = sends(texelOf(m), light[m]);
            });
            const double change = tbb::parallel_reduce(
                tbb::blocked_range<size_t>(0, traced, 4096), 0.0,
                [&](const tbb::blocked_range<size_t>& r, double worst) {
                    for (size_t m = r.begin(); m < r.end(); ++m) {
                        next[m] = direct[m] + bounce(m);
                        const double grown = std::abs(luminance(glm::dvec3(next[m] - light[m])));
                        worst = std::max(worst, grown / std::max(luminance(glm::dvec3(next[m])), floor));
                    }
                    return worst;
                },
                [](double a, double b) { return std::max(a, b); });
            light.swap(next);
            ++stats.passes;
            stats.change = change;
            if (progress) progress(stats.passes, s.maxPasses);
            if (stats.change < s.tolerance) break;
        }
    };
    converge();
    // The day's words, each relit face taking what its texels' rays hit: the
    // cosine rays but those on faces drawn toward, which the drawn rays bring.
    auto solveDay = [&] {
        if (!day) return;
        std::vector<FaceRow> rows(relit.size());
        tbb::parallel_for(tbb::blocked_range<size_t>(0, relit.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t n = r.begin(); n < r.end(); ++n) {
                FaceRow& row = rows[n];
                for (size_t m = n * perFace; m < (n + 1) * perFace; ++m) {
                    const float share = 1.0f / float(raysOf(m) * perFace);
                    auto take = [&](uint32_t hit) {
                        if (hit < kHitOnDrawnFace) row.emplace_back(hit / uint32_t(perFace), share);
                    };
                    for (size_t i = m * baseRays; i < (m + 1) * baseRays; ++i) take(hits[i]);
                    for (uint32_t e = extraStart[m]; e < extraStart[m + 1]; ++e) take(extraHits[e]);
                    for (const GuidedHit* g = &guided[m * guidedRays]; g != &guided[m * guidedRays] + guidedRays; ++g)
                        if (g->reached()) row.emplace_back(g->texel / uint32_t(perFace), g->weight / float(perFace));
                }
                mergeByFace(row);
            }
        });
        stats.passes = std::max(stats.passes, solveDayLight(relit, rows, sources, s.tolerance, s.maxPasses, dayLight));
    };
    solveDay();

    // Rays drawn toward the faces that pass each region the most light, as the
    // converged light shows it (a sunlit patch, a lamp-lit wall;
    // voxel/bounce_guide.h); the cosine rays' hits on them then count only as a
    // control variate.
    std::optional<BounceGuide> guide;
    if (guidedRays > 0) {
        const BounceGuide::Settings gs{s.guidedFaces, s.guideProbeRays, s.guidedNearest};
        std::vector<glm::vec3> summedSent;
        if (day) {
            summedSent.resize(count);
            for (size_t t = 0; t < count; ++t) summedSent[t] = summed(t, sent[t], Part::Sent);
        }
        guide.emplace(faces, k, relit, day ? std::span<const glm::vec3>(summedSent) : std::span<const glm::vec3>(sent),
                      kMissed, gs, [&](glm::dvec3 start, glm::dvec3 dir) {
                          const std::optional<BrickHit> hit = table.firstHit(start, dir, std::numeric_limits<double>::infinity());
                          return hit ? scene.texelAt(*hit, start + dir * hit->t) : kMissed;
                      });
        tbb::parallel_for(tbb::blocked_range<size_t>(0, relit.size(), 16), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t n = r.begin(); n < r.end(); ++n) {
                const glm::dvec3 normal = faceNormal(faces[relit[n]].dir);
                for (size_t m = n * perFace; m < (n + 1) * perFace; ++m)
                    drawn[m] = guide->draw(table, m, startOf(m) - normal * s.epsilon, normal, s.epsilon,
                                           splitmix64(seedOf(m) ^ 5), {&hits[m * baseRays], baseRays},
                                           luminance(glm::dvec3(summed(texelOf(m), light[m] - direct[m], Part::Bounced))),
                                           {&guided[m * guidedRays], guidedRays});
                rays[n] += guidedRays * perFace;
            }
        });
    }

    // The standard error of each texel's light over its base rays, from what each
    // ray brought (the sky's radiance, or the hit's, or on a face drawn toward
    // its share of the control variate, and the drawn rays'); where it passes
    // s.relativeError of the light (or of a hundredth of the mean, where the light
    // is dimmer), enough rays more to bring it there, up to s.maxExtraRays, in
    // all no more than s.extraShare of the base rays (each texel's cut alike).
    // With the day's sun, the mean of the light summed with the day's words.
    if (day) {
        mean = 0.0;
        for (size_t m = 0; m < traced; ++m) mean += luminance(glm::dvec3(summed(texelOf(m), light[m], Part::Light))) / double(traced);
    }
    const double dim = 0.01 * mean;
    std::vector<uint32_t> wanted(traced, 0);
    if (s.relativeError > 0.0 && s.maxExtraRays > 0)
        tbb::parallel_for(tbb::blocked_range<size_t>(0, traced, 1024), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t m = r.begin(); m < r.end(); ++m) {
                double sum = luminance(sky[m].radiance) * rayLights.skyIntensity;
                double squares = sky[m].squares * rayLights.skyIntensity * rayLights.skyIntensity;
                auto sentAt = [&](uint32_t t) { return luminance(glm::dvec3(summed(t, sent[t], Part::Sent))); };
                for (const uint32_t* hit = &hits[m * baseRays]; hit != &hits[m * baseRays] + baseRays; ++hit) {
                    if (*hit == kMissed) continue;
                    const double l = *hit < kHitOnDrawnFace
                                         ? sentAt(*hit)
                                         : drawn[m].beta * luminance(glm::dvec3(
                                                               guide->faceLight((*hit & ~kHitOnDrawnFace) / uint32_t(perFace))));
                    sum += l, squares += l * l;
                }
                const double average = sum / baseRays;
                double variance = std::max(squares / baseRays - average * average, 0.0) / baseRays;
                if (drawn[m].faces != 0 && guidedRays > 0) {
                    // The drawn rays' part: each ray's own estimate, times guidedRays:
                    // what it reached less beta times its face's mean light.
                    double drawnSum = 0.0, drawnSquares = 0.0;
                    for (const GuidedHit* g = &guided[m * guidedRays]; g != &guided[m * guidedRays] + guidedRays; ++g) {
                        if (!g->reached()) continue;
                        const double mean = drawn[m].beta * luminance(glm::dvec3(guide->faceLight(g->texel / uint32_t(perFace))));
                        const double v = g->weight * guidedRays * (sentAt(g->texel) - mean);
                        drawnSum += v, drawnSquares += v * v;
                    }
                    const double drawnMean = drawnSum / guidedRays;
                    variance += std::max(drawnSquares / guidedRays - drawnMean * drawnMean, 0.0) / guidedRays;
                }
                const double error = std::sqrt(variance);
                const double target = s.relativeError * std::max(luminance(glm::dvec3(summed(texelOf(m), light[m], Part::Light))), dim);
                if (!(error > target)) continue;
                const double more = baseRays * ((error / target) * (error / target) - 1.0);
                wanted[m] = uint32_t(std::min(std::ceil(more / 32.0) * 32.0, double(s.maxExtraRays)));
            }
        });
    uint64_t extra = 0;
    for (uint32_t w : wanted) extra += w;
    if (extra > 0) {
        const double scale = std::min(1.0, s.extraShare * double(traced) * baseRays / double(extra));
        for (size_t m = 0; m < traced; ++m) extraStart[m + 1] = extraStart[m] + uint32_t(wanted[m] * scale);
        extraHits.assign(extraStart[traced], kMissed);
        stats.extraRays = extraStart[traced];
        tbb::parallel_for(tbb::blocked_range<size_t>(0, traced, 64), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t m = r.begin(); m < r.end(); ++m) {
                const uint32_t n = extraStart[m + 1] - extraStart[m];
                if (n == 0) continue;
                const SkySums more = traceTexelRays(table, scene, rayLights, startOf(m), faceNormal(faces[relit[m / perFace]].dir),
                                                    shiftOf(seedOf(m)), baseRays, n, &extraHits[extraStart[m]]);
                if (guide) guide->takeIn(m, drawn[m], {&extraHits[extraStart[m]], n});
                sky[m].radiance += more.radiance;
                sky[m].zenith += more.zenith, sky[m].horizon += more.horizon;
                setDirect(m);
            }
        });
    }
    // With the day's sun the texels' weights are the sky's direct light the
    // frame reads: they take the extra rays too, and so do the words' sources.
    if (day && extra > 0) {
        for (size_t m = 0; m < traced; ++m) {
            FaceTexel& t = texels[texelOf(m)];
            const double scale = double(t.samples) / raysOf(m);
            t.skyHorizon = float(sky[m].horizon * scale), t.skyZenith = float(sky[m].zenith * scale);
        }
        sources = daySources(faces, k, texels, *lights.day, [&](size_t f) { return glm::vec3(scene.albedo(f)); });
    }
    if (extra > 0 || guidedRays > 0) converge(), solveDay();
    for (uint64_t n : rays) stats.rays += n;
    stats.rays += stats.extraRays;
    for (size_t m = 0; m < traced; ++m) texels[texelOf(m)].light = light[m];
    return stats;
}

std::vector<uint32_t> facesSeeingChange(const BrickTable& table, const World& world, std::span<const ExposedFace> faces,
                                        uint32_t k, std::span<const FaceTexel> texels, std::span<const glm::vec3> change,
                                        std::span<const double> threshold, std::span<const uint8_t> skip,
                                        uint32_t probeRays) {
    const size_t perFace = size_t(k) * k;
    if (texels.size() != faces.size() * perFace || change.size() != texels.size() || skip.size() != faces.size() ||
        threshold.size() != faces.size())
        throw Error::internal("facesSeeingChange", "texels, changes and faces differ in count");
    const LightScene scene(world, faces, k, texels, {});
    std::vector<uint8_t> seeing(faces.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, faces.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t f = r.begin(); f < r.end(); ++f) {
            if (skip[f]) continue;
            const ExposedFace& face = faces[f];
            const glm::dvec3 n = faceNormal(face.dir), start = texelPoint(face, 1, 0, 0) + n * 1e-4;
            const uint64_t h = splitmix64(texelSeed(face, 0, 0) ^ 0x70726f6265ull);
            const glm::dvec2 shift(unitInterval(h), unitInterval(splitmix64(h)));
            glm::dvec3 sent(0.0);
            for (uint32_t ray = 0; ray < probeRays; ++ray) {
                const glm::dvec2 u = r2(ray, shift);
                const glm::dvec3 d = cosineAbout(n, u.x, u.y);
                const std::optional<BrickHit> hit = table.firstHit(start, d, std::numeric_limits<double>::infinity());
                if (!hit) continue;
                const uint32_t t = scene.texelAt(*hit, start + d * hit->t);
                if (t != kMissed) sent += glm::dvec3(change[t]);
            }
            seeing[f] = std::abs(luminance(sent)) / std::max(probeRays, 1u) > threshold[f];
        }
    });
    std::vector<uint32_t> list;
    for (size_t f = 0; f < faces.size(); ++f)
        if (seeing[f]) list.push_back(uint32_t(f));
    return list;
}

LightBakeStats bakeLight(const BrickTable& table, const World& world, std::span<const ExposedFace> faces, uint32_t k,
                         const LightSources& lights, const LightBakeSettings& s, std::span<FaceTexel> texels,
                         const BakeProgress& progress, std::span<glm::vec3> dayLight) {
    std::vector<uint32_t> every(faces.size());
    std::iota(every.begin(), every.end(), 0u);
    return relightFaces(table, world, faces, k, lights, s, texels, every, progress, dayLight);
}

}  // namespace grotto::voxel
