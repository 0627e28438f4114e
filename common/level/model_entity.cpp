#include "level/model_entity.h"

#include "brush/brush_build.h"
#include "brush/convex_hull.h"
#include "brush/texture_mapping.h"
#include "modelio/model_files.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

namespace ks::level {

namespace {

glm::dmat3 entity_rotation(const Entity& e) {
    return glm::mat3_cast(dquat_from_ypr_degrees(DVec3(e.rotation)));
}

// The model's vertices scaled, each once; with `cells` > 0 snapped to a grid of that many cells along the
// largest side first (fewer, coarser corners).
std::vector<DVec3> hull_points(const modelio::ImportedModel& model, double scale, int cells) {
    const DVec3 extent = DVec3(model.bounds.max - model.bounds.min) * scale;
    const double step = cells > 0 ? std::max({extent.x, extent.y, extent.z}) / cells : 0.0;
    std::set<std::tuple<double, double, double>> seen;
    std::vector<DVec3> points;
    for (const modelio::ImportedMesh& mesh : model.meshes)
        for (const Vec3& v : mesh.positions) {
            DVec3 p = DVec3(v) * scale;
            if (step > 0) p = glm::round(p / step) * step;
            if (seen.emplace(p.x, p.y, p.z).second) points.push_back(p);
        }
    return points;
}

Result<brush::Brush> hull_brush(const modelio::ImportedModel& model, double scale) {
    Error last("the model has no volume");
    for (int cells : {0, 64, 32, 16, 8}) {
        const std::vector<DVec3> points = hull_points(model, scale, cells);
        if (points.size() > brush::kMaxHullPoints) continue;
        Result<brush::Brush> hull = brush::make_from_points(points);
        if (!hull) {
            last = hull.error();
            continue;
        }
        if (hull->faces().size() <= kMaxModelHullFaces) return hull;
        last = Error("its hull has more than " + std::to_string(kMaxModelHullFaces) + " faces");
    }
    return last;
}

std::string model_subject(const Entity& e) {
    return "model " + std::to_string(e.id) + (e.name.empty() ? "" : " \"" + e.name + "\"");
}

} // namespace

Result<std::shared_ptr<const modelio::ImportedModel>> entity_model(const Entity& entity) {
    const auto* props = entity.try_as<ModelProps>();
    if (!props)
        return Error(std::string(type_name(entity.type())) + " " + std::to_string(entity.id) +
                     " is not a model");
    if (Result<void> name = modelio::check_model_name(props->file); !name) return name.error();
    return modelio::import_cached(modelio::resolve_model_file(props->file));
}

Mat4 model_matrix(const Entity& entity) {
    const float scale = entity.try_as<ModelProps>() ? entity.as<ModelProps>().scale : 1.0f;
    return entity_frame(entity).matrix() * glm::scale(Mat4(1.0f), Vec3(scale));
}

Result<std::optional<brush::Brush>> model_collision(const Entity& entity) {
    const auto* props = entity.try_as<ModelProps>();
    if (!props)
        return Error(std::string(type_name(entity.type())) + " " + std::to_string(entity.id) +
                     " is not a model");
    if (props->collision.value == "none" || props->collision.value == "mesh")
        return std::optional<brush::Brush>();
    Result<std::shared_ptr<const modelio::ImportedModel>> model = entity_model(entity);
    if (!model) return model.error();
    const double scale = props->scale;
    Result<brush::Brush> local =
        props->collision.value == "box"
            ? brush::make_box(DVec3((*model)->bounds.min) * scale, DVec3((*model)->bounds.max) * scale)
            : hull_brush(**model, scale);
    if (!local)
        return Error(model_subject(entity) + ": no " + props->collision.value +
                         " collision: " + local.error().message,
                     Location((*model)->path.string()), "choose collision \"box\" or \"none\"");
    Result<brush::Brush> world = brush::transformed(*local, entity_rotation(entity), DVec3(entity.position));
    if (!world) return world.error();
    return std::optional<brush::Brush>(std::move(*world));
}

Result<std::optional<CollisionMesh>> model_mesh_collision(const Entity& entity) {
    const auto* props = entity.try_as<ModelProps>();
    if (!props || props->collision.value != "mesh") return std::optional<CollisionMesh>();
    Result<std::shared_ptr<const modelio::ImportedModel>> model = entity_model(entity);
    if (!model) return model.error();
    const modelio::ImportedModel& m = **model;
    if (m.triangle_count > kMaxModelMeshTriangles)
        return Error(model_subject(entity) + ": no mesh collision: " + std::to_string(m.triangle_count) +
                         " triangles, more than " + std::to_string(kMaxModelMeshTriangles),
                     Location(m.path.string()),
                     "simplify the model, or choose collision \"hull\" or \"box\"");
    const glm::dmat3 rotation = entity_rotation(entity);
    const DVec3 position(entity.position);
    const double scale = props->scale;
    CollisionMesh out;
    out.triangles.reserve(m.triangle_count);
    for (const modelio::ImportedMesh& mesh : m.meshes) {
        const auto base = static_cast<std::uint32_t>(out.vertices.size());
        for (const Vec3& v : mesh.positions) out.vertices.push_back(rotation * (DVec3(v) * scale) + position);
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
            out.triangles.push_back(
                {base + mesh.indices[i], base + mesh.indices[i + 1], base + mesh.indices[i + 2]});
    }
    return std::optional<CollisionMesh>(std::move(out));
}

PlacedShape model_bounding_shape(const Entity& entity) {
    PlacedShape shape;
    shape.frame = entity_frame(entity);
    Result<std::shared_ptr<const modelio::ImportedModel>> model = entity_model(entity);
    if (!model) {
        shape.local_centre = Vec3(0, 0.5f, 0);
        shape.half = Vec3(0.5f);
        return shape;
    }
    const float scale = entity.as<ModelProps>().scale;
    shape.local_centre = ((*model)->bounds.min + (*model)->bounds.max) * 0.5f * scale;
    shape.half = ((*model)->bounds.max - (*model)->bounds.min) * 0.5f * scale;
    return shape;
}

} // namespace ks::level
