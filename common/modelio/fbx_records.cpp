// A binary FBX file's records walked with every length checked (fbx_records.h). The rules are those of
// assimp 5.2.5's FBXBinaryTokenizer: a record is its end offset, property count and property bytes (32-bit
// before version 7500, 64-bit from it), a name of up to 255 bytes without NUL, its properties, and, when it
// ends after them, its children followed by a null record of zeros.
#include "modelio/fbx_records.h"

#include <limits>
#include <vector>

namespace ks::modelio {

namespace {

constexpr std::string_view kMagic = "Kaydara FBX Binary";
constexpr std::size_t kVersionAt = 23, kFirstRecordAt = 27;

class Reader {
  public:
    explicit Reader(std::string_view file) : file_(file) {}

    // A little-endian unsigned of `bytes` at `at`, only when it lies before `limit`.
    std::optional<std::uint64_t> number(std::size_t at, std::size_t bytes, std::size_t limit) const {
        if (limit > file_.size() || at > limit || bytes > limit - at) return std::nullopt;
        std::uint64_t value = 0;
        for (std::size_t i = 0; i < bytes; ++i)
            value |= std::uint64_t(static_cast<unsigned char>(file_[at + i])) << (8 * i);
        return value;
    }

    // The end of the property starting at `at` (its type code), or damage; `limit` is the end of the
    // record's property bytes.
    std::optional<FbxDamage> skip_property(std::size_t& at, std::size_t limit) const {
        const std::size_t type_at = at;
        const char type = file_[at++];
        std::uint64_t size = 0;
        switch (type) {
        case 'C':
            size = 1;
            break;
        case 'Y':
            size = 2;
            break;
        case 'I':
        case 'F':
            size = 4;
            break;
        case 'D':
        case 'L':
            size = 8;
            break;
        case 'b':
            size = limit - at;
            break; // assimp takes the rest of the property bytes
        case 'R':
        case 'S': {
            const auto length = number(at, 4, limit);
            if (!length) return FbxDamage{type_at, "a string property's length is cut off"};
            size = 4 + *length;
            break;
        }
        case 'f':
        case 'd':
        case 'l':
        case 'i':
        case 'c': {
            const auto count = number(at, 4, limit), encoding = number(at + 4, 4, limit),
                       stored = number(at + 8, 4, limit);
            if (!count || !encoding || !stored)
                return FbxDamage{type_at, "an array property's header is cut off"};
            const std::uint64_t stride = type == 'c' ? 1 : (type == 'd' || type == 'l') ? 8 : 4;
            if (*count * stride > std::numeric_limits<std::uint32_t>::max())
                return FbxDamage{type_at,
                                 "an array of " + std::to_string(*count) + " elements is larger than 4 GiB"};
            if (*encoding == 0 && *count * stride != *stored)
                return FbxDamage{type_at, "an array of " + std::to_string(*count) +
                                              " elements says it takes " + std::to_string(*stored) +
                                              " bytes"};
            if (*encoding > 1)
                return FbxDamage{type_at, "an array's encoding " + std::to_string(*encoding) + " is unknown"};
            size = 12 + *stored;
            break;
        }
        default:
            return FbxDamage{type_at, "unknown property type code " +
                                          std::to_string(static_cast<unsigned char>(type))};
        }
        if (size > limit - at) return FbxDamage{type_at, "a property runs past its record's property bytes"};
        at += static_cast<std::size_t>(size);
        return std::nullopt;
    }

