#include "app/viewer/viewer.h"

#include "app/viewer/fly_camera.h"
#include "app/viewer/imgui_session.h"
#include "app/viewer/panel.h"
#include "app/viewer/path_player.h"
#include "app/viewer/path_recorder.h"
#include "app/viewer/presenter.h"
#include "app/viewer/settings_patch.h"
#include "app/viewer/view_script.h"
#include "app/viewer/window.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "common/printable.h"
#include "engine/image_output.h"
#include "engine/scene/live_scene.h"
#include "engine/renderer.h"
#include "engine/scene/scene_objects.h"
#include "voxel/object_worlds.h"
#include "voxel/world.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

namespace grotto::viewer {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kScriptStep = 1.0 / 60.0;  // seconds a scripted frame advances: runs are reproducible
constexpr size_t kGraphFrames = 120;

class Viewer {
public:
    explicit Viewer(const ViewOptions& o)
        : options_(o),
          script_(o.script ? std::optional<ViewScript>(ViewScript::load(*o.script)) : std::nullopt),
          loaded_(voxel::World::load(o.world)),
          desc_(loaded_.desc()),
          window_("grotto view - " + o.world.filename().string(), o.size.width, o.size.height),
          imgui_(window_.handle),
          ctx_(contextOptions(window_)) {
        live_ = std::make_unique<LiveScene>(ctx_, std::move(loaded_));
        const voxel::World& world = live_->world();
        // Command-line AO flags, as every command takes them, over the world's: kept
        // in desc_ too, so the panel, scripts and a saved world start from them.
        const AoOptions ao = app::resolveAo(world, o.ao);
        desc_.ao = app::aoDescWithFlags(world.desc().ao, o.ao);
        aoOptions_ = ao;
        objectWorlds_ = voxel::loadObjectWorlds(desc_);
        if (!objectWorlds_.empty()) objects_ = uploadObjects(ctx_, objectWorlds_, desc_);
        const VkExtent2D fb = window_.framebufferSize();
        renderScale_ = o.renderScale;
        renderSize_ = scaled(fb);
        renderer_ = std::make_unique<Renderer>(ctx_, live_->gpu(), desc_.lighting, ao, renderSize_.width,
                                               renderSize_.height, objects_.get());
        renderer_->setDisplayImage(true);  // the final view: the colour through the tone map
        desc_.detail = app::resolveDetail(world, o.ao);
        renderer_->setCulling(cullingOptions(desc_.detail));
        presenter_ = std::make_unique<Presenter>(ctx_, fb, o.vsync);
        const voxel::CameraDesc start = world.camera(o.camera, aspect());
        const voxel::IndexBox b = world.bounds();
        const double extent = b.empty() ? 10.0 : glm::length(glm::dvec3(b.max - b.min + 1)) * world.voxelSize();
        fly_ = std::make_unique<FlyCamera>(start, extent / 8.0);  // crosses the world in about 8 s
        for (const auto& [name, c] : desc_.cameras) panel_.cameras.push_back(name);
        for (const auto& [name, p] : desc_.paths) panel_.paths.push_back(name);
        panel_.quads = live_->gpu().quadCount;
        panel_.activeVoxels = world.stats().solidVoxels;
        panel_.saveWorldAs = (o.world.parent_path() / (o.world.stem().string() + "-edited.json")).string();
        panel_.savePathAs = (o.world.parent_path() / (o.world.stem().string() + "-recorded.json")).string();
        panel_.hidden = o.hidePanel;
        panel_.renderScale = o.renderScale;
    }

    ~Viewer() {
        vk::destroy(ctx_, shown_);
        presenter_.reset();
        renderer_.reset();
        objects_.reset();
        live_.reset();
    }

