// The runtime model's campaign and HUD state: CampaignProgress (levels in order, results, totals),
// accuracy and time texts, the "Objective complete" banner's timer and the objective list's rows.
#include "game/game_test_levels.h"
#include "level/level_io.h"
#include "runtime/model/campaign_progress.h"
#include "runtime/model/hud_presentation.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <utility>

using namespace ks;
using namespace ks::runtime;

namespace {
level::Campaign two_levels() {
    return {"Test run", {{"one.json", "First Light"}, {"more/two.json", "Second Wind"}}};
}
} // namespace

TEST_CASE("campaign progress: levels in order, a result per win, totals, and no step past the end") {
    CampaignProgress progress(two_levels(), "/data/campaigns/run.json");
    CHECK(progress.count() == 2);
    CHECK(progress.index() == 0);
    CHECK(progress.current().title == "First Light");
    CHECK(progress.current_path() == std::filesystem::path("/data/campaigns/one.json"));
    CHECK_FALSE(progress.on_last_level());
    CHECK_FALSE(progress.advance()); // not won yet
    CHECK(progress.last_result() == nullptr);

    progress.record_win({"ignored", 62.5, 3, 4, 20, 15, ""});
    CHECK(progress.results().size() == 1);
    CHECK(progress.last_result()->title == "First Light"); // the campaign's title, not the level's name
    CHECK_FALSE(progress.finished());
    // A retry after a win (Play Again is not offered, but a second win must not add a row).
    progress.record_win({"", 60.0, 4, 4, 18, 16, ""});
    CHECK(progress.results().size() == 1);
    CHECK(progress.results()[0].seconds == 60.0);

    REQUIRE(progress.advance());
    CHECK(progress.index() == 1);
    CHECK(progress.current_path() == std::filesystem::path("/data/campaigns/more/two.json"));
    CHECK(progress.on_last_level());
    progress.record_win({"", 30.25, 2, 5, 10, 4, ""});
    CHECK(progress.finished());
    CHECK_FALSE(progress.advance());
    const LevelResult total = progress.totals();
    CHECK(total.title == "Test run");
    CHECK(total.seconds == doctest::Approx(90.25));
    CHECK(total.robots_killed == 6);
    CHECK(total.robots_total == 9);
    CHECK(total.shots == 28);
    CHECK(total.hits == 20);
    progress.record_win({"", 1.0, 0, 0, 0, 0, ""}); // after the end: nothing changes
    CHECK(progress.results().size() == 2);
}

TEST_CASE("accuracy: hits over shots as a whole percent, a dash without a shot") {
    CHECK(accuracy_text(15, 20) == "75 %");
    CHECK(accuracy_text(1, 3) == "33 %");
    CHECK(accuracy_text(2, 3) == "67 %");
    CHECK(accuracy_text(0, 12) == "0 %");
    CHECK(accuracy_text(5, 5) == "100 %");
    CHECK(accuracy_text(0, 0) == "-");
    CHECK(accuracy_text(9, 4) == "100 %"); // never above 100
    CHECK(accuracy_text(-1, 4) == "0 %");
}

TEST_CASE("level time: minutes, seconds and tenths; never 60 seconds; nothing that is not a time") {
    CHECK(format_time(0.0) == "0:00.0");
    CHECK(format_time(5.2) == "0:05.2");
    CHECK(format_time(16.43) == "0:16.4");
    CHECK(format_time(125.36) == "2:05.4");
    CHECK(format_time(59.96) == "1:00.0"); // rounded before it is split
    CHECK(format_time(3600.0) == "60:00.0");
    CHECK(format_time(-3.0) == "0:00.0");
    CHECK(format_time(NAN) == "0:00.0");
    CHECK(format_time(INFINITY) == "0:00.0");
}

TEST_CASE(
    "objective banner: an ObjectiveCompleted event shows the objective's text, then it fades and ends") {
    level::LoadReport report;
    auto lv = level::load_level_file(test::data_dir() / "levels" / "logic_hall.json", &report);
    REQUIRE_MESSAGE(lv.ok(), report.str());
    auto g = game_test::make_game(*lv);
    ObjectiveFlash flash;
    const float dt = static_cast<float>(g->settings().step);
    g->step({});
    flash.after_step(*g, dt);
    CHECK_FALSE(flash.visible());
    REQUIRE(g->complete_objective("clear_hall"));
    flash.after_step(*g, 0.0f);
    CHECK(flash.visible());
    CHECK(flash.text() == "Clear the hall");
    CHECK(flash.strength() == 1.0f);
    CHECK(flash.age() == 0.0f);
    float t = 0.0f;
    for (; t < ObjectiveFlash::kSeconds - ObjectiveFlash::kFadeSeconds * 0.5f; t += dt) {
        g->step({});
        flash.after_step(*g, dt);
    }
    CHECK(flash.visible());
    CHECK(flash.strength() == doctest::Approx(0.5f).epsilon(0.05));
    for (; t < ObjectiveFlash::kSeconds + 0.1f; t += dt) {
        g->step({});
        flash.after_step(*g, dt);
    }
    CHECK_FALSE(flash.visible());
    CHECK(flash.strength() == 0.0f);
}

