// --ao cache in the renderer (composite_cache.comp, face_cache_aov.comp), with
// validation on:
//  - every pixel of a world far from the origin reads the cache at its own exact
//    surface point: the AO and sun AOVs equal the CPU's FaceCacheLookup there;
//  - with the sky's ambient, a closed room gets no light at all, a room with a
//    window some, and open ground the sky's light; today's screen-space AO lights
//    the closed room like the ground;
//  - the shipped houses world: its closed room is dark, and its door object,
//    shut, keeps the sun and the sky out of its room (the objects' shadow and
//    light over the cache's);
//  - with full light, a lamp taken out of a sealed room leaves it black in the
//    very next frame, and put back lights it as before;
//  - without a bake, full light is baked on a thread of its own, and once taken
//    holds the edits made meanwhile as a bake of the edited world does;
//  - the light AOV is the light each pixel was lit with: albedo x (sun + light)
//    is the frame's colour.
#include "engine/lab/surface_points.h"
#include "voxel/path_trace.h"
#include "engine/renderer.h"
#include "engine/scene/live_scene.h"
#include "engine/session.h"
#include "tests/dense_world.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"
#include "tests/test_util.h"
#include "voxel/face_cache_layout.h"
#include "voxel/face_cache_lookup.h"

#include <cmath>

namespace grotto {
namespace {

using FaceCacheRender = test::GpuTest;

AoOptions cacheAo(const voxel::World& world, double radius) {
    AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), "test");
    ao.method = AoMethod::Cache;
    ao.estimator.radius = float(radius);
    return ao;
}

TEST_F(FaceCacheRender, EveryPixelReadsTheCacheAtItsOwnPoint) {
    // A floor with pillars and a roof over part of it, half-voxel cells, far from the origin.
    const voxel::World world = test::makeVoxelWorld(
        {-6, 0, -6}, {17, 9, 17},
        [](int x, int y, int z) { return y == 0 || ((x + 8) % 5 == 1 && (z + 8) % 4 == 1) || (y == 6 && x < 4); }, 0.5,
        glm::dvec3(-3000.25, 7.0, 1234.0));
    LiveScene scene(ctx(), voxel::World(world));
    voxel::FaceBakeSettings settings = worldBakeSettings(world, 1.5, 3);
    settings.rays = 16, settings.sunRays = 2;
    scene.bakeFaceCache(settings);
    voxel::Lighting lighting = world.desc().lighting;
    lighting.ambientFrom = voxel::AmbientSource::Sky;
    Renderer renderer(ctx(), scene.gpu(), lighting, cacheAo(world, 1.5), 96, 72);
    const glm::dvec3 o = world.origin();
    const Camera camera =
        makeCamera(test::lookAt(o + glm::dvec3(-2.0, 7.5, -3.0), o + glm::dvec3(6.0, 0.0, 5.0), 70.0), 96, 72);
    renderer.render(camera);
    const FrameImages f = renderer.readback(camera, true);

    const LiveFaceCache& cache = *scene.faceCache();
    const voxel::FaceCacheLookup lookup(cache.faces(), cache.texels(), 3);
    const SurfacePoints sp = surfacePoints(f, camera, world.voxelSize(), o);
    ASSERT_GT(sp.points.size(), f.ao.size() / 2);
    size_t off = 0, occluded = 0, shadowed = 0;
    for (size_t i = 0; i < sp.points.size(); ++i) {
        const glm::dvec3 n = sp.normals[i];
        const int axis = std::abs(n.x) > 0.5 ? 0 : std::abs(n.y) > 0.5 ? 1 : 2;
        const uint8_t dir = uint8_t(2 * axis + (n[axis] < 0.0 ? 1 : 0));
        const voxel::CachedLight c = lookup.at((sp.points[i] - o) / world.voxelSize(), dir);
        ASSERT_GT(c.samples, 0u) << "pixel " << sp.pixels[i] << ": a face the cache lacks";
        const uint32_t p = sp.pixels[i];
        // The texels' packed steps (AO 8 bits, sun 5).
        if (std::abs(f.ao[p] - c.ao) > 0.6 * voxel::kFaceTexelStep[0] + 1e-4 ||
            std::abs(f.shadow[p] - c.sun) > 0.6 * voxel::kFaceTexelStep[1] + 1e-4)
            ++off;
        occluded += c.ao < 0.8;
        shadowed += c.sun < 0.5;
    }
    // Pixels on a face's very edge may take the neighbour's plane in one and not the other.
    EXPECT_LE(off, sp.points.size() / 200) << off << " of " << sp.points.size() << " pixels read other light";
    EXPECT_GT(occluded, sp.points.size() / 20);
    EXPECT_GT(shadowed, sp.points.size() / 20);
}

