#include "model/prefab_sync.h"

#include "model/field_access.h"

#include <algorithm>

namespace ks::editor {

PrefabSync::PrefabSync(const level::Level& level) : level_(level), next_id_(level.next_id) {
    for (const level::Entity& e : level.entities)
        if (!e.name.empty()) names_.insert(e.name);
}

std::string PrefabSync::unique_name(const std::string& base) {
    if (base.empty()) return base;
    std::string name = base;
    for (int n = 2; names_.contains(name); ++n) name = base + "_" + std::to_string(n);
    names_.insert(name);
    return name;
}

const level::Entity* PrefabSync::find(int id) const {
    if (auto it = updated_.find(id); it != updated_.end()) return &it->second;
    for (const level::Entity& e : added_)
        if (e.id == id) return &e;
    return removed_.contains(id) ? nullptr : level_.find(id);
}

int PrefabSync::changed_count() const {
    return static_cast<int>(updated_.size() + removed_.size() + added_.size());
}

Result<void> PrefabSync::sync(level::Group& instance, const Prefab& prefab) {
    level::PrefabLink& link = instance.prefab;
    const Frame frame{instance.position, instance.yaw};
    const size_t count = prefab.entities.size();
    link.overrides.resize(link.members.size());
    // Names first: links inside the prefab name its entities, and must name the instance's.
    std::unordered_map<std::string, std::string> renames;
    for (size_t i = 0; i < count; ++i) {
        const std::string& prefab_name = prefab.entities[i].name;
        if (i >= link.members.size()) {
            const int id = next_id_++;
            link.members.push_back(id);
            link.overrides.emplace_back();
            level::Entity made = prefab.entities[i];
            made.id = id;
            made.name = unique_name(prefab_name);
            added_.push_back(std::move(made));
            added_ids_.push_back(id);
            instance.entities.insert(std::lower_bound(instance.entities.begin(), instance.entities.end(), id),
                                     id);
        }
        if (const level::Entity* member = link.members[i] ? find(link.members[i]) : nullptr;
            member && !prefab_name.empty())
            renames.emplace(prefab_name, member->name);
    }
    for (size_t i = 0; i < count; ++i) {
        if (link.members[i] == 0) continue; // deleted in this instance: stays deleted
        const level::Entity* current = find(link.members[i]);
        if (!current) {
            link.members[i] = 0;
            continue;
        }
        auto after = refreshed_member(prefab.entities[i], *current, frame, link.overrides[i], renames);
        if (!after) return after.error();
        // The range checks a placed entity gets (a frame far out could push a member past the level's
        // limits).
        if (auto r = set_entity_field(*after, "position", after->position); !r)
            return Error("prefab '" + prefab.name + "': entity " + std::to_string(i + 1) + ": " +
                             r.error().message,
                         Location{}, "place the instance closer to the level");
        if (*after == *current) continue;
        if (auto it =
                std::find_if(added_.begin(), added_.end(), [&](const auto& e) { return e.id == after->id; });
            it != added_.end())
            *it = std::move(*after);
        else
            updated_[after->id] = std::move(*after);
    }
    for (size_t i = count; i < link.members.size(); ++i) {
        const int id = link.members[i];
        if (id == 0) continue;
        removed_.insert(id);
        updated_.erase(id);
        std::erase(instance.entities, id);
    }
    link.members.resize(std::min(link.members.size(), count));
    link.overrides.resize(link.members.size());
    return ok();
}

void PrefabSync::write(LevelChange& change) const {
    for (size_t i = 0; i < level_.entities.size(); ++i) {
        const level::Entity& e = level_.entities[i];
        if (removed_.contains(e.id))
            change.removals.push_back({i, e});
        else if (auto it = updated_.find(e.id); it != updated_.end())
            change.updates.push_back({e, it->second});
    }
    const size_t base = level_.entities.size() - change.removals.size();
    for (size_t k = 0; k < added_.size(); ++k) change.insertions.push_back({base + k, added_[k]});
    if (next_id_ != level_.next_id) change.next_id = Change<int>{level_.next_id, next_id_};
}

} // namespace ks::editor
