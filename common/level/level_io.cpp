#include "level/level_io.h"

#include "core/files.h"
#include "core/log.h"
#include "jsonio/describe.h"
#include "jsonio/document.h"
#include "jsonio/json_writer.h"
#include "jsonio/number_text.h"
#include "jsonio/position_map.h"
#include "level/diagnostics.h"
#include "level/level_checks.h"
#include "level/level_migrate.h"
#include "level/level_reader.h"
#include "level/level_writer.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace ks::level {

namespace {

using Json = nlohmann::ordered_json;

std::string format_hint() {
    return "a level file starts with {\"format\": \"killswitch-level\", \"version\": " +
           std::to_string(kFormatVersion) + ", ...}";
}

int read_version(const Json& document, DiagnosticSink& sink) {
    auto it = document.find("version");
    if (it == document.end()) {
        sink.error("version", "missing required field \"version\"",
                   "add \"version\": " + std::to_string(kFormatVersion));
        return -1;
    }
    const double number = it->is_number() ? it->get<double>() : 0.5;
    const bool whole = it->is_number() && std::isfinite(number) && number == std::floor(number);
    if (!whole) {
        sink.error("version", "version must be a whole number, found " + jsonio::quote(*it),
                   "this build reads versions 0 to " + std::to_string(kFormatVersion));
        return -1;
    }
    const std::string version_text = jsonio::format_readable(number);
    if (number > kFormatVersion) {
        sink.error("version",
                   "this level was made by a newer Killswitch (format version " + version_text +
                       "; this build reads up to version " + std::to_string(kFormatVersion) + ")",
                   "update Killswitch to open it");
        return -1;
    }
    if (number < 0) {
        sink.error("version", "version " + version_text + " is not a valid format version",
                   "this build reads versions 0 to " + std::to_string(kFormatVersion));
        return -1;
    }
    return static_cast<int>(number);
}

// Parses, migrates, reads and checks; every problem goes to the sink.
std::optional<Level> parse_level(std::string_view text, DiagnosticSink& sink, jsonio::Document& parsed) {
    parsed = jsonio::Document::parse(text, sink.file(), {"level", format_hint()});
    parsed.report_to(sink);
    if (!parsed.root()) return std::nullopt;
    Json& document = *parsed.root();
    auto format = document.find("format");
    if (format == document.end()) {
        sink.error("format", "missing required field \"format\"", "add \"format\": \"killswitch-level\"");
        return std::nullopt;
    }
    if (!format->is_string() || format->get<std::string>() != kFormatName) {
        sink.error("format", "not a Killswitch level: format is " + jsonio::quote(*format),
                   "a level file has \"format\": \"killswitch-level\"");
        return std::nullopt;
    }
    const int version = read_version(document, sink);
    if (version < 0) return std::nullopt;
    if (version < kFormatVersion) {
        for (const std::string& step : migrate(document, version))
            sink.warning("version", "upgraded from an older format (" + step + ")",
                         "save the level to write it in version " + std::to_string(kFormatVersion));
    }

    ReadLevel read = read_level(document, sink);
    // Settings::sun_direction is stored unit length; a designer may write any non-zero direction.
    read.level.settings.sun_direction = normalized_direction(read.level.settings.sun_direction);
    check_level(read.level, sink, read.source_index);
    return std::move(read.level);
}

Result<Level> finish(std::optional<Level> level, DiagnosticSink& sink, const std::string& file,
                     LoadReport* report) {
    LoadReport local;
    local.diagnostics = sink.take_sorted();
    if (!report) {
        for (const Diagnostic& d : local.diagnostics)
            if (d.severity == Diagnostic::Severity::Warning) log::warn(d.error.str());
    }
    Result<Level> result = local.has_errors() || !level ? Result<Level>(errors_of(local.diagnostics, file))
                                                        : Result<Level>(std::move(*level));
    if (report) *report = std::move(local);
    return result;
}

} // namespace

bool LoadReport::has_errors() const {
    return error_count() > 0;
}

int LoadReport::error_count() const {
    return static_cast<int>(std::count_if(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& d) {
        return d.severity == Diagnostic::Severity::Error;
    }));
}

int LoadReport::warning_count() const {
    return static_cast<int>(diagnostics.size()) - error_count();
}

std::string LoadReport::str() const {
    std::string out;
    for (const Diagnostic& d : diagnostics) {
        out += d.severity == Diagnostic::Severity::Error ? "error: " : "warning: ";
        out += d.error.str();
        out += '\n';
    }
    return out;
}

Result<Level> load_level_string(std::string_view text, const std::string& file_name, LoadReport* report) {
    jsonio::Document document;
    DiagnosticSink sink(file_name, &document.positions());
    std::optional<Level> level = parse_level(text, sink, document);
    return finish(std::move(level), sink, file_name, report);
}

Result<Level> load_level_file(const std::filesystem::path& path, LoadReport* report) {
    Result<std::string> text = files::read_text(path);
    if (!text) {
        if (report) {
            report->diagnostics.clear();
            report->diagnostics.push_back({Diagnostic::Severity::Error, text.error()});
        }
        return text.error();
    }
    return load_level_string(*text, path.string(), report);
}

std::string save_level_string(const Level& level) {
    return jsonio::write_document(write_level(level));
}

Result<void> save_level_file(const std::filesystem::path& path, const Level& level) {
    return files::write_atomic(path, save_level_string(level));
}

nlohmann::json entity_to_json(const Entity& entity) {
    return nlohmann::json(write_entity(entity));
}

Result<Entity> entity_from_json(const nlohmann::json& json, const std::string& context, LoadReport* report) {
    DiagnosticSink sink(context);
    const Json ordered(json);
    std::optional<Entity> entity = read_entity(ordered, "", sink);
    if (entity) check_entity(*entity, "", sink);
    LoadReport local;
    local.diagnostics = sink.take_sorted();
    Result<Entity> result = local.has_errors() || !entity
                                ? Result<Entity>(errors_of(local.diagnostics, context))
                                : Result<Entity>(std::move(*entity));
    if (report) *report = std::move(local);
    return result;
}

LoadReport validate(const Level& level, const std::string& file_name) {
    DiagnosticSink sink(file_name);
    check_level(level, sink);
    LoadReport report;
    report.diagnostics = sink.take_sorted();
    return report;
}

} // namespace ks::level
