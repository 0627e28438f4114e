// The runtime's input plumbing without a window: event-fed key and button state (taps shorter than a frame
// count once), mouse look that sums to the same turn at any frame rate, the per-frame step budget that
// keeps a slow machine from spiralling, and the --input-script parser with its errors.
#include "core/fixed_step.h"
#include "runtime/model/input_script.h"
#include "runtime/model/input_state.h"
#include "runtime/model/keyboard_mouse_input.h"
#include "runtime/model/step_budget.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace ks;
using namespace ks::runtime;

namespace {
constexpr int kKeyE = 'E';
constexpr int kPress = InputState::kPress, kRelease = InputState::kRelease, kRepeat = 2;
} // namespace

TEST_CASE("input state: a tap between two polls counts once; repeats and releases are not presses") {
    InputState s;
    // Press and release before the game looks (xdotool's click, a quick tap at 4 fps).
    s.key(kKeyE, kPress);
    s.key(kKeyE, kRelease);
    CHECK_FALSE(s.held(kKeyE));
    CHECK(s.take_press(kKeyE));
    CHECK_FALSE(s.take_press(kKeyE)); // once
    // Held with auto-repeat: one press.
    s.key(kKeyE, kPress);
    s.key(kKeyE, kRepeat);
    s.key(kKeyE, kRepeat);
    CHECK(s.held(kKeyE));
    CHECK(s.take_press(kKeyE));
    CHECK_FALSE(s.take_press(kKeyE));
    CHECK(s.down_or_tapped(kKeyE)); // still held
    s.key(kKeyE, kRelease);
    CHECK_FALSE(s.down_or_tapped(kKeyE));
    // A tap of W between two steps still moves the player for one step.
    s.key('W', kPress);
    s.key('W', kRelease);
    CHECK(s.down_or_tapped('W'));
    CHECK_FALSE(s.down_or_tapped('W'));
    // Buttons likewise.
    s.button(0, kPress);
    s.button(0, kRelease);
    CHECK(s.take_click(0));
    CHECK_FALSE(s.take_click(0));
}

TEST_CASE("input state: absurd codes are ignored, focus loss releases everything") {
    InputState s;
    s.key(-1, kPress); // GLFW_KEY_UNKNOWN
    s.key(100000, kPress);
    s.button(-3, kPress);
    s.button(99, kPress);
    CHECK_FALSE(s.take_press(-1));
    CHECK_FALSE(s.take_press(100000));
    CHECK_FALSE(s.take_click(99));
    s.key('W', kPress);
    s.button(1, kPress);
    s.release_all();
    CHECK_FALSE(s.held('W'));
    CHECK_FALSE(s.button_held(1));
    CHECK_FALSE(s.take_press('W'));
}

TEST_CASE("mouse look: the same hand motion turns the same amount at 4 fps and at 144 fps") {
    // 300 px right and 120 px down over one second, reported in `frames` pieces; each frame runs the fixed
    // steps its time covers and each step takes the motion since the previous one.
    Options options;
    options.mouse_sensitivity = 1.7f;
    auto turn = [&](int frames, float& yaw, float& pitch) {
        InputState s;
        FixedStepClock clock(1.0 / 120.0);
        s.cursor(0.0, 0.0);
        yaw = pitch = 0.0f;
        for (int f = 1; f <= frames; ++f) {
            s.cursor(300.0 * f / frames, 120.0 * f / frames);
            const int steps = clock.advance(1.0 / frames);
            for (int i = 0; i < steps; ++i) {
                double dx = 0, dy = 0;
                s.take_motion(dx, dy);
                float y = 0, p = 0;
                look_from_motion(dx, dy, options, y, p);
                yaw += y;
                pitch += p;
            }
        }
    };
    float yaw4 = 0, pitch4 = 0, yaw144 = 0, pitch144 = 0, yaw_odd = 0, pitch_odd = 0;
    turn(4, yaw4, pitch4);
    turn(144, yaw144, pitch144);
    turn(7, yaw_odd, pitch_odd); // frames that do not divide the 120 Hz step
    const float expected_yaw = -300.0f * Options::kRadiansPerPixel * 1.7f;
    const float expected_pitch = -120.0f * Options::kRadiansPerPixel * 1.7f;
    CHECK(yaw4 == doctest::Approx(expected_yaw).epsilon(1e-5));
    CHECK(yaw144 == doctest::Approx(expected_yaw).epsilon(1e-5));
    CHECK(yaw_odd == doctest::Approx(expected_yaw).epsilon(1e-5));
    CHECK(pitch4 == doctest::Approx(expected_pitch).epsilon(1e-5));
    CHECK(pitch144 == doctest::Approx(expected_pitch).epsilon(1e-5));
    // Invert Y flips only the pitch.
    options.invert_y = true;
    float y = 0, p = 0;
    look_from_motion(10.0, 10.0, options, y, p);
    CHECK(y < 0.0f);
    CHECK(p > 0.0f);
    // Capturing the cursor (its jump to the lock point) is not a look.
    InputState s;
    s.cursor(100, 100);
    s.cursor(640, 360);
    s.clear_latches();
    s.cursor(645, 360);
    double dx = 0, dy = 0;
    s.take_motion(dx, dy);
    CHECK(dx == 0.0); // the first position after clear is only the new origin
    s.cursor(650, 360);
    s.take_motion(dx, dy);
    CHECK(dx == 5.0);
}

