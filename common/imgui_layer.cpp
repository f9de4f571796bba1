// App's ImGui layer: starting and stopping ImGui and its backends, and the frame around the panel.
#include "common/app.hpp"

#include "common/error.hpp"
#include "common/gl_profile.hpp"
#include "common/panel_state.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <iostream>

namespace ocean {

// ImGui frames run in every run (its capture flags judge the keys, app_input.cpp), but the panel is
// only drawn in a window or with --ui. ImGui's OpenGL 3 backend is started only then: in 1.86 it loads its GL
// functions through libGL.so.1 and GLX, which a GPU server rendering through EGL may not have.
void App::init_imgui(bool draw_panel) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini files left in the working directory
    ImGui::StyleColorsDark();
    panel_fit_ = std::make_unique<PanelFit>();
    imgui_ready_ = true;
    if (GLFWwindow* window = context_->window()) {
        glfwSetWindowUserPointer(window, this);
        // Ours before ImGui's backend, which chains to them (imgui_impl_glfw.cpp): the presses
        // reach the App's queue as they happen (app_input.cpp).
        glfwGetCursorPos(window, &cursor_.x, &cursor_.y);
        glfwSetCursorPosCallback(window, &App::on_cursor_pos);
        glfwSetScrollCallback(window, &App::on_scroll);
        glfwSetKeyCallback(window, &App::on_key);
        glfwSetMouseButtonCallback(window, &App::on_mouse_button);
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        panel_state_ = std::make_unique<PanelState>(panel_state_path(step_name()));
    }
    if (!draw_panel) {
        ImGui::GetIO().Fonts->Build();  // what the renderer's NewFrame would do; no texture needed
        return;
    }
    if (!ImGui_ImplOpenGL3_Init(kBuildProfile == GlProfile::Core45   ? "#version 450 core"
                                 : kBuildProfile == GlProfile::Core41 ? "#version 410 core"
                                                                      : "#version 300 es"))
        throw Error("ImGui's OpenGL 3 backend cannot start: it loads GL through libGL.so.1 "
                    "(install libgl1), even when the context comes from EGL");
    imgui_renderer_ready_ = true;
}

// Input for this frame's widgets: from the window, or (headless) a display of the target's size.
void App::begin_imgui_frame(double dt) {
    if (imgui_renderer_ready_) ImGui_ImplOpenGL3_NewFrame();
    if (context_->window() != nullptr) {
        ImGui_ImplGlfw_NewFrame();
    } else {
        ImGui::GetIO().DisplaySize = ImVec2(float(framebuffer_size_.x), float(framebuffer_size_.y));
        ImGui::GetIO().DeltaTime = float(dt > 0 ? dt : 1.0 / 60.0);
    }
    // The panel's text grows with a large display (panel_state.hpp).
    ImGuiIO& io = ImGui::GetIO();
    io.FontGlobalScale = panel_font_scale(io.DisplaySize.x, io.DisplaySize.y);
    ImGui::NewFrame();
}

// The widgets become draw data (drawn over the frame by App::frame where the panel shows).
void App::end_imgui_frame() { ImGui::Render(); }

void App::shutdown_imgui() {
    if (!imgui_ready_) return;
    if (imgui_renderer_ready_) ImGui_ImplOpenGL3_Shutdown();
    imgui_renderer_ready_ = false;
    if (context_ && context_->window() != nullptr) {
        ImGui_ImplGlfw_Shutdown();  // puts our callbacks back; they find no App from now on
        glfwSetWindowUserPointer(context_->window(), nullptr);
    }
    if (panel_state_) panel_state_->flush(std::cerr);  // a change made in the last second before closing, too
    panel_state_.reset();
    panel_fit_.reset();
    ImGui::DestroyContext();
    imgui_ready_ = false;
}

}  // namespace ocean
