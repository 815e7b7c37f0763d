#pragma once
// The measuring part of `grotto stability`: plays the session's path over a range
// of frames and measures the temporal metrics (docs/metrics.md) at AO resolution.
#include "app/cost_difference.h"
#include "engine/session.h"

#include <nlohmann/json.hpp>

#include <optional>

namespace grotto::app {

struct StabilityRunOptions {
    int first = 1, last = 2;  // the path's frames measured, 1-based
    int fps = 24;             // frame i shows the path at (i - 1) / fps seconds
    int spp = 256;            // reference rays per pixel
    int referenceEvery = 4;   // a pair of consecutive frames traced every K frames
    uint32_t width = 0, height = 0;
    bool pathHasEdits = false;  // report the edits' figures (empty when none fell in the range)
    // The path keys the time of day: the colour's flicker is also measured with
    // the light held (each frame rendered again under the frame before's light),
    // which leaves out the change the light itself makes.
    bool pathHasDay = false;
    bool sun = false;           // the sun each frame shows against exact rays (engine/lab/sun_agreement.h)
    bool quiet = false;         // no progress lines
};

struct StabilityFigures {
    // "reference" (frames, rays), "flicker", "color", "error_mean",
    // "error_mean_from_frame", "error", "ghosting", "cost_ms", for a path with
    // edits "edits" and "edit_recovery", and with the sun measured "sun": the
    // run's JSON beside its settings.
    nlohmann::json figures;
    size_t matchedPixels = 0, referencePixels = 0;  // what the flicker and error figures were measured over
    int steadyFrom = 0;                             // the first frame of the steady-state error means
    size_t steadyFrames = 0;                        // reference frames from there on
    size_t edits = 0;                               // edit events measured
    double frameWallMs = 0.0;                       // median
    CostDifference chain;                           // the AO chain's wall time
    std::optional<CostDifference> temporal;         // the temporal pass's, when it runs
};

// The session plays its path (RenderSession::playPath), started at `first`'s time.
StabilityFigures runStability(vk::Context& ctx, RenderSession& session, const AoOptions& ao,
                              const StabilityRunOptions& options);

}  // namespace grotto::app
