// An ASCII FBX file's connections checked for cycles before assimp reads it (fbx_connections.h).
#include "modelio/fbx_connections.h"

#include <charconv>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace ks::modelio {

namespace {

struct Link {
    std::int64_t child = 0, parent = 0;
    int line = 0;
};

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

// `C: "OO",child,parent` or `C: "OP",child,parent,"property"`; false for any other line.
bool parse_link(std::string_view line, Link& out) {
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

} // namespace

Result<void> check_fbx_connections(std::string_view text, const std::filesystem::path& path) {
    if (text.starts_with("Kaydara FBX Binary")) return ok();
    std::unordered_map<std::int64_t, std::vector<std::pair<std::int64_t, int>>>
        parents; // child -> (parent, line)
    int line_number = 0;
    for (size_t start = 0; start < text.size();) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        ++line_number;
        Link link;
        if (parse_link(text.substr(start, end - start), link))
            parents[link.child].push_back({link.parent, line_number});
        start = end + 1;
    }
    // Depth-first from every object along child -> parent links, iteratively (the point is not to recurse):
    // 0 unseen, 1 on the current path, 2 done.
    std::unordered_map<std::int64_t, int> state;
    for (const auto& [root, unused] : parents) {
        if (state[root] != 0) continue;
        std::vector<std::pair<std::int64_t, size_t>> stack{{root, 0}};
        state[root] = 1;
        while (!stack.empty()) {
            auto& [object, next] = stack.back();
            const auto it = parents.find(object);
            if (it == parents.end() || next >= it->second.size()) {
                state[object] = 2;
                stack.pop_back();
                continue;
            }
            const auto [parent, line] = it->second[next++];
            int& seen = state[parent];
            if (seen == 1)
                return Error(
                    "line " + std::to_string(line) + ": the connection of object " + std::to_string(object) +
                        " to " + std::to_string(parent) +
                        " closes a loop (an object its own ancestor), which the FBX reader cannot follow",
                    Location(path.string()), "export the FBX again from the modelling tool");
            if (seen == 0) {
                seen = 1;
                stack.push_back({parent, 0});
            }
        }
    }
    return ok();
}

} // namespace ks::modelio