    void run() {
        std::vector<double> frameMs, renderMs, presentMs;
        while (!window_.shouldClose() && (!options_.frames || frame_ < *options_.frames)) {
            const auto start = Clock::now();
            window_.poll();
            applyScript();
            resizeIfNeeded();
            const double dt = script_ ? kScriptStep : std::min(lastFrameSeconds_, 0.25);
            flyFromInput(dt);
            const Camera camera = currentCamera(dt);
            lastCamera_ = camera;
            if (objects_) renderer_->setObjectPoses(objects_->poses(playClock_));  // objects move on the play clock
            const VkExtent2D fb = window_.framebufferSize();
            if (fb.width == 0 || fb.height == 0) {  // minimised: nothing to show, so nothing to render
                glfwWaitEventsTimeout(script_ ? 0.0 : 0.05);
                ++frame_;
                continue;
            }
            const auto beforeRender = Clock::now();
            panel_.stats = renderer_->render(camera, sequence_++);
            const auto afterRender = Clock::now();
            if (panel_.view != "final" || pendingShot_) readback(camera);
            ImDrawData* ui = drawUi();
            presenter_->present(panel_.view == "final" ? renderer_->displayImage() : shown_, ui,
                                wantWindowCapture() ? &windowPixels_ : nullptr);
            const auto end = Clock::now();
            lastFrameSeconds_ = std::chrono::duration<double>(end - start).count();
            frameMs.push_back(lastFrameSeconds_ * 1e3);
            renderMs.push_back(std::chrono::duration<double, std::milli>(afterRender - beforeRender).count());
            presentMs.push_back(std::chrono::duration<double, std::milli>(end - afterRender).count());
            panel_.frameMs.push_back(float(lastFrameSeconds_ * 1e3));
            if (panel_.frameMs.size() > kGraphFrames) panel_.frameMs.pop_front();
            ++frame_;
        }
        if (options_.screenshot) screenshot(*options_.screenshot);
        if (options_.captureWindow) {
            if (windowPixels_.empty()) throw Error("--capture-window", "no frame was shown to capture", "give --frames 1 or more");
            const VkExtent2D e = presenter_->extent();
            writeSrgb8(*options_.captureWindow, e.width, e.height, windowPixels_);
            std::printf("wrote %s (%ux%u, the window as shown)\n", printable(options_.captureWindow->string()).c_str(),
                        e.width, e.height);
        }
        if (options_.bench) printBench(frameMs, renderMs, presentMs);
        app::requireNoValidationMessages(ctx_);
    }

private:
    static vk::ContextOptions contextOptions(const Window& w) {
        vk::ContextOptions o;
        o.instanceExtensions = w.vulkanExtensions();
        o.createSurface = [&w](VkInstance instance) { return w.createSurface(instance); };
        return o;
    }

    bool wantWindowCapture() const {
        return options_.captureWindow && options_.frames && frame_ + 1 == *options_.frames;
    }

    // The script's actions for this frame; errors name the script's file and action.
    void applyScript() {
        if (!script_) return;
        for (const ScriptAction& a : script_->at(frame_)) {
            // The field errors name: "frame 8 set" (a script's frame, its verb).
            const std::string where = "frame " + std::to_string(a.frame) + " " + verbName(a.kind);
            switch (a.kind) {
            case ScriptAction::Kind::Key:
                if (isHeld(a.key)) scriptKeys_[scriptKeyName(a.key)] = a.down;
                else pressHotkey(a.key);
                break;
            case ScriptAction::Kind::Look: scriptLook_ += a.vec; break;
            case ScriptAction::Kind::Wheel: scriptWheel_ += a.wheel; break;
            case ScriptAction::Kind::Set:
                for (const auto& [key, value] : a.settings) {
                    const std::string field = where + "." + key;
                    if (key == "view") setView(value, field);
                    else if (key == "play") playFromScript(value, field);
                    else if (key.rfind("edit.", 0) == 0) setEdit(key, value, field);
                    else applyPatch(voxel::settingPatch(key, value), script_->file(), where);
                }
                break;
            case ScriptAction::Kind::Resize:
                window_.setSize(uint32_t(a.vec.x), uint32_t(a.vec.y));
                waitForSize();
                break;
            case ScriptAction::Kind::Minimize: window_.minimize(); waitForSize(); break;
            case ScriptAction::Kind::Restore: window_.restore(); waitForSize(); break;
            case ScriptAction::Kind::Camera: jumpTo(a.camera); break;
            case ScriptAction::Kind::Screenshot: pendingShot_ = a.path; break;
            case ScriptAction::Kind::Record: recordKey(); break;
            case ScriptAction::Kind::SavePath: savePath(a.path); break;
            case ScriptAction::Kind::Click: click(a.vec, a.button == MouseButton::Left); break;
            case ScriptAction::Kind::Undo: undo(); break;
            case ScriptAction::Kind::SaveWorld: saveWorld(a.path); break;
            }
        }
    }

