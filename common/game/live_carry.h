#pragma once
// What the live play-test's rebuild (live_update.h) knows about the edit, handed to the carry_from of the
// Game and of each of its systems: which entities the running game's level had, which the edited level
// has, and which the edit moved. Each system takes over its own part of the running game's state with it
// (the rule is live_update.h's; the definitions are together in live_carry.cpp).
#include "level/level.h"

#include <span>
#include <unordered_map>

namespace ks::game {

class LevelEdit {
  public:
    // Both levels must outlive it (it points at their entities).
    LevelEdit(const level::Level& before, const level::Level& edited);

    // The running game's level had it: its running state, when it has one, is carried.
    bool existed(int entity_id) const { return before_.contains(entity_id); }
    // The edited level has it.
    bool remains(int entity_id) const { return edited_.contains(entity_id); }
    // The edit moved it (an entity of the edited level): its place or turn in the file changed, or it is new.
    bool moved(int entity_id) const;

  private:
    using EntityIndex = std::unordered_map<int, const level::Entity*>;
    static EntityIndex index_entities(const level::Level& level);

    EntityIndex before_;
    EntityIndex edited_;
};

// The record of level entity `entity_id` among `records` (the first), or null.
template <class Record>
const Record* find_by_entity(std::span<const Record> records, int entity_id) {
    for (const Record& r : records)
        if (r.entity_id == entity_id) return &r;
    return nullptr;
}

} // namespace ks::game
