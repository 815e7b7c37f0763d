// A stability run along a path (docs/metrics.md): each frame of the playing path
// rendered and compared with the frame before (flicker of the raw, spatial and
// temporal AO, of the reference and of the display colour, that with the light
// held too on a path through the day), with the reference
// traced on pairs of frames (error, ghosting by age since disocclusion), the
// pixels near each of the path's edits measured against references of the world
// before and after it, the sun against exact rays (--sun), and the cost per pass;
// summarised as the run's figures.
#include "app/stability_run.h"

#include "app/ao_cost.h"
#include "app/cost_difference.h"
#include "app/options.h"
#include "app/progress.h"
#include "app/stability_baseline.h"
#include "engine/camera_path.h"
#include "engine/lab/ao_metrics.h"
#include "engine/lab/edit_metrics.h"
#include "engine/lab/sun_agreement.h"
#include "engine/lab/surface_points.h"
#include "engine/lab/temporal_metrics.h"
#include "engine/image_output.h"
#include "voxel/reference_ao.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace grotto::app {
namespace {

using json = nlohmann::json;

// The error over surface pixels (docs/metrics.md), as JSON.
json errorJson(const std::vector<float>& ao, const std::vector<float>& reference, const std::vector<uint8_t>& mask) {
    const AoError e = aoError(ao, reference, mask);
    if (e.pixels == 0) return {{"pixels", 0}};
    // JSON has no infinity: an exact match reports 99 dB.
    return {{"pixels", e.pixels}, {"mae", e.mae}, {"rmse", e.rmse}, {"psnr", std::min(e.psnr, 99.0)}, {"bias", e.bias}};
}

// The G-buffer's surface points at the AO pixels, with the AO pixel each stands for.
struct AoPoints {
    std::vector<glm::dvec3> points, normals;
    std::vector<size_t> index;
};

AoPoints aoPoints(const voxel::World& world, std::span<const voxel::PosedWorld> objects, const FrameImages& frame,
                  const Camera& camera, const AoFrame& ao) {
    const SurfacePoints sp = surfacePoints(frame, camera, world, objects);
    AoPoints out;
    for (size_t k = 0; k < sp.pixels.size(); ++k) {
        const uint32_t x = sp.pixels[k] % frame.width, y = sp.pixels[k] / frame.width;
        if (x % ao.scale || y % ao.scale) continue;
        out.points.push_back(sp.points[k]);
        out.normals.push_back(sp.normals[k]);
        out.index.push_back(size_t(y / ao.scale) * ao.width + x / ao.scale);
    }
    return out;
}

// The reference on `world` (its brick table `bricks`) at the points whose AO pixel
// is set in `only` (all when empty); 1 elsewhere.
// The objects are traced at the frame's poses.
std::vector<float> referenceAt(const voxel::BrickTable& bricks, const voxel::World& world,
                               std::span<const voxel::PosedWorld> objects, const AoPoints& at,
                               size_t pixels, double radius, int spp, uint64_t& rays,
                               const std::vector<uint8_t>& only = {}) {
    std::vector<glm::dvec3> points, normals;
    std::vector<size_t> index;
    for (size_t k = 0; k < at.index.size(); ++k)
        if (only.empty() || only[at.index[k]]) {
            points.push_back(at.points[k]);
            normals.push_back(at.normals[k]);
            index.push_back(at.index[k]);
        }
    const voxel::ReferenceAo r =
        voxel::referenceAo(bricks, world, objects, points, normals, {.radius = radius, .spp = uint32_t(spp)});
    rays += r.rays;
    std::vector<float> v(pixels, 1.0f);
    for (size_t k = 0; k < index.size(); ++k) v[index[k]] = r.visibility[k];
    return v;
}

// The temporal pass's frames of history per AO pixel.
std::vector<float> historyAt(const FrameImages& frame, const AoFrame& ao) {
    std::vector<float> out(size_t(ao.width) * ao.height);
    for (uint32_t y = 0; y < ao.height; ++y)
        for (uint32_t x = 0; x < ao.width; ++x)
            out[size_t(y) * ao.width + x] = frame.aoHistory[size_t(y * ao.scale) * frame.width + x * ao.scale];
    return out;
}

// 1 for the AO pixels in `only` whose surface existed in `world`: the voxel behind
// the face solid, the one in front of it empty.
std::vector<uint8_t> existedBefore(const voxel::World& world, const AoPoints& at, const std::vector<uint8_t>& only) {
    std::vector<uint8_t> existed(only.size(), 0);
    for (size_t k = 0; k < at.index.size(); ++k) {
        if (!only[at.index[k]]) continue;
        const glm::dvec3 p = (at.points[k] - world.origin()) / world.voxelSize();
        auto voxel = [](glm::dvec3 q) { return glm::ivec3(glm::floor(q)); };
        existed[at.index[k]] = world.solid(voxel(p - 0.5 * at.normals[k])) && !world.solid(voxel(p + 0.5 * at.normals[k]));
    }
    return existed;
}

// An edit event of the run: the frame the path's edits were applied before, what
// they changed, and the world as it was, for the pre-edit reference.
struct EditEvent {
    int frame;
    voxel::WorldBox box;
    voxel::World before;
    voxel::BrickTable beforeBricks;
    std::vector<EditFrame> frames;
};

json editsJson(const std::vector<EditEvent>& events, double& staleMax, int& recoveryMax,
               bool& recoveryMeasured) {
    json out = json::array();
    for (const EditEvent& e : events) {
        const EditRecovery r = editRecovery(e.frames, e.frame);
        json frames = json::array();
        for (const EditFrame& f : e.frames)
            frames.push_back({{"frame", f.frame}, {"pixels", f.pixels}, {"old_surface_pixels", f.oldSurfaces},
                              {"mae", f.mae}, {"stale", f.stale},
                              {"closer_to_pre", f.closerToPre}});
        out.push_back({{"frame", e.frame},
                       {"box", {{"min", {e.box.min.x, e.box.min.y, e.box.min.z}}, {"max", {e.box.max.x, e.box.max.y, e.box.max.z}}}},
                       {"frames", frames},
                       {"stale_after_edit_frame", r.staleAfter},
                       {"steady_mae", r.steadyMae ? json(*r.steadyMae) : json()},
                       {"recovered_within_frames", r.recoveredWithin ? json(*r.recoveredWithin) : json()}});
        staleMax = std::max(staleMax, r.staleAfter);
        if (r.steadyMae) {
            recoveryMeasured = true;
            // Never recovering within the window counts as the whole window.
            recoveryMax = std::max(recoveryMax, r.recoveredWithin.value_or(kEditWindow));
        }
    }
    return out;
}

// Ages from here on share one ghosting bin: history is full long before.
constexpr int kGhostAgeCap = 32;

struct Mean {
    double sum = 0.0;
    size_t n = 0;
    void add(double v) { sum += v, ++n; }
    double value() const { return n ? sum / double(n) : 0.0; }
};

}  // namespace