    // The fly camera, or the playing path's camera at its clock (its cuts restart
    // the history; at its end the fly camera takes over where it stopped).
    Camera currentCamera(double dt) {
        if (!player_.playing()) return makeCamera(fly_->desc(), renderSize_.width, renderSize_.height);
        const PathPlayer::Frame f = player_.next(dt, renderSize_.width, renderSize_.height);
        if (f.cut) cut();
        if (f.ended) stopPath(f.camera);
        return f.camera;
    }

    double aspect() const { return double(renderSize_.width) / double(renderSize_.height); }

    void playPath(const std::string& name) {
        player_.play(desc_.paths.at(name), live_->world().camera("", aspect()));
        panel_.playing = name;
        cut();
    }

    void stopPath(const Camera& at) {
        fly_->jumpTo(describe(at, fly_->desc()));
        player_.stop();
        panel_.playing.clear();
    }

    void pressHotkey(ScriptKey key) {
        if (key == ScriptKey::F12) pendingShot_ = nextShotName();
        if (key == ScriptKey::Tab) panel_.hidden = !panel_.hidden;
        if (key == ScriptKey::R) recordKey();
    }

    // Records this frame's camera once it has moved (flyFromInput), so a key is the
    // camera of the frame shown at its time.
    void recordKey() { recordPending_ = true; }

    void addPendingKey() {
        if (!std::exchange(recordPending_, false)) return;
        if (!recordStart_) recordStart_ = playClock_;
        if (recorder_.add(playClock_ - *recordStart_, fly_->desc()))
            panel_.message = "path key " + std::to_string(recorder_.size()) + " at " +
                             std::to_string(playClock_ - *recordStart_) + " s";
        panel_.recordedKeys = recorder_.size();
    }

    void savePath(const std::filesystem::path& file) {
        recorder_.save(file);
        panel_.message = "wrote " + file.string();
        std::printf("wrote %s (%zu keys)\n", printable(file.string()).c_str(), recorder_.size());
    }

    // A click at a window pixel: the panel's edit where the view ray first meets a
    // voxel (dig and paint at the voxel hit, place in front of the face it hit).
    // `primary`: the left button; any other does nothing yet.
    // The view ray through a window pixel (the window may show the frame scaled)
    // and the first voxel it hits.
    struct Pick {
        glm::dvec3 origin, direction;
        std::optional<voxel::RayHit> hit;
    };
    Pick pick(glm::dvec2 pixel) const {
        const VkExtent2D window = presenter_->extent();
        const Camera camera = makeCamera(fly_->desc(), renderSize_.width, renderSize_.height);
        const glm::dvec2 p = pixel * glm::dvec2(double(renderSize_.width) / std::max(window.width, 1u),
                                                double(renderSize_.height) / std::max(window.height, 1u));
        Pick k{camera.position, camera.rayDirection(p.x, p.y), std::nullopt};
        k.hit = live_->world().raycast(k.origin, k.direction, 1e12);
        return k;
    }

    // The orbit's pivot: the surface under the pixel, else the point a second's flight ahead.
    glm::dvec3 pointUnder(glm::dvec2 pixel) const {
        const Pick k = pick(pixel);
        return k.origin + k.direction * (k.hit ? k.hit->distance : fly_->speed());
    }

