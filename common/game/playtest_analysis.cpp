#include "game/playtest_analysis.h"

#include "game/autoplay.h"
#include "game/bot_profiles.h"
#include "game/game.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ks::game {

namespace {

// Positions in the report to the centimetre: a path of thousands of points stays readable and small, and
// a float so rounded reads back from its shortest text exactly.
Vec3 rounded(const Vec3& p) {
    return glm::round(p * 100.0f) / 100.0f;
}

struct RunSlot {
    std::optional<RunRecord> record;
    std::optional<Error> error;
    geometry::Aabb level_bounds = geometry::Aabb::empty();
};

struct Shared {
    const level::Level& level;
    const AnalysisOptions& options;
    AutoplaySettings bot;                                 // the options' profile
    std::shared_ptr<const nav::NavMesh> robot_navigation; // copied by every game (null: each builds one)
    std::stop_token stop;
    AnalysisProgress* progress = nullptr;
};

RunOutcome outcome_of(Phase phase) {
    return phase == Phase::Won    ? RunOutcome::Win
           : phase == Phase::Dead ? RunOutcome::Death
                                  : RunOutcome::Timeout;
}

// One run with `seed`; false when stopped before it ended (the slot is left empty).
bool play_run(const Shared& shared, const std::shared_ptr<nav::NavMesh>& mesh, std::uint64_t seed, int worker,
              RunSlot& slot) {
    GameOptions game_options;
    game_options.seed = seed;
    game_options.settings.difficulty = shared.options.difficulty;
    game_options.navigation = shared.robot_navigation;
    auto created = Game::create(shared.level, game_options);
    if (!created) {
        slot.error = created.error();
        return true;
    }
    Game& game = **created;
    slot.level_bounds = game.level_bounds();
    Autoplay bot(game, mesh, seed, shared.bot);
    RunRecord& run = slot.record.emplace();
    run.seed = seed;
    const double step = game.settings().step;
    const auto max_steps = std::max<std::int64_t>(1, std::llround(shared.options.seconds / step));
    const auto sample_every = std::max<std::int64_t>(1, std::llround(shared.options.path_interval / step));
    run.path.push_back(rounded(game.player().feet));
    for (std::int64_t steps = 1; steps <= max_steps && game.phase() == Phase::Playing; ++steps) {
        if (shared.stop.stop_requested()) {
            slot.record.reset();
            return false;
        }
        game.step(bot.decide(game));
        for (const Event& e : game.events()) {
            if (e.type == EventType::PlayerDamaged)
                run.damage.push_back(
                    {game.time(), rounded(game.player().feet), rounded(e.position), e.amount});
            else if (e.type == EventType::PlayerDied)
                run.death = rounded(game.player().feet);
        }
        if (steps % sample_every == 0) run.path.push_back(rounded(game.player().feet));
        if (shared.progress && steps % 240 == 0)
            shared.progress->set_running(worker, static_cast<float>(steps) / static_cast<float>(max_steps));
    }
    if (run.path.back() != rounded(game.player().feet)) run.path.push_back(rounded(game.player().feet));
    run.outcome = outcome_of(game.phase());
    run.time = game.time();
    run.damage_taken = game.player().damage_taken;
    run.robots_killed = game.robots_killed();
    run.shots = game.player().shots;
    run.state_hash = game.state_hash();
    return true;
}

// A worker: takes the next run until none is left, the analysis is stopped or a run failed. `mesh` is the
// bot's mesh, its own: queries keep state in the mesh, and it serves run after run (as the soak does).
void work(const Shared& shared, int worker, const std::shared_ptr<nav::NavMesh>& mesh, std::atomic<int>& next,
          std::vector<RunSlot>& slots, std::atomic<bool>& failed) {
    for (int i = next.fetch_add(1); i < static_cast<int>(slots.size()); i = next.fetch_add(1)) {
        if (failed.load() || shared.stop.stop_requested()) return;
        RunSlot& slot = slots[static_cast<std::size_t>(i)];
        if (!play_run(shared, mesh, static_cast<std::uint64_t>(i) + 1, worker, slot)) return;
        if (slot.error) {
            failed = true;
            return;
        }
        if (shared.progress) shared.progress->finish_run(worker);
    }
}

// The bot's mesh, one per worker (copies of one build), and the robots' mesh every game copies (null when
// the level has none: each game then gives its own answer, robots standing guard). The two builds are most
// of an analysis' fixed cost, so they run side by side.
Result<std::vector<std::shared_ptr<nav::NavMesh>>> build_meshes(const level::Level& level, int workers,
                                                                std::shared_ptr<const nav::NavMesh>& robots) {
    std::optional<Result<std::shared_ptr<nav::NavMesh>>> bot;
    {
        std::jthread builder(
            [&] { bot.emplace(build_autoplay_mesh(level, AutoplaySettings{}.cylinder_keep_out)); });
        if (auto built = build_robot_navigation(level)) robots = std::move(*built);
    }
    if (!*bot) {
        const Error& e = bot->error();
        return Error("the bot cannot plan on this level: " + e.message, e.where,
                     e.hint.empty() ? "give the level a floor the player can walk on" : e.hint);
    }
    std::vector<std::shared_ptr<nav::NavMesh>> meshes{**bot};
    while (static_cast<int>(meshes.size()) < workers) {
        auto copy = meshes.front()->clone();
        if (!copy) return copy.error();
        meshes.push_back(std::move(*copy));
    }
    return meshes;
}

Error option_error(const std::string& what, const std::string& option, const std::string& hint) {
    return Error(what, Location("analysis options", 0, 0, option), hint);
}
} // namespace

