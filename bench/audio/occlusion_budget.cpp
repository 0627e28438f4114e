#include "audio/occlusion_budget.h"
#include "physics/bench_util.h"

#include "audio/occlusion.h"
#include "core/paths.h"
#include "core/random.h"
#include "game/game.h"
#include "level/level_io.h"
#include "nav/nav_mesh.h"
#include "physics/character.h"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>

namespace ks::bench::audio_bench {
namespace {

constexpr float kFrame = 1.0f / 60.0f;
constexpr float kListenerSpeed = 15.0f; // the player's run speed
constexpr float kSourceSpeed = 6.0f;
constexpr float kEyeHeight = 3.0f;
constexpr float kSourceHeight = 1.5f;

// Something walking from corner to corner of a path on the mesh, a new random path when it arrives.
struct Walker {
    std::vector<Vec3> corners;
    std::size_t next = 0;
    Vec3 at{0.0f};
    float speed = 0.0f;
};

class WalkLevel {
  public:
    bool load() {
        auto lv = level::load_level_file(paths::level("main.json"));
        if (!lv) {
            std::printf("cannot load levels/main.json: %s\n", lv.error().str().c_str());
            return false;
        }
        auto game = game::Game::create(*lv);
        if (!game) {
            std::printf("cannot build the game for levels/main.json: %s\n", game.error().str().c_str());
            return false;
        }
        game_ = std::move(*game);
        // A mesh of our own (the game's is const): the robots' settings, so walkers go where robots go.
        const physics::CharacterSettings character;
        auto mesh = nav::NavMesh::build(
            *lv, nav::robot_nav_settings(character.step_height, character.max_slope_degrees));
        if (!mesh) {
            std::printf("cannot build the navigation mesh of levels/main.json: %s\n",
                        mesh.error().str().c_str());
            return false;
        }
        mesh_ = std::move(*mesh);
        for (const nav::NavTriangle& t : mesh_->triangles())
            if (t.a.y < 0.5f) surface_.push_back(t); // the ground floor, where every point is reachable
        return !surface_.empty();
    }

    Vec3 random_point(Rng& rng) const {
        const nav::NavTriangle& t = surface_[rng.below(static_cast<std::uint32_t>(surface_.size()))];
        float u = rng.uniform(), v = rng.uniform();
        if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
        return t.a + u * (t.b - t.a) + v * (t.c - t.a);
    }

    void step(Walker& w, Rng& rng, float dt) {
        float left = w.speed * dt;
        for (int guard = 0; left > 0.0f && guard < 64; ++guard) {
            if (w.next >= w.corners.size()) {
                w.corners.clear();
                (void)mesh_->find_path(w.at, random_point(rng), w.corners);
                w.next = 0;
                if (w.corners.empty()) return;
            }
            const Vec3 d = w.corners[w.next] - w.at;
            const float len = glm::length(d);
            if (len <= left) {
                w.at = w.corners[w.next++];
                left -= len;
            } else {
                w.at += d * (left / len);
                left = 0.0f;
            }
        }
    }

    bool blocked(Vec3 from, Vec3 to) const {
        const Vec3 d = to - from;
        const float len = glm::length(d);
        if (!(len > 1e-4f)) return false;
        physics::RayFilter filter;
        filter.layers = physics::layer::kBlocksSight; // walls, floors, closed doors; not characters
        return game_->world().ray_any({from, d / len, len}, filter);
    }

