#include "runtime/model/logic_debugger.h"

#include "jsonio/text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <utility>

namespace ks::runtime {

bool LogicBreak::matches(const game::LogicRecord& r) const {
    if (r.is_action) return false;
    if (event && r.event != *event) return false;
    return entity < 0 || (r.source.kind == game::LogicEnd::Kind::Entity && r.source.id == entity);
}

std::string LogicBreak::text() const {
    const std::string name = event ? std::string(level::event_name(*event)) : "";
    if (entity < 0) return name.empty() ? "any event" : name;
    return std::to_string(entity) + (name.empty() ? "" : ":" + name);
}

LogicBreak LogicBreak::at(const game::LogicRecord& r) {
    LogicBreak b;
    b.event = r.event;
    if (r.source.kind == game::LogicEnd::Kind::Entity) b.entity = r.source.id;
    return b;
}

Result<LogicBreak> parse_logic_break(std::string_view spec) {
    const Location where("command line", 0, 0, "--logic-break");
    const std::string fix = "give an entity id (--logic-break 68), an event (--logic-break on_enter) or both "
                            "(--logic-break 68:on_enter); the editor's inspector shows an entity's id";
    LogicBreak b;
    const std::size_t colon = spec.find(':');
    std::string_view id_text = colon == std::string_view::npos ? spec : spec.substr(0, colon);
    std::string_view event_text =
        colon == std::string_view::npos ? std::string_view{} : spec.substr(colon + 1);
    if (colon == std::string_view::npos && !spec.empty() &&
        !std::isdigit(static_cast<unsigned char>(spec[0])))
        std::swap(id_text, event_text); // an event name alone
    if (!id_text.empty()) {
        int id = 0;
        const auto [end, ec] = std::from_chars(id_text.data(), id_text.data() + id_text.size(), id);
        if (ec != std::errc() || end != id_text.data() + id_text.size() || id <= 0)
            return Error(jsonio::quote_text(id_text) + " is not an entity id", where, fix);
        b.entity = id;
    }
    if (!event_text.empty()) {
        b.event = level::event_from_name(event_text);
        if (!b.event)
            return Error(
                jsonio::quote_text(event_text) + " is not an event (one of " +
                    [] {
                        std::string all;
                        for (const auto e : level::all_events())
                            all += (all.empty() ? "" : ", ") + std::string(level::event_name(e));
                        return all;
                    }() +
                    ")",
                where, fix);
    }
    if (colon != std::string_view::npos && (id_text.empty() || event_text.empty()))
        return Error(jsonio::quote_text(spec) + " needs both sides of the ':'", where, fix);
    if (b.entity < 0 && !b.event) return Error("an entity id or an event is needed", where, fix);
    return b;
}

void LogicDebugger::reset(const level::Level& level, double step_seconds) {
    level_ = &level;
    names_.emplace(level);
    step_seconds_ = step_seconds;
    entries_.clear();
    hit_.reset();
    halted_ = step_requested_ = false;
}

bool LogicDebugger::may_step() {
    if (!halted_) return true;
    return std::exchange(step_requested_, false);
}

void LogicDebugger::after_step(const game::Game& game) {
    if (!names_) return;
    if (hit_ && hit_->record.step != game.steps()) hit_.reset(); // a step taken since: the next hit is new
    names_->add_spawned(game.events());
    for (const game::LogicRecord& r : game.logic().records()) {
        entries_.push_back({r, game::logic_trace_line(r, *names_, step_seconds_)});
        if (entries_.size() > kMaxEntries) entries_.pop_front();
        if (break_ && break_->matches(r) && !hit_) {
            halted_ = true;
            hit_ = entries_.back();
        }
    }
}

Vec3 LogicDebugger::place(const game::LogicEnd& end, const game::Game& game) const {
    const Vec3 eye = game.player().eye();
    if (end.kind != game::LogicEnd::Kind::Entity) return eye;
    for (const game::Robot& r : game.robots())
        if (r.entity_id == end.id) return r.feet + Vec3(0.0f, game.settings().robot_height * 0.6f, 0.0f);
    if (level_)
        if (const level::Entity* e = level_->find(end.id)) return e->position + Vec3(0.0f, 1.5f, 0.0f);
    return eye;
}

} // namespace ks::runtime