    void click(glm::dvec2 pixel, bool primary) {
        if (!primary || panel_.editMode == "none") return;
        const voxel::World& world = live_->world();
        const std::optional<voxel::RayHit> hit = pick(pixel).hit;
        if (!hit) return;
        glm::ivec3 voxel = hit->voxel;
        if (panel_.editMode == "place" && hit->face >= 0) voxel[hit->face / 2] += hit->face % 2 == 0 ? 1 : -1;
        const double vs = world.voxelSize();
        const glm::dvec3 centre = world.origin() + (glm::dvec3(voxel) + 0.5) * vs;
        const double radius = std::max(panel_.brushRadius, 0.5) * vs;
        const voxel::Edit edit = panel_.editMode == "dig"     ? voxel::Edit::carveSphere(centre, radius)
                                 : panel_.editMode == "place" ? voxel::Edit::fillSphere(centre, radius, panel_.material)
                                                              : voxel::Edit::paintSphere(centre, radius, panel_.material);
        edited(live_->apply(edit));
    }

    void undo() { edited(live_->undo()); }

    void edited(const voxel::EditResult& r) {
        if (r.voxels.empty()) return;
        renderer_->invalidateHistory(r.box);
        panel_.quads = live_->gpu().quadCount;
        panel_.activeVoxels = live_->world().stats().solidVoxels;
        panel_.message = std::to_string(r.changed) + " voxels changed";
    }

    void saveWorld(const std::filesystem::path& file) {
        requireOutputPath(file);
        // With the settings as the panel has them.
        const voxel::World::SavedFiles saved = live_->world().save(file, desc_);
        panel_.message = "wrote " + saved.world.string() + " and " + saved.grid.string();
        std::printf("wrote %s and %s\n", printable(saved.world.string()).c_str(), printable(saved.grid.string()).c_str());
    }

    // The window system applies size changes asynchronously: give it a moment.
    void waitForSize() {
        for (int i = 0; i < 20; ++i) {
            glfwWaitEventsTimeout(0.01);
            window_.poll();
        }
    }

    // A script's setting that is the viewer's own, refused as the file readers do.
    [[noreturn]] void refuse(const std::string& field, const std::string& what, const std::string& hint) const {
        throw Error(script_->file().string(), "field '" + field + "': " + what, hint);
    }

    void setView(const nlohmann::json& value, const std::string& field) {
        const std::string v = value.is_string() ? value.get<std::string>() : "";
        if (std::find(kViews.begin(), kViews.end(), v) == kViews.end())
            refuse(field, "unknown view " + value.dump(),
                   "accepted: final, ao, raw, spatial, temporal, history, edges, normal, depth, shadow");
        panel_.view = v;
    }

    // The edit brush, as the panel sets it: edit.mode (none, dig, place, paint),
    // edit.radius (voxels, 0.5 to 64), edit.material (1 to 255).
    void setEdit(const std::string& key, const nlohmann::json& v, const std::string& field) {
        if (key == "edit.mode") {
            const std::string m = v.is_string() ? v.get<std::string>() : "";
            if (m != "none" && m != "dig" && m != "place" && m != "paint")
                refuse(field, "unknown mode " + v.dump(), "accepted: none, dig, place, paint");
            panel_.editMode = m;
        } else if (key == "edit.radius") {
            if (!v.is_number() || !(v.get<double>() >= 0.5 && v.get<double>() <= 64.0))
                refuse(field, "value " + v.dump() + " is out of range", "accepted: 0.5 to 64 (voxels)");
            panel_.brushRadius = v.get<double>();
        } else if (key == "edit.material") {
            if (!v.is_number_integer() || v.get<int>() < 1 || v.get<int>() > 255)
                refuse(field, "value " + v.dump() + " is out of range", "accepted: whole numbers 1 to 255");
            panel_.material = v.get<int>();
        } else {
            refuse(field, "unknown setting", "edit.mode, edit.radius, edit.material");
        }
    }

    void playFromScript(const nlohmann::json& v, const std::string& field) {
        const std::string name = v.is_string() ? v.get<std::string>() : "";
        if (!desc_.paths.count(name)) {
            std::string known;
            for (const std::string& p : panel_.paths) known += (known.empty() ? "" : ", ") + p;
            refuse(field, "no path " + v.dump() + " in the world",
                   "the world's paths: " + (known.empty() ? std::string("none") : known));
        }
        playPath(name);
    }

    void jumpTo(const std::string& name) {
        fly_->jumpTo(live_->world().camera(name, aspect()));
        cut();
    }

