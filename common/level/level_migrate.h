#pragma once
// Older level files are upgraded in memory, one version step at a time, before they are read: migration
// N turns a version-N document into a version-(N+1) one. Adding a format version means adding one function
// to the table and bumping kFormatVersion; files on disk are only rewritten when a designer saves.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ks::level {

struct Migration {
    int from_version;
    const char* summary; // what changed, for the docs and the load warning
    void (*apply)(nlohmann::ordered_json& document);
    // False for a step that only says which types a file may hold (2 -> 3 added the brush type): the file
    // reads exactly as before, so loading it is no news worth a warning.
    bool changes_document = true;
};

// Index N holds the step from version N to N+1; its size is kFormatVersion.
const std::vector<Migration>& migrations();

// Upgrades `document` from `version` to kFormatVersion. Returns the summaries of the steps applied that
// change the document (the load warns with each).
std::vector<std::string> migrate(nlohmann::ordered_json& document, int version);

} // namespace ks::level