  private:
    std::string_view file_;
};

// A record whose children are being read: they end at `children_end`, then the null record, then `end`.
struct OpenRecord {
    std::size_t end = 0, children_end = 0;
    std::string_view name;
};

} // namespace

bool is_binary_fbx(std::string_view file) {
    return file.starts_with(kMagic);
}

std::optional<FbxDamage> walk_binary_fbx(std::string_view file,
                                         const std::function<void(const FbxRecord&)>& visit) {
    const Reader read(file);
    const auto version = read.number(kVersionAt, 4, file.size());
    if (!version || file.size() < kFirstRecordAt)
        return FbxDamage{0, "the file is too short for a binary FBX header"};
    const std::size_t word = *version >= 7500 ? 8 : 4, null_record = 3 * word + 1;
    std::vector<OpenRecord> open;
    std::size_t cursor = kFirstRecordAt;
    for (;;) {
        const std::size_t limit = open.empty() ? file.size() : open.back().children_end;
        if (open.empty() && cursor >= file.size()) return std::nullopt;
        if (!open.empty() && cursor >= limit) { // the children are read: the null record, then the end
            for (std::size_t i = cursor; i < open.back().end; ++i)
                if (file[i] != '\0')
                    return FbxDamage{cursor, "the null record after the children of \"" +
                                                 std::string(open.back().name) + "\" is not all zeros"};
            cursor = open.back().end;
            open.pop_back();
            continue;
        }
        const std::size_t at = cursor;
        const auto end = read.number(at, word, limit);
        if (!end) return FbxDamage{at, "a record's header is cut off"};
        if (*end == 0) { // the null record: the end of the file's records; inside a record assimp reads on
            if (open.empty()) return std::nullopt;
            cursor += word;
            continue;
        }
        if (*end > limit)
            return FbxDamage{
                at, "a record says it ends at byte " + std::to_string(*end) +
                        (open.empty() ? ", past the end of the file"
                                      : ", past the children of \"" + std::string(open.back().name) + "\"")};
        if (*end < at + word)
            return FbxDamage{at,
                             "a record says it ends at byte " + std::to_string(*end) + ", before it begins"};
        const auto count = read.number(at + word, word, limit),
                   bytes = read.number(at + 2 * word, word, limit),
                   name_length = read.number(at + 3 * word, 1, limit);
        if (!count || !bytes || !name_length) return FbxDamage{at, "a record's header is cut off"};
        const std::size_t name_at = at + 3 * word + 1;
        if (*name_length > limit - name_at) return FbxDamage{at, "a record's name is cut off"};
        FbxRecord record;
        record.at = at;
        record.depth = open.size();
        record.parent = open.empty() ? std::string_view() : open.back().name;
        record.name = file.substr(name_at, static_cast<std::size_t>(*name_length));
        if (record.name.find('\0') != std::string_view::npos)
            return FbxDamage{at, "a record's name holds a NUL byte"};
        const std::size_t properties_at = name_at + record.name.size();
        if (*bytes > limit - properties_at)
            return FbxDamage{at, "the record \"" + std::string(record.name) + "\" says its properties take " +
                                     std::to_string(*bytes) + " bytes, more than are left"};
        const std::size_t properties_end = properties_at + static_cast<std::size_t>(*bytes);
        std::size_t p = properties_at;
        for (std::uint64_t i = 0; i < *count; ++i) {
            if (p >= properties_end)
                return FbxDamage{at, "the record \"" + std::string(record.name) + "\" says it has " +
                                         std::to_string(*count) + " properties, more than its bytes hold"};
            if (auto damage = read.skip_property(p, properties_end)) return damage;
        }
        if (p != properties_end)
            return FbxDamage{at, "the record \"" + std::string(record.name) +
                                     "\"'s properties do not fill its property bytes"};
        record.properties = file.substr(properties_at, properties_end - properties_at);
        visit(record);
        cursor = properties_end;
        if (cursor < *end) { // children
            if (*end - cursor < null_record)
                return FbxDamage{at, "the record \"" + std::string(record.name) +
                                         "\" has no room for the null record after its children"};
            if (open.size() + 1 >= kMaxFbxNesting)
                return FbxDamage{at,
                                 "records are nested more than " + std::to_string(kMaxFbxNesting) + " deep"};
            open.push_back(
                {static_cast<std::size_t>(*end), static_cast<std::size_t>(*end) - null_record, record.name});
            continue;
        }
        if (cursor != *end)
            return FbxDamage{at, "the record \"" + std::string(record.name) + "\" says it ends at byte " +
                                     std::to_string(*end) + ", inside its own properties"};
    }
}

} // namespace ks::modelio
