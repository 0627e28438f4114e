// The shipped models' level lists (render/model_lod_list.h: robot.lods.json beside robot.gltf): a good list
// read as written, every kind of bad list refused with its place and a fix. Needs no GL context.
#include "render/model_lod_list.h"

#include "test_support.h"

#include <doctest/doctest.h>

#include <string>

namespace ks::render {
namespace {

const char* kGood = R"({
  "format": "killswitch-model-lods",
  "version": 1,
  "model": "robot.gltf",
  "levels": [
    {"file": "robot.gltf", "deviation": 0, "triangles": 6076},
    {"file": "robot_lod1.gltf", "deviation": 0.0181, "triangles": 3812},
    {"file": "robot_lod2.glb", "deviation": 0.0573, "triangles": 1976}
  ]
})";

std::string with(const std::string& from, const std::string& to) {
    std::string text = kGood;
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

std::string refusal(const std::string& text) {
    auto list = parse_model_lods(text, "models/robot.lods.json", "robot.gltf");
    REQUIRE_FALSE(list);
    return list.error().str();
}

} // namespace

TEST_CASE("a model's level list is read as the generator writes it") {
    auto list = parse_model_lods(kGood, "models/robot.lods.json", "robot.gltf");
    REQUIRE_MESSAGE(list, list.error().str());
    REQUIRE(list->size() == 3);
    CHECK((*list)[0].file == "robot.gltf");
    CHECK((*list)[0].deviation == 0.0f);
    CHECK((*list)[1].file == "robot_lod1.gltf");
    CHECK((*list)[1].deviation == doctest::Approx(0.0181));
    CHECK((*list)[2].triangles == 1976);
    CHECK(model_lods_path("assets/models/robot.gltf") ==
          std::filesystem::path("assets/models/robot.lods.json"));
    // The committed lists are read by the same reader (the renderer draws with them).
    const auto robot = test::read_file(test::source_dir() / "assets/models/robot.lods.json");
    auto shipped = parse_model_lods(robot, "robot.lods.json", "robot.gltf");
    REQUIRE_MESSAGE(shipped, shipped.error().str());
    CHECK(shipped->size() >= 3);
}

TEST_CASE("a bad level list is refused with its place and a fix") {
    struct Case {
        std::string text, expected;
    };
    const Case cases[] = {
        {"", "empty"},
        {"{\"format\": ", "robot.lods.json:1:"},
        {with("killswitch-model-lods", "killswitch-level"), "not a Killswitch level list"},
        {with("\"version\": 1", "\"version\": 2"), "version"},
        {with("\"model\": \"robot.gltf\"", "\"model\": \"door.gltf\""), "the list is for \"door.gltf\""},
        {with("\"file\": \"robot_lod1.gltf\"", "\"file\": \"../robot_lod1.gltf\""),
         "not a .gltf or .glb file name"},
        {with("\"file\": \"robot_lod1.gltf\"", "\"file\": \"robot_lod1.png\""),
         "not a .gltf or .glb file name"},
        {with("\"deviation\": 0.0181", "\"deviation\": -1"), "deviation"},
        {with("\"deviation\": 0.0181", "\"deviation\": \"nan\""), "deviation"},
        {with("\"deviation\": 0.0573", "\"deviation\": 0.01"), "smaller than the finer one's"},
        {with("{\"file\": \"robot.gltf\", \"deviation\": 0,",
              "{\"file\": \"robot.gltf\", \"deviation\": 0.5,"),
         "the first level must be the model itself"},
        {with("\"triangles\": 3812", "\"triangles\": 1.5"), "triangles"},
        {with("\"triangles\": 3812}", "\"triangles\": 3812, \"tris\": 4}"),
         ""}, // unknown field: a warning only
        {R"({"format": "killswitch-model-lods", "version": 1, "model": "robot.gltf", "levels": []})",
         "expected 1 to 8 levels"},
        {R"({"format": "killswitch-model-lods", "version": 1, "model": "robot.gltf", "levels": {}})",
         "expected 1 to 8 levels"},
        {R"({"format": "killswitch-model-lods", "version": 1, "model": "robot.gltf"})", "levels"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.text);
        if (c.expected.empty()) {
            CHECK(parse_model_lods(c.text, "models/robot.lods.json", "robot.gltf"));
            continue;
        }
        const std::string message = refusal(c.text);
        CHECK_MESSAGE(test::contains_text(message, c.expected), message);
        CHECK_MESSAGE(test::contains_text(message, "robot.lods.json"), message);
    }
    // More levels than any generator writes.
    std::string many =
        R"({"format": "killswitch-model-lods", "version": 1, "model": "robot.gltf", "levels": [)";
    for (int i = 0; i <= kMaxModelLods; ++i)
        many += std::string(i ? "," : "") + "{\"file\": \"robot.gltf\", \"deviation\": 0, \"triangles\": 1}";
    CHECK(test::contains_text(refusal(many + "]}"), "expected 1 to 8 levels"));
}

} // namespace ks::render