TEST_CASE("step budget: at most 30 steps per frame, the rest dropped; no spiral when steps are slow") {
    StepBudget budget(30);
    int ran = 0;
    for (int i = 0; i < 1000; ++i) ran += budget.take() ? 1 : 0; // a 8.3 s hitch (a level loading)
    CHECK(ran == 30);
    CHECK(budget.dropped() == 970);
    budget.new_frame();
    CHECK(budget.take());
    CHECK(StepBudget(0).max_steps() == 1);

    // A machine where a step costs 12 ms (slower than the 8.3 ms it simulates) and drawing 100 ms: without a
    // budget each frame runs more steps than the last; with it the frame time settles.
    auto frame_times = [](bool with_budget) {
        FixedStepClock clock(1.0 / 120.0);
        StepBudget b(30);
        double frame = 0.1;
        std::vector<double> times;
        for (int f = 0; f < 12; ++f) {
            const int steps = clock.advance(frame);
            b.new_frame();
            int run = 0;
            for (int i = 0; i < steps; ++i)
                if (!with_budget || b.take()) ++run;
            frame = 0.1 + 0.012 * run;
            times.push_back(frame);
        }
        return times;
    };
    const auto spiral = frame_times(false);
    const auto capped = frame_times(true);
    CHECK(spiral.back() > 10.0 * spiral.front()); // the spiral the budget prevents
    CHECK(capped.back() <= 0.1 + 0.012 * 30 + 1e-9);
    CHECK(capped.back() == doctest::Approx(capped[capped.size() - 2]));
}

TEST_CASE("input script: parses keys, buttons, motion and menu clicks in frame order") {
    const std::string text = "# walk in, open, shoot\n"
                             "0 click Play\n"
                             "5 key w down   # hold\n"
                             "40 key w up\n"
                             "41 key e tap\n"
                             "42 mouse left click\n"
                             "43 look 120 -8.5\n"
                             "44 move 10 20\n"
                             "44 key escape tap\n"
                             "45 click Main Menu\n"
                             "50 quit\n";
    auto events = parse_input_script(text, "s.txt");
    REQUIRE(events);
    REQUIRE(events->size() == 10);
    const auto& e = *events;
    CHECK(e[0].kind == ScriptEvent::Kind::ClickButton);
    CHECK(e[0].label == "Play");
    CHECK(e[1].kind == ScriptEvent::Kind::Key);
    CHECK(e[1].code == 'W');
    CHECK(e[1].action == 1);
    CHECK(e[1].frame == 5);
    CHECK(e[2].action == 0);
    CHECK(e[3].code == 'E');
    CHECK(e[3].action == 2);
    CHECK(e[4].kind == ScriptEvent::Kind::Mouse);
    CHECK(e[4].code == 0);
    CHECK(e[5].kind == ScriptEvent::Kind::Look);
    CHECK(e[5].y == doctest::Approx(-8.5));
    CHECK(e[7].code == 256); // GLFW_KEY_ESCAPE
    CHECK(e[8].label == "Main Menu");
    CHECK(e[9].kind == ScriptEvent::Kind::Quit);
    CHECK(e[9].line == 11);
}

TEST_CASE("input script: bad lines are refused with the file, line and a fix") {
    struct Bad {
        const char* text;
        const char* says;
    };
    const Bad cases[] = {
        {"x key w down\n", "not a frame number"},
        {"-3 key w down\n", "not a frame number"},
        {"10 key w down\n5 key w up\n", "comes after frame"},
        {"1 key ctrl down\n", "unknown key"},
        {"1 key w press\n", "key action"},
        {"1 mouse middle click\n", "unknown mouse button"},
        {"1 look 5\n", "two finite numbers"},
        {"1 move nan 3\n", "two finite numbers"},
        {"1 click\n", "needs a button label"},
        {"1 jump\n", "unknown command"},
        {"1 quit now\n", "unexpected 'now'"},
    };
    for (const auto& c : cases) {
        CAPTURE(c.text);
        auto parsed = parse_input_script(std::string("# header\n") + c.text, "bad.txt");
        REQUIRE_FALSE(parsed);
        const std::string message = parsed.error().str();
        CHECK(message.find(c.says) != std::string::npos);
        CHECK(message.find("bad.txt:") != std::string::npos);
        CHECK(parsed.error().where.line >= 2);
    }
    auto empty = parse_input_script("\n# nothing\n   \n", "e.txt");
    REQUIRE(empty);
    CHECK(empty->empty());
}
