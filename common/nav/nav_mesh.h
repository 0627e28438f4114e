#pragma once
// A level's navigation mesh (Recast, tiled) and the path queries on it (Detour). Built once at level load
// from the entities' static solid shapes; doors are polygons flagged as doors whose Walk flag is set and
// cleared as they open and close, so a closed door blocks paths without a rebuild.
//
// Queries keep their working memory inside the mesh (Detour's node pool, corridor and point buffers): they
// allocate nothing per call, and a NavMesh is for one thread at a time.
#include "core/math.h"
#include "core/result.h"
#include "level/level.h"
#include "nav/nav_settings.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

class dtNavMesh;
class dtNavMeshQuery;
class dtQueryFilter;

namespace ks::nav {

struct DoorFootprint;
struct InputGeometry;

enum class PathStatus : std::uint8_t {
    Found,        // the path reaches the end point
    Partial,      // the end cannot be reached; the path ends at the reachable point nearest to it
    StartOffMesh, // no walkable polygon within the query extents of the start
    EndOffMesh,   // no walkable polygon within the query extents of the end
};
const char* status_name(PathStatus status);

// One triangle of the mesh's surface for drawing: its polygon's flags (nav_flags.h) and, for doorway
// polygons, the door entity's id (0 otherwise).
struct NavTriangle {
    Vec3 a{0.0f}, b{0.0f}, c{0.0f};
    std::uint16_t flags = 0;
    int door_id = 0;
};

struct NavStats {
    int tiles_with_polygons = 0;
    int tile_columns = 0, tile_rows = 0;
    int polygons = 0;
    int door_polygons = 0;
    int input_triangles = 0;
};

class NavMesh {
  public:
    // Builds the mesh for `level`. Errors: unusable settings, an entity with non-finite or absurd numbers
    // (named), a level with nothing walkable (named, with what to add), a Recast/Detour failure.
    static Result<std::unique_ptr<NavMesh>> build(const level::Level& level, const NavSettings& settings);
    // The mesh build(edited, previous.settings()) makes, made from `previous` (a mesh built from `before`
    // with those settings) where it can: each tile whose input is the same in both levels
    // (same_tile_input: its triangles, its doorways, the grid) is copied, the others are built again, so an
    // edit costs the tiles it touches (the live play-test's moved wall). Every query answers as on a fresh
    // build: the same tiles at the same references, the doors as the level starts them. An edit that
    // changes the level's bounds changes the grid: every tile is built. `built_tiles` (when given) is set
    // to the number of tiles built rather than copied.
    static Result<std::unique_ptr<NavMesh>> rebuild(const NavMesh& previous, const level::Level& before,
                                                    const level::Level& edited, int* built_tiles = nullptr);
    // A copy with its own Detour mesh and query, every tile restored at its reference (so polygon references,
    // door state and every query answer are the original's): many games of one level build the mesh once
    // (game::GameOptions::navigation). Reads the original only, so threads may copy one mesh at once.
    Result<std::unique_ptr<NavMesh>> clone() const;
    ~NavMesh();
    NavMesh(const NavMesh&) = delete;
    NavMesh& operator=(const NavMesh&) = delete;

    // Opens or closes a door's polygons (no rebuild). False when the level has no door with that id, or the
    // door has no polygons (it stands where nothing is walkable).
    bool set_door_open(int door_entity_id, bool open);
    bool door_open(int door_entity_id) const;

    // The straight path (corners of the string-pulled corridor) from `from` to `to`, both snapped to the
    // nearest polygon within settings.query_extents. `out` is cleared and filled; keep one vector around
    // and the query allocates nothing.
    PathStatus find_path(const Vec3& from, const Vec3& to, std::vector<Vec3>& out);
    // The closest point on the walkable surface within `half_extents` of `p`.
    std::optional<Vec3> nearest_point(const Vec3& p, const Vec3& half_extents);
    // Length along the mesh from `from` to `to` (for how far a sound travels); nullopt when not reachable.
    std::optional<float> path_length(const Vec3& from, const Vec3& to);
    bool reachable(const Vec3& from, const Vec3& to);
    // Which connected piece of the walkable surface (through the doors open now) holds the nearest polygon
    // within `half_extents` of `p`: 1, 2, ...; 0 when there is none. Two points are reachable from each
    // other exactly when their islands are equal and not 0, so asking many points costs one flood of the
    // polygons (redone on the first call after a door opens or closes) and a polygon lookup each.
    int island(const Vec3& p, const Vec3& half_extents);
    // True when the straight line from `from` to `to` stays on walkable polygons (Detour's raycast along
    // the surface): a robot may walk it directly.
    bool walkable_line(const Vec3& from, const Vec3& to);

    // The surface as triangles (detail mesh) with flags, for drawing.
    std::vector<NavTriangle> triangles() const;
    const NavStats& stats() const { return stats_; }
    const NavSettings& settings() const { return settings_; }

    // A built mesh as bytes (its stats, Detour's parameters and tiles at their references, the doors'
    // polygons) and back: the disk cache's payload (nav_cache.h). read_tiles gives nullptr when the bytes do
    // not hold a whole mesh Detour accepts.
    std::string write_tiles() const;
    static std::unique_ptr<NavMesh> read_tiles(std::string_view payload, const NavSettings& settings);

  private:
    NavMesh();
    // The mesh of `input`: each tile copied from `previous` when its input is the same as in
    // `previous_input` (both given), else built; counts the built tiles in `built_tiles` (when given).
    static Result<std::unique_ptr<NavMesh>> build_tiles(const InputGeometry& input, const std::string& name,
                                                        const NavSettings& settings, const NavMesh* previous,
                                                        const InputGeometry* previous_input,
                                                        int* built_tiles);
    struct Door {
        int entity_id = 0;
        bool open = false;
        std::vector<std::uint64_t> polygons; // dtPolyRef, widened to stay independent of Detour's typedef
    };
    // Nearest polygon to p within the query extents (0 when none); writes the point on it.
    std::uint64_t nearest_polygon(const Vec3& p, const Vec3& half_extents, Vec3& on_mesh) const;
    // Fills corridor_ with the polygons from `from` to (the reachable point nearest) `to`; start and end
    // are the snapped end points. Shortest uses any-angle search where the settings ask for it.
    enum class CorridorMode : std::uint8_t { Shortest, AnyCorridor };
    PathStatus corridor(const Vec3& from, const Vec3& to, CorridorMode mode, Vec3& start, Vec3& end,
                        int& polygon_count);
    // String-pulls the corridor into straight_points_; returns the number of corners (0 on failure).
    int straighten(const Vec3& start, const Vec3& end, int polygon_count);
    int find_door(int entity_id) const; // index into doors_, -1 when none
    void number_islands();
    void index_door_polygons(const std::vector<DoorFootprint>& footprints);

    NavSettings settings_;
    NavStats stats_;
    std::unique_ptr<dtNavMesh, void (*)(dtNavMesh*)> mesh_;
    std::unique_ptr<dtNavMeshQuery, void (*)(dtNavMeshQuery*)> query_;
    std::unique_ptr<dtQueryFilter> filter_;
    std::vector<Door> doors_;
    // island() answers: polygon reference -> island number; empty until asked, cleared when a door changes.
    std::unordered_map<std::uint64_t, int> islands_;
    // Query scratch, sized once at build.
    std::vector<std::uint32_t> corridor_; // dtPolyRef
    std::vector<float> straight_points_;  // x, y, z per corner
};

} // namespace ks::nav