// Ground, a closed house and a house with a window toward the sky, seen from
// inside each and from outside: the mean colour of what each camera sees.
TEST_F(FaceCacheRender, AClosedRoomGetsNoSkyAndARoomWithAWindowSome) {
    auto house = [](int x, int y, int z, int x0, bool window) {
        const bool in = x >= x0 && x <= x0 + 8 && y >= 1 && y <= 7 && z >= 0 && z <= 8;
        const bool inside = x > x0 && x < x0 + 8 && y > 1 && y < 7 && z > 0 && z < 8;
        const bool hole = window && y == 7 && x >= x0 + 3 && x <= x0 + 5 && z >= 3 && z <= 5;
        return in && !inside && !hole;
    };
    const voxel::World world = test::makeVoxelWorld({-10, 0, -10}, {40, 8, 20}, [&](int x, int y, int z) {
        return y == 0 || house(x, y, z, 0, false) || house(x, y, z, 16, true);
    });
    LiveScene scene(ctx(), voxel::World(world));
    voxel::FaceBakeSettings settings = worldBakeSettings(world, 4.0, 2);
    settings.rays = 64;
    scene.bakeFaceCache(settings);
    voxel::Lighting lighting = world.desc().lighting;
    lighting.ambientFrom = voxel::AmbientSource::Sky;
    const glm::dvec3 o = world.origin();
    auto meanColour = [&](const AoOptions& ao, glm::dvec3 eye, glm::dvec3 target) {
        Renderer renderer(ctx(), scene.gpu(), lighting, ao, 48, 36);
        const Camera camera = makeCamera(test::lookAt(o + eye, o + target, 80.0), 48, 36);
        renderer.render(camera);
        const FrameImages f = renderer.readback(camera, false);
        double sum = 0.0;
        for (size_t i = 0; i < f.color.size(); i += 4) sum += f.color[i] + f.color[i + 1] + f.color[i + 2];
        return sum / double(f.color.size() / 4);
    };
    AoOptions gtao = aoOptionsFor(world.desc().ao, 1.0, "test");
    const AoOptions cache = cacheAo(world, 4.0);
    // Looking down at open ground, at the floor of each room from under its ceiling.
    const double ground = meanColour(cache, {30.0, 12.0, 14.0}, {30.5, 0.0, 16.0});
    const double closed = meanColour(cache, {4.5, 6.0, 4.5}, {4.6, 1.0, 4.0});
    const double window = meanColour(cache, {20.5, 6.0, 4.5}, {20.6, 1.0, 4.0});
    const double closedGtao = meanColour(gtao, {4.5, 6.0, 4.5}, {4.6, 1.0, 4.0});
    EXPECT_GT(ground, 0.2);
    EXPECT_EQ(closed, 0.0);  // no ray leaves the room: no sky, no sun
    EXPECT_GT(window, 0.02 * ground);
    EXPECT_LT(window, 0.6 * ground);
    EXPECT_GT(closedGtao, 0.2 * ground);  // screen-space AO: lit like outdoors
}