    // A camera cut or new settings: the history and the noise sequence start again,
    // so a still after it matches `render` of the same camera frame for frame.
    void cut() {
        renderer_->resetHistory();
        sequence_ = 0;
    }

    void applyPatch(const voxel::json& patch, const std::filesystem::path& file, const std::string& field) {
        voxel::WorldDesc d = desc_;
        const AoOptions ao = applyViewerPatch(d, patch, live_->world().voxelSize(), file, field);
        if (patch.contains("lighting")) renderer_->setLighting(d.lighting);
        if (patch.contains("ao")) renderer_->setAo(ao);
        if (patch.contains("detail")) renderer_->setCulling(cullingOptions(d.detail));
        desc_ = std::move(d);
        aoOptions_ = ao;
        cut();
    }

    // The frame's size for a window of `fb` pixels at the render scale.
    VkExtent2D scaled(VkExtent2D fb) const {
        return {std::max(uint32_t(std::lround(fb.width * renderScale_)), 1u),
                std::max(uint32_t(std::lround(fb.height * renderScale_)), 1u)};
    }

    void resizeIfNeeded() {
        const VkExtent2D fb = window_.framebufferSize();
        if (fb.width != presented_.width || fb.height != presented_.height) {
            presented_ = fb;
            presenter_->resize(fb);
        }
        if (fb.width == 0 || fb.height == 0) return;  // minimised: keep rendering at the last size
        const VkExtent2D size = scaled(fb);
        if (size.width != renderSize_.width || size.height != renderSize_.height) {
            renderSize_ = size;
            renderer_->resize(size.width, size.height);
            sequence_ = 0;
        }
    }

