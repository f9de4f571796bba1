// The window's presses as events (common/input_events.hpp), fed as App's GLFW callbacks feed them:
// a press and release between two frames still acts, several taps act as many times, a key typed
// into an ImGui field is not the app's, and a drag starts where the button went down.
#include "common/input_events.hpp"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <vector>

namespace {

using ocean::InputEvent;
using ocean::InputQueue;
using ocean::KeyAction;

// The header repeats GLFW's numbers so that it needs no window system: they must be GLFW's.
static_assert(ocean::input::kPress == GLFW_PRESS && ocean::input::kRelease == GLFW_RELEASE &&
              ocean::input::kRepeat == GLFW_REPEAT);
static_assert(ocean::input::kMouseLeft == GLFW_MOUSE_BUTTON_LEFT && ocean::input::kMouseRight == GLFW_MOUSE_BUTTON_RIGHT);
static_assert(ocean::input::kKeyF1 == GLFW_KEY_F1 && ocean::input::kKeyF5 == GLFW_KEY_F5 &&
              ocean::input::kKeyEscape == GLFW_KEY_ESCAPE && ocean::input::kKeyC == GLFW_KEY_C);

// What one frame does with the queue (App::read_input): the actions of its events, in order.
std::vector<KeyAction> frame_actions(InputQueue& queue, bool keyboard_captured = false) {
    std::vector<KeyAction> actions;
    for (const InputEvent& e : queue.take())
        if (const KeyAction a = ocean::key_action(e, keyboard_captured); a != KeyAction::None) actions.push_back(a);
    return actions;
}

void tap(InputQueue& queue, int key) {
    queue.key(key, GLFW_PRESS, {0, 0});
    queue.key(key, GLFW_RELEASE, {0, 0});
}

TEST(InputEvents, TapWithinOneFrameActs) {
    InputQueue queue;
    tap(queue, GLFW_KEY_F1);  // both between two frames: polling would see the key up
    EXPECT_EQ(frame_actions(queue), std::vector<KeyAction>{KeyAction::TogglePanel});
    EXPECT_TRUE(queue.empty());
    EXPECT_TRUE(frame_actions(queue).empty());  // taken once
}

TEST(InputEvents, EveryTapOfASlowFrameActs) {
    InputQueue queue;
    for (int i = 0; i < 6; ++i) tap(queue, GLFW_KEY_F1);
    EXPECT_EQ(frame_actions(queue), std::vector<KeyAction>(6, KeyAction::TogglePanel));
}

TEST(InputEvents, EachFrameworkKey) {
    InputQueue queue;
    for (int key : {GLFW_KEY_ESCAPE, GLFW_KEY_F5, GLFW_KEY_C, GLFW_KEY_X}) tap(queue, key);
    EXPECT_EQ(frame_actions(queue),
              (std::vector<KeyAction>{KeyAction::Quit, KeyAction::ReloadShaders, KeyAction::SwitchCamera}));
}

TEST(InputEvents, RepeatsAreNotPresses) {
    InputQueue queue;
    queue.key(GLFW_KEY_F1, GLFW_PRESS, {0, 0});
    for (int i = 0; i < 10; ++i) queue.key(GLFW_KEY_F1, GLFW_REPEAT, {0, 0});  // held
    queue.key(GLFW_KEY_F1, GLFW_RELEASE, {0, 0});
    EXPECT_EQ(frame_actions(queue), std::vector<KeyAction>{KeyAction::TogglePanel});
}

TEST(InputEvents, KeysTypedIntoAFieldAreImGuis) {
    InputQueue queue;
    tap(queue, GLFW_KEY_C);
    tap(queue, GLFW_KEY_F1);
    EXPECT_TRUE(frame_actions(queue, /*keyboard_captured=*/true).empty());
    tap(queue, GLFW_KEY_F1);  // the field let go: the next frame's F1 is the app's
    EXPECT_EQ(frame_actions(queue, false), std::vector<KeyAction>{KeyAction::TogglePanel});
}

TEST(InputEvents, MouseButtonsKeepWhereTheyWent) {
    InputQueue queue;
    queue.mouse_button(GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS, {120, 45});
    const std::vector<InputEvent> events = queue.take();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, InputEvent::MouseButton);
    EXPECT_EQ(events[0].code, GLFW_MOUSE_BUTTON_RIGHT);
    EXPECT_TRUE(events[0].pressed);
    EXPECT_EQ(events[0].at, glm::dvec2(120, 45));
    EXPECT_EQ(ocean::key_action(events[0], false), KeyAction::None);
}

// The bug it replaces: the first frame of a drag counted the motion from the last frame's cursor
// to the press (62 degrees in step04).
TEST(DragTracker, FirstFrameMovesFromThePress) {
    InputQueue queue;
    ocean::DragTracker drag;
    EXPECT_EQ(drag.frame(queue.take(), {10, 10}, false), glm::dvec2(0));  // the cursor at a frame
    queue.mouse_button(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {500, 300});    // moved far, then down
    EXPECT_EQ(drag.frame(queue.take(), {520, 300}, false), glm::dvec2(20, 0));
    EXPECT_TRUE(drag.dragging());
    EXPECT_EQ(drag.frame(queue.take(), {530, 310}, false), glm::dvec2(10, 10));
    queue.mouse_button(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, {540, 310});
    EXPECT_EQ(drag.frame(queue.take(), {900, 700}, false), glm::dvec2(10, 0));  // up at 540: no further
    EXPECT_FALSE(drag.dragging());
    EXPECT_TRUE(drag.ended()) << "the frame of the release";
    EXPECT_EQ(drag.frame(queue.take(), {0, 0}, false), glm::dvec2(0));
    EXPECT_FALSE(drag.ended()) << "once";
}

TEST(DragTracker, WholeDragBetweenTwoFrames) {
    InputQueue queue;
    ocean::DragTracker drag;
    queue.mouse_button(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {100, 100});
    queue.mouse_button(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, {160, 90});
    EXPECT_EQ(drag.frame(queue.take(), {400, 400}, false), glm::dvec2(60, -10));
    EXPECT_FALSE(drag.dragging());
    EXPECT_TRUE(drag.ended()) << "a drag that never was dragging() at a frame still ends (its flags line)";
}

TEST(DragTracker, PressOnThePanelStartsNoDrag) {
    InputQueue queue;
    ocean::DragTracker drag;
    queue.mouse_button(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {50, 50});
    EXPECT_EQ(drag.frame(queue.take(), {80, 50}, /*mouse_captured=*/true), glm::dvec2(0));
    EXPECT_EQ(drag.frame(queue.take(), {200, 50}, false), glm::dvec2(0));  // still the panel's drag
    queue.mouse_button(GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS, {200, 50});  // other buttons drag nothing
    EXPECT_EQ(drag.frame(queue.take(), {250, 50}, false), glm::dvec2(0));
}

}  // namespace
