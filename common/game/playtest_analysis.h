#pragma once
// Automated play-tests: the autoplay bot (game/autoplay.h) plays a level N times, seeds 1..N, headless, on
// worker threads, and what it met becomes a PlaytestReport (game/playtest_report.h): outcomes, times,
// damage and deaths and where they happened, and its paths. The editor's Analyze action runs it in the
// background on the level being edited; `killswitch-editor --analyze LEVEL` runs it for CI and scripts.
// It lives beside the headless runner because it is one more driver of the game (the editor's model may
// not see the game, and the runtime or a CI tool can call it as it is).
//
// Each run is a game and a bot of its own, built from the same level with its seed; runs share only
// read-only data (the level, the robot clips), and each worker thread plans on a bot mesh of its own. A
// run's record depends on its seed alone, and records are put in seed order, so the report is the same
// whatever the number of threads or the order they finish in.
#include "game/playtest_report.h"

#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <stop_token>
#include <thread>

namespace ks::game {

struct AnalysisOptions {
    int runs = 20;                       // seeds 1..runs
    double seconds = 300.0;              // simulated time limit of a run
    int threads = 0;                     // worker threads; 0: std::thread::hardware_concurrency()
    double path_interval = 0.25;         // simulated seconds between samples of the bot's path
    float cell_size = 4.0f;              // heat map cells, world units along x and z
    std::string level_name;              // the report's "level" (a file name); the level's name when empty
    std::string bot_profile = "perfect"; // who plays (game/bot_profiles.h)
    Difficulty difficulty = Difficulty::Normal;
};

inline constexpr int kMaxAnalysisThreads = 256;

// Where an analysis has got to, readable from any thread while it runs (nothing in it is reallocated).
class AnalysisProgress {
  public:
    void reset(int runs);
    // 0..1: finished runs plus the running ones' simulated time against their limit.
    float fraction() const;
    int runs_done() const { return done_.load(std::memory_order_relaxed); }
    int runs_total() const { return total_.load(std::memory_order_relaxed); }
    void set_running(int worker, float fraction);
    void finish_run(int worker);

  private:
    std::atomic<int> done_{0}, total_{0};
    std::array<std::atomic<float>, kMaxAnalysisThreads> running_{}; // per worker: its current run's part
};

// The number of worker threads `requested` (0: every hardware thread) gives for `runs` runs.
int analysis_threads(int requested, int runs);

// Checks the options: runs in 1..10000, seconds in (0, 86400], threads in 0..kMaxAnalysisThreads, a finite
// path interval of at least one game step, a cell size in [0.25, 1000] and a known bot profile; the error
// names the option and its range.
Result<void> check_analysis_options(const AnalysisOptions& options);

// Plays the runs and summarises them. Checked first: the options, that a game can be built from the level
// and that the bot can plan on it (each error says why and how to fix it). `stop` is looked at between
// steps: when it is requested, the runs under way are dropped and the report holds the finished ones,
// marked cancelled. `progress`, when given, is updated as the runs go.
Result<PlaytestReport> analyze_level(const level::Level& level, const AnalysisOptions& options,
                                     std::stop_token stop = {}, AnalysisProgress* progress = nullptr);

// analyze_level on a thread of its own, for a window that must keep drawing: poll finished(), then take
// the result once. Destroying it cancels the analysis and waits for its threads.
class BackgroundAnalysis {
  public:
    BackgroundAnalysis(level::Level level, AnalysisOptions options);
    ~BackgroundAnalysis();
    BackgroundAnalysis(const BackgroundAnalysis&) = delete;
    BackgroundAnalysis& operator=(const BackgroundAnalysis&) = delete;

    const AnalysisProgress& progress() const { return progress_; }
    void cancel() { thread_.request_stop(); }
    bool cancelling() const { return thread_.get_stop_token().stop_requested(); }
    bool finished() const { return finished_.load(std::memory_order_acquire); }
    // The report or the error; only once finished() (an error otherwise).
    Result<PlaytestReport> take_result();

  private:
    AnalysisProgress progress_;
    std::optional<Result<PlaytestReport>> result_;
    std::atomic<bool> finished_{false};
    std::jthread thread_; // last: it starts after the members it writes exist
};

} // namespace ks::game
