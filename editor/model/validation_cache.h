#pragma once
// The validation panel's issues, kept per revision of the level (and of the prefab folders). The walk
// check (a navigation mesh build, most of a validation's time on a large level) is redone only when its
// inputs change, in the window on a background thread; the cheap checks on its mesh run every time.
#include "model/prefab_library.h"
#include "model/reachability.h"
#include "model/validation.h"

#include <cstdint>
#include <future>
#include <memory>
#include <vector>

namespace ks::editor {

class ValidationCache {
  public:
    // The issues of `level` as it is at `revision` (Editor::revision); during a drag (`dragging`: an open
    // transaction) the walk check waits for the commit while every other rule stays live.
    const std::vector<Issue>& issues(const level::Level& level, const PrefabLibrary& prefabs,
                                     std::uint64_t revision, bool dragging);
    ValidationOptions& options() { return options_; }
    size_t walk_checks_run() const { return walk_checks_run_; } // how often issues() ran the walk check
    // With background_reachability: whether a walk check is still running, and waiting for it (tests).
    bool reachability_pending() const { return walk_job_.valid(); }
    void wait_for_reachability() { poll_walk_job(true); }

  private:
    void poll_walk_job(bool wait);

    ValidationOptions options_;
    std::vector<Issue> issues_;
    std::uint64_t issues_key_ = ~0ull;
    std::vector<Issue> walk_issues_;
    std::uint64_t walk_fingerprint_ = 0;
    bool walk_known_ = false;
    size_t walk_checks_run_ = 0;
    // The running background walk check and the fingerprint it answers for.
    std::future<PanelReachability> walk_job_;
    std::shared_ptr<nav::NavMesh> walk_mesh_; // the newest check's mesh: robots are asked of it every time
    std::uint64_t walk_job_fingerprint_ = 0;
    std::uint64_t walk_results_ = 0; // finished walk checks taken in: part of issues()' cache key
};

} // namespace ks::editor
