// An FBX file's connections read (ASCII or binary) and checked for cycles before assimp reads it
// (fbx_checks.h).
#include "modelio/fbx_checks.h"

#include "modelio/fbx_records.h"

#include <charconv>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

namespace ks::modelio {

namespace {

// ---- ASCII: `C: "OO",child,parent` or `C: "OP",child,parent,"property"` lines ----

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

bool parse_ascii_link(std::string_view line, FbxLink& out) {
    size_t i = 0;
    while (i < line.size() && is_space(line[i])) ++i;
    line.remove_prefix(i);
    if (!line.starts_with("C:")) return false;
    line.remove_prefix(2);
    while (!line.empty() && is_space(line.front())) line.remove_prefix(1);
    if (!line.starts_with("\"OO\"") && !line.starts_with("\"OP\"")) return false;
    line.remove_prefix(4);
    std::int64_t ids[2] = {0, 0};
    for (std::int64_t& id : ids) {
        while (!line.empty() && (is_space(line.front()) || line.front() == ',')) line.remove_prefix(1);
        const auto [end, ec] = std::from_chars(line.data(), line.data() + line.size(), id);
        if (ec != std::errc()) return false;
        line.remove_prefix(static_cast<size_t>(end - line.data()));
    }
    out.child = ids[0];
    out.parent = ids[1];
    return true;
}

void read_ascii_links(std::string_view text, std::vector<FbxLink>& links) {
    size_t line_number = 0;
    for (size_t start = 0; start < text.size();) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        ++line_number;
        FbxLink link;
        link.place = line_number;
        if (parse_ascii_link(text.substr(start, end - start), link)) links.push_back(link);
        start = end + 1;
    }
}

// ---- Binary: "C" records inside the top-level "Connections" (fbx_records.h walks and checks the file) ----

std::optional<std::uint64_t> number_at(std::string_view bytes, std::size_t at, std::size_t size) {
    if (at > bytes.size() || size > bytes.size() - at) return std::nullopt;
    std::uint64_t value = 0;
    for (std::size_t i = 0; i < size; ++i)
        value |= std::uint64_t(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
    return value;
}

// A "C" record's properties: 'S' "OO"/"OP", then the two ids as 'L' (FBX 7); anything else is no link.
std::optional<FbxLink> binary_link(const FbxRecord& c) {
    const std::string_view p = c.properties;
    const auto length = number_at(p, 1, 4);
    if (p.empty() || p[0] != 'S' || !length || *length != 2 || p.size() < 7) return std::nullopt;
    const std::string_view kind = p.substr(5, 2);
    if (kind != "OO" && kind != "OP") return std::nullopt;
    FbxLink link;
    link.place = c.at;
    std::size_t next = 7;
    for (std::int64_t* id : {&link.child, &link.parent}) {
        const auto value = number_at(p, next + 1, 8);
        if (next >= p.size() || p[next] != 'L' || !value) return std::nullopt;
        *id = static_cast<std::int64_t>(*value);
        next += 9;
    }
    return link;
}

std::optional<FbxDamage> read_binary_links(std::string_view file, std::vector<FbxLink>& links) {
    return walk_binary_fbx(file, [&](const FbxRecord& record) {
        if (record.depth == 1 && record.parent == "Connections" && record.name == "C")
            if (const auto link = binary_link(record)) links.push_back(*link);
    });
}

// ---- ASCII nesting: assimp's parser recurses once per "{" ----

// The line of the first "{" deeper than kMaxFbxNesting (outside strings and ";" comments), if any.
std::optional<std::size_t> too_deep_line(std::string_view text) {
    std::size_t depth = 0, line = 1;
    bool in_string = false, in_comment = false;
    for (char c : text) {
        if (c == '\n') {
            ++line;
            in_comment = false;
        } else if (in_comment) {
            continue;
        } else if (c == '"') {
            in_string = !in_string;
        } else if (in_string) {
            continue;
        } else if (c == ';') {
            in_comment = true;
        } else if (c == '{') {
            if (++depth >= kMaxFbxNesting) return line;
        } else if (c == '}' && depth > 0) {
            --depth;
        }
    }
    return std::nullopt;
}

// Depth-first along child -> parent links, iteratively (the point is not to recurse): the first link found
// that reaches an object on the current path.
std::optional<FbxLink> first_loop(const std::vector<FbxLink>& links) {
    std::unordered_map<std::int64_t, std::vector<const FbxLink*>> parents;
    for (const FbxLink& link : links) parents[link.child].push_back(&link);
    enum class Seen { No, OnPath, Done };
    std::unordered_map<std::int64_t, Seen> state;
    for (const FbxLink& start : links) {
        if (state[start.child] != Seen::No) continue;
        std::vector<std::pair<std::int64_t, size_t>> stack{{start.child, 0}};
        state[start.child] = Seen::OnPath;
        while (!stack.empty()) {
            auto& [object, next] = stack.back();
            const auto& up = parents[object];
            if (next >= up.size()) {
                state[object] = Seen::Done;
                stack.pop_back();
                continue;
            }
            const FbxLink& link = *up[next++];
            Seen& seen = state[link.parent];
            if (seen == Seen::OnPath) return link;
            if (seen == Seen::No) {
                seen = Seen::OnPath;
                stack.push_back({link.parent, 0});
            }
        }
    }
    return std::nullopt;
}

} // namespace

FbxLinks read_fbx_links(std::string_view file) {
    FbxLinks result;
    result.binary = is_binary_fbx(file);
    if (result.binary)
        (void)read_binary_links(file, result.links); // the links before any damage
    else
        read_ascii_links(file, result.links);
    return result;
}

Result<void> check_fbx_file(std::string_view file, const std::filesystem::path& path) {
    FbxLinks read;
    read.binary = is_binary_fbx(file);
    if (read.binary) {
        if (const auto damage = read_binary_links(file, read.links))
            return Error("byte " + std::to_string(damage->at) + ": " + damage->what, Location(path.string()),
                         "the binary FBX file is damaged (cut short or corrupted): export it again from the "
                         "modelling tool");
    } else {
        if (const auto line = too_deep_line(file))
            return Error("line " + std::to_string(*line) + ": scopes are nested more than " +
                             std::to_string(kMaxFbxNesting) + " deep",
                         Location(path.string()), "export the FBX again from the modelling tool");
        read_ascii_links(file, read.links);
    }
    const std::optional<FbxLink> loop = first_loop(read.links);
    if (!loop) return ok();
    return Error((read.binary ? "byte " : "line ") + std::to_string(loop->place) +
                     ": the connection of object " + std::to_string(loop->child) + " to " +
                     std::to_string(loop->parent) +
                     " closes a loop (an object its own ancestor), which the FBX reader cannot follow",
                 Location(path.string()), "export the FBX again from the modelling tool");
}

} // namespace ks::modelio
