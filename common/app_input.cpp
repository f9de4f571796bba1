// App's window input: the framework's keys (F1, Esc, F5, C), the mouse and keys that move the
// camera, and the mouse a step reads (frame_input()).
//
// Presses come from the window system's events, not from polling once a frame: the GLFW callbacks
// below queue every key and mouse-button press and release as it arrives (during poll_events),
// and read_input() acts on each press of the frame in order, so a tap shorter than a frame, or
// several taps within one, all count (input_events.hpp). Held keys (WASD, shift, step07's arrows)
// are still read as held, once a frame.
#include "common/app.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <iostream>
#include <utility>

namespace ocean {

namespace {

App* app_of(GLFWwindow* window) { return static_cast<App*>(glfwGetWindowUserPointer(window)); }

}  // namespace

// GLFW's glfwGetCursorPos asks the X server where the pointer is now, which may be past a press
// still in the queue: the motion events, delivered in order with the presses, say where it was.
void App::on_cursor_pos(GLFWwindow* window, double x, double y) {
    if (App* app = app_of(window)) app->cursor_ = {x, y};
}

void App::on_scroll(GLFWwindow* window, double /*dx*/, double dy) {
    App* app = app_of(window);
    if (app != nullptr && !ImGui::GetIO().WantCaptureMouse) app->scroll_accumulated_ += float(dy);
}

void App::on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
    if (App* app = app_of(window)) app->input_queue_.key(key, action, app->cursor_);
}

void App::on_mouse_button(GLFWwindow* window, int button, int action, int /*mods*/) {
    if (App* app = app_of(window)) app->input_queue_.mouse_button(button, action, app->cursor_);
}

// Once a frame, after ImGui's NewFrame (begin_imgui_frame). ImGui's capture flags are per frame:
// NewFrame sets them from the widgets as the last frame left them (a text field being edited, a
// slider held), which is the state the queued events arrived in, so one flag judges all of the
// frame's events: a key typed into a text field is not the app's, a press on the panel starts no
// drag. The lines printed say what a key did (in the terminal, and for tests/smoke/window_input.sh).
void App::read_input() {
    frame_input_ = FrameInput{};
    GLFWwindow* window = context_->window();
    if (window == nullptr) return;
    const ImGuiIO& io = ImGui::GetIO();
    const std::vector<InputEvent> events = input_queue_.take();
    for (const InputEvent& event : events) {
        act_on_key(key_action(event, io.WantCaptureKeyboard));
        if (event.kind == InputEvent::MouseButton && event.pressed && !io.WantCaptureMouse)
            frame_input_.presses.push_back(event);
    }
    frame_input_.cursor = cursor_;
    frame_input_.drag = glm::vec2(drag_.frame(events, frame_input_.cursor, io.WantCaptureMouse));
    // From the events, not from dragging() before and after: a whole drag within one frame ends too.
    frame_input_.drag_ended = drag_.ended();
    frame_input_.scroll = std::exchange(scroll_accumulated_, 0.0f);
}

void App::act_on_key(KeyAction action) {
    switch (action) {
        case KeyAction::None: break;
        case KeyAction::TogglePanel:
            panel_visible_ = !panel_visible_;
            std::cout << (panel_visible_ ? "panel: shown (F1 hides it)" : "panel: hidden (F1 shows it)") << std::endl;
            break;
        case KeyAction::Quit: context_->request_close(); break;
        case KeyAction::ReloadShaders:
            programs_.rebuild_all();
            std::cout << "shaders: rebuilt (F5)" << std::endl;
            break;
        case KeyAction::SwitchCamera:
            if (!camera_enabled_) break;
            camera_.mode = camera_.mode == Camera::Orbit ? Camera::Fly : Camera::Orbit;
            std::cout << (camera_.mode == Camera::Fly ? "camera: fly (WASD, Q/E, shift; C for orbit)"
                                                      : "camera: orbit (drag, wheel; C for fly)")
                      << std::endl;
            break;
    }
}

// When a drag ends, the view it left, as the flags that start a step there.
void App::report_camera() const {
    std::cout << "camera: --set camera_yaw=" << camera_.yaw_deg << " --set camera_pitch=" << camera_.pitch_deg
              << " --set camera_distance=" << camera_.distance << std::endl;
}

// What the camera reads this frame; nothing reaches it while ImGui has the mouse or the keyboard.
// Moving the camera changes no parameter's generation: nothing is rebuilt for it.
CameraInput App::read_camera_input() const {
    CameraInput input;
    GLFWwindow* window = context_->window();
    if (window == nullptr) return input;
    input.drag = frame_input_.drag;
    input.scroll = frame_input_.scroll;
    if (!ImGui::GetIO().WantCaptureKeyboard) {
        auto key = [&](int k) { return glfwGetKey(window, k) == GLFW_PRESS ? 1.0f : 0.0f; };
        input.move = {key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_E) - key(GLFW_KEY_Q),
                      key(GLFW_KEY_W) - key(GLFW_KEY_S)};
        input.fast = key(GLFW_KEY_LEFT_SHIFT) > 0;
    }
    return input;
}

}  // namespace ocean
