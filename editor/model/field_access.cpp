#include "model/field_access.h"

#include "level/sound_name.h"
#include "level/texture_names.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <type_traits>

namespace ks::editor {
namespace {

template <class T>
constexpr FieldKind kind_of() {
    if constexpr (std::is_same_v<T, float>)
        return FieldKind::Float;
    else if constexpr (std::is_same_v<T, int>)
        return FieldKind::Int;
    else if constexpr (std::is_same_v<T, bool>)
        return FieldKind::Bool;
    else if constexpr (std::is_same_v<T, std::string>)
        return FieldKind::String;
    else if constexpr (std::is_same_v<T, Vec2>)
        return FieldKind::Vec2;
    else if constexpr (std::is_same_v<T, Vec3>)
        return FieldKind::Vec3;
    else if constexpr (std::is_same_v<T, level::Color>)
        return FieldKind::Color;
    else if constexpr (std::is_same_v<T, level::SoundName>)
        return FieldKind::Sound;
    else {
        static_assert(std::is_same_v<T, level::Choice>, "a field type the editor does not know");
        return FieldKind::Choice;
    }
}

template <class T>
FieldDescriptor describe(const T& value, const level::FieldInfo& info) {
    FieldDescriptor d{info.name, info.tooltip, info.min, info.max, info.unit, kind_of<T>(), {}, info.slider};
    if constexpr (std::is_same_v<T, std::string>)
        if (level::is_texture_field(info.name)) d.kind = FieldKind::Texture;
    if constexpr (std::is_same_v<T, level::Choice>) d.options = value.options;
    if constexpr (std::is_same_v<T, level::Color>) d.min = 0, d.max = 1;
    return d;
}

template <class T>
FieldValue to_value(const T& value) {
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, int>)
        return static_cast<double>(value);
    else if constexpr (std::is_same_v<T, level::Choice> || std::is_same_v<T, level::SoundName>)
        return value.value;
    else
        return value;
}

template <class T>
void store(T& target, const FieldValue& value) {
    if constexpr (std::is_same_v<T, float>)
        target = static_cast<float>(std::get<double>(value));
    else if constexpr (std::is_same_v<T, int>)
        target = static_cast<int>(std::get<double>(value));
    else if constexpr (std::is_same_v<T, level::Choice> || std::is_same_v<T, level::SoundName>)
        target.value = std::get<std::string>(value);
    else
        target = std::get<T>(value);
}

// A robot's patrol is a list, not one value: it is edited point by point (editor_patrol.cpp), so the
// by-name field access below leaves it out; so is a brush's faces (shaped by the brush tools, not typed).
struct Describer {
    std::vector<FieldDescriptor> out;
    template <class T>
    void field(T& value, const level::FieldInfo& info) {
        out.push_back(describe(value, info));
    }
    void field(level::Patrol&, const level::FieldInfo&) {}
    void field(brush::Brush&, const level::FieldInfo&) {}
};

// Calls fn(value, descriptor) for the field called `name`; `found` says whether there was one.
template <class F>
struct Finder {
    std::string_view name;
    F& fn;
    bool found = false;
    template <class T>
    void field(T& value, const level::FieldInfo& info) {
        if (found || name != info.name) return;
        found = true;
        fn(value, describe(value, info));
    }
    void field(level::Patrol&, const level::FieldInfo&) {}
    void field(brush::Brush&, const level::FieldInfo&) {}
};

template <class Visitable, class F>
bool find_field(Visitable& object, std::string_view name, F&& fn) {
    Finder<F> finder{name, fn};
    object.visit(finder);
    return finder.found;
}

template <class F>
bool find_prop(level::Props& props, std::string_view name, F&& fn) {
    return std::visit([&](auto& p) { return find_field(p, name, fn); }, props);
}

FieldDescriptor name_field() {
    return {"name", "Free text shown in the outliner", 0, 0, "", FieldKind::String, {}};
}
FieldDescriptor position_field() {
    return {"position", "Where the entity stands (its bottom centre; a floor's walking surface)",
            -1e5,       1e5,
            "units",    FieldKind::Vec3,
            {}};
}
FieldDescriptor rotation_field() {
    return {"rotation", "Yaw, pitch and roll", -360, 360, "deg", FieldKind::Vec3, {}};
}

Error unknown_field(std::string_view name, const std::vector<FieldDescriptor>& fields,
                    std::string_view owner) {
    std::string names;
    for (const auto& f : fields) names += (names.empty() ? "" : ", ") + f.name;
    return Error("unknown field '" + std::string(name) + "' for " + std::string(owner), Location{},
                 "fields: " + names);
}

// Values usually come from float fields: print them as the shortest float so 0.1f reads "0.1".
std::string fmt_double(double v) {
    char buf[64];
    const auto as_float = static_cast<float>(v);
    auto res = std::isfinite(v) && static_cast<double>(as_float) == v
                   ? std::to_chars(buf, buf + sizeof buf, as_float)
                   : std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, res.ptr);
}

