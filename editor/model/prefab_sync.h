#pragma once
// Bringing prefab instances in line with their prefab, window-free: the entity updates, the entities a
// grown prefab adds and a shrunk one removes, gathered for several instances and turned into one
// LevelChange (so placing, applying, reverting and updating are each one undoable step).
#include "core/result.h"
#include "model/command.h"
#include "model/prefab.h"

#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace ks::editor {

class PrefabSync {
  public:
    explicit PrefabSync(const level::Level& level);

    // Makes `instance` (a group of `data` with a PrefabLink to `prefab`) follow the prefab: members it
    // lacks are made (unique names, fresh ids), members beyond the prefab's entities are removed.
    Result<void> sync(level::Group& instance, const Prefab& prefab);
    // The entity as the sync has it now (updated or new), or the level's.
    const level::Entity* find(int id) const;
    // Ids of the entities sync made, in order.
    const std::vector<int>& added_ids() const { return added_ids_; }
    int changed_count() const;

    // Writes the gathered updates, removals, insertions and next_id into `change` (the editor section is
    // the caller's).
    void write(LevelChange& change) const;

  private:
    std::string unique_name(const std::string& base);

    const level::Level& level_;
    std::unordered_map<int, level::Entity> updated_;
    std::set<int> removed_;
    std::vector<level::Entity> added_;
    std::vector<int> added_ids_;
    std::set<std::string> names_;
    int next_id_;
};

} // namespace ks::editor
