// The level logic's bookkeeping: the objectives' progress, the link queue (zero-delay links ready in this
// step, delayed ones in a heap on their due step), the per-step budget and the problems said once.
#include "game/level_logic.h"

#include "core/log.h"

#include <algorithm>
#include <utility>

namespace ks::game {
LevelLogic::LevelLogic(GameCore& core, PlayerSystem& player, RobotSystem& robots,
                       Interactables& interactables, Spawners& spawners)
    : core_(core), player_(player), robots_(robots), interactables_(interactables), spawners_(spawners) {}

int LevelLogic::current_objective() const {
    for (std::size_t i = 0; i < objectives_.size(); ++i)
        if (!objectives_[i].completed) return static_cast<int>(i);
    return -1;
}

bool LevelLogic::all_objectives_complete() const {
    return !objectives_.empty() && current_objective() < 0;
}

void LevelLogic::fire(LinkRange range, level::LinkEvent event) {
    for (std::uint32_t k = range.first; k < range.first + range.count; ++k) {
        LogicLink& link = links_[k];
        if (link.event != event || (link.once && link.fired)) continue;
        link.fired = true;
        if (link.delay_steps <= 0) {
            if (ready_.size() - ready_head_ >= static_cast<std::size_t>(kMaxActionsPerStep)) {
                ++dropped_;
                continue;
            }
            ready_.push_back(k);
        } else if (pending_.size() >= kMaxPending) {
            ++dropped_;
            if (!std::exchange(pending_full_reported_, true))
                report("more than " + std::to_string(kMaxPending) +
                       " delayed actions wait at once; the newest are dropped");
        } else {
            pending_.push_back({core_.steps + link.delay_steps, sequence_++, k});
            std::push_heap(pending_.begin(), pending_.end(), Pending::later);
        }
    }
}

void LevelLogic::fire_entity(int entity_id, level::LinkEvent event) {
    record_event({LogicEnd::Kind::Entity, entity_id}, event);
    if (entity_links_.empty()) return;
    if (auto it = entity_links_.find(entity_id); it != entity_links_.end()) fire(it->second, event);
}

void LevelLogic::reset_budget() {
    spent_ = 0;
    ready_.clear();
    ready_head_ = 0;
}

void LevelLogic::begin_step() {
    reset_budget();
    // More due than one step may run wait for the next step rather than being dropped.
    while (!pending_.empty() && pending_.front().due <= core_.steps &&
           ready_.size() < static_cast<std::size_t>(kMaxActionsPerStep)) {
        std::pop_heap(pending_.begin(), pending_.end(), Pending::later);
        ready_.push_back(pending_.back().link);
        pending_.pop_back();
    }
}

bool LevelLogic::next_ready(std::uint32_t& link) {
    if (ready_head_ >= ready_.size()) return false;
    if (spent_ >= kMaxActionsPerStep) {
        dropped_ += static_cast<std::int64_t>(ready_.size() - ready_head_);
        ready_.clear();
        ready_head_ = 0;
        if (!std::exchange(overflow_reported_, true))
            report(
                "more than " + std::to_string(kMaxActionsPerStep) +
                " actions in one step (a zero-delay loop of links?); the rest of that step's were dropped");
        return false;
    }
    link = ready_[ready_head_++];
    ++spent_;
    return true;
}

void LevelLogic::record_event(LogicEnd source, level::LinkEvent event) {
    LogicRecord r;
    r.step = core_.steps;
    r.event = event;
    r.source = source;
    records_.push_back(r);
}

void LevelLogic::record_action(const LogicLink& link, int index) {
    LogicRecord r;
    r.step = core_.steps;
    r.is_action = true;
    r.event = link.event;
    r.action = link.action;
    r.source = link.source_end;
    r.target = link.target_end;
    r.link = index;
    records_.push_back(r);
}

void LevelLogic::report(std::string problem) {
    if (problems_.size() >= kMaxProblems) return;
    if (std::find(problems_.begin(), problems_.end(), problem) != problems_.end()) return;
    log::warn("level logic: " + problem);
    problems_.push_back(std::move(problem));
}

} // namespace ks::game
