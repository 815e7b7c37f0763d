#pragma once
// What an edit leaves behind in the AO (docs/metrics.md), at AO resolution. For
// each frame from the one an edit is applied before, over the surface pixels
// within R (the AO radius) of the box the edit changed:
//   error: MAE against the reference traced on the world as edited (post-edit);
//   stale: the share of those pixels closer to the reference traced on the world
//          before the edit (pre-edit) than to the post-edit one by more than
//          kStaleMargin: pixels still showing the AO of a world that is gone.
//          Only surfaces that existed before the edit count: one the edit
//          uncovered (the sides of a dug hole) had no AO before it. And only
//          pixels whose temporal history reaches back before the edit (more
//          frames of history than have passed since it): one whose history
//          restarted holds nothing of the old world, and where it still leans
//          to the pre-edit reference, the estimator itself errs (the error
//          figure shows that). `closerToPre` is the share of old surfaces closer
//          to the pre-edit reference whatever the cause.
// Recovery: the steady-state error is the mean over frames kEditSteadyFrom ..
// kEditWindow - 1 after the edit (the history has refilled by then); the edit has
// recovered at the first frame whose error is within kEditRecoveryFactor of it.
#include "engine/lab/temporal_metrics.h"
#include "voxel/edit.h"

#include <optional>
#include <vector>

namespace grotto {

inline constexpr double kStaleMargin = 0.05;
inline constexpr int kEditSteadyFrom = 16, kEditWindow = 24;
inline constexpr double kEditRecoveryFactor = 1.2;
inline constexpr int kEditRecoveryTarget = 8;  // frames: what the shipped edit paths are held to

// 1 for surface pixels whose point lies within `radius` of the box (0 inside it).
std::vector<uint8_t> nearBox(const AoFrame& frame, const voxel::WorldBox& box, double radius);

struct EditFrame {
    int frame = 0;           // the frame's number in the run
    size_t pixels = 0;       // within R of the edit
    size_t oldSurfaces = 0;  // of those, on surfaces that existed before the edit
    double mae = 0.0;        // over `pixels`
    double stale = 0.0;        // share of `oldSurfaces`
    double closerToPre = 0.0;  // share of `oldSurfaces`, history or not
};

// `ao` (temporal), `history` (its frames of history), `pre` and `post` hold a value
// per AO pixel; pixels set in `near` count for the error, those also set in
// `existed` for stale. `sinceEdit`: frames since the edit's frame (0 on it).
EditFrame editFrame(int frame, int sinceEdit, const std::vector<float>& ao, const std::vector<float>& history,
                    const std::vector<float>& pre, const std::vector<float>& post, const std::vector<uint8_t>& near,
                    const std::vector<uint8_t>& existed);

struct EditRecovery {
    std::optional<double> steadyMae;     // unset when the window was cut short
    std::optional<int> recoveredWithin;  // frames after the edit's frame; unset without a steady state
    double staleAfter = 0.0;             // the largest stale share from the frame after the edit's on
};

// `frames` in order, the first being the edit's own frame `editFrame`.
EditRecovery editRecovery(const std::vector<EditFrame>& frames, int editFrame);

}  // namespace grotto
