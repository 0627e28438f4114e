#pragma once
// The game's end of the live play-test, window-free (docs/editor.md, "Live play-test"): the channel to the
// editor that started this game (core/live_channel.h, from the environment the editor set), each level
// document it sends read with the level loader and played through game/live_update.h, and the answer sent
// back: Applied with a summary, or Refused with the loader's or the build's message. A refused update
// changes nothing: the game plays on with the level it had. The app shows notes() as a toast.
#include "core/live_channel.h"
#include "core/result.h"
#include "game/live_update.h"
#include "level/level.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ks::runtime {

// A level update that builds: the level and the game on it with the running state carried over.
struct LiveEdit {
    level::Level level;
    game::LiveRebuild rebuild;
    // The edit changed the level's scenery (level/scenery.h): the view builds its scene and light bake
    // again. When false (robots, pickups, spawners, triggers, links, lights switched...), the running
    // view keeps its scene and bake and follows the new game.
    bool scenery_changed = true;
};

// Reads `text` (a whole level document) with the level loader and rebuilds `running` on it. Errors are the
// loader's (every problem at its line:column) or the game build's, naming the entity.
Result<LiveEdit> apply_live_level(std::string_view text, const game::Game& running,
                                  const level::Level& before, const game::GameOptions& options);

class LiveEdits {
  public:
    explicit LiveEdits(live::LiveClient client) : client_(std::move(client)) {}
    // When the editor started this game live (its environment says so).
    static std::optional<LiveEdits> from_environment();

    // Once a frame: reads the channel; the newest level update that builds comes back (older ones waiting
    // in the same poll are superseded), each refused one is answered and noted. `now`: seconds, any clock.
    std::optional<LiveEdit> poll(double now, const game::Game& running, const level::Level& before,
                                 const game::GameOptions& options);
    // What happened in the last poll (connected, applied, refused), for the toast and the log.
    const std::vector<live::LiveNote>& notes() const { return notes_; }
    bool connected() const { return client_.connected(); }
    int applied() const { return applied_; } // level updates played so far
    int refused() const { return refused_; }
    // The player chose "Back to editor".
    void say_bye() { client_.send(live::FrameType::Bye, {}); }

  private:
    live::LiveClient client_;
    std::vector<live::Frame> frames_;
    std::vector<live::LiveNote> notes_;
    int applied_ = 0, refused_ = 0;
};

} // namespace ks::runtime
