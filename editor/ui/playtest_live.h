#pragma once
// The editor's end of the live play-test (docs/editor.md, "Live play-test"): while the game it started runs,
// every edit (anything that changes the document's revision: entities, lights, links, brushes, materials,
// level settings) goes to the game as the whole level document, at most every kPushInterval, over a Unix
// socket the editor listens on (core/live_channel.h). The game answers Applied or Refused; both, and the
// channel's own news (connected, a stranger refused, garbage), go to the log and the status file.
#include "core/live_channel.h"
#include "core/result.h"
#include "level/level.h"
#include "ui/editor_log.h"

#include <nlohmann/json_fwd.hpp>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ks::editor::ui {

class LivePlayLink {
  public:
    static constexpr std::chrono::milliseconds kPushInterval{200};

    explicit LivePlayLink(EditorLog& log) : log_(log) {}

    // A new channel for a play-test of the document as it is at the next poll: the environment to give the
    // game (live::kSocketVariable, live::kTokenVariable), or an error (the play-test then runs without it).
    Result<std::vector<std::pair<std::string, std::string>>> open();
    void close();
    // Every editor frame and idle poll: the channel's news, and the level pushed when it changed. True
    // while an edit waits to be sent (the window asks for another frame).
    bool poll(const level::Level& level, std::uint64_t revision);
    void status(nlohmann::json& playtest) const; // "live" in the status file's "playtest"
    bool connected() const { return server_ && server_->connected(); }

  private:
    void note(const live::LiveNote& n) { log_.line(n.text, n.error); }

    EditorLog& log_;
    std::optional<live::LiveServer> server_;
    std::optional<std::uint64_t> sent_revision_; // the game has it (or was sent it); set at the first poll
    std::chrono::steady_clock::time_point last_push_{};
    int pushed_ = 0, applied_ = 0, refused_ = 0;
    std::string last_answer_; // the game's last Applied or Refused text
};

} // namespace ks::editor::ui
