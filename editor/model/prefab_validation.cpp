// The `prefab` rule (prefab_library.h): instances whose prefab cannot be followed.
#include "model/prefab_library.h"
#include "model/validation.h"

#include <algorithm>

namespace ks::editor {

void check_prefab_instances(const level::Level& level, const PrefabLibrary& library,
                            std::vector<Issue>& out) {
    for (const level::Group& g : level.editor.groups) {
        if (!g.has_prefab) continue;
        const auto first = std::find_if(g.prefab.members.begin(), g.prefab.members.end(),
                                        [&](int id) { return id != 0 && level.find(id); });
        if (first == g.prefab.members.end()) continue;
        const auto prefab = library.get(g.prefab.prefab);
        if (prefab) continue;
        Issue issue;
        issue.rule = Rule::Prefab;
        issue.severity = IssueSeverity::Warning;
        issue.entity_id = *first;
        issue.message = "prefab instance '" + g.name + "' (group " + std::to_string(g.id) +
                        ") cannot follow its prefab: " + prefab.error().message +
                        (prefab.error().hint.empty() ? "" : " (" + prefab.error().hint + ")") +
                        "; its entities stay as they are";
        issue.fix = {"Unlink the instance", fixes::UnlinkPrefab{g.id}};
        out.push_back(std::move(issue));
    }
}

} // namespace ks::editor
