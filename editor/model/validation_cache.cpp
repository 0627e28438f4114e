// ValidationCache: the design rules per revision, the walk check only when its inputs change.
#include "model/validation_cache.h"

#include "model/patrol_validation.h"

#include <chrono>

namespace ks::editor {

void ValidationCache::poll_walk_job(bool wait) {
    if (!walk_job_.valid()) return;
    if (!wait && walk_job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    PanelReachability done = walk_job_.get();
    walk_issues_ = std::move(done.issues);
    walk_mesh_ = std::move(done.mesh);
    walk_fingerprint_ = walk_job_fingerprint_;
    walk_known_ = true;
    ++walk_results_;
}

const std::vector<Issue>& ValidationCache::issues(const level::Level& level, const PrefabLibrary& prefabs,
                                                  std::uint64_t revision, bool dragging) {
    // In the window the walk check runs in the background; a finished one changes the key.
    poll_walk_job(false);
    const std::uint64_t key =
        ((revision + (walk_results_ << 32) + (prefabs.revision() << 48)) << 1) | (dragging ? 1u : 0u);
    if (issues_key_ == key) return issues_;
    ValidationOptions options = options_;
    options.check_reachability = false;
    issues_ = validate_design(level, options);
    check_prefab_instances(level, prefabs, issues_);
    if (options_.check_reachability && !dragging) {
        const std::uint64_t fingerprint = walk_fingerprint(level, options_);
        const bool stale = !walk_known_ || fingerprint != walk_fingerprint_;
        if (stale && options_.background_reachability) {
            if (!walk_job_.valid()) { // one at a time; a newer level is checked when this one ends
                walk_job_fingerprint_ = fingerprint;
                walk_job_ = std::async(std::launch::async, [level, o = options_]() {
                    return check_panel_reachability(level, o);
                });
                ++walk_checks_run_;
            }
        } else if (stale) {
            PanelReachability done = check_panel_reachability(level, options_);
            walk_issues_ = std::move(done.issues);
            walk_mesh_ = std::move(done.mesh);
            walk_fingerprint_ = fingerprint;
            walk_known_ = true;
            ++walk_checks_run_;
        }
        issues_.insert(issues_.end(), walk_issues_.begin(), walk_issues_.end());
        // Robots move without changing the mesh: asked again on every validation, no rebuild.
        if (walk_mesh_) {
            check_robot_reach(level, *walk_mesh_, options_, issues_);
            check_patrol_on_mesh(level, *walk_mesh_, options_, issues_);
            check_trigger_reach(level, *walk_mesh_, options_, issues_);
        }
    }
    issues_key_ = key;
    return issues_;
}

} // namespace ks::editor
