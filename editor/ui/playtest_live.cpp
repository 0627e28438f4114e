// The editor's end of the live play-test (playtest_live.h).
#include "ui/playtest_live.h"

#include "level/level_io.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

namespace ks::editor::ui {

Result<std::vector<std::pair<std::string, std::string>>> LivePlayLink::open() {
    close();
    auto folder = live::socket_folder();
    if (!folder) return folder.error();
    auto token = live::random_token();
    if (!token) return token.error();
    auto server =
        live::LiveServer::listen(*folder / ("killswitch-live-" + std::to_string(getpid()) + ".sock"), *token);
    if (!server) return server.error();
    server_.emplace(std::move(*server));
    sent_revision_.reset();
    pushed_ = applied_ = refused_ = 0;
    last_answer_.clear();
    return std::vector<std::pair<std::string, std::string>>{{live::kSocketVariable, server_->path().string()},
                                                            {live::kTokenVariable, server_->token()}};
}

void LivePlayLink::close() {
    server_.reset();
}

bool LivePlayLink::poll(const level::Level& level, std::uint64_t revision) {
    if (!server_) return false;
    if (!sent_revision_) sent_revision_ = revision;
    std::vector<live::Frame> frames;
    std::vector<live::LiveNote> notes;
    server_->poll(frames, notes);
    for (const auto& n : notes) note(n);
    for (const live::Frame& f : frames) {
        if (f.type == live::FrameType::Applied) {
            ++applied_;
            last_answer_ = f.payload;
            log_.line("live edit applied in the game: " + f.payload);
        } else if (f.type == live::FrameType::Refused) {
            ++refused_;
            last_answer_ = f.payload;
            log_.line("live edit refused by the game: " + f.payload, true);
        } else if (f.type == live::FrameType::Bye) {
            log_.line("the game went back to the editor");
        }
    }
    if (!server_->connected() || revision == sent_revision_) return false;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_push_ < kPushInterval) return true;
    server_->send(live::FrameType::Level, level::save_level_string(level));
    sent_revision_ = revision;
    last_push_ = now;
    ++pushed_;
    return false;
}

void LivePlayLink::status(nlohmann::json& playtest) const {
    nlohmann::json live;
    live["open"] = server_.has_value();
    live["connected"] = connected();
    live["pushed"] = pushed_;
    live["applied"] = applied_;
    live["refused"] = refused_;
    live["last_answer"] = last_answer_;
    playtest["live"] = live;
}

} // namespace ks::editor::ui
