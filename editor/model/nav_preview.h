#pragma once
// The robots' navigation mesh as the editor shows it: built in the background from a copy of the level
// (the same nav::NavMesh::build the game runs at load), so an edit never waits for it; the newest finished
// build's triangles are what the viewport draws. Window-free, so tests drive it.
#include "core/result.h"
#include "level/level.h"
#include "nav/nav_mesh.h"

#include <cstdint>
#include <future>
#include <optional>
#include <string>
#include <vector>

namespace ks::editor {

struct NavPreviewStats {
    int builds = 0;             // finished builds
    double last_build_ms = 0.0; // wall time of the newest finished build
    std::size_t triangles = 0;  // in the newest finished build
    std::size_t door_triangles = 0;
};

class NavPreview {
  public:
    NavPreview() = default;
    ~NavPreview();
    NavPreview(const NavPreview&) = delete;
    NavPreview& operator=(const NavPreview&) = delete;

    // Call every frame while the preview is shown: starts a build when `revision` differs from the shown
    // one and no build is running (a running build finishes first; the newest revision is built next), and
    // takes a finished build. Returns true when the shown mesh changed.
    bool update(const level::Level& level, std::uint64_t revision);
    // Waits for the running build, if any, and takes it (tests; closing).
    void finish();

    bool building() const { return pending_.valid(); }
    const std::vector<nav::NavTriangle>& triangles() const { return triangles_; }
    const std::string& error() const { return error_; } // why the newest build failed; empty when it did not
    const NavPreviewStats& stats() const { return stats_; }

  private:
    struct Built {
        std::unique_ptr<nav::NavMesh> mesh; // null when the build failed
        std::string error;
        double ms = 0.0;
    };
    void take(Built built);

    std::future<Built> pending_;
    std::uint64_t pending_revision_ = 0;
    std::optional<std::uint64_t> shown_revision_;
    std::vector<nav::NavTriangle> triangles_;
    std::string error_;
    NavPreviewStats stats_;
};

} // namespace ks::editor
