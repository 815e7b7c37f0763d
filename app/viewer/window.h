#pragma once
// The viewer's window (GLFW): its Vulkan surface, size and the input of a frame.
#include <vulkan/vulkan.h>

#include <glm/vec2.hpp>

#include <string>
#include <vector>

struct GLFWwindow;

namespace grotto::viewer {

class Window {
public:
    // Throws grotto::Error (input) when no window system can be reached (no X
    // display): the viewer needs one, or xvfb-run.
    Window(const std::string& title, uint32_t width, uint32_t height);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    std::vector<const char*> vulkanExtensions() const;  // what the surface needs of the instance
    VkSurfaceKHR createSurface(VkInstance instance) const;
    VkExtent2D framebufferSize() const;  // 0 x 0 while minimised
    bool shouldClose() const;
    void poll() const;

    bool keyDown(int glfwKey) const;
    bool mouseDown(int glfwButton) const;
    glm::dvec2 cursor() const;
    double takeWheel();  // notches scrolled since the last call

    void setSize(uint32_t width, uint32_t height);
    void minimize();
    void restore();

    GLFWwindow* handle = nullptr;

private:
    double wheel_ = 0.0;
};

}  // namespace grotto::viewer
