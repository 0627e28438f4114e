// The game's end of the live play-test (live_edits.h).
#include "runtime/model/live_edits.h"

#include "level/level_io.h"
#include "level/scenery.h"

namespace ks::runtime {

Result<LiveEdit> apply_live_level(std::string_view text, const game::Game& running,
                                  const level::Level& before, const game::GameOptions& options) {
    auto loaded = level::load_level_string(text, "live update");
    if (!loaded) return loaded.error();
    auto rebuilt = game::rebuild_for_edit(running, before, *loaded, options);
    if (!rebuilt) return rebuilt.error();
    const bool scenery_changed = !level::same_scenery(before, *loaded);
    return LiveEdit{std::move(*loaded), std::move(*rebuilt), scenery_changed};
}

std::optional<LiveEdits> LiveEdits::from_environment() {
    auto client = live::LiveClient::from_environment();
    if (!client) return std::nullopt;
    return LiveEdits(std::move(*client));
}

std::optional<LiveEdit> LiveEdits::poll(double now, const game::Game& running, const level::Level& before,
                                        const game::GameOptions& options) {
    frames_.clear();
    notes_.clear();
    client_.poll(now, frames_, notes_);
    if (frames_.empty()) return std::nullopt;
    // Only the newest document matters: each is the whole level.
    const live::Frame& newest = frames_.back();
    auto edit = apply_live_level(newest.payload, running, before, options);
    if (!edit) {
        const std::string why = edit.error().str();
        client_.send(live::FrameType::Refused, why);
        ++refused_;
        notes_.push_back({true, "live edit refused: " + why});
        return std::nullopt;
    }
    const std::string summary = edit->rebuild.summary();
    client_.send(live::FrameType::Applied, summary);
    ++applied_;
    notes_.push_back({false, "live edit applied: " + summary});
    return std::move(*edit);
}

} // namespace ks::runtime
