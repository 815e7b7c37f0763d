#pragma once
// The least memory a pass can move: each image it declares (pass_decl.h) read
// once and written once, whole. A depth attachment counts both (the draw tests
// and writes it). Buffers (the scene, the face cache) are not declared, so a
// pass that reads them moves more: this is the floor of its image traffic.
#include "engine/frame/frame_targets.h"
#include "engine/frame/pass_decl.h"

#include <cstdint>

namespace grotto {

uint64_t declaredImageBytes(const PassDecl& decl, const FrameTargets& targets);

}  // namespace grotto