Result<void> check_number(const FieldDescriptor& field, double v, const char* component = nullptr) {
    std::string what = "'" + field.name + "'" + (component ? std::string(".") + component : "");
    if (!std::isfinite(v))
        return Error(what + " must be a finite number", Location{}, "got " + fmt_double(v));
    if (v < field.min || v > field.max)
        return Error(what + " = " + fmt_double(v) + " is out of range", Location{},
                     "valid range is " + fmt_double(field.min) + " .. " + fmt_double(field.max) +
                         (field.unit.empty() ? "" : " " + field.unit));
    return ok();
}

bool parse_double(std::string_view text, double& out) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    if (text.empty()) return false;
    auto res = std::from_chars(text.data(), text.data() + text.size(), out);
    return res.ec == std::errc() && res.ptr == text.data() + text.size();
}

bool parse_components(std::string_view text, double* out, int count) {
    for (int i = 0; i < count; ++i) {
        size_t comma = text.find(',');
        if ((i + 1 < count) != (comma != std::string_view::npos)) return false;
        if (!parse_double(text.substr(0, comma), out[i])) return false;
        if (comma != std::string_view::npos) text.remove_prefix(comma + 1);
    }
    return true;
}

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

} // namespace

const char* field_kind_name(FieldKind kind) {
    switch (kind) {
    case FieldKind::Float:
        return "number";
    case FieldKind::Int:
        return "integer";
    case FieldKind::Bool:
        return "true/false";
    case FieldKind::String:
        return "text";
    case FieldKind::Vec2:
        return "x,z pair";
    case FieldKind::Vec3:
        return "x,y,z triple";
    case FieldKind::Color:
        return "colour";
    case FieldKind::Choice:
        return "choice";
    case FieldKind::Sound:
        return "sound name";
    case FieldKind::Texture:
        return "texture name";
    }
    return "?";
}

std::vector<FieldDescriptor> describe_entity_fields(const level::Entity& entity) {
    Describer d;
    d.out = {name_field(), position_field(), rotation_field()};
    level::Props copy = entity.props; // visit() takes non-const references
    std::visit([&](auto& p) { p.visit(d); }, copy);
    return d.out;
}

std::vector<FieldDescriptor> describe_settings_fields() {
    Describer d;
    level::Settings copy;
    copy.visit(d);
    return d.out;
}

std::vector<FieldDescriptor> common_fields(const std::vector<const level::Entity*>& entities) {
    if (entities.empty()) return {};
    std::vector<FieldDescriptor> result = describe_entity_fields(*entities.front());
    for (size_t i = 1; i < entities.size(); ++i) {
        auto other = describe_entity_fields(*entities[i]);
        std::erase_if(result, [&](const FieldDescriptor& f) {
            for (const auto& o : other)
                if (o.name == f.name && o.kind == f.kind) return false;
            return true;
        });
    }
    return result;
}

