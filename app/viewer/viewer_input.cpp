// The viewer's input: flight keys, mouse look and orbit, clicks, undo, and the
// hotkeys (R records a key, Tab hides the panel, F12 takes a screenshot).
#include "app/viewer/viewer_internal.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <utility>

namespace grotto::viewer {

void Viewer::flyFromInput(double dt) {
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
    const bool playing = session_->playing();
    if (playing && (in.forward || in.back || in.left || in.right || in.up || in.down || in.look != glm::dvec2(0.0)))
        stopPath(lastCamera_);
    // Middle drag orbits the point under the cursor where the drag began.
    const bool middle = window_.mouseDown(GLFW_MOUSE_BUTTON_MIDDLE) && !io.WantCaptureMouse;
    if (middle && !orbitPivot_) orbitPivot_ = pointUnder(cursor * contentScale());
    if (!middle) orbitPivot_.reset();
    if (orbitPivot_) fly_->orbit(*orbitPivot_, cursor - lastOrbitCursor_);
    lastOrbitCursor_ = cursor;
    if (!session_->playing()) fly_->update(in, dt);
    // Edits before the clock moves on: they belong to this frame, as its recorded key does.
    const bool left = window_.mouseDown(GLFW_MOUSE_BUTTON_LEFT) && !io.WantCaptureMouse;
    if (left && !leftDown_) click(cursor * contentScale(), true);
    leftDown_ = left;
    const bool ctrl = window_.keyDown(GLFW_KEY_LEFT_CONTROL) || window_.keyDown(GLFW_KEY_RIGHT_CONTROL);
    const bool z = keys && ctrl && window_.keyDown(GLFW_KEY_Z);
    if (z && !undoDown_) undo();
    undoDown_ = z;
    addPendingKey();
    playClock_ += dt;
    const bool r = keys && window_.keyDown(GLFW_KEY_R);
    if (r && !recordDown_) recordKey();
    recordDown_ = r;
    if (keys && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Tab), false)) panel_.hidden = !panel_.hidden;
    if (keys && glfwGetKey(window_.handle, GLFW_KEY_F12) == GLFW_PRESS && !f12Down_) pendingShot_ = nextShotName();
    f12Down_ = glfwGetKey(window_.handle, GLFW_KEY_F12) == GLFW_PRESS;
    panel_.speed = fly_->speed();
}

// Framebuffer pixels per window coordinate (HiDPI displays).
glm::dvec2 Viewer::contentScale() const {
    int ww = 0, wh = 0;
    glfwGetWindowSize(window_.handle, &ww, &wh);
    const VkExtent2D fb = window_.framebufferSize();
    return ww > 0 && wh > 0 ? glm::dvec2(double(fb.width) / ww, double(fb.height) / wh) : glm::dvec2(1.0);
}

void Viewer::pressHotkey(ScriptKey key) {
    if (key == ScriptKey::F12) pendingShot_ = nextShotName();
    if (key == ScriptKey::Tab) panel_.hidden = !panel_.hidden;
    if (key == ScriptKey::R) recordKey();
}

}  // namespace grotto::viewer