  private:
    std::unique_ptr<game::Game> game_;
    std::unique_ptr<nav::NavMesh> mesh_;
    std::vector<nav::NavTriangle> surface_;
};

// Where everyone is, frame by frame, and the true answer of every source's ray.
struct Recording {
    int sources = 0;
    int frames = 0;
    std::vector<Vec3> listener;      // per frame
    std::vector<Vec3> positions;     // frames x sources
    std::vector<std::uint8_t> truth; // frames x sources: 1 blocked
};

Recording record(WalkLevel& level, int sources, int frames) {
    Recording r;
    r.sources = sources;
    r.frames = frames;
    Rng rng(7);
    Walker listener;
    listener.at = level.random_point(rng);
    listener.speed = kListenerSpeed;
    std::vector<Walker> walkers(static_cast<std::size_t>(sources));
    for (std::size_t i = 0; i < walkers.size(); ++i) {
        walkers[i].at = level.random_point(rng);
        walkers[i].speed = i % 2 == 0 ? kSourceSpeed : 0.0f; // half walk like robots, half stand (machines)
    }
    for (int f = 0; f < frames; ++f) {
        level.step(listener, rng, kFrame);
        r.listener.push_back(listener.at + Vec3(0.0f, kEyeHeight, 0.0f));
        for (Walker& w : walkers) {
            if (w.speed > 0.0f) level.step(w, rng, kFrame);
            r.positions.push_back(w.at + Vec3(0.0f, kSourceHeight, 0.0f));
            r.truth.push_back(level.blocked(r.listener.back(), r.positions.back()) ? 1 : 0);
        }
    }
    return r;
}

// Runs the scheduler with `budget` over the recording; fills `amounts` (frames x sources) and the row,
// comparing the muffled decision with `reference` amounts when given.
BudgetRow simulate(const WalkLevel& level, const Recording& r, int budget, std::vector<float>& amounts,
                   const std::vector<float>* reference) {
    audio::OcclusionScheduler scheduler(r.sources, {budget, 0.08f});
    for (int i = 0; i < r.sources; ++i) scheduler.start(i);
    amounts.assign(r.truth.size(), 0.0f);
    long rays = 0, stale = 0, differs = 0, blocked = 0;
    double ray_seconds = 0.0;
    auto query = [&](Vec3 from, Vec3 to) { return level.blocked(from, to); };
    const auto n = static_cast<std::size_t>(r.sources);
    for (int f = 0; f < r.frames; ++f) {
        const std::size_t base = static_cast<std::size_t>(f) * n;
        const std::span<const Vec3> positions(r.positions.data() + base, n);
        const double t0 = physics::bench::cpu_seconds();
        rays += scheduler.update(kFrame, r.listener[static_cast<std::size_t>(f)], positions, query);
        ray_seconds += physics::bench::cpu_seconds() - t0;
        for (int i = 0; i < r.sources; ++i) {
            const std::size_t k = base + static_cast<std::size_t>(i);
            amounts[k] = scheduler.amount(i);
            blocked += r.truth[k];
            stale += (scheduler.target(i) > 0.5f) != (r.truth[k] != 0);
            if (reference) differs += (amounts[k] > 0.5f) != ((*reference)[k] > 0.5f);
        }
    }
    const double samples = static_cast<double>(r.truth.size());
    BudgetRow row;
    row.sources = r.sources;
    row.budget = budget;
    row.rays_per_frame = static_cast<double>(rays) / r.frames;
    row.ray_us_per_frame = ray_seconds * 1e6 / r.frames;
    row.stale_pct = 100.0 * static_cast<double>(stale) / samples;
    row.decision_pct = 100.0 * static_cast<double>(differs) / samples;
    row.blocked_pct = 100.0 * static_cast<double>(blocked) / samples;
    return row;
}

} // namespace

std::vector<BudgetRow> measure_budgets(int sources, const std::vector<int>& budgets, int frames) {
    WalkLevel level;
    if (!level.load()) return {};
    const Recording recording = record(level, sources, frames);
    std::vector<float> reference, amounts;
    std::vector<BudgetRow> rows;
    BudgetRow every = simulate(level, recording, sources, reference, nullptr);
    for (int budget : budgets)
        if (budget < sources) rows.push_back(simulate(level, recording, budget, amounts, &reference));
    rows.push_back(every);
    return rows;
}

} // namespace ks::bench::audio_bench