    void flyFromInput(double dt) {
        ImGuiIO& io = ImGui::GetIO();
        const bool keys = !io.WantCaptureKeyboard;
        auto held = [&](const char* scriptName, int key) {
            auto it = scriptKeys_.find(scriptName);
            return (it != scriptKeys_.end() && it->second) || (keys && window_.keyDown(key));
        };
        FlyInput in;
        in.forward = held("W", GLFW_KEY_W);
        in.back = held("S", GLFW_KEY_S);
        in.left = held("A", GLFW_KEY_A);
        in.right = held("D", GLFW_KEY_D);
        in.down = held("Q", GLFW_KEY_Q);
        in.up = held("E", GLFW_KEY_E);
        in.fast = held("SHIFT", GLFW_KEY_LEFT_SHIFT);
        const glm::dvec2 cursor = window_.cursor();
        if (window_.mouseDown(GLFW_MOUSE_BUTTON_RIGHT) && !io.WantCaptureMouse) in.look = cursor - lastCursor_;
        lastCursor_ = cursor;
        in.look += std::exchange(scriptLook_, glm::dvec2(0.0));
        const double wheel = window_.takeWheel();
        in.wheel = (io.WantCaptureMouse ? 0.0 : wheel) + std::exchange(scriptWheel_, 0.0);
        // A flight key or a look takes the camera back from a playing path.
        if (player_.playing() && (in.forward || in.back || in.left || in.right || in.up || in.down || in.look != glm::dvec2(0.0)))
            stopPath(currentCamera(0.0));
        // Middle drag orbits the point under the cursor where the drag began.
        const bool middle = window_.mouseDown(GLFW_MOUSE_BUTTON_MIDDLE) && !io.WantCaptureMouse;
        if (middle && !orbitPivot_) orbitPivot_ = pointUnder(cursor * contentScale());
        if (!middle) orbitPivot_.reset();
        if (orbitPivot_) fly_->orbit(*orbitPivot_, cursor - lastOrbitCursor_);
        lastOrbitCursor_ = cursor;
        if (!player_.playing()) fly_->update(in, dt);
        addPendingKey();
        playClock_ += dt;
        const bool left = window_.mouseDown(GLFW_MOUSE_BUTTON_LEFT) && !io.WantCaptureMouse;
        if (left && !leftDown_) click(cursor * contentScale(), true);
        leftDown_ = left;
        const bool ctrl = window_.keyDown(GLFW_KEY_LEFT_CONTROL) || window_.keyDown(GLFW_KEY_RIGHT_CONTROL);
        const bool z = keys && ctrl && window_.keyDown(GLFW_KEY_Z);
        if (z && !undoDown_) undo();
        undoDown_ = z;
        const bool r = keys && window_.keyDown(GLFW_KEY_R);
        if (r && !recordDown_) recordKey();
        recordDown_ = r;
        if (keys && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Tab), false)) panel_.hidden = !panel_.hidden;
        if (keys && glfwGetKey(window_.handle, GLFW_KEY_F12) == GLFW_PRESS && !f12Down_) pendingShot_ = nextShotName();
        f12Down_ = glfwGetKey(window_.handle, GLFW_KEY_F12) == GLFW_PRESS;
        panel_.speed = fly_->speed();
    }

    // Framebuffer pixels per window coordinate (HiDPI displays).
    glm::dvec2 contentScale() const {
        int ww = 0, wh = 0;
        glfwGetWindowSize(window_.handle, &ww, &wh);
        const VkExtent2D fb = window_.framebufferSize();
        return ww > 0 && wh > 0 ? glm::dvec2(double(fb.width) / ww, double(fb.height) / wh) : glm::dvec2(1.0);
    }

    std::filesystem::path nextShotName() {
        for (;; ++shotCounter_) {
            char name[32];
            std::snprintf(name, sizeof name, "grotto-%03d.png", shotCounter_);
            if (!std::filesystem::exists(name)) return name;
        }
    }

    // Reads the frame back for an AOV view or a screenshot.
    void readback(const Camera& camera) {
        const FrameImages f = renderer_->readback(camera, true);
        const std::vector<float> shown = panel_.view == "final" ? std::vector<float>() : aovDisplay(f, panel_.view);
        if (pendingShot_) {
            writeShot(*pendingShot_, f, shown, camera);
            pendingShot_.reset();
        }
        if (panel_.view == "final") return;
        if (shown_.extent.width != f.width || shown_.extent.height != f.height) {
            vk::destroy(ctx_, shown_);
            shown_ = vk::createImage(ctx_, {f.width, f.height}, VK_FORMAT_R32G32B32A32_SFLOAT,
                                     VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                         VK_IMAGE_USAGE_SAMPLED_BIT);  // sampled: an image gets a view
        }
        vk::Buffer staging = vk::uploadBuffer(ctx_, shown.data(), shown.size() * sizeof(float),
                                              VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        ctx_.submitAndWait([&](VkCommandBuffer cmd) {
            vk::transition(cmd, shown_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                           VK_ACCESS_TRANSFER_WRITE_BIT);
            VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                     .imageExtent = {f.width, f.height, 1}};
            vkCmdCopyBufferToImage(cmd, staging.buffer, shown_.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            vk::transition(cmd, shown_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                           VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                           VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        });
        vk::destroy(ctx_, staging);
    }

    // What the view shows: a PNG of the final view holds the tone-mapped colour as
    // `render` writes it, of an AOV view that AOV as the window shows it (`shown`,
    // aovDisplay). An EXR holds the scene-linear colour and every AOV, the shown one
    // among them.
    void writeShot(const std::filesystem::path& path, const FrameImages& f, const std::vector<float>& shown,
                   const Camera& camera) {
        if (imageFormatFor(path) == ImageFormat::Exr) writeFrame(path, f, camera, true);
        else if (shown.empty()) writeFrame(path, f, camera, false);
        else writeSrgb8(path, f.width, f.height, encodeSrgb8(shown), &camera);
        panel_.message = "wrote " + path.string();
        std::printf("wrote %s (%ux%u)\n", printable(path.string()).c_str(), f.width, f.height);
    }

    // The last frame rendered, with the camera it was rendered from.
    void screenshot(const std::filesystem::path& path) {
        const bool aov = panel_.view != "final";
        const FrameImages f = renderer_->readback(lastCamera_, aov || imageFormatFor(path) == ImageFormat::Exr);
        writeShot(path, f, aov ? aovDisplay(f, panel_.view) : std::vector<float>(), lastCamera_);
    }

    ImDrawData* drawUi() {
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        if (!panel_.hidden) {
            panel_.desc = &desc_;
            panel_.ao = &aoOptions_;
            const voxel::json patch = drawPanel(panel_);
            try {
                if (!patch.empty()) applyPatch(patch, "panel", "panel");
            } catch (const Error& e) {
                panel_.message = e.what();
            }
            if (!panel_.jumpTo.empty()) jumpTo(std::exchange(panel_.jumpTo, ""));
            if (!panel_.play.empty()) playPath(std::exchange(panel_.play, ""));
            if (std::exchange(panel_.screenshot, false)) pendingShot_ = nextShotName();
            try {
                if (panel_.renderScale != renderScale_) renderScale_ = panel_.renderScale;
                if (std::exchange(panel_.undo, false)) undo();
                if (std::exchange(panel_.saveWorld, false)) saveWorld(panel_.saveWorldAs);
                if (std::exchange(panel_.record, false)) recordKey();
                if (std::exchange(panel_.savePath, false)) savePath(panel_.savePathAs);
            } catch (const Error& e) {
                panel_.message = e.what();
            }
        }
        ImGui::Render();
        return ImGui::GetDrawData();
    }

    void printBench(const std::vector<double>& frameMs, const std::vector<double>& renderMs,
                    const std::vector<double>& presentMs) const {
        // The first frames compile pipelines and fill caches.
        const size_t skip = std::min<size_t>(frameMs.size() / 4, 10);
        auto med = [&](const std::vector<double>& v) {
            return app::median(std::vector<double>(v.begin() + long(skip), v.end()));
        };
        const double frame = med(frameMs);
        std::printf("view bench: %s, %ux%u, %zu frames (median after %zu warm-up)\n", options_.world.c_str(),
                    renderSize_.width, renderSize_.height, frameMs.size() - skip, skip);
        std::printf("  frame %.2f ms (%.1f fps): render %.2f ms, panel + present %.2f ms\n", frame,
                    frame > 0 ? 1000.0 / frame : 0.0, med(renderMs), med(presentMs));
    }

    ViewOptions options_;
    // Script and world are read before the window opens: bad input shows no window.
    std::optional<ViewScript> script_;
    voxel::World loaded_;  // moved into live_ once the device exists
    voxel::WorldDesc desc_;
    Window window_;
    ImguiSession imgui_;
    vk::Context ctx_;
    AoOptions aoOptions_;
    std::unique_ptr<LiveScene> live_;
    PathRecorder recorder_;
    PathPlayer player_;  // a world's path playing, if any
    std::optional<glm::dvec3> orbitPivot_;
    glm::dvec2 lastOrbitCursor_{0.0};
    double playClock_ = 0.0;  // seconds shown so far: recorded keys' times
    std::optional<double> recordStart_;  // the play clock at the first key: the path's time 0
    bool recordPending_ = false;
    std::vector<voxel::World> objectWorlds_;
    std::unique_ptr<SceneObjects> objects_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<Presenter> presenter_;
    std::unique_ptr<FlyCamera> fly_;
    PanelState panel_;
    vk::Image shown_;  // an AOV view's pixels
    VkExtent2D renderSize_{}, presented_{};
    Camera lastCamera_;
    double renderScale_ = 1.0;  // frame pixels per window pixel (the panel's "render scale")
    uint32_t frame_ = 0, sequence_ = 0;
    double lastFrameSeconds_ = 1.0 / 60.0;
    std::map<std::string, bool> scriptKeys_;
    glm::dvec2 scriptLook_{0.0}, lastCursor_{0.0};
    double scriptWheel_ = 0.0;
    std::optional<std::filesystem::path> pendingShot_;
    bool f12Down_ = false, leftDown_ = false, undoDown_ = false, recordDown_ = false;
    int shotCounter_ = 1;
    std::vector<uint8_t> windowPixels_;
};

}  // namespace

void runViewer(const ViewOptions& options) {
    Viewer viewer(options);
    viewer.run();
}

}  // namespace grotto::viewer
