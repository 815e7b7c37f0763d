#include "app/viewer/window.h"

#include "grotto/error.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

namespace grotto::viewer {

Window::Window(const std::string& title, uint32_t width, uint32_t height) {
    if (!glfwInit()) {
        const char* why = nullptr;
        glfwGetError(&why);
        throw Error("display", std::string("no window system could be reached") + (why ? std::string(" (") + why + ")" : ""),
                    "run the viewer on a desktop, or headless under xvfb-run");
    }
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw Error("display", "GLFW found no Vulkan loader", "install the Debian package libvulkan1");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    handle = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!handle) {
        glfwTerminate();
        throw Error("display", "the window could not be created", "check the display (DISPLAY) and --size");
    }
    glfwSetWindowUserPointer(handle, this);
    // Installed before ImGui's GLFW backend, which keeps it and calls it after its own.
    glfwSetScrollCallback(handle, [](GLFWwindow* w, double, double y) {
        static_cast<Window*>(glfwGetWindowUserPointer(w))->wheel_ += y;
    });
}

Window::~Window() {
    glfwDestroyWindow(handle);
    glfwTerminate();
}

std::vector<const char*> Window::vulkanExtensions() const {
    uint32_t n = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&n);
    return std::vector<const char*>(names, names + n);
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    const VkResult r = glfwCreateWindowSurface(instance, handle, nullptr, &surface);
    if (r != VK_SUCCESS) throw Error("display", "the window's Vulkan surface could not be created", "check the display");
    return surface;
}

VkExtent2D Window::framebufferSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(handle, &w, &h);
    if (glfwGetWindowAttrib(handle, GLFW_ICONIFIED)) w = h = 0;
    return {uint32_t(w), uint32_t(h)};
}

bool Window::shouldClose() const { return glfwWindowShouldClose(handle); }
void Window::poll() const { glfwPollEvents(); }
bool Window::keyDown(int key) const { return glfwGetKey(handle, key) == GLFW_PRESS; }
bool Window::mouseDown(int button) const { return glfwGetMouseButton(handle, button) == GLFW_PRESS; }

glm::dvec2 Window::cursor() const {
    glm::dvec2 p;
    glfwGetCursorPos(handle, &p.x, &p.y);
    return p;
}

double Window::takeWheel() {
    const double w = wheel_;
    wheel_ = 0.0;
    return w;
}

void Window::setSize(uint32_t width, uint32_t height) { glfwSetWindowSize(handle, int(width), int(height)); }
void Window::minimize() { glfwIconifyWindow(handle); }
void Window::restore() { glfwRestoreWindow(handle); }

}  // namespace grotto::viewer
