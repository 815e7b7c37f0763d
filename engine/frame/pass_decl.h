#pragma once
// What a pass declares: the render targets it reads and writes, how, and the name
// its GPU time is reported under. The renderer derives every layout transition and
// barrier between passes from these (FrameTargets::recordBarriers); the targets
// themselves are declared in frame_targets.cpp.
#include <cstdint>
#include <vector>

namespace grotto {

enum class TargetId {
    Depth, Surface, Motion, Color, Display, Normals, Shadow, ShadowHistory, ObjectLight, ObjectLightHistory,
    AoDepthAtlas, AoThickness, AoBentNormal, AoRaw, AoSpatial0, AoSpatial1, AoHistory, AoFull, CacheLight, AtlasRecord,
};
inline constexpr int kTargetCount = int(TargetId::AtlasRecord) + 1;

// Which image of a history (a target with two copies): the one this frame writes,
// or the one the frame before wrote. The targets flip them at each frame's start
// (FrameTargets::advanceHistories); a target of one copy has only Current.
enum class Copy : uint8_t { Current, Previous };

// One image of a target.
struct TargetRef {
    TargetId id;
    Copy copy = Copy::Current;
    constexpr TargetRef(TargetId target, Copy which = Copy::Current) : id(target), copy(which) {}
};

// The AO after `passes` spatial denoise passes: the raw AO when there are none,
// else the denoiser's ping-pong image the last pass wrote (AoTargets::denoised).
constexpr TargetRef denoisedTarget(uint32_t passes) {
    return passes == 0 ? TargetId::AoRaw : (passes - 1) % 2 == 0 ? TargetId::AoSpatial0 : TargetId::AoSpatial1;
}

enum class Access : uint8_t {
    Read,             // a compute shader reads it in GENERAL (as a storage image)
    Sampled,          // a compute shader samples it in SHADER_READ_ONLY_OPTIMAL (the G-buffer, once drawn)
    Write,            // a compute shader writes it in GENERAL
    DepthAttachment,  // a draw tests and writes it as its depth attachment
    ColorAttachment,  // a draw writes it as a colour attachment
};

struct TargetUse {
    TargetRef target;
    Access access;
};

struct PassDecl {
    // Its entry in FrameStats::passMs: stability's cost_ms keys and bench's
    // pass_ms_median read these names. Null for work that is not timed on its own.
    const char* timestamp;
    std::vector<TargetUse> uses;
};

}  // namespace grotto