Result<void> check_field_value(const FieldDescriptor& field, const FieldValue& value) {
    auto wrong_type = [&] { return Error("'" + field.name + "' expects a " + field_kind_name(field.kind)); };
    switch (field.kind) {
    case FieldKind::Float:
    case FieldKind::Int: {
        if (!std::holds_alternative<double>(value)) return wrong_type();
        double v = std::get<double>(value);
        if (auto r = check_number(field, v); !r) return r;
        if (field.kind == FieldKind::Int && v != std::floor(v))
            return Error("'" + field.name + "' must be a whole number", Location{}, "got " + fmt_double(v));
        return ok();
    }
    case FieldKind::Bool:
        return std::holds_alternative<bool>(value) ? ok() : Result<void>(wrong_type());
    case FieldKind::String:
    case FieldKind::Texture: {
        if (!std::holds_alternative<std::string>(value)) return wrong_type();
        if (field.kind == FieldKind::Texture && std::get<std::string>(value).empty())
            return Error("'" + field.name + "' is empty", Location{},
                         "name a surface material from assets/textures (the texture browser lists them)");
        for (char c : std::get<std::string>(value))
            if (static_cast<unsigned char>(c) < 0x20)
                return Error("'" + field.name + "' contains a control character", Location{},
                             "use plain text");
        return ok();
    }
    case FieldKind::Vec2: {
        if (!std::holds_alternative<Vec2>(value)) return wrong_type();
        const Vec2 v = std::get<Vec2>(value);
        if (auto r = check_number(field, v.x, "x"); !r) return r;
        return check_number(field, v.y, "z");
    }
    case FieldKind::Vec3: {
        if (!std::holds_alternative<Vec3>(value)) return wrong_type();
        const Vec3 v = std::get<Vec3>(value);
        const char* names[3] = {"x", "y", "z"};
        for (int i = 0; i < 3; ++i)
            if (auto r = check_number(field, v[i], names[i]); !r) return r;
        return ok();
    }
    case FieldKind::Color: {
        if (!std::holds_alternative<level::Color>(value)) return wrong_type();
        const auto c = std::get<level::Color>(value);
        for (auto [v, n] : {std::pair{c.r, "r"}, std::pair{c.g, "g"}, std::pair{c.b, "b"}})
            if (auto r = check_number(field, v, n); !r) return r;
        return ok();
    }
    case FieldKind::Choice: {
        if (!std::holds_alternative<std::string>(value)) return wrong_type();
        for (const auto& o : field.options)
            if (o == std::get<std::string>(value)) return ok();
        std::string opts;
        for (const auto& o : field.options) opts += (opts.empty() ? "" : ", ") + o;
        return Error("'" + std::get<std::string>(value) + "' is not an option of '" + field.name + "'",
                     Location{}, "options: " + opts);
    }
    case FieldKind::Sound: {
        if (!std::holds_alternative<std::string>(value)) return wrong_type();
        const auto problem = level::sound_name_problem(
            std::get<std::string>(value), static_cast<int>(field.min), static_cast<int>(field.max));
        if (problem.message.empty()) return ok();
        return Error("'" + field.name + "': " + problem.message, Location{}, problem.hint);
    }
    }
    return wrong_type();
}

Result<FieldValue> get_entity_field(const level::Entity& entity, std::string_view name) {
    if (name == "name") return FieldValue(entity.name);
    if (name == "position") return FieldValue(entity.position);
    if (name == "rotation") return FieldValue(entity.rotation);
    level::Props copy = entity.props;
    FieldValue out;
    if (find_prop(copy, name, [&](auto& v, const FieldDescriptor&) { out = to_value(v); })) return out;
    return unknown_field(name, describe_entity_fields(entity), std::string(level::type_name(entity.type())));
}

Result<void> set_entity_field(level::Entity& entity, std::string_view name, const FieldValue& value) {
    auto set_common = [&](auto& target, const FieldDescriptor& field) -> Result<void> {
        if (auto r = check_field_value(field, value); !r) return r;
        store(target, value);
        return ok();
    };
    if (name == "name") return set_common(entity.name, name_field());
    if (name == "position") return set_common(entity.position, position_field());
    if (name == "rotation") return set_common(entity.rotation, rotation_field());
    Result<void> result = ok();
    bool found = find_prop(entity.props, name, [&](auto& target, const FieldDescriptor& field) {
        result = check_field_value(field, value);
        if (result) store(target, value);
    });
    if (!found)
        return unknown_field(name, describe_entity_fields(entity),
                             std::string(level::type_name(entity.type())));
    return result;
}