void AnalysisProgress::reset(int runs) {
    for (auto& r : running_) r.store(0.0f, std::memory_order_relaxed);
    done_.store(0, std::memory_order_relaxed);
    total_.store(std::max(0, runs), std::memory_order_relaxed);
}

float AnalysisProgress::fraction() const {
    const int total = runs_total();
    if (total <= 0) return 0.0f;
    float sum = static_cast<float>(runs_done());
    for (const auto& r : running_) sum += r.load(std::memory_order_relaxed);
    return std::clamp(sum / static_cast<float>(total), 0.0f, 1.0f);
}

void AnalysisProgress::set_running(int worker, float fraction) {
    if (worker >= 0 && worker < kMaxAnalysisThreads)
        running_[static_cast<std::size_t>(worker)].store(std::clamp(fraction, 0.0f, 1.0f),
                                                         std::memory_order_relaxed);
}

void AnalysisProgress::finish_run(int worker) {
    set_running(worker, 0.0f);
    done_.fetch_add(1, std::memory_order_relaxed);
}

int analysis_threads(int requested, int runs) {
    const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return std::clamp(requested > 0 ? requested : hardware, 1, std::clamp(runs, 1, kMaxAnalysisThreads));
}

Result<void> check_analysis_options(const AnalysisOptions& o) {
    if (o.runs < 1 || o.runs > 10000)
        return option_error("the number of runs must be 1..10000", "runs", "e.g. --runs 20");
    if (!(o.seconds > 0.0 && o.seconds <= 86400.0))
        return option_error("the time limit must be in (0, 86400] seconds", "seconds", "e.g. --seconds 300");
    if (o.threads < 0 || o.threads > kMaxAnalysisThreads)
        return option_error("threads must be 0..256 (0: every hardware thread)", "threads",
                            "e.g. --threads 2");
    if (!(o.path_interval >= 1.0 / 120.0 && o.path_interval <= 3600.0))
        return option_error("the path interval must be 1/120 s .. 3600 s", "path_interval", "e.g. 0.25");
    if (!(o.cell_size >= 0.25f && o.cell_size <= 1000.0f))
        return option_error("the heat map cell size must be 0.25 .. 1000 units", "cell_size", "e.g. 4");
    if (auto profile = bot_profile(o.bot_profile, Location("analysis options", 0, 0, "bot_profile"));
        !profile)
        return profile.error();
    return ok();
}

Result<PlaytestReport> analyze_level(const level::Level& level, const AnalysisOptions& options,
                                     std::stop_token stop, AnalysisProgress* progress) {
    if (auto checked = check_analysis_options(options); !checked) return checked.error();
    const int threads = analysis_threads(options.threads, options.runs);
    if (progress) progress->reset(options.runs);
    std::shared_ptr<const nav::NavMesh> robot_navigation;
    auto meshes = build_meshes(level, threads, robot_navigation);
    if (!meshes) return meshes.error();

    // A failed run stops the others; a stop from outside does too (stop_callback forwards it).
    std::stop_source abort;
    std::stop_callback forward(stop, [&abort] { abort.request_stop(); });
    const Shared shared{
        level, options, *bot_profile(options.bot_profile, {}), robot_navigation, abort.get_token(), progress};
    std::vector<RunSlot> slots(static_cast<std::size_t>(options.runs));
    std::atomic<int> next{0};
    std::atomic<bool> failed{false};
    {
        std::vector<std::jthread> workers;
        for (int t = 1; t < threads; ++t)
            workers.emplace_back(
                [&, t] { work(shared, t, (*meshes)[static_cast<std::size_t>(t)], next, slots, failed); });
        work(shared, 0, meshes->front(), next, slots, failed);
    } // the workers join here

    // The first failed run by seed, whichever thread met it first: the same error every time.
    for (const RunSlot& slot : slots)
        if (slot.error) return *slot.error;
    ReportSetup setup;
    setup.level = options.level_name.empty() ? level.name : options.level_name;
    setup.level_hash = level_fingerprint(level);
    setup.requested = options.runs;
    setup.seconds_limit = options.seconds;
    setup.path_interval = options.path_interval;
    setup.cell_size = options.cell_size;
    setup.bot_profile = options.bot_profile;
    setup.difficulty = options.difficulty;
    std::vector<RunRecord> runs;
    for (RunSlot& slot : slots) {
        if (slot.record) runs.push_back(std::move(*slot.record));
        if (!setup.level_area.valid() && slot.level_bounds.valid()) setup.level_area = slot.level_bounds;
    }
    setup.cancelled = static_cast<int>(runs.size()) < options.runs;
    return summarize_runs(std::move(runs), setup);
}

BackgroundAnalysis::BackgroundAnalysis(level::Level level, AnalysisOptions options)
    : thread_([this, level = std::move(level), options = std::move(options)](std::stop_token stop) {
          result_.emplace(analyze_level(level, options, stop, &progress_));
          finished_.store(true, std::memory_order_release);
      }) {}

BackgroundAnalysis::~BackgroundAnalysis() {
    thread_.request_stop();
}

Result<PlaytestReport> BackgroundAnalysis::take_result() {
    if (!finished() || !result_)
        return Error("the analysis has not finished", {}, "wait until finished() says so");
    Result<PlaytestReport> out = std::move(*result_);
    result_.reset();
    return out;
}

} // namespace ks::game
