// App's window input: the mouse and keys that move the camera (the panel's keys are read through
// ImGui, in panel.cpp).
#include "common/app.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <utility>

namespace ocean {

void App::on_scroll(GLFWwindow* window, double /*dx*/, double dy) {
    auto* app = static_cast<App*>(glfwGetWindowUserPointer(window));
    if (app != nullptr && !ImGui::GetIO().WantCaptureMouse) app->scroll_accumulated_ += float(dy);
}

// What the camera reads this frame; nothing reaches it while ImGui has the mouse or the keyboard.
// Moving the camera changes no parameter's generation: nothing is rebuilt for it.
CameraInput App::read_camera_input() {
    CameraInput input;
    GLFWwindow* window = context_->window();
    if (window == nullptr) return input;
    const ImGuiIO& io = ImGui::GetIO();
    glm::dvec2 mouse;
    glfwGetCursorPos(window, &mouse.x, &mouse.y);
    if (!io.WantCaptureMouse && glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS)
        input.drag = glm::vec2(mouse - last_mouse_);
    last_mouse_ = mouse;
    input.scroll = std::exchange(scroll_accumulated_, 0.0f);
    if (!io.WantCaptureKeyboard) {
        auto key = [&](int k) { return glfwGetKey(window, k) == GLFW_PRESS ? 1.0f : 0.0f; };
        input.move = {key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_E) - key(GLFW_KEY_Q),
                      key(GLFW_KEY_W) - key(GLFW_KEY_S)};
        input.fast = key(GLFW_KEY_LEFT_SHIFT) > 0;
    }
    return input;
}

}  // namespace ocean
