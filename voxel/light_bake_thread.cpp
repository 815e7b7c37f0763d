#include "voxel/light_bake_thread.h"

#include "grotto/error.h"
#include "voxel/brick_table.h"
#include "voxel/light_bake.h"

#include <algorithm>
#include <utility>

namespace grotto::voxel {
namespace {
struct Stopped {};  // thrown from a progress call to leave the bake early
}  // namespace

LightBakeThread::LightBakeThread(const World& world, const FaceBakeSettings& settings) {
    if (!settings.fullLight) throw Error::internal("LightBakeThread", "settings without full light");
    thread_ = std::thread(&LightBakeThread::run, this, World(world), settings);
}

LightBakeThread::~LightBakeThread() {
    stop_.store(true, std::memory_order_relaxed);
    if (thread_.joinable()) thread_.join();
}

void LightBakeThread::wait() {
    if (thread_.joinable()) thread_.join();
}

BakedLight LightBakeThread::take() {
    wait();
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
    return std::move(result_);
}

void LightBakeThread::run(World world, FaceBakeSettings settings) {
    try {
        const BrickTable table(world);
        BakedLight baked;
        baked.faces = exposedFaces(table, world);
        const uint32_t k = settings.texelsPerSide;
        const LightBakeSettings light;
        const LightSources lights = lightSources(world.desc().lighting);
        requireLightBakeFits(world, baked.faces.size(), k, light, lights.day.has_value());
        baked.texels.resize(baked.faces.size() * k * k);
        if (lights.day) baked.dayLight.resize(baked.faces.size() * kDayLightWords);
        auto share = [&](double from, size_t done, size_t total) {
            if (stop_.load(std::memory_order_relaxed)) throw Stopped{};
            done_.store(from + 0.5 * double(done) / double(std::max<size_t>(total, 1)), std::memory_order_relaxed);
        };
        bakeFacesInSteps(table, world, baked.faces, settings, baked.texels,
                         [&](size_t done, size_t total) { share(0.0, done, total); });
        bakeLight(table, world, baked.faces, k, lights, light, baked.texels,
                  [&](size_t done, size_t total) { share(0.5, done, total); }, baked.dayLight);
        baked.glowing = glowingFaces(world, baked.faces);
        result_ = std::move(baked);
        done_.store(1.0, std::memory_order_relaxed);
    } catch (const Stopped&) {
    } catch (...) {
        error_ = std::current_exception();
    }
    finished_.store(true, std::memory_order_release);
}

}  // namespace grotto::voxel
