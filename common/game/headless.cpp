#include "game/headless.h"

#include "core/files.h"
#include "core/log.h"
#include "core/paths.h"
#include "game/autoplay.h"
#include "game/bot_profiles.h"
#include "game/logic_trace.h"
#include "game/replay.h"
#include "level/level_io.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>

namespace ks::game {

std::string HeadlessStats::to_json() const {
    nlohmann::json j;
    j["outcome"] = outcome;
    j["sim_time_s"] = sim_time_s;
    j["robots_killed"] = robots_killed;
    j["damage_taken"] = damage_taken;
    j["shots"] = shots;
    j["steps_per_second"] = steps_per_second;
    char hash[32];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(state_hash));
    j["state_hash"] = hash;
    return j.dump();
}

std::string HeadlessStats::summary() const {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer,
                  "%s after %.2f s simulated (%lld steps): %d robots killed, %.0f damage taken, %d shots, "
                  "%.0f steps/s, state %016llx",
                  outcome.c_str(), sim_time_s, static_cast<long long>(steps), robots_killed,
                  static_cast<double>(damage_taken), shots, steps_per_second,
                  static_cast<unsigned long long>(state_hash));
    return buffer;
}

const std::vector<std::string>& headless_flags() {
    static const std::vector<std::string> flags{"headless", "autoplay"};
    return flags;
}

const std::vector<std::string>& headless_option_names() {
    static const std::vector<std::string> names{"headless",    "autoplay",   "level",      "seconds",
                                                "seed",        "record",     "replay",     "stats-json",
                                                "logic-trace", "difficulty", "bot-profile"};
    return names;
}

Result<void> parse_run_limits(const CommandLine& cl, double& seconds, std::uint64_t& seed,
                              std::string_view seconds_hint) {
    auto parsed = cl.get_double("seconds", seconds);
    if (!parsed) return parsed.error();
    if (!(*parsed > 0.0 && *parsed <= 86400.0))
        return Error("--seconds must be in (0, 86400]", Location("command line", 0, 0, "--seconds"),
                     "give " + std::string(seconds_hint) + " in seconds, e.g. --seconds 300");
    seconds = *parsed;
    if (auto s = cl.get("seed")) {
        char* end = nullptr;
        seed = std::strtoull(s->c_str(), &end, 10);
        if (s->empty() || *end != '\0' || (*s)[0] == '-')
            return Error("--seed must be a non-negative integer", Location("command line", 0, 0, "--seed"),
                         "e.g. --seed 42");
    }
    return {};
}

Result<void> parse_difficulty_option(const CommandLine& cl, Difficulty& difficulty) {
    if (auto d = cl.get("difficulty")) {
        auto parsed = parse_difficulty(*d, Location("command line", 0, 0, "--difficulty"));
        if (!parsed) return parsed.error();
        difficulty = *parsed;
    }
    return {};
}

Result<HeadlessOptions> parse_headless_options(const CommandLine& cl) {
    HeadlessOptions o;
    o.level = paths::resolve_user_path(cl.get_or("level", paths::level("main.json").string()));
    if (auto limits = parse_run_limits(cl, o.seconds, o.seed, "the simulated time limit"); !limits)
        return limits.error();
    o.autoplay = cl.has("autoplay");
    if (auto d = parse_difficulty_option(cl, o.difficulty); !d) return d.error();
    if (auto profile = cl.get("bot-profile")) {
        const Location where("command line", 0, 0, "--bot-profile");
        if (auto known = bot_profile(*profile, where); !known) return known.error();
        if (!o.autoplay) return Error("--bot-profile needs --autoplay", where, "add --autoplay");
        o.bot_profile = *profile;
    }
    if (auto r = cl.get("record")) o.record = *r;
    if (auto r = cl.get("replay")) o.replay = paths::resolve_user_path(*r);
    if (auto r = cl.get("stats-json")) o.stats_json = *r;
    if (auto r = cl.get("logic-trace")) {
        if (r->empty())
            return Error("--logic-trace needs a file name", Location("command line", 0, 0, "--logic-trace"),
                         "e.g. --logic-trace run.trace, or - for standard output");
        o.logic_trace = *r;
    }
    if (!o.record.empty() && !o.replay.empty())
        return Error("--record and --replay cannot be used together", Location("command line"),
                     "record a run first, then replay that file in a second run");
    if (o.autoplay && !o.replay.empty())
        return Error("--autoplay and --replay cannot be used together", Location("command line"),
                     "a replay supplies every input itself");
    return o;
}

