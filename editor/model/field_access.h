#pragma once
// Reading and writing any property by its field name, typed and range-checked against the FieldInfo that the
// level format's visit() lists. The inspector, the script language and multi-selection editing all go through
// here, so there is one place that knows how a field's text is parsed and what range it must respect.
#include "core/result.h"
#include "level/level.h"

#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace ks::editor {

// Sound: a sound name (level::SoundName), travelling as a string; its min and max bound the name's length.
// Texture: a texture field's name (level::is_texture_field), travelling as a string; whether the material
// exists is the validation's texture rule (a draft may name one that does not, so the fix can be offered).
enum class FieldKind { Float, Int, Bool, String, Vec2, Vec3, Color, Choice, Sound, Texture };
const char* field_kind_name(FieldKind kind);

// A field as the inspector shows it: widget kind, range, unit, tooltip and, for choices, the options.
struct FieldDescriptor {
    std::string name;
    std::string tooltip;
    double min = -1e6;
    double max = 1e6;
    std::string unit;
    FieldKind kind = FieldKind::Float;
    std::vector<std::string> options; // Choice only
    bool slider = false;              // Float, Int: shown as a slider over [min, max] (FieldInfo::slider)
    bool operator==(const FieldDescriptor&) const = default;
};

// Numbers travel as double (Int and Float), choices and sound names as their string.
using FieldValue = std::variant<bool, double, std::string, Vec2, Vec3, level::Color>;

// Every field of an entity: the common "name", "position", "rotation", then the type's own properties.
std::vector<FieldDescriptor> describe_entity_fields(const level::Entity& entity);
std::vector<FieldDescriptor> describe_settings_fields();
// Fields shared (same name and kind) by every entity given, in the first entity's order.
std::vector<FieldDescriptor> common_fields(const std::vector<const level::Entity*>& entities);

Result<FieldValue> get_entity_field(const level::Entity& entity, std::string_view name);
// Type- and range-checked; on error the entity is unchanged.
Result<void> set_entity_field(level::Entity& entity, std::string_view name, const FieldValue& value);
// The value a freshly placed entity of the same type has (revert-to-default). Name reverts to "".
Result<FieldValue> default_entity_field(const level::Entity& entity, std::string_view name);

Result<FieldValue> get_settings_field(const level::Settings& settings, std::string_view name);
Result<void> set_settings_field(level::Settings& settings, std::string_view name, const FieldValue& value);

// Text as designers and scripts write it: "12.5", "true", "1,2,3", "#ffcc80", a choice's option, free text.
Result<FieldValue> parse_field_value(const FieldDescriptor& field, std::string_view text);
std::string format_field_value(const FieldValue& value);

// Checks a value against a field's kind and range without storing it.
Result<void> check_field_value(const FieldDescriptor& field, const FieldValue& value);

} // namespace ks::editor
