#include "engine/lab/edit_metrics.h"

#include <algorithm>
#include <cmath>

namespace grotto {

std::vector<uint8_t> nearBox(const AoFrame& frame, const voxel::WorldBox& box, double radius) {
    std::vector<uint8_t> near(frame.world.size(), 0);
    if (box.empty()) return near;
    for (size_t p = 0; p < near.size(); ++p) {
        if (!frame.surface[p]) continue;
        const glm::dvec3 outside = glm::max(glm::max(box.min - frame.world[p], frame.world[p] - box.max), glm::dvec3(0.0));
        near[p] = glm::dot(outside, outside) <= radius * radius;
    }
    return near;
}

EditFrame editFrame(int frame, int sinceEdit, const std::vector<float>& ao, const std::vector<float>& history,
                    const std::vector<float>& pre, const std::vector<float>& post, const std::vector<uint8_t>& near,
                    const std::vector<uint8_t>& existed) {
    EditFrame f{.frame = frame};
    double error = 0.0;
    size_t stale = 0, closer = 0;
    for (size_t p = 0; p < near.size(); ++p) {
        if (!near[p]) continue;
        ++f.pixels;
        error += std::abs(double(ao[p]) - post[p]);
        if (!existed[p]) continue;
        ++f.oldSurfaces;
        const bool leans = std::abs(double(ao[p]) - pre[p]) + kStaleMargin < std::abs(double(ao[p]) - post[p]);
        closer += leans;
        // A history restarted on the edit's frame holds at most sinceEdit + 1 frames
        // (bilinear reprojection averages lengths: half a frame for rounding).
        stale += leans && history[p] > float(sinceEdit) + 1.5f;
    }
    if (f.pixels) f.mae = error / double(f.pixels);
    if (f.oldSurfaces) f.stale = double(stale) / double(f.oldSurfaces), f.closerToPre = double(closer) / double(f.oldSurfaces);
    return f;
}

EditRecovery editRecovery(const std::vector<EditFrame>& frames, int editFrame) {
    EditRecovery r;
    double sum = 0.0;
    int counted = 0;
    for (const EditFrame& f : frames) {
        const int after = f.frame - editFrame;
        if (after > 0) r.staleAfter = std::max(r.staleAfter, f.stale);
        if (after >= kEditSteadyFrom && after < kEditWindow && f.pixels) sum += f.mae, ++counted;
    }
    if (counted < kEditWindow - kEditSteadyFrom) return r;
    r.steadyMae = sum / counted;
    for (const EditFrame& f : frames)
        if (f.pixels && f.mae <= kEditRecoveryFactor * *r.steadyMae) {
            r.recoveredWithin = f.frame - editFrame;
            break;
        }
    return r;
}

}  // namespace grotto
