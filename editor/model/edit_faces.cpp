// Brush faces one by one: edit_faces.h. The selection and the per-face attribute edits; replacing a texture
// across the level and texture lock are in edit_faces_level.cpp.
#include "model/edit_faces.h"

#include "brush/texture_mapping.h"
#include "level/entity_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace ks::editor {
namespace {
using level::Entity;

constexpr double kRadiansToDegrees = 180.0 / 3.14159265358979323846;

std::string face_label(const Entity& e, int face) {
    return "face " + std::to_string(face) + " of brush " + std::to_string(e.id) +
           (e.name.empty() ? "" : " (\"" + e.name + "\")");
}

// (-180, 180]: the range locked_attributes gives, so a turned and a typed angle read alike.
double wrapped_degrees(double degrees) {
    double d = std::remainder(degrees, 360.0);
    if (d <= -180.0) d += 360.0;
    return d;
}

Result<void> check_scale(glm::dvec2 scale) {
    for (int k = 0; k < 2; ++k) {
        const char* axis = k == 0 ? "u" : "v";
        if (!std::isfinite(scale[k]))
            return Error(std::string("the ") + axis + " scale must be a finite number", Location{},
                         "give world units per texture repeat, such as 4");
        if (std::abs(scale[k]) < kMinTextureScale || std::abs(scale[k]) > kMaxTextureScale) {
            char text[160];
            std::snprintf(text, sizeof text, "the %s scale %g is outside %g .. %g (either sign)", axis,
                          scale[k], kMinTextureScale, kMaxTextureScale);
            return Error(text, Location{}, "give world units per texture repeat, such as 4 (negative flips)");
        }
    }
    return ok();
}

// The face's corners in the entity's frame.
std::vector<DVec3> face_corners(const brush::Brush& b, int face) {
    std::vector<DVec3> out;
    for (int v : b.polygons()[static_cast<size_t>(face)]) out.push_back(b.vertices()[static_cast<size_t>(v)]);
    return out;
}

// What an attribute edit does to one face: the brush (for its corners), the face index, the attributes.
using FaceEdit = std::function<Result<void>(const brush::Brush&, int, brush::FaceAttributes&)>;

Result<void> edit_faces(Editor& editor, const std::string& name, const FaceEdit& edit,
                        std::string merge_key = {}) {
    return edit_selected_faces(
        editor, name,
        [&](const Entity&, const brush::Brush& b, int face, brush::FaceAttributes& at) {
            return edit(b, face, at);
        },
        std::move(merge_key));
}

Result<const brush::Brush*> face_brush(const Document& doc, int entity, const char* what) {
    const Entity* e = doc.level.find(entity);
    if (!e) return Error(std::string(what) + ": no entity " + std::to_string(entity));
    const auto* props = e->try_as<level::BrushProps>();
    if (!props)
        return Error(std::string(what) + ": entity " + std::to_string(entity) + " is a " +
                         std::string(level::type_name(e->type())) + ", not a brush",
                     Location{}, "pick a brush's face");
    if (doc.locked.contains(entity))
        return Error(std::string(what) + ": brush " + std::to_string(entity) + " is locked", Location{},
                     "unlock it first");
    return &props->brush;
}

} // namespace