StabilityFigures runStability(vk::Context& ctx, RenderSession& session, const AoOptions& ao, const StabilityRunOptions& o) {
    const int first = o.first;
    const uint32_t scale = ao.chain.fullResolution || faceCached(ao) ? 1 : 2;  // the face cache's AO is per pixel
    const double tolerance = 0.5 * session.world().voxelSize();
    LiveScene& live = session.scene();
    std::vector<EditEvent> events;
    std::map<std::string, std::vector<double>> passMs;
    std::vector<double> wallMs, chainMs, temporalMs;
    Mean flickerRaw, flickerSpatial, flickerTemporal, flickerReference, flickerColor, flickerHeld;
    SunAgreement sunAll;
    json sunWorst;  // the frame whose sun was off at the largest share of its pixels facing the sun
    FrameThumbnails thumbnails;  // the display colour of some frames, for a later run to be compared with
    size_t matchedPixels = 0, referencePixels = 0;  // what the flicker and error figures were measured over
    std::map<int, std::pair<Mean, Mean>> ghosting;  // age -> temporal, spatial MAE
    json errors = json::array();
    uint64_t rays = 0;
    {
        const voxel::World& world = live.world();
        Renderer& renderer = session.renderer();
        AoCostTimer costs(ctx, live.gpu(), world.desc().lighting, ao, o.width, o.height, session.objects());
        AoFrame before;
        Camera beforeCamera;
        std::vector<voxel::ObjectPose> beforePoses;
        std::vector<float> beforeReference;
        std::vector<uint16_t> age;
        // Renderers of their own (their own histories), sharing the scene: one lit
        // by the frame before's light, one by the sun alone.
        std::optional<Renderer> held, sunOnly;
        if (o.pathHasDay) held.emplace(ctx, live.gpu(), session.lighting(), ao, o.width, o.height, session.objects());
        if (o.sun) sunOnly.emplace(ctx, live.gpu(), sunAlone(session.lighting()), ao, o.width, o.height, session.objects());
        voxel::Lighting lightBefore = session.lighting();
        std::optional<Progress> progress;
        if (!o.quiet) progress.emplace(o.last - o.first + 1, stdout);
        for (int i = o.first; i <= o.last; ++i) {
            const double time = double(i - 1) / o.fps;
            std::optional<voxel::World> preEdit;  // a deep copy: the pre-edit reference traces it
            if (session.pathEditsPending(time)) preEdit.emplace(live.world());
            const RenderSession::PathFrame pathFrame = session.pathFrame(time, o.width, o.height);
            const Camera& camera = pathFrame.camera;
            if (!pathFrame.edited.empty()) {
                voxel::BrickTable bricks(*preEdit);
                events.push_back({i, pathFrame.edited, std::move(*preEdit), std::move(bricks), {}});
            }
            const std::vector<voxel::ObjectPose> poses = session.poses();
            const std::vector<voxel::PosedWorld> posed = session.posedObjects();
            const FrameStats stats = costs.render(renderer, camera, uint32_t(i), i > first + 1);  // 2 frames of warm-up
            for (const auto& [name, ms] : stats.passMs) passMs[name].push_back(ms);
            wallMs.push_back(stats.wallMs);
            const FrameImages frame = renderer.readback(camera, true);
            AoFrame now = aoFrame(frame, camera, scale);
            Reprojection match;
            if (i > first) {
                match = reproject(now, before, beforeCamera, tolerance, poses, beforePoses);
                matchedPixels += size_t(std::count_if(match.nearest.begin(), match.nearest.end(), [](int32_t q) { return q >= 0; }));
                flickerRaw.add(flicker(now.raw, before.raw, match));
                flickerSpatial.add(flicker(now.spatial, before.spatial, match));
                flickerTemporal.add(flicker(now.temporal, before.temporal, match));
                flickerColor.add(colorFlicker(now, before, match));
            }
            if (held) {
                held->setLighting(lightBefore);
                held->render(camera, uint32_t(i));
                if (i > first) flickerHeld.add(colorFlicker(aoFrame(held->readback(camera, true), camera, scale), before, match));
                lightBefore = session.lighting();
            }
            if (sunOnly) {
                const voxel::Lighting sunLight = sunAlone(session.lighting());
                sunOnly->setLighting(sunLight);
                sunOnly->render(camera, uint32_t(i));
                const SunAgreement s = sunAgainstRays(sunOnly->readback(camera, true), camera, world, posed, sunLight);
                sunAll.surface += s.surface, sunAll.facing += s.facing, sunAll.off += s.off, sunAll.aovOff += s.aovOff;
                const double exact = s.surface ? 1.0 - double(s.off) / double(s.surface) : 1.0;
                if (sunWorst.is_null() || exact < sunWorst["share_exact"].get<double>())
                    sunWorst = {{"frame", i}, {"share_exact", exact}, {"off_pixels", s.off}, {"surface_pixels", s.surface}};
            }
            if (keepsThumbnail(i, first, o.last))
                thumbnails.emplace_back(i, colorThumbnail(srgb8Pixels(frame), frame.width, frame.height));
            // The sequence's first frame counts as disoccluded everywhere.
            age = i > first ? disocclusionAge(match, age, now.world.size()) : std::vector<uint16_t>(now.world.size(), 0);
            std::vector<float> reference;
            const bool referenceFrame = (i - first) % o.referenceEvery < 2;
            const bool editWindow = std::any_of(events.begin(), events.end(),
                                                [&](const EditEvent& e) { return i - e.frame < kEditWindow; });
            // The surface points only on frames that trace.
            const AoPoints points = referenceFrame || editWindow ? aoPoints(world, posed, frame, camera, now) : AoPoints{};
            for (EditEvent& e : events) {
                if (i - e.frame >= kEditWindow) continue;
                // Only the pixels near the edit: the pre- and post-edit references differ nowhere else.
                const std::vector<uint8_t> near = nearBox(now, e.box, ao.estimator.radius);
                const auto pre = referenceAt(e.beforeBricks, e.before, posed, points, near.size(), ao.estimator.radius, o.spp, rays, near);
                const auto post = referenceAt(live.bricks(), world, posed, points, near.size(), ao.estimator.radius, o.spp, rays, near);
                e.frames.push_back(editFrame(i, i - e.frame, now.temporal, historyAt(frame, now), pre, post, near,
                                             existedBefore(e.before, points, near)));
            }
            if (referenceFrame) {
                reference = referenceAt(live.bricks(), world, posed, points, now.world.size(), ao.estimator.radius,
                                        o.spp, rays);
                errors.push_back({{"frame", i},
                                  {"spatial", errorJson(now.spatial, reference, now.surface)},
                                  {"temporal", errorJson(now.temporal, reference, now.surface)}});
                referencePixels += size_t(std::count_if(now.surface.begin(), now.surface.end(), [](uint8_t v) { return v != 0; }));
                if (!beforeReference.empty() && i > first)
                    flickerReference.add(flicker(reference, beforeReference, match));
                for (size_t p = 0; p < age.size(); ++p)
                    if (now.surface[p]) {
                        auto& bin = ghosting[std::min<int>(age[p], kGhostAgeCap)];
                        bin.first.add(std::abs(now.temporal[p] - reference[p]));
                        bin.second.add(std::abs(now.spatial[p] - reference[p]));
                    }
            }
            const bool traced = !reference.empty();
            beforeReference = std::move(reference);
            before = std::move(now);
            beforeCamera = camera;
            beforePoses = poses;
            if (progress) progress->step("frame " + std::to_string(i) + (traced ? " + reference" : ""));
        }
        if (progress) progress->finish();
        chainMs = costs.chainMs();
        temporalMs = costs.temporalMs();
    }
    json cost = json::object();
    for (const auto& [name, ms] : passMs) cost[name] = median(ms);
    cost["frame_wall"] = median(wallMs);
    // Wall-time differences against the same frames without AO and without the
    // temporal pass: the reliable figures where timestamps miss passes (lavapipe).
    // Below their noise they read 0, with the noise beside them (app/cost_difference.h).
    const CostDifference chain = costDifference(chainMs), temporalPass = costDifference(temporalMs);
    cost["ao_chain_wall"] = chain.ms;
    cost["ao_chain_wall_noise"] = chain.noiseMs;
    if (!temporalMs.empty()) cost["temporal_wall"] = temporalPass.ms, cost["temporal_wall_noise"] = temporalPass.noiseMs;
    // The cumulative curve (docs/metrics.md): error over the pixels disoccluded within the last k
    // frames (age <= k), cumulative over the exact ages below the cap; and the
    // error at each age on its own (the last bin: kGhostAgeCap and older).
    json byAge = json::array(), within = json::array();
    Mean temporalWithin, spatialWithin;
    for (const auto& [k, bins] : ghosting) {
        byAge.push_back({{"frames_since_disocclusion", k}, {"pixels", bins.first.n},
                         {"mae_temporal", bins.first.value()}, {"mae_spatial", bins.second.value()}});
        if (k >= kGhostAgeCap) continue;
        temporalWithin.sum += bins.first.sum, temporalWithin.n += bins.first.n;
        spatialWithin.sum += bins.second.sum, spatialWithin.n += bins.second.n;
        within.push_back({{"disoccluded_within_frames", k}, {"pixels", temporalWithin.n},
                          {"mae_temporal", temporalWithin.value()}, {"mae_spatial", spatialWithin.value()}});
    }
    const json ghostCurve = {{"within", within}, {"by_age", byAge}};
    // Steady state: the frames after the history could fill (all frames when
    // the path is shorter than that). A shorter history, or none, starts no
    // earlier than the default one would, so a spatial-only run of the same path
    // is averaged over the same frames.
    int steadyFrom = first + int(std::max(ao.chain.temporalHistory, kDefaultTemporalHistory));
    if (errors.empty() || errors.back()["frame"].get<int>() < steadyFrom) steadyFrom = first;
    size_t steadyFrames = 0;
    for (const json& e : errors) steadyFrames += e["frame"].get<int>() >= steadyFrom;
    auto meanError = [&](const char* which, const char* metric) {
        Mean m;
        for (const json& e : errors)
            if (e["frame"].get<int>() >= steadyFrom && e[which].contains(metric))
                m.add(e[which][metric].get<double>());
        return m.value();
    };
    json steady = json::object();
    for (const char* which : {"spatial", "temporal"})
        for (const char* metric : {"mae", "rmse", "psnr", "bias"})
            steady[which][metric] = meanError(which, metric);
    StabilityFigures f;
    f.matchedPixels = matchedPixels;
    f.referencePixels = referencePixels;
    f.figures = {{"reference", {{"frames", errors.size()}, {"rays", rays}}},
                 {"flicker", {{"raw", flickerRaw.value()}, {"spatial", flickerSpatial.value()},
                              {"temporal", flickerTemporal.value()}, {"reference", flickerReference.value()}}},
                 {"color", {{"flicker", flickerColor.value()}, {"thumbnails", thumbnailsJson(thumbnails)}}},
                 {"error_mean", steady}, {"error_mean_from_frame", steadyFrom}, {"error", errors},
                 {"ghosting", ghostCurve}, {"cost_ms", cost}};
    if (o.pathHasDay) f.figures["color"]["flicker_light_held"] = flickerHeld.value();
    if (o.sun) {
        const double share = sunAll.surface ? 1.0 - double(sunAll.off) / double(sunAll.surface) : 1.0;
        f.figures["sun"] = {{"surface_pixels", sunAll.surface}, {"facing_pixels", sunAll.facing},
                            {"off_pixels", sunAll.off}, {"share_exact", share}, {"worst_frame", sunWorst},
                            {"aov_off_pixels", sunAll.aovOff}};
    }
    if (o.pathHasEdits) {
        // The worst over the run's edits; a run whose windows were cut short has no recovery figure.
        double staleMax = 0.0;
        int recoveryMax = 0;
        bool recoveryMeasured = false;
        f.figures["edits"] = editsJson(events, staleMax, recoveryMax, recoveryMeasured);
        f.figures["edit_recovery"] = {{"stale_after_edit_frame", staleMax},
                                      {"recovered_within_frames", recoveryMeasured ? json(recoveryMax) : json()}};
    }
    f.steadyFrom = steadyFrom;
    f.steadyFrames = steadyFrames;
    f.edits = events.size();
    f.frameWallMs = median(wallMs);
    f.chain = chain;
    if (!temporalMs.empty()) f.temporal = temporalPass;
    return f;
}

}  // namespace grotto::app
