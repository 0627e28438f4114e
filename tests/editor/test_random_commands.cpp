// Seeded random command sequences: after any mix of edits, undo-all gives back the byte-identical start,
// redo-all the byte-identical end, and undoing k steps then redoing them lands on the same text.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"

#include "core/random.h"
#include "level/level_io.h"

#include <filesystem>

using namespace ks;
using namespace ks::editor;
using level::EntityType;

namespace {
Vec3 random_point(Rng& rng) {
    return {rng.uniform(-40, 40), rng.uniform(0, 8), rng.uniform(-40, 40)};
}

void select_some(Editor& ed, Rng& rng) {
    std::vector<int> ids;
    for (const auto& e : ed.level().entities)
        if (rng.chance(0.3f)) ids.push_back(e.id);
    (void)select(ed, ids, rng.chance(0.5f) ? SelectMode::Replace : SelectMode::Toggle);
}

// One random edit through the same calls the UI makes; failures (nothing selected, out of range) are fine,
// they must just leave no trace.
void random_edit(Editor& ed, Rng& rng, std::string& clipboard) {
    const auto type = static_cast<EntityType>(rng.below(static_cast<std::uint32_t>(EntityType::Count)));
    switch (rng.below(14)) {
    case 0:
    case 1:
        (void)place(ed, type, random_point(rng), rng.uniform(-360, 360));
        break;
    case 2:
        select_some(ed, rng);
        break;
    case 3:
        (void)move_selection(ed, random_point(rng) * 0.1f, rng.chance(0.5f));
        break;
    case 4:
        (void)rotate_selection(ed, rng.uniform(-200, 200));
        break;
    case 5:
        (void)scale_selection(ed, {rng.uniform(0.5f, 2), rng.uniform(0.5f, 2), rng.uniform(0.5f, 2)});
        break;
    case 6:
        (void)duplicate(ed);
        break;
    case 7:
        (void)delete_selection(ed);
        break;
    case 8:
        clipboard = copy(ed);
        break;
    case 9:
        (void)paste_text(ed, clipboard);
        break;
    case 10:
        (void)set_field_text(ed, "name", "n" + std::to_string(rng.below(100)));
        break;
    case 11:
        (void)nudge(ed, static_cast<int>(rng.below(3)), rng.chance(0.5f) ? 1 : -1);
        break;
    case 12:
        (void)set_setting(ed, "fog_density", FieldValue(static_cast<double>(rng.uniform(0, 0.05f))));
        break;
    case 13: {
        ed.begin_transaction("Random drag");
        for (int i = 0; i < 5; ++i) (void)move_selection(ed, {rng.uniform(-1, 1), 0, rng.uniform(-1, 1)});
        if (rng.chance(0.3f))
            ed.cancel_transaction();
        else
            ed.commit_transaction();
        break;
    }
    }
}
} // namespace

TEST_CASE("random command sequences keep the undo/redo invariants (seeded)") {
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        CAPTURE(seed);
        Rng rng(seed);
        Editor ed;
        for (int i = 0; i < 8; ++i) (void)place(ed, EntityType::Pickup, random_point(rng));
        ed.end_merging();
        // Start from a saved-like state: the first steps are the baseline.
        const size_t baseline_steps = ed.history().undo_count();
        const std::string start = editor_test::text_of(ed);
        std::string clipboard;
        for (int i = 0; i < 120; ++i) {
            random_edit(ed, rng, clipboard);
            // Every state is a valid level as far as the format is concerned.
            if (i % 20 == 0) {
                auto report = level::validate(ed.level());
                REQUIRE_MESSAGE(!report.has_errors(), report.str());
            }
        }
        const std::string end = editor_test::text_of(ed);
        const size_t steps = ed.history().undo_count();

        // Partial undo then redo returns to the same text.
        const size_t k = rng.below(static_cast<std::uint32_t>(steps - baseline_steps + 1));
        for (size_t i = 0; i < k; ++i) REQUIRE(ed.undo());
        for (size_t i = 0; i < k; ++i) REQUIRE(ed.redo());
        CHECK(editor_test::text_of(ed) == end);

        while (ed.history().undo_count() > baseline_steps) REQUIRE(ed.undo());
        CHECK(editor_test::text_of(ed) == start);
        while (ed.redo()) {
        }
        CHECK(editor_test::text_of(ed) == end);
        CHECK(ed.history().undo_count() == steps);

        // What the editor produced loads back to the same level (save/load equality).
        auto reloaded = level::load_level_string(end, "random.json");
        REQUIRE_MESSAGE(reloaded.ok(), (reloaded.ok() ? std::string() : reloaded.error().str()));
        CHECK(reloaded->settings == ed.level().settings);
        REQUIRE(reloaded->entities.size() == ed.level().entities.size());
        for (size_t i = 0; i < reloaded->entities.size(); ++i) {
            CAPTURE(i);
            CHECK(reloaded->entities[i].position == ed.level().entities[i].position);
            CHECK(reloaded->entities[i].rotation == ed.level().entities[i].rotation);
            CHECK(reloaded->entities[i].props == ed.level().entities[i].props);
            CHECK(reloaded->entities[i] == ed.level().entities[i]);
        }
        CHECK(*reloaded == ed.level());
        CHECK(level::save_level_string(*reloaded) == end);
    }
}