TEST_F(FaceCacheRender, TheHousesWorldsClosedRoomIsDarkAndItsDoorKeepsTheSunAndSkyOut) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "houses.json");
    AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), "houses.json");
    ASSERT_EQ(ao.method, AoMethod::Cache) << "the world asks for the cache";
    const uint32_t w = 64, h = 48;
    RenderSession session(ctx(), voxel::World(world), ao, voxel::Detail{}, w, h);
    session.bakeFaceCache();
    // Frames enough for the objects' light (the door's) to converge.
    auto view = [&](const std::string& name, double time) {
        session.setTime(time);
        const Camera camera = makeCamera(world.camera(name, double(w) / h), w, h);
        for (uint32_t i = 0; i < 8; ++i) session.renderer().render(camera, i);
        return session.renderer().readback(camera, true);
    };
    auto meanColour = [](const FrameImages& f) {
        double sum = 0.0;
        for (size_t i = 0; i < f.color.size(); i += 4) sum += f.color[i] + f.color[i + 1] + f.color[i + 2];
        return sum / double(f.color.size() / 4);
    };
    auto sunlitWorldPixels = [](const FrameImages& f) {
        size_t n = 0;
        for (size_t i = 0; i < f.shadow.size(); ++i) n += f.surfaceIds[i] != 0 && gpu::surfaceObject(f.surfaceIds[i]) == 0 && f.shadow[i] > 0.5f;
        return n;
    };
    // The ambient light alone: no sun.
    voxel::Lighting lighting = world.desc().lighting;
    lighting.sunIntensity = 0.0f;
    session.setLighting(lighting);
    const double ground = meanColour(view("ground", 0.0)), closed = meanColour(view("closed", 0.0)),
                 window = meanColour(view("window", 0.0));
    EXPECT_GT(ground, 0.2);
    EXPECT_LT(closed, 0.05 * ground);
    EXPECT_GT(window, closed + 0.01 * ground) << "sky through the window";  // 2.3% measured: a dark room, one window
    // The door's room: the shut door keeps the sky out as a wall would; open, the sky comes in.
    const double doorShut = meanColour(view("door", 0.0)), doorOpen = meanColour(view("door", 1.5));
    EXPECT_LT(doorShut, 0.05 * ground);
    EXPECT_GT(doorOpen, doorShut + 0.01 * ground);
    // The sun on the floor inside the door's room: none with the door shut (time 0),
    // a patch through the doorway with it open (time 1.5).
    session.setLighting(world.desc().lighting);
    const size_t shut = sunlitWorldPixels(view("door", 0.0)), open = sunlitWorldPixels(view("door", 1.5));
    EXPECT_EQ(shut, 0u) << "the door casts the sun's shadow over the cached sun";
    EXPECT_GT(open, size_t(w * h / 200)) << "the sun through the open doorway";
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

TEST_F(FaceCacheRender, TheCachesOwnLightWordsDecideHowTheyAreRead) {
    // The same pillars baked with sky light and with full light. Over the sky
    // light's cache a frame asked for full light keeps the sky's light (there is
    // no full light to read); over the full light's cache a frame asked for the
    // sky shows that light (there are no sky weights). Neither reads one kind of
    // light word as the other, which would paint garbage.
    const voxel::World world = test::makeVoxelWorld(
        {0, 0, 0}, {16, 6, 16}, [](int x, int y, int z) { return y == 0 || (x % 5 == 1 && z % 4 == 1); }, 1.0,
        glm::dvec3(0.0));
    const Camera camera = makeCamera(test::lookAt({-2.0, 6.0, -3.0}, {8.0, 0.0, 8.0}, 70.0), 48, 32);
    auto render = [&](LiveScene& scene, voxel::AmbientSource from) {
        voxel::Lighting lighting = world.desc().lighting;
        lighting.ambientFrom = from;
        Renderer renderer(ctx(), scene.gpu(), lighting, cacheAo(world, 1.5), 48, 32);
        renderer.render(camera);
        return renderer.readback(camera, false).color;
    };
    auto mean = [](const std::vector<float>& c) {
        double sum = 0.0;
        for (size_t i = 0; i < c.size(); i += 4) sum += c[i] + c[i + 1] + c[i + 2];
        return sum / double(c.size());
    };
    voxel::FaceBakeSettings settings = worldBakeSettings(world, 1.5, 2);
    settings.rays = 16, settings.sunRays = 1;
    LiveScene sky(ctx(), voxel::World(world));
    sky.bakeFaceCache(settings);
    const std::vector<float> skyLight = render(sky, voxel::AmbientSource::Sky);
    EXPECT_EQ(render(sky, voxel::AmbientSource::Full), skyLight);
    settings.fullLight = true;
    LiveScene full(ctx(), voxel::World(world));
    full.bakeFaceCache(settings);
    const std::vector<float> fullLight = render(full, voxel::AmbientSource::Full);
    EXPECT_EQ(render(full, voxel::AmbientSource::Sky), fullLight);
    // Full light adds the light bounced off the sunlit floor and pillars.
    EXPECT_GT(mean(fullLight), 1.02 * mean(skyLight));
    EXPECT_LT(mean(fullLight), 2.0 * mean(skyLight));
}