Result<HeadlessStats> run_headless(const HeadlessOptions& options) {
    Recording replay;
    std::uint64_t seed = options.seed;
    if (!options.replay.empty()) {
        auto loaded = load_recording_file(options.replay);
        if (!loaded) return loaded.error();
        replay = std::move(*loaded);
        if (seed != replay.seed && seed != 1)
            log::warn("--seed " + std::to_string(seed) + " ignored: the replay was recorded with seed " +
                      std::to_string(replay.seed));
        seed = replay.seed;
    }
    // A replay plays against the robots it was recorded with.
    const Difficulty difficulty = options.replay.empty() ? options.difficulty : replay.difficulty;
    auto level = level::load_level_file(options.level);
    if (!level) return level.error();
    GameOptions game_options;
    game_options.seed = seed;
    game_options.settings.difficulty = difficulty;
    auto created = Game::create(*level, game_options);
    if (!created) return created.error();
    Game& game = **created;

    std::unique_ptr<Autoplay> bot;
    if (options.autoplay) {
        auto profile = bot_profile(options.bot_profile, Location("command line", 0, 0, "--bot-profile"));
        if (!profile) return profile.error();
        auto made = Autoplay::create(*level, game, seed, *profile);
        if (!made) return made.error();
        bot = std::make_unique<Autoplay>(std::move(*made));
    }
    if (options.on_start)
        if (auto started = options.on_start(*level, game); !started) return started.error();
    std::optional<LogicTraceWriter> trace;
    if (!options.logic_trace.empty()) {
        auto opened = LogicTraceWriter::open(options.logic_trace, *level, game.settings().step);
        if (!opened) return opened.error();
        trace.emplace(std::move(*opened));
    }
    Recording record;
    record.seed = seed;
    record.level = options.level.string();
    record.difficulty = difficulty;

    const double step = game.settings().step;
    std::int64_t max_steps = static_cast<std::int64_t>(options.seconds / step + 0.5);
    if (!options.replay.empty()) max_steps = static_cast<std::int64_t>(replay.inputs.size());
    if (!options.record.empty()) record.inputs.reserve(static_cast<std::size_t>(max_steps));

    // Wall-clock time is read only to report the simulation speed; it never enters the simulation.
    const auto start = std::chrono::steady_clock::now();
    std::int64_t steps = 0;
    while (steps < max_steps && game.phase() == Phase::Playing) {
        Input input;
        if (!options.replay.empty())
            input = replay.inputs[static_cast<std::size_t>(steps)];
        else if (bot)
            input = bot->decide(game);
        if (!options.record.empty()) record.inputs.push_back(input);
        game.step(input);
        ++steps;
        if (trace)
            if (auto written = trace->write(game); !written) return written.error();
        if (options.after_step)
            if (auto observed = options.after_step(game); !observed) return observed.error();
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.on_finish)
        if (auto finished = options.on_finish(game); !finished) return finished.error();

    HeadlessStats stats;
    stats.outcome = game.phase() == Phase::Won ? "win" : game.phase() == Phase::Dead ? "death" : "timeout";
    stats.sim_time_s = game.time();
    stats.robots_killed = game.robots_killed();
    stats.damage_taken = game.player().damage_taken;
    stats.shots = game.player().shots;
    stats.steps_per_second = wall > 0.0 ? static_cast<double>(steps) / wall : 0.0;
    stats.state_hash = game.state_hash();
    stats.steps = steps;

    if (!options.record.empty())
        if (auto saved = save_recording_file(options.record, record); !saved) return saved.error();
    if (!options.stats_json.empty()) {
        const std::string json = stats.to_json() + "\n";
        if (options.stats_json == "-")
            std::cout << json << std::flush;
        else if (auto w = files::write_atomic(options.stats_json, json); !w)
            return w.error();
    }
    return stats;
}

} // namespace ks::game
