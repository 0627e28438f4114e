#include "game/logic_trace.h"

#include "jsonio/text.h"

#include <cerrno>
#include <cstring>

namespace ks::game {

LogicTraceNames::LogicTraceNames(const level::Level& level) {
    for (const level::Entity& e : level.entities)
        entities_[e.id] = std::string(level::type_name(e.type())) + ":" + std::to_string(e.id) + ":" +
                          jsonio::quote_text(e.name);
    for (std::size_t i = 0; i < level.objectives.size(); ++i)
        objectives_.push_back("objective:" + std::to_string(i) + ":" +
                              jsonio::quote_text(level.objectives[i].id));
}

void LogicTraceNames::add_spawned(int robot_id, int spawner_id) {
    const auto spawner = entities_.find(spawner_id);
    const std::string name =
        spawner == entities_.end() ? "\"\"" : spawner->second.substr(spawner->second.find('"'));
    entities_[robot_id] = "robot:" + std::to_string(robot_id) + ":" + name;
}

void LogicTraceNames::add_spawned(std::span<const Event> events) {
    for (const Event& e : events)
        if (e.type == EventType::RobotSpawned) add_spawned(e.entity, static_cast<int>(e.amount));
}

std::string LogicTraceNames::end(const LogicEnd& end) const {
    switch (end.kind) {
    case LogicEnd::Kind::None:
        return "-";
    case LogicEnd::Kind::Level:
        return "level";
    case LogicEnd::Kind::Objective:
        if (end.id >= 0 && static_cast<std::size_t>(end.id) < objectives_.size()) return objectives_[end.id];
        return "objective:" + std::to_string(end.id) + ":\"\"";
    case LogicEnd::Kind::Entity:
        break;
    }
    const auto it = entities_.find(end.id);
    return it != entities_.end() ? it->second : "entity:" + std::to_string(end.id) + ":\"\"";
}

std::string logic_trace_line(const LogicRecord& r, const LogicTraceNames& names, double step_seconds) {
    char time[32];
    std::snprintf(time, sizeof time, "%.3f", static_cast<double>(r.step) * step_seconds);
    std::string line = std::to_string(r.step) + " " + time;
    if (!r.is_action)
        return line + " event " + std::string(level::event_name(r.event)) + " " + names.end(r.source) +
               " - -";
    return line + " action " + std::string(level::action_name(r.action)) + " " + names.end(r.source) + " " +
           names.end(r.target) + " " + (r.link >= 0 ? std::to_string(r.link) : "-");
}

void LogicTraceWriter::Close::operator()(std::FILE* f) const {
    if (f != stdout) std::fclose(f);
}

LogicTraceWriter::LogicTraceWriter(std::filesystem::path path, const level::Level& level, double step_seconds)
    : path_(std::move(path)), names_(level), step_seconds_(step_seconds) {}

Result<LogicTraceWriter> LogicTraceWriter::open(const std::filesystem::path& path, const level::Level& level,
                                                double step_seconds) {
    LogicTraceWriter writer(path, level, step_seconds);
    if (path == "-") {
        writer.file_.reset(stdout);
    } else {
        writer.file_.reset(std::fopen(path.c_str(), "w"));
        if (!writer.file_)
            return Error(std::string("cannot write the logic trace: ") + std::strerror(errno),
                         Location(path.string()),
                         "give --logic-trace a file in a folder that exists and you may write");
    }
    if (auto header = writer.put(std::string(kLogicTraceHeader) + "\n"); !header) return header.error();
    return writer;
}

Result<void> LogicTraceWriter::write(const Game& game) {
    names_.add_spawned(game.events());
    const std::span<const LogicRecord> records = game.logic().records();
    if (records.empty()) return {};
    std::string text;
    for (const LogicRecord& r : records) text += logic_trace_line(r, names_, step_seconds_) + "\n";
    return put(text);
}

Result<void> LogicTraceWriter::put(const std::string& text) {
    if (std::fwrite(text.data(), 1, text.size(), file_.get()) != text.size() || std::fflush(file_.get()) != 0)
        return Error(std::string("cannot write the logic trace: ") + std::strerror(errno),
                     Location(path_.string()), "free space on the disk or give --logic-trace another file");
    return {};
}

} // namespace ks::game
