#include "app/viewer/imgui_session.h"

#include "engine/image_output.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>

namespace grotto::viewer {

ImguiSession::ImguiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working directory
    ImGui::StyleColorsDark();
    // ImGui's colours are sRGB values; the swapchain image encodes what is written
    // to it, so they go in linear to come out as ImGui meant them.
    for (ImVec4& c : ImGui::GetStyle().Colors) c = ImVec4(srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z), c.w);
    ImGui_ImplGlfw_InitForVulkan(window, true);
}

ImguiSession::~ImguiSession() {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

}  // namespace grotto::viewer
