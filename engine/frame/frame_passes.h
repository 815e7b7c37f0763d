#pragma once
// Every pass a frame may have, registered once: the pass set makes, drops and
// remakes them as the frame plan says (pass_set.h). The order is the order they
// are made in, not the frame's (that is Renderer::recordFrame).
#include "engine/frame/pass_set.h"
#include "engine/passes/composite_pass.h"
#include "engine/passes/denoise_pass.h"
#include "engine/passes/depth_prefilter_pass.h"
#include "engine/passes/display_pass.h"
#include "engine/passes/estimator_pass.h"
#include "engine/passes/face_cache_aov_pass.h"
#include "engine/passes/face_cache_trace_pass.h"
#include "engine/passes/gbuffer_pass.h"
#include "engine/passes/hiz_pass.h"
#include "engine/passes/normals_pass.h"
#include "engine/passes/object_light_pass.h"
#include "engine/passes/shadow_edge_pass.h"
#include "engine/passes/shadow_pass.h"
#include "engine/passes/temporal_pass.h"
#include "engine/passes/upsample_pass.h"

namespace grotto {

using FramePasses =
    PassSet<GBufferPass, HizPass, CompositePass, AskingCompositePass, DisplayPass, NormalsPass, ShadowPass,
            ObjectLightPass, FaceCacheTracePass, DepthPrefilterPass, EstimatorPass, BentNormalsPass, DenoisePass,
            UpsamplePass, TemporalPass, FaceCacheAovPass, ShadowEdgePass>;

}  // namespace grotto