// One LevelChange for every selected face (grouped by entity).
Result<void> edit_selected_faces(Editor& editor, const std::string& name, const FaceAttributeEdit& edit,
                                 std::string merge_key) {
    const Document& doc = editor.doc();
    if (doc.faces.empty()) return Error(name + ": no face is selected", Location{}, "pick brush faces first");
    std::map<int, std::vector<int>> by_entity; // entity id -> face indices, in id order
    for (const FaceRef& f : doc.faces) by_entity[f.entity].push_back(f.face);
    auto change = std::make_unique<LevelChange>();
    for (const auto& [id, faces] : by_entity) {
        const Entity* e = doc.level.find(id);
        if (!e || !e->try_as<level::BrushProps>())
            continue; // follow_face_selection keeps this from happening
        if (doc.locked.contains(id))
            return Error(name + ": brush " + std::to_string(id) + " is locked", Location{},
                         "unlock it first");
        const brush::Brush& local = e->as<level::BrushProps>().brush;
        std::vector<brush::FaceAttributes> attributes;
        for (const brush::Face& f : local.faces()) attributes.push_back(f.attributes);
        for (int face : faces) {
            if (face < 0 || face >= static_cast<int>(attributes.size()))
                continue; // follow_face_selection keeps them in range
            brush::FaceAttributes& at = attributes[static_cast<size_t>(face)];
            if (auto r = edit(*e, local, face, at); !r)
                return Error(name + ": " + face_label(*e, face) + ": " + r.error().message, Location{},
                             r.error().hint);
            at.rotation_degrees = wrapped_degrees(at.rotation_degrees);
        }
        auto rebuilt = local.with_attributes(std::move(attributes));
        if (!rebuilt) return Error(name + ": brush " + std::to_string(id) + ": " + rebuilt.error().message);
        if (*rebuilt == local) continue;
        Entity after = *e;
        after.as<level::BrushProps>().brush = std::move(*rebuilt);
        change->updates.push_back({*e, std::move(after)});
    }
    if (change->empty()) return ok();
    change->set_name(name);
    change->merge_key = std::move(merge_key);
    editor.execute(std::move(change), doc.selection);
    return ok();
}

Result<void> select_face(Editor& editor, int entity, int face, SelectMode mode) {
    auto b = face_brush(editor.doc(), entity, "Select face");
    if (!b) return b.error();
    const int count = static_cast<int>((*b)->faces().size());
    if (face < 0 || face >= count)
        return Error("Select face: brush " + std::to_string(entity) + " has faces 0 to " +
                         std::to_string(count - 1) + ", not " + std::to_string(face),
                     Location{}, "give a face index in that range");
    const FaceRef ref{entity, face, (*b)->faces()[static_cast<size_t>(face)].plane};
    std::vector<FaceRef> faces = editor.doc().faces;
    const auto at = std::find(faces.begin(), faces.end(), ref);
    switch (mode) {
    case SelectMode::Replace:
        faces = {ref};
        break;
    case SelectMode::Add:
        if (at == faces.end()) faces.push_back(ref);
        break;
    case SelectMode::Toggle:
        if (at == faces.end())
            faces.push_back(ref);
        else
            faces.erase(at);
        break;
    case SelectMode::Remove:
        if (at != faces.end()) faces.erase(at);
        break;
    }
    editor.set_face_selection(std::move(faces));
    return ok();
}

Result<void> select_faces_of_selection(Editor& editor) {
    std::vector<FaceRef> faces;
    for (int id : editor.doc().selection) {
        const Entity* e = editor.doc().level.find(id);
        if (!e || !e->try_as<level::BrushProps>() || editor.doc().locked.contains(id)) continue;
        const auto& all = e->as<level::BrushProps>().brush.faces();
        for (size_t i = 0; i < all.size(); ++i) faces.push_back({id, static_cast<int>(i), all[i].plane});
    }
    if (faces.empty())
        return Error("Select faces: no unlocked brush is selected", Location{}, "select brushes first");
    editor.set_face_selection(std::move(faces));
    return ok();
}

void clear_face_selection(Editor& editor) {
    editor.set_face_selection({});
}

Result<int> face_facing(const Entity& entity, const DVec3& direction) {
    const auto* props = entity.try_as<level::BrushProps>();
    if (!props) return Error("entity " + std::to_string(entity.id) + " is not a brush");
    if (!is_finite(direction) || glm::length(direction) < 1e-12)
        return Error("a face direction must be a non-zero vector", Location{},
                     "give one such as +y or 0,1,0");
    const glm::dmat3 rotation = glm::mat3_cast(dquat_from_ypr_degrees(DVec3(entity.rotation)));
    const DVec3 want = glm::normalize(direction);
    int best = 0;
    double best_dot = -2.0;
    const auto& faces = props->brush.faces();
    for (size_t i = 0; i < faces.size(); ++i) {
        const double d = glm::dot(rotation * faces[i].plane.normal, want);
        if (d > best_dot + 1e-12) best = static_cast<int>(i), best_dot = d;
    }
    return best;
}

