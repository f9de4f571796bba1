// The window's key and mouse-button presses, kept as events so that none is lost: the GLFW
// callbacks (App::on_key, App::on_mouse_button in app_input.cpp) push each press and release into
// an InputQueue as it arrives, and once a frame the App takes the queue and acts on every press in
// order. Polling the keys once a frame instead misses a press and release that fall between two
// frames (a quick tap at 15 fps, a normal one at 6 fps). No GLFW here: the unit tests feed the
// queue as the callbacks do (tests/unit/test_input_events.cpp). Header-only: small, and built
// into whatever includes it.
#pragma once

#include <glm/vec2.hpp>

#include <utility>
#include <vector>

namespace ocean {

// GLFW's values (glfw3.h), repeated so that this header needs no window system.
namespace input {
inline constexpr int kRelease = 0, kPress = 1, kRepeat = 2;  // GLFW_RELEASE, GLFW_PRESS, GLFW_REPEAT
inline constexpr int kMouseLeft = 0, kMouseRight = 1;        // GLFW_MOUSE_BUTTON_LEFT, _RIGHT
inline constexpr int kKeyC = 67, kKeyEscape = 256, kKeyF1 = 290, kKeyF5 = 294;
}  // namespace input

struct InputEvent {
    enum Kind { Key, MouseButton };
    Kind kind = Key;
    int code = 0;        // the GLFW key or mouse button
    bool pressed = true;  // false: released
    glm::dvec2 at{0.0};  // the cursor, in window pixels, when it happened
};

class InputQueue {
public:
    // What the GLFW key callback receives; key repeats are not presses (holding F1 toggles once).
    void key(int key, int action, glm::dvec2 cursor);
    // What the GLFW mouse-button callback receives, with the cursor where the button went down.
    void mouse_button(int button, int action, glm::dvec2 cursor);
    // The events since the last take, oldest first; the queue is empty after.
    std::vector<InputEvent> take();
    bool empty() const { return events_.empty(); }

private:
    std::vector<InputEvent> events_;
};

// What the framework does with a key press (App::handle_keys).
enum class KeyAction { None, TogglePanel, Quit, ReloadShaders, SwitchCamera };
// The action of one event: a press of F1, Esc, F5 or C, unless ImGui holds the keyboard (a text
// field being typed in, a slider being dragged: `keyboard_captured`). Releases act on nothing.
KeyAction key_action(const InputEvent& event, bool keyboard_captured);

// The left-button drag across frames, from the button's events: the first frame's motion is from
// where the button went down (not from where the cursor was at the frame before), and a press,
// move and release between two frames still counts.
class DragTracker {
public:
    // This frame's drag in pixels, from its events (oldest first) and the cursor now. A press that
    // `mouse_captured` (ImGui's panel under it) starts no drag.
    glm::dvec2 frame(const std::vector<InputEvent>& events, glm::dvec2 cursor, bool mouse_captured);
    bool dragging() const { return dragging_; }
    // Whether a drag ended within the last frame's events: one that started in an earlier frame,
    // or a press, move and release all between two frames (common at 3 to 10 frames a second),
    // which was never dragging() at a frame.
    bool ended() const { return ended_; }

private:
    bool dragging_ = false, ended_ = false;
    glm::dvec2 last_{0.0};
};

// Definitions.

inline void InputQueue::key(int key, int action, glm::dvec2 cursor) {
    if (action == input::kRepeat) return;
    events_.push_back({InputEvent::Key, key, action == input::kPress, cursor});
}

inline void InputQueue::mouse_button(int button, int action, glm::dvec2 cursor) {
    if (action == input::kRepeat) return;
    events_.push_back({InputEvent::MouseButton, button, action == input::kPress, cursor});
}

inline std::vector<InputEvent> InputQueue::take() { return std::exchange(events_, {}); }

inline KeyAction key_action(const InputEvent& event, bool keyboard_captured) {
    if (event.kind != InputEvent::Key || !event.pressed || keyboard_captured) return KeyAction::None;
    switch (event.code) {
        case input::kKeyF1: return KeyAction::TogglePanel;
        case input::kKeyEscape: return KeyAction::Quit;
        case input::kKeyF5: return KeyAction::ReloadShaders;
        case input::kKeyC: return KeyAction::SwitchCamera;
        default: return KeyAction::None;
    }
}

inline glm::dvec2 DragTracker::frame(const std::vector<InputEvent>& events, glm::dvec2 cursor, bool mouse_captured) {
    glm::dvec2 drag(0.0);
    ended_ = false;
    for (const InputEvent& e : events) {
        if (e.kind != InputEvent::MouseButton || e.code != input::kMouseLeft) continue;
        if (e.pressed) {
            if (dragging_) drag += e.at - last_;  // a press without its release (focus lost): go on
            dragging_ = dragging_ || !mouse_captured;
            last_ = e.at;
        } else if (dragging_) {
            drag += e.at - last_;
            dragging_ = false;
            ended_ = true;
        }
    }
    if (dragging_) {
        drag += cursor - last_;
        last_ = cursor;
    }
    return drag;
}

}  // namespace ocean