// A sealed room 16 x 8 x 12 of albedo 0.6 (material 1) with one lamp (material 2),
// seen from inside, and the settings its full light is baked with.
const glm::ivec3 kRoomSize(16, 8, 12), kLamp(5, 3, 6);
voxel::World sealedLampRoom() {
    voxel::Material wall, glow;
    wall.albedo = glm::vec3(0.6f);
    glow.albedo = glm::vec3(0.8f), glow.emissionColor = glm::vec3(1.0f, 0.7f, 0.4f), glow.emissionIntensity = 6.0f;
    return voxel::test::denseWorld(kRoomSize, {wall, glow}, [&](int x, int y, int z) {
        if (glm::ivec3(x, y, z) == kLamp) return 2;
        const glm::ivec3 last = kRoomSize - 1;
        return x == 0 || y == 0 || z == 0 || x == last.x || y == last.y || z == last.z ? 1 : 0;
    });
}
voxel::FaceBakeSettings roomLightSettings(const voxel::World& world) {
    voxel::FaceBakeSettings settings = worldBakeSettings(world, 1.5, 2);
    settings.rays = 32, settings.fullLight = true;
    return settings;
}
const Camera kInRoom = makeCamera(test::lookAt({13.5, 6.0, 2.5}, {5.0, 2.0, 7.0}, 80.0), 48, 32);

// The room's frame with full light: its mean colour.
struct RoomFrame {
    Renderer renderer;
    RoomFrame(vk::Context& ctx, LiveScene& scene)
        : renderer(ctx, scene.gpu(), fullLight(scene.world()), cacheAo(scene.world(), 1.5), 48, 32) {}
    static voxel::Lighting fullLight(const voxel::World& world) {
        voxel::Lighting lighting = world.desc().lighting;
        lighting.ambientFrom = voxel::AmbientSource::Full;
        return lighting;
    }
    double operator()() {
        renderer.render(kInRoom);
        const std::vector<float> c = renderer.readback(kInRoom, false).color;
        double sum = 0.0;
        for (size_t i = 0; i < c.size(); i += 4) sum += c[i] + c[i + 1] + c[i + 2];
        return sum / double(c.size() / 4);
    }
};

TEST_F(FaceCacheRender, ALampTakenOutOfASealedRoomLeavesItBlackInTheNextFrame) {
    const voxel::World world = sealedLampRoom();
    LiveScene scene(ctx(), voxel::World(world));
    scene.bakeFaceCache(roomLightSettings(world));
    RoomFrame frame(ctx(), scene);
    const glm::ivec3 lamp = kLamp;
    const double lit = frame();
    EXPECT_GT(lit, 0.1);
    scene.apply(voxel::Edit::carveBox({lamp, lamp}));
    EXPECT_EQ(frame(), 0.0);  // no light left behind, nor any from the sky or sun
    scene.apply(voxel::Edit::fillBox({lamp, lamp}, 2));
    EXPECT_NEAR(frame(), lit, 0.02 * lit);  // lit again at once, as baked
}

// Without a bake, full light starts as the GPU's tracer leaves it, the sky's light
// alone (black in a sealed room), while the world's light is baked on a thread
// of its own; taken between frames and brought up to the edits made meanwhile,
// it is the light a bake of the edited world holds.
TEST_F(FaceCacheRender, WithoutABakeFullLightIsBakedOnItsOwnThreadAndCatchesUpWithTheEditsMadeMeanwhile) {
    const voxel::World world = sealedLampRoom();
    const voxel::FaceBakeSettings settings = roomLightSettings(world);
    LiveScene scene(ctx(), voxel::World(world));
    scene.progressiveFaceCache(settings);
    ASSERT_TRUE(scene.faceCache()->lightPending());
    RoomFrame frame(ctx(), scene);
    const double unlit = frame();  // the lamp's own faces alone: the sky's light is none
    // A second lamp and a low wall, while the light is baking.
    const glm::ivec3 second(12, 5, 3);
    scene.apply(voxel::Edit::fillBox({second, second}, 2));
    scene.apply(voxel::Edit::fillBox({{8, 1, 1}, {8, 2, 10}}, 1));
    EXPECT_TRUE(scene.faceCache()->lightPending());
    scene.faceCache()->waitForLight();
    ASSERT_TRUE(scene.takeBakedLight());
    EXPECT_FALSE(scene.faceCache()->lightPending());
    EXPECT_EQ(scene.faceCache()->lightBaked(), 1.0);
    EXPECT_EQ(scene.faceCache()->unconverged(), 0u);

    LiveScene baked(ctx(), voxel::World(scene.world()));
    baked.bakeFaceCache(settings);
    const LiveFaceCache &live = *scene.faceCache(), &fresh = *baked.faceCache();
    ASSERT_TRUE(std::ranges::equal(live.faces(), fresh.faces()));
    auto light = [](const voxel::FaceTexel& t) { return double(t.light.r + t.light.g + t.light.b); };
    double mean = 0.0, worst = 0.0;
    for (const voxel::FaceTexel& t : fresh.texels()) mean += light(t) / double(fresh.texels().size());
    ASSERT_GT(mean, 0.0);
    for (size_t t = 0; t < fresh.texels().size(); ++t) {
        const double a = light(live.texels()[t]), b = light(fresh.texels()[t]);
        worst = std::max(worst, std::abs(a - b) / std::max(b, mean));
    }
    std::printf("[ measured ] worst texel off a fresh bake by %.4f of max(its light, the mean)\n", worst);
    EXPECT_LT(worst, 0.05);  // the edits' rule leaves up to 1/64 standing, and the bakes' noise differs (LightEdit)
    const double lit = frame();
    RoomFrame bakedFrame(ctx(), baked);
    EXPECT_NEAR(lit, bakedFrame(), 0.02 * lit);
    EXPECT_GT(lit, 0.1);
    std::printf("[ measured ] mean colour %.4f before the light was taken, %.4f after\n", unlit, lit);
    EXPECT_LT(unlit, 0.25 * lit);
}