void follow_face_selection(Document& doc) {
    if (doc.faces.empty()) return;
    std::vector<FaceRef> kept;
    for (FaceRef ref : doc.faces) {
        const Entity* e = doc.level.find(ref.entity);
        if (!e || !e->try_as<level::BrushProps>()) continue;
        const brush::Brush& b = e->as<level::BrushProps>().brush;
        const bool same = ref.face >= 0 && ref.face < static_cast<int>(b.faces().size()) &&
                          b.faces()[static_cast<size_t>(ref.face)].plane == ref.plane;
        if (!same) {
            ref.face = b.find_face(ref.plane);
            if (ref.face < 0) continue;
            ref.plane = b.faces()[static_cast<size_t>(ref.face)].plane;
        }
        if (std::find(kept.begin(), kept.end(), ref) == kept.end()) kept.push_back(ref);
    }
    doc.faces = std::move(kept);
}

std::vector<SelectedFace> selected_faces(const Document& doc) {
    std::vector<SelectedFace> out;
    for (const FaceRef& ref : doc.faces) {
        const Entity* e = doc.level.find(ref.entity);
        if (!e || !e->try_as<level::BrushProps>()) continue;
        const auto& faces = e->as<level::BrushProps>().brush.faces();
        if (ref.face < 0 || ref.face >= static_cast<int>(faces.size())) continue;
        out.push_back({e, ref.face, faces[static_cast<size_t>(ref.face)]});
    }
    return out;
}

Result<void> set_face_material(Editor& editor, const std::string& material) {
    if (material.empty() || material.find_first_of(" \t\n") != std::string::npos)
        return Error("Set face material: a material name is one word, got \"" + material + "\"", Location{},
                     "pick one from the texture browser");
    return edit_faces(editor, "Set face material", [&](const brush::Brush&, int, brush::FaceAttributes& at) {
        at.material = material;
        return ok();
    });
}

Result<void> set_face_offset(Editor& editor, glm::dvec2 offset, std::string merge_key) {
    if (!std::isfinite(offset.x) || !std::isfinite(offset.y))
        return Error("Set face offset: the offset must be two finite numbers");
    return edit_faces(
        editor, "Set face offset",
        [&](const brush::Brush&, int, brush::FaceAttributes& at) {
            at.offset = offset;
            return ok();
        },
        std::move(merge_key));
}

Result<void> shift_face_offset(Editor& editor, glm::dvec2 delta, std::string merge_key) {
    if (!std::isfinite(delta.x) || !std::isfinite(delta.y))
        return Error("Shift face offset: the shift must be two finite numbers");
    return edit_faces(
        editor, "Shift face offset",
        [&](const brush::Brush&, int, brush::FaceAttributes& at) {
            at.offset += delta;
            return ok();
        },
        std::move(merge_key));
}

Result<void> set_face_scale(Editor& editor, glm::dvec2 scale, std::string merge_key) {
    if (auto r = check_scale(scale); !r)
        return Error("Set face scale: " + r.error().message, {}, r.error().hint);
    return edit_faces(
        editor, "Set face scale",
        [&](const brush::Brush&, int, brush::FaceAttributes& at) {
            at.scale = scale;
            return ok();
        },
        std::move(merge_key));
}

Result<void> set_face_rotation(Editor& editor, double degrees, std::string merge_key) {
    if (!std::isfinite(degrees)) return Error("Set face rotation: the angle must be a finite number");
    return edit_faces(
        editor, "Set face rotation",
        [&](const brush::Brush&, int, brush::FaceAttributes& at) {
            at.rotation_degrees = degrees;
            return ok();
        },
        std::move(merge_key));
}

Result<void> turn_face_texture(Editor& editor, double delta_degrees, std::string merge_key) {
    if (!std::isfinite(delta_degrees)) return Error("Turn face texture: the angle must be a finite number");
    return edit_faces(
        editor, "Turn face texture",
        [&](const brush::Brush&, int, brush::FaceAttributes& at) {
            at.rotation_degrees += delta_degrees;
            return ok();
        },
        std::move(merge_key));
}

