#pragma once
// The viewer's state, one class whose methods live in a file per seam:
// viewer.cpp (the loop, settings and size), viewer_input.cpp (keys, mouse and
// hotkeys), viewer_script.cpp (a --script's actions), viewer_edits.cpp (picking
// and edits), viewer_paths.cpp (paths played and recorded) and viewer_views.cpp
// (AOV views and screenshots). Internal to app/viewer.
#include "app/viewer/fly_camera.h"
#include "app/viewer/imgui_session.h"
#include "app/viewer/panel.h"
#include "app/viewer/path_recorder.h"
#include "app/viewer/presenter.h"
#include "app/viewer/view_script.h"
#include "app/viewer/viewer.h"
#include "app/viewer/window.h"
#include "engine/session.h"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grotto::viewer {

class Viewer {
public:
    explicit Viewer(const ViewOptions& options);
    ~Viewer();
    void run();

private:
    // A frame's view: the camera and the index that seeds its noise.
    struct View {
        Camera camera;
        uint32_t index = 0;
    };

    // viewer.cpp
    static vk::ContextOptions contextOptions(const Window& w);
    bool wantWindowCapture() const;
    Renderer& renderer() { return session_->renderer(); }
    double aspect() const { return double(renderSize_.width) / double(renderSize_.height); }
    void cut();
    void applyPatch(const voxel::json& patch, const std::filesystem::path& file, const std::string& field);
    VkExtent2D scaled(VkExtent2D fb) const;
    void resizeIfNeeded();
    void waitForSize();
    void jumpTo(const std::string& name);
    ImDrawData* drawUi();
    void printBench(const std::vector<double>& frameMs, const std::vector<double>& renderMs,
                    const std::vector<double>& presentMs) const;

    // viewer_input.cpp
    void flyFromInput(double dt);
    glm::dvec2 contentScale() const;
    void pressHotkey(ScriptKey key);

    // viewer_script.cpp
    void applyScript();
    [[noreturn]] void refuse(const std::string& field, const std::string& what, const std::string& hint) const;
    void setView(const nlohmann::json& value, const std::string& field);
    void setEdit(const std::string& key, const nlohmann::json& value, const std::string& field);
    void playFromScript(const nlohmann::json& value, const std::string& field);

    // viewer_edits.cpp
    struct Pick {
        glm::dvec3 origin, direction;
        std::optional<voxel::RayHit> hit;
    };
    Pick pick(glm::dvec2 pixel) const;
    glm::dvec3 pointUnder(glm::dvec2 pixel) const;
    void click(glm::dvec2 pixel, bool primary);
    void undo();
    void edited(const voxel::EditResult& r);
    void saveWorld(const std::filesystem::path& file);

    // viewer_paths.cpp
    View nextView(double dt);
    void playPath(const std::string& name);
    void stopPath(const Camera& at);
    void recordKey() { recordPending_ = true; }
    void addPendingKey();
    void savePath(const std::filesystem::path& file);

    // viewer_views.cpp
    std::filesystem::path nextShotName();
    void readback(const Camera& camera);
    void writeShot(const std::filesystem::path& path, const FrameImages& f, const std::vector<float>& shown,
                   const Camera& camera);
    void screenshot(const std::filesystem::path& path);

    ViewOptions options_;
    // Script and world are read before the window opens: bad input shows no window.
    std::optional<ViewScript> script_;
    voxel::World loaded_;  // moved into the session once the device exists
    voxel::WorldDesc desc_;
    Window window_;
    ImguiSession imgui_;
    vk::Context ctx_;
    AoOptions aoOptions_;
    std::unique_ptr<RenderSession> session_;
    PathRecorder recorder_;
    std::optional<glm::dvec3> orbitPivot_;
    glm::dvec2 lastOrbitCursor_{0.0};
    double playClock_ = 0.0;  // seconds shown so far: the time of the frame being made, of recorded keys and edits
    std::optional<double> recordStart_;  // the play clock at the first key: the path's time 0
    bool recordPending_ = false;
    double pathClock_ = 0.0;   // the playing path's time at the next frame
    uint32_t pathFrames_ = 0;  // frames of the playing path shown: its frame numbers, as flythrough's
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

}  // namespace grotto::viewer
