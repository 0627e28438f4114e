// An FBX file's connections read (ASCII or binary) and checked for cycles before assimp reads it
// (fbx_connections.h).
#include "modelio/fbx_connections.h"

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

// ---- Binary: node records (end offset, property count, property bytes, name) nested by end offsets ----

constexpr std::string_view kBinaryMagic{"Kaydara FBX Binary  \0", 21};
constexpr size_t kVersionAt = 23, kFirstRecordAt = 27;

// Little-endian reads that refuse to pass `limit`.
class BinaryReader {
  public:
    BinaryReader(std::string_view file, bool wide) : file_(file), wide_(wide) {}

    std::optional<std::uint64_t> unsigned_at(size_t at, size_t bytes, size_t limit) const {
        if (limit > file_.size() || at > limit || bytes > limit - at) return std::nullopt;
        std::uint64_t value = 0;
        for (size_t i = 0; i < bytes; ++i)
            value |= std::uint64_t(static_cast<unsigned char>(file_[at + i])) << (8 * i);
        return value;
    }

    struct Record {
        size_t end = 0;           // one past the record, its children included
        size_t properties_at = 0; // the first property's type code
        size_t children_at = 0;   // after the properties
        std::string_view name;
    };

    // The record at `at`, inside [at, limit); nullopt for the null record that ends a list, or for lengths
    // that leave the limit.
    std::optional<Record> record_at(size_t at, size_t limit) const {
        const size_t word = wide_ ? 8 : 4;
        const auto end = unsigned_at(at, word, limit);
        const auto property_bytes = unsigned_at(at + 2 * word, word, limit);
        const auto name_length = unsigned_at(at + 3 * word, 1, limit);
        if (!end || !property_bytes || !name_length || *end == 0) return std::nullopt;
        Record record;
        record.properties_at = at + 3 * word + 1 + size_t(*name_length);
        if (*end <= at || *end > limit || record.properties_at > *end ||
            *property_bytes > *end - record.properties_at)
            return std::nullopt;
        record.end = size_t(*end);
        record.children_at = record.properties_at + size_t(*property_bytes);
        record.name = file_.substr(at + 3 * word + 1, size_t(*name_length));
        return record;
    }

    // A "C" record's properties: 'S' "OO"/"OP", then the two ids as 'L' (FBX 7); anything else is no link.
    std::optional<FbxLink> link_in(const Record& c, size_t at) const {
        const size_t limit = c.children_at;
        const auto type = unsigned_at(c.properties_at, 1, limit);
        const auto length = unsigned_at(c.properties_at + 1, 4, limit);
        if (!type || *type != 'S' || !length || *length != 2) return std::nullopt;
        const size_t kind_at = c.properties_at + 5;
        if (!unsigned_at(kind_at, 2, limit)) return std::nullopt;
        const std::string_view kind = file_.substr(kind_at, 2);
        if (kind != "OO" && kind != "OP") return std::nullopt;
        FbxLink link;
        link.place = at;
        size_t next = kind_at + 2;
        for (std::int64_t* id : {&link.child, &link.parent}) {
            const auto id_type = unsigned_at(next, 1, limit);
            const auto value = unsigned_at(next + 1, 8, limit);
            if (!id_type || *id_type != 'L' || !value) return std::nullopt;
            *id = static_cast<std::int64_t>(*value);
            next += 9;
        }
        return link;
    }

  private:
    std::string_view file_;
    bool wide_ = false;
};

void read_binary_links(std::string_view file, std::vector<FbxLink>& links) {
    BinaryReader probe(file, false);
    const auto version = probe.unsigned_at(kVersionAt, 4, file.size());
    if (!version) return;
    const BinaryReader reader(file, *version >= 7500);
    for (size_t at = kFirstRecordAt; at < file.size();) {
        const auto top = reader.record_at(at, file.size());
        if (!top) return;
        if (top->name == "Connections")
            for (size_t child_at = top->children_at; child_at < top->end;) {
                const auto c = reader.record_at(child_at, top->end);
                if (!c) break;
                if (c->name == "C")
                    if (const auto link = reader.link_in(*c, child_at)) links.push_back(*link);
                child_at = c->end;
            }
        at = top->end;
    }
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
    result.binary = file.starts_with(kBinaryMagic);
    if (result.binary)
        read_binary_links(file, result.links);
    else
        read_ascii_links(file, result.links);
    return result;
}

Result<void> check_fbx_connections(std::string_view file, const std::filesystem::path& path) {
    const FbxLinks read = read_fbx_links(file);
    const std::optional<FbxLink> loop = first_loop(read.links);
    if (!loop) return ok();
    return Error((read.binary ? "byte " : "line ") + std::to_string(loop->place) +
                     ": the connection of object " + std::to_string(loop->child) + " to " +
                     std::to_string(loop->parent) +
                     " closes a loop (an object its own ancestor), which the FBX reader cannot follow",
                 Location(path.string()), "export the FBX again from the modelling tool");
}

} // namespace ks::modelio