Result<void> fit_face_texture(Editor& editor, glm::dvec2 repeats) {
    if (!std::isfinite(repeats.x) || !std::isfinite(repeats.y) || repeats.x <= 0 || repeats.y <= 0 ||
        repeats.x > 1000 || repeats.y > 1000)
        return Error("Fit texture: the repeats must be numbers above 0 and at most 1000", Location{},
                     "give 1,1 for the texture once across the face");
    return edit_faces(
        editor, "Fit texture",
        [&](const brush::Brush& b, int face, brush::FaceAttributes& at) -> Result<void> {
            const brush::TextureAxes axes =
                brush::texture_axes({b.faces()[static_cast<size_t>(face)].plane, at});
            glm::dvec2 lo(1e300), hi(-1e300);
            for (const DVec3& p : face_corners(b, face)) {
                const glm::dvec2 t{glm::dot(p, axes.u), glm::dot(p, axes.v)};
                lo = glm::min(lo, t), hi = glm::max(hi, t);
            }
            glm::dvec2 scale = (hi - lo) / repeats;
            for (int k = 0; k < 2; ++k) {
                if (scale[k] < kMinTextureScale) {
                    char text[160];
                    std::snprintf(text, sizeof text,
                                  "the face is %g units across along %s: too small to fit %g repeats",
                                  hi[k] - lo[k], k == 0 ? "u" : "v", repeats[k]);
                    return Error(text, Location{}, "fit a larger face, or set its scale by hand");
                }
                if (at.scale[k] < 0) scale[k] = -scale[k]; // a flipped texture stays flipped
                // The lowest texture coordinate on the face is 0: offset = -min(dot(p, u) / scale).
                at.offset[k] = -std::min(lo[k] / scale[k], hi[k] / scale[k]);
            }
            at.scale = scale;
            return ok();
        });
}

Result<void> align_face_texture_to_edge(Editor& editor, int edge) {
    return edit_faces(
        editor, "Align texture",
        [&](const brush::Brush& b, int face, brush::FaceAttributes& at) -> Result<void> {
            const std::vector<DVec3> corners = face_corners(b, face);
            const int count = static_cast<int>(corners.size());
            if (edge < 0 || edge >= count)
                return Error("it has edges 0 to " + std::to_string(count - 1) + ", not " +
                                 std::to_string(edge),
                             Location{}, "give an edge index in that range");
            const DVec3 from = corners[static_cast<size_t>(edge)];
            const DVec3 along = corners[static_cast<size_t>((edge + 1) % count)] - from;
            if (glm::length(along) < kMinAlignEdge)
                return Error("edge " + std::to_string(edge) + " is too short to give a direction", Location{},
                             "align to a longer edge");
            const brush::Plane& plane = b.faces()[static_cast<size_t>(face)].plane;
            const brush::TextureAxes base = brush::base_texture_axes(plane.normal);
            at.rotation_degrees =
                std::atan2(glm::dot(along, base.v), glm::dot(along, base.u)) * kRadiansToDegrees;
            const brush::TextureAxes axes = brush::texture_axes({plane, at});
            at.offset = {-glm::dot(from, axes.u) / at.scale.x, -glm::dot(from, axes.v) / at.scale.y};
            return ok();
        });
}

Result<void> copy_face_attributes(Editor& editor) {
    const auto faces = selected_faces(editor.doc());
    if (faces.empty()) return Error("Copy face: no face is selected", Location{}, "pick a brush face first");
    editor.face_session().copied = faces.front().face.attributes;
    return ok();
}

Result<void> paste_face_attributes(Editor& editor) {
    const auto& copied = editor.face_session().copied;
    if (!copied) return Error("Paste face: nothing is copied", Location{}, "copy a face's attributes first");
    const brush::FaceAttributes attributes = *copied;
    return edit_faces(editor, "Paste face attributes",
                      [&](const brush::Brush&, int, brush::FaceAttributes& at) {
                          at = attributes;
                          return ok();
                      });
}

} // namespace ks::editor