TEST_CASE("objective list rows: at most six, around the current objective, the last ones when all are done") {
    const ObjectiveRows few = objective_rows(3, 1);
    CHECK(few.first == 0);
    CHECK(few.end == 3);
    CHECK(few.hidden_before + few.hidden_after == 0);
    const ObjectiveRows early = objective_rows(10, 1);
    CHECK(early.first == 0);
    CHECK(early.end == 6);
    CHECK(early.hidden_after == 4);
    const ObjectiveRows middle = objective_rows(10, 5);
    CHECK(middle.first == 3); // two done ones before the current
    CHECK(middle.end == 9);
    CHECK(middle.hidden_before == 3);
    CHECK(middle.hidden_after == 1);
    const ObjectiveRows late = objective_rows(10, 9);
    CHECK(late.first == 4);
    CHECK(late.end == 10);
    const ObjectiveRows done = objective_rows(10, -1);
    CHECK(done.first == 4);
    CHECK(done.end == 10);
    const ObjectiveRows none = objective_rows(0, -1);
    CHECK(none.first == 0);
    CHECK(none.end == 0);
}

TEST_CASE("message line: fades in over 0.2 s and out over the last 0.5 s") {
    game::ShownMessage m;
    m.text = "Hello";
    m.duration = 4.0f;
    m.time_left = 0.0f;
    CHECK(message_alpha(m) == 0.0f);
    m.time_left = 4.0f;
    CHECK(message_alpha(m) == 0.0f);
    m.time_left = 3.9f;
    CHECK(message_alpha(m) == doctest::Approx(0.5f));
    m.time_left = 2.0f;
    CHECK(message_alpha(m) == 1.0f);
    m.time_left = 0.25f;
    CHECK(message_alpha(m) == doctest::Approx(0.5f));
}

TEST_CASE("message line: never covers the objective panel or the bars, at any window size and panel size") {
    // Text measured as a fixed-width font of 24 px at 720 (13 px per character, lines as tall as the font, as
    // ImGui sets them), wrapped at `wrap`.
    auto measure_for = [](std::size_t chars, float s) {
        return [chars, s](float wrap) {
            const float advance = 13.0f * s, line = 24.0f * s;
            const float per_line = std::max(1.0f, std::floor(wrap / advance));
            const float lines = std::ceil(static_cast<float>(chars) / per_line);
            return std::pair(std::min(static_cast<float>(chars), per_line) * advance, lines * line);
        };
    };
    const std::pair<float, float> sizes[] = {{1280, 720},  {1920, 1080}, {800, 600},   {1024, 768},
                                             {2560, 1440}, {640, 480},   {1280, 1024}, {3440, 1440}};
    const std::size_t messages[] = {12, 40, 69, 140};
    const float widest_texts[] = {0.0f, 200.0f, 430.0f, 2000.0f};
    for (const auto& [w, h] : sizes)
        for (const float widest : widest_texts)
            for (int lines = 1; lines <= ObjectiveRows::kMaxRows + 2; ++lines)
                for (const std::size_t chars : messages) {
                    const float s = hud_scale(h);
                    const HudBox panel = objective_panel_box(w, s, widest * s, lines);
                    const MessageLayout l = message_layout(w, h, s, panel, measure_for(chars, s));
                    INFO(w << "x" << h << ", panel " << widest << " wide with " << lines << " rows, " << chars
                           << " characters");
                    CHECK_FALSE(l.box.overlaps(panel));
                    CHECK_FALSE(l.box.overlaps(status_bars_box(s)));
                    CHECK(l.box.x0 >= 0.0f);
                    CHECK(l.box.x1 <= w);
                }
    // Lockdown at 1280x720 (three objectives, a message of one line at 60 % of the width): the message stays
    // upper middle, centred, below the panel.
    const HudBox lockdown = objective_panel_box(1280, 1, 430, 3);
    const MessageLayout l = message_layout(1280, 720, 1, lockdown, measure_for(58, 1));
    CHECK(l.box.y0 >= lockdown.y1);
    CHECK(l.box.y1 < 720 * 0.3f);
    CHECK((l.box.x0 + l.box.x1) * 0.5f == doctest::Approx(640));
    // Without objectives and with a short message it keeps its old place at 17 % of the height.
    CHECK(message_layout(1280, 720, 1, HudBox{}, measure_for(12, 1)).text_y == doctest::Approx(720 * 0.17f));
    // A panel of eight lines pushes a centred message into the banner's band: it moves up beside the panel.
    const HudBox tall = objective_panel_box(1280, 1, 300, 8);
    const MessageLayout beside = message_layout(1280, 720, 1, tall, measure_for(40, 1));
    CHECK(beside.box.y0 < tall.y1);
    CHECK(beside.box.x1 <= tall.x0);
}
