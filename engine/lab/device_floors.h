#pragma once
// What this device can do at best, for setting each pass's time against: the
// bandwidth of a plain copy kernel (its reads and writes) and the rate of a
// kernel of nothing but independent multiply-adds. `grotto bench --floors`
// divides each pass's declared image bytes (engine/frame/pass_traffic.h) by the
// bandwidth to give the pass's floor.
#include "engine/vk/context.h"

namespace grotto {

struct DeviceFloors {
    double copyBytesPerMs = 0.0;  // bytes read plus bytes written, a millisecond
    double fmaPerMs = 0.0;        // float multiply-adds (one a lane), a millisecond
};

// Best of a few timed runs of each kernel (GPU timestamps around several
// dispatches), the copy over `copyMiB` (far past any cache at the default; the
// tests take less) and the multiply-adds over 4096 threads a MiB of it.
// Throws grotto::Error (internal) when the copy did not copy.
DeviceFloors measureDeviceFloors(vk::Context& ctx, uint32_t copyMiB = 64);

}  // namespace grotto