Result<FieldValue> default_entity_field(const level::Entity& entity, std::string_view name) {
    level::Entity fresh;
    fresh.props = level::default_props(entity.type());
    if (name == "position" || name == "rotation") return FieldValue(Vec3(0.0f));
    return get_entity_field(fresh, name);
}

Result<FieldValue> get_settings_field(const level::Settings& settings, std::string_view name) {
    level::Settings copy = settings;
    FieldValue out;
    if (find_field(copy, name, [&](auto& v, const FieldDescriptor&) { out = to_value(v); })) return out;
    return unknown_field(name, describe_settings_fields(), "level settings");
}

Result<void> set_settings_field(level::Settings& settings, std::string_view name, const FieldValue& value) {
    Result<void> result = ok();
    bool found = find_field(settings, name, [&](auto& target, const FieldDescriptor& field) {
        result = check_field_value(field, value);
        if (result) store(target, value);
    });
    if (!found) return unknown_field(name, describe_settings_fields(), "level settings");
    return result;
}

Result<FieldValue> parse_field_value(const FieldDescriptor& field, std::string_view text) {
    auto bad = [&](const char* example) {
        return Error("cannot read '" + std::string(text) + "' as the " + field_kind_name(field.kind) + " '" +
                         field.name + "'",
                     Location{}, std::string("write it like ") + example);
    };
    FieldValue value;
    switch (field.kind) {
    case FieldKind::Float:
    case FieldKind::Int: {
        double v = 0;
        if (!parse_double(text, v)) return bad(field.kind == FieldKind::Int ? "12" : "2.5");
        // Fields are floats: round now so that "0.7" compares equal to the stored 0.7f.
        value = field.kind == FieldKind::Float && std::isfinite(v) && std::abs(v) < 3e38
                    ? static_cast<double>(static_cast<float>(v))
                    : v;
        break;
    }
    case FieldKind::Bool:
        if (text == "true" || text == "on" || text == "1")
            value = true;
        else if (text == "false" || text == "off" || text == "0")
            value = false;
        else
            return bad("true or false");
        break;
    case FieldKind::String:
    case FieldKind::Choice:
    case FieldKind::Sound:
    case FieldKind::Texture:
        value = std::string(text);
        break;
    case FieldKind::Vec2: {
        double c[2];
        if (!parse_components(text, c, 2)) return bad("10,20");
        value = Vec2(static_cast<float>(c[0]), static_cast<float>(c[1]));
        break;
    }
    case FieldKind::Vec3: {
        double c[3];
        if (!parse_components(text, c, 3)) return bad("1,2,3");
        value = Vec3(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]));
        break;
    }
    case FieldKind::Color: {
        if (text.size() != 7 || text[0] != '#') return bad("#ffcc80");
        float rgb[3];
        for (int i = 0; i < 3; ++i) {
            int hi = hex_digit(text[1 + 2 * i]), lo = hex_digit(text[2 + 2 * i]);
            if (hi < 0 || lo < 0) return bad("#ffcc80");
            rgb[i] = static_cast<float>(hi * 16 + lo) / 255.0f;
        }
        value = level::Color{rgb[0], rgb[1], rgb[2]};
        break;
    }
    }
    if (auto r = check_field_value(field, value); !r) return r.error();
    return value;
}

std::string format_field_value(const FieldValue& value) {
    struct Formatter {
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(double d) const { return fmt_double(d); }
        std::string operator()(const std::string& s) const { return s; }
        std::string operator()(const Vec2& v) const { return fmt_double(v.x) + "," + fmt_double(v.y); }
        std::string operator()(const Vec3& v) const {
            return fmt_double(v.x) + "," + fmt_double(v.y) + "," + fmt_double(v.z);
        }
        std::string operator()(const level::Color& c) const {
            char buf[8];
            auto byte = [](float f) {
                return static_cast<int>(std::lround(std::clamp(f, 0.0f, 1.0f) * 255.0f));
            };
            std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
            return buf;
        }
    };
    return std::visit(Formatter{}, value);
}

} // namespace ks::editor