TEST_F(FaceCacheRender, TheLightAovIsTheLightEachPixelWasLitWith) {
    const voxel::World world = test::makeVoxelWorld(
        {0, 0, 0}, {16, 6, 16}, [](int x, int y, int z) { return y == 0 || (x % 5 == 1 && z % 4 == 1); }, 1.0,
        glm::dvec3(0.0));
    voxel::FaceBakeSettings settings = worldBakeSettings(world, 1.5, 2);
    settings.rays = 16, settings.sunRays = 1, settings.fullLight = true;
    LiveScene scene(ctx(), voxel::World(world));
    scene.bakeFaceCache(settings);
    voxel::Lighting lighting = world.desc().lighting;
    lighting.ambientFrom = voxel::AmbientSource::Full;
    Renderer renderer(ctx(), scene.gpu(), lighting, cacheAo(world, 1.5), 48, 32);
    const Camera camera = makeCamera(test::lookAt({-2.0, 6.0, -3.0}, {8.0, 0.0, 8.0}, 70.0), 48, 32);
    renderer.render(camera);
    const FrameImages f = renderer.readback(camera, true);
    ASSERT_EQ(f.light.size(), 3 * f.depth.size());
    const voxel::LightSources lights = voxel::lightSources(lighting);
    // Where the cache's texels disagree about the sun, exact rays decide a pixel's
    // sun after the shadow AOV was read (docs/face-cache.md, "Shadow edges"): there
    // the colour less albedo x light leaves some share of the sun's light, not
    // necessarily the AOV's.
    size_t surfaces = 0, lit = 0, exact = 0;
    for (size_t i = 0; i < f.depth.size(); ++i) {
        if (!std::isfinite(f.depth[i])) continue;
        ++surfaces;
        const glm::dvec3 n(f.normal[3 * i], f.normal[3 * i + 1], f.normal[3 * i + 2]);
        const double cosSun = std::max(glm::dot(n, glm::normalize(lights.sunDirection)), 0.0);
        lit += f.light[3 * i + 1] > 0.0f;
        bool same = true;
        for (int c = 0; c < 3; ++c) {
            const double albedo = lighting.exposure * f.albedo[3 * i + c];
            const double want = albedo * (lights.sun[c] * cosSun * f.shadow[i] + f.light[3 * i + c]);
            same = same && std::abs(f.color[4 * i + c] - want) <= 1e-3 * want + 1e-5;
            const double sunShare = (f.color[4 * i + c] - albedo * f.light[3 * i + c]) / (albedo * lights.sun[c] * cosSun);
            if (cosSun > 0.05)
                EXPECT_TRUE(sunShare > -1e-3 && sunShare < 1.0 + 1e-3) << "pixel " << i << ", channel " << c << ": " << sunShare;
            else
                EXPECT_NEAR(f.color[4 * i + c], albedo * f.light[3 * i + c], 1e-3 * want + 1e-5) << "pixel " << i;
        }
        exact += same;
    }
    EXPECT_GT(surfaces, f.depth.size() / 3);
    EXPECT_EQ(lit, surfaces);  // the sky reaches every face of this open world
    EXPECT_GT(exact, surfaces * 8 / 10) << exact << " of " << surfaces;  // 615 of 687: the rest on shadow edges
}

}  // namespace
}  // namespace grotto
