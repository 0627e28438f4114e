#pragma once
// The occlusion ray budget against its error on a real level: sources at random walkable points of
// levels/main.json (half of them walking, as robots do), a listener walking random paths across the level,
// rays against the game's physics world. Each budget is compared with casting every source's ray every
// frame (the truth).
#include <vector>

namespace ks::bench::audio_bench {

struct BudgetRow {
    int sources = 0;
    int budget = 0;              // rays per update at most (= sources: every ray every frame)
    double rays_per_frame = 0.0; // average cast
    double ray_us_per_frame = 0.0;
    double stale_pct = 0.0;    // frames x sources where the last answer differs from this frame's truth
    double decision_pct = 0.0; // ... where muffled (amount > 0.5) differs from the every-ray scheduler's
    double blocked_pct = 0.0;  // how often the truth is "blocked" (how much occlusion the scene has)
};

// Runs `frames` 60 Hz frames for each budget; empty on failure (the reason is printed).
std::vector<BudgetRow> measure_budgets(int sources, const std::vector<int>& budgets, int frames);

} // namespace ks::bench::audio_bench
