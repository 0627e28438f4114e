// Field access by name: the inspector's descriptors, typed parsing and formatting, range checks.
#include "model/field_access.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace ks;
using namespace ks::editor;
using level::EntityType;

namespace {
level::Entity make(EntityType type) {
    level::Entity e;
    e.id = 1;
    e.props = level::default_props(type);
    return e;
}

const FieldDescriptor& field(const std::vector<FieldDescriptor>& fields, const std::string& name) {
    for (const auto& f : fields)
        if (f.name == name) return f;
    FAIL("no field " << name);
    return fields.front();
}
} // namespace

TEST_CASE("fields: every entity type lists name, position, rotation and its own props with ranges") {
    for (auto type : level::all_types()) {
        CAPTURE(level::type_name(type));
        auto fields = describe_entity_fields(make(type));
        // A brush's faces are shaped by the brush tools, not typed into fields.
        REQUIRE(fields.size() > (type == EntityType::Brush ? 2u : 3u));
        CHECK(fields[0].name == "name");
        CHECK(fields[1].name == "position");
        CHECK(fields[2].name == "rotation");
        for (const auto& f : fields) {
            CHECK_FALSE(f.tooltip.empty());
            CHECK(f.min <= f.max);
            // Each field reads back and writes back its current value.
            level::Entity e = make(type);
            auto value = get_entity_field(e, f.name);
            REQUIRE(value.ok());
            CHECK(set_entity_field(e, f.name, *value).ok());
            CHECK(e == make(type));
        }
    }
    auto robot = describe_entity_fields(make(EntityType::Robot));
    const auto& hp = field(robot, "hit_probability");
    CHECK(hp.kind == FieldKind::Float);
    CHECK(hp.min == 0);
    CHECK(hp.max == 1);
    auto pickup = describe_entity_fields(make(EntityType::Pickup));
    CHECK(field(pickup, "kind").options == std::vector<std::string>{"health", "ammo", "shield"});
    CHECK(field(describe_entity_fields(make(EntityType::Stair)), "steps").kind == FieldKind::Int);
    CHECK(field(describe_settings_fields(), "gravity").max == 0);
}

TEST_CASE("fields: parsing each kind, and the errors say what would be valid") {
    const auto stair = describe_entity_fields(make(EntityType::Stair));
    const auto& steps = field(stair, "steps");
    CHECK(std::get<double>(*parse_field_value(steps, "12")) == 12.0);
    CHECK_FALSE(parse_field_value(steps, "12.5").ok()); // whole numbers only
    CHECK_FALSE(parse_field_value(steps, "0").ok());    // below the minimum of 1
    CHECK_FALSE(parse_field_value(steps, "").ok());
    CHECK_FALSE(parse_field_value(steps, "12abc").ok());
    const auto& size = field(stair, "size");
    CHECK(std::get<Vec3>(*parse_field_value(size, "12, 6 ,12")) == Vec3(12, 6, 12));
    CHECK_FALSE(parse_field_value(size, "1,2").ok());
    CHECK_FALSE(parse_field_value(size, "1,2,3,4").ok());
    auto nan = parse_field_value(size, "nan,1,1");
    REQUIRE_FALSE(nan.ok());
    CHECK(nan.error().message.find("finite") != std::string::npos);
    auto inf = parse_field_value(size, "1,inf,1");
    CHECK_FALSE(inf.ok());
    auto huge = parse_field_value(size, "1e30,1,1");
    REQUIRE_FALSE(huge.ok());
    CHECK(huge.error().hint.find("0.01 .. 10000 units") != std::string::npos);

    const auto floor = describe_entity_fields(make(EntityType::Floor));
    CHECK(std::get<Vec2>(*parse_field_value(field(floor, "size"), "120,200")) == Vec2(120, 200));
    CHECK(std::get<bool>(*parse_field_value(field(floor, "ceiling"), "true")));
    CHECK_FALSE(parse_field_value(field(floor, "ceiling"), "yes").ok());

    const auto light = describe_entity_fields(make(EntityType::TopLight));
    auto color = parse_field_value(field(light, "color"), "#FF8000");
    REQUIRE(color.ok());
    CHECK(format_field_value(*color) == "#ff8000");
    CHECK_FALSE(parse_field_value(field(light, "color"), "#ff80").ok());
    CHECK_FALSE(parse_field_value(field(light, "color"), "#gg8000").ok());
    CHECK_FALSE(parse_field_value(field(light, "color"), "red").ok());

    CHECK_FALSE(parse_field_value(field(light, "name"), "tab\there").ok()); // control characters
}

TEST_CASE("fields: formatting prints floats shortest, so inspector text round-trips") {
    CHECK(format_field_value(FieldValue(static_cast<double>(0.1f))) == "0.1");
    CHECK(format_field_value(FieldValue(0.1)) == "0.1");
    CHECK(format_field_value(FieldValue(Vec3(1.5f, -2, 0.25f))) == "1.5,-2,0.25");
    CHECK(format_field_value(FieldValue(true)) == "true");
    level::Entity e = make(EntityType::Robot);
    for (const auto& f : describe_entity_fields(e)) {
        auto text = format_field_value(*get_entity_field(e, f.name));
        auto parsed = parse_field_value(f, text);
        REQUIRE_MESSAGE(parsed.ok(), f.name << " = " << text);
        CHECK(*parsed == *get_entity_field(e, f.name));
    }
}

TEST_CASE("fields: wrong names and types are errors listing the valid ones; defaults come from the type") {
    level::Entity door = make(EntityType::Door);
    auto unknown = set_entity_field(door, "widht", FieldValue(3.0));
    REQUIRE_FALSE(unknown.ok());
    CHECK(unknown.error().hint.find("width") != std::string::npos);
    CHECK_FALSE(set_entity_field(door, "width", FieldValue(std::string("3"))).ok());
    CHECK_FALSE(set_entity_field(door, "open", FieldValue(1.0)).ok());
    REQUIRE(set_entity_field(door, "width", FieldValue(3.0)).ok());
    CHECK(std::get<double>(*default_entity_field(door, "width")) == 5.0);
    CHECK(std::get<Vec3>(*default_entity_field(door, "position")) == Vec3(0));
    CHECK_FALSE(default_entity_field(door, "nope").ok());

    level::Settings settings;
    CHECK_FALSE(set_settings_field(settings, "gravity", FieldValue(10.0)).ok()); // must be <= 0
    REQUIRE(set_settings_field(settings, "gravity", FieldValue(-10.0)).ok());
    CHECK(settings.gravity == -10.0f);
    CHECK_FALSE(get_settings_field(settings, "gravitas").ok());
}
