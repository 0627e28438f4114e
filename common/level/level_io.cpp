#include "level/level_io.h"

#include "core/files.h"
#include "core/log.h"
#include "jsonio/describe.h"
#include "jsonio/json_writer.h"
#include "jsonio/number_text.h"
#include "jsonio/parse_failure.h"
#include "jsonio/position_map.h"
#include "level/diagnostics.h"
#include "level/level_checks.h"
#include "level/level_migrate.h"
#include "level/level_reader.h"
#include "level/level_writer.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::level {

using jsonio::PositionMap;

namespace {

using Json = nlohmann::ordered_json;

constexpr size_t kMaxErrorsInMessage = 50;
std::string format_hint() {
    return "a level file starts with {\"format\": \"killswitch-level\", \"version\": " +
           std::to_string(kFormatVersion) + ", ...}";
}

bool is_blank(std::string_view text) {
    return std::all_of(text.begin(), text.end(),
                       [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; });
}

// Offset of the first byte that cannot be in a UTF-8 text file (NUL, other control bytes, broken UTF-8),
// or npos. Files that fail this are binary or corrupt: one clear message beats a cryptic parse error.
size_t first_binary_byte(std::string_view text) {
    size_t i = 0;
    while (i < text.size()) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x80) {
            if (c < 0x20 && c != '\n' && c != '\r' && c != '\t') return i;
            ++i;
            continue;
        }
        const int continuation = c >= 0xF0 && c <= 0xF4   ? 3
                                 : c >= 0xE0 && c <= 0xEF ? 2
                                 : c >= 0xC2 && c <= 0xDF ? 1
                                                          : -1;
        if (continuation < 0) return i;
        for (int k = 1; k <= continuation; ++k) {
            if (i + static_cast<size_t>(k) >= text.size() ||
                (static_cast<unsigned char>(text[i + static_cast<size_t>(k)]) & 0xC0) != 0x80)
                return i;
        }
        i += static_cast<size_t>(continuation) + 1;
    }
    return std::string_view::npos;
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

Error combined_error(const std::vector<Diagnostic>& diagnostics, const std::string& file) {
    std::vector<Error> errors;
    size_t total = 0;
    for (const Diagnostic& d : diagnostics) {
        if (d.severity != Diagnostic::Severity::Error) continue;
        if (++total <= kMaxErrorsInMessage) errors.push_back(d.error);
    }
    if (total > kMaxErrorsInMessage)
        errors.emplace_back("... and " + std::to_string(total - kMaxErrorsInMessage) + " more errors",
                            Location(file));
    Error combined = combine_errors(errors);
    if (combined.where.file.empty()) combined.where.file = file;
    return combined;
}

// Parses, migrates, reads and checks; every problem goes to the sink.
std::optional<Level> parse_level(std::string_view text, DiagnosticSink& sink, PositionMap& positions) {
    // Some Windows editors start UTF-8 files with a byte-order mark; it is not JSON, but it is not an error.
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    if (is_blank(text)) {
        sink.error_at({}, "", "file is empty", format_hint());
        return std::nullopt;
    }
    if (size_t bad = first_binary_byte(text); bad != std::string_view::npos) {
        char byte[8];
        std::snprintf(byte, sizeof(byte), "0x%02x",
                      static_cast<unsigned>(static_cast<unsigned char>(text[bad])));
        sink.error_at(jsonio::position_of_offset(text, bad), "",
                      std::string("file is not a text file (byte ") + byte + " at offset " +
                          std::to_string(bad) + ")",
                      "this does not look like a level file; " + format_hint());
        return std::nullopt;
    }

    positions = PositionMap::scan(text);
    std::string patched;
    std::string_view to_parse = text;
    if (!positions.overflowing_numbers().empty()) {
        patched = std::string(text);
        for (const jsonio::OverflowingNumber& n : positions.overflowing_numbers()) {
            sink.error_at(n.position, n.path, "number " + n.token + " overflows to infinity",
                          "write a finite number within the field's range");
            sink.mark_reported(n.path);
            patched.replace(n.offset, n.length,
                            "null" + std::string(n.length - 4, ' ')); // same length: positions hold
        }
        to_parse = patched;
    }

    Json document;
    try {
        document = Json::parse(to_parse);
    } catch (const nlohmann::json::parse_error& e) {
        const jsonio::ParseFailure failure = jsonio::describe_parse_error(text, e);
        if (failure.at_end)
            sink.error_at(failure.position, "", "file ends early (truncated?): " + failure.message,
                          "complete the file or restore it from a backup");
        else
            sink.error_at(failure.position, "", failure.message, "fix the JSON syntax at this place");
        return std::nullopt;
    } catch (const nlohmann::json::exception& e) {
        sink.error_at({}, "", std::string("JSON could not be read: ") + e.what(), "fix the JSON syntax");
        return std::nullopt;
    }

    for (const jsonio::DuplicateKey& d : positions.duplicate_keys())
        sink.error_at(d.second, d.path,
                      "duplicate key (also at line " + std::to_string(d.first.line) + ":" +
                          std::to_string(d.first.column) + "); only one would be kept",
                      "remove one of them");

    if (!document.is_object()) {
        sink.error_at(positions.find(""), "",
                      "expected the level as a JSON object {...}, found " +
                          std::string(document.is_array() ? "an array" : document.type_name()),
                      format_hint());
        return std::nullopt;
    }
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
    Result<Level> result = local.has_errors() || !level
                               ? Result<Level>(combined_error(local.diagnostics, file))
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
    PositionMap positions;
    DiagnosticSink sink(file_name, &positions);
    std::optional<Level> level = parse_level(text, sink, positions);
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
                                ? Result<Entity>(combined_error(local.diagnostics, context))
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
