#include "level/brush_faces.h"

#include "jsonio/describe.h"
#include "jsonio/json_path.h"
#include "jsonio/object_reader.h"

#include <array>

namespace ks::level {
namespace {

using Json = nlohmann::ordered_json;
using jsonio::element_path;

constexpr const char* kFaceExample =
    "{\"plane\": [0, 1, 0, 4], \"material\": \"concrete\", \"offset\": [0, 0], \"scale\": [1, 1], "
    "\"rotation\": 0}";

// The brush module names a plane's parts and a scale's components as fields; the file writes them as array
// elements.
constexpr std::array<std::array<const char*, 2>, 4> kFieldToElement = {{
    {".plane.normal", ".plane"},
    {".plane.distance", ".plane[3]"},
    {".scale.x", ".scale[0]"},
    {".scale.y", ".scale[1]"},
}};

// One face, or false with its problems reported.
bool read_face(const Json& value, const std::string& path, DiagnosticSink& sink, brush::Face& out) {
    jsonio::ObjectReader reader(value, path, sink, "brush face");
    if (!reader.is_object()) return false;
    brush::Face face;
    face.attributes.material = std::string(kDefaultBrushMaterial);
    double plane[4] = {0, 0, 0, 0};
    bool ok = reader.numbers("plane", plane, 4, jsonio::Range(), jsonio::Need::Required);
    face.plane = {{plane[0], plane[1], plane[2]}, plane[3]};
    if (const Json* material = reader.get("material"))
        ok &= jsonio::read_text(*material, reader.path_of("material"), sink, face.attributes.material, 64,
                                "name a material from assets/textures, e.g. \"concrete\"");
    if (reader.get("offset")) ok &= reader.numbers("offset", &face.attributes.offset.x, 2, jsonio::Range());
    if (reader.get("scale")) ok &= reader.numbers("scale", &face.attributes.scale.x, 2, jsonio::Range());
    if (reader.get("rotation"))
        ok &= reader.number("rotation", face.attributes.rotation_degrees, jsonio::Range(-3600, 3600, "deg"));
    reader.finish();
    if (ok) out = std::move(face);
    return ok;
}

} // namespace

std::string brush_error_path(const std::string& faces_path, const std::string& brush_path) {
    constexpr std::string_view kFaces = "faces";
    std::string rest = brush_path.rfind(kFaces, 0) == 0 ? brush_path.substr(kFaces.size()) : std::string();
    for (const auto& [field, element] : kFieldToElement) {
        const std::string_view f(field);
        if (rest.size() >= f.size() && rest.compare(rest.size() - f.size(), f.size(), f) == 0) {
            rest.replace(rest.size() - f.size(), f.size(), element);
            break;
        }
    }
    return faces_path + rest;
}

bool read_brush_faces(const Json& value, const std::string& path, DiagnosticSink& sink, brush::Brush& out) {
    if (!value.is_array()) {
        sink.error(path, "expected an array of brush faces, found " + jsonio::describe_value(value),
                   std::string("write \"faces\": [") + kFaceExample + ", ...] (a box has six)");
        return false;
    }
    // Refused whole before any face is read: a generator gone wrong, not a brush.
    if (value.size() > brush::kMaxFaces) {
        sink.error(path,
                   "a brush of " + std::to_string(value.size()) + " faces is beyond the limit of " +
                       std::to_string(brush::kMaxFaces),
                   "split the shape into several brushes");
        return false;
    }
    std::vector<brush::Face> faces(value.size());
    bool ok = true;
    for (size_t i = 0; i < value.size(); ++i)
        ok &= read_face(value[i], element_path(path, i), sink, faces[i]);
    if (!ok) return false;
    Result<brush::Brush> made = brush::Brush::from_faces(std::move(faces));
    if (!made) {
        const Error& e = made.error();
        sink.error(brush_error_path(path, e.where.path), e.message, e.hint);
        return false;
    }
    out = std::move(*made);
    return true;
}

Json brush_faces_json(const brush::Brush& brush) {
    Json faces = Json::array();
    for (const brush::Face& face : brush.faces()) {
        const brush::Plane& p = face.plane;
        const brush::FaceAttributes& a = face.attributes;
        Json json = Json::object();
        json["plane"] = Json::array({p.normal.x, p.normal.y, p.normal.z, p.distance});
        json["material"] = a.material;
        json["offset"] = Json::array({a.offset.x, a.offset.y});
        json["scale"] = Json::array({a.scale.x, a.scale.y});
        json["rotation"] = a.rotation_degrees;
        faces.push_back(std::move(json));
    }
    return faces;
}

void check_brush_materials(const brush::Brush& brush, const std::string& faces_path, DiagnosticSink& sink) {
    for (size_t i = 0; i < brush.faces().size(); ++i)
        if (brush.faces()[i].attributes.material.empty())
            sink.error(jsonio::member_path(element_path(faces_path, i), "material"), "material is empty",
                       "name a material from assets/textures, e.g. \"concrete\"");
}

} // namespace ks::level
