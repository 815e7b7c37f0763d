#pragma once
// Dear ImGui's context and its GLFW backend for a window's lifetime, with its
// colours made right for an sRGB swapchain.
struct GLFWwindow;

namespace grotto::viewer {

class ImguiSession {
public:
    explicit ImguiSession(GLFWwindow* window);
    ~ImguiSession();
    ImguiSession(const ImguiSession&) = delete;
    ImguiSession& operator=(const ImguiSession&) = delete;
};

}  // namespace grotto::viewer
