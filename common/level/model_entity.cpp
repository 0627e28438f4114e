#include "level/model_entity.h"

#include "brush/brush_build.h"
#include "brush/convex_hull.h"
#include "brush/decomposition_cache.h"
#include "brush/texture_mapping.h"
#include "modelio/model_files.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <span>
#include <tuple>

namespace ks::level {

namespace {

glm::dmat3 entity_rotation(const Entity& e) {
    return glm::mat3_cast(dquat_from_ypr_degrees(DVec3(e.rotation)));
}

// `points` with each snapped to a grid of `cells` cells along their largest side, each once.
std::vector<DVec3> snapped(std::span<const DVec3> points, int cells) {
    DVec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const DVec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const DVec3 extent = hi - lo;
    const double step = std::max({extent.x, extent.y, extent.z}) / cells;
    std::set<std::tuple<double, double, double>> seen;
    std::vector<DVec3> out;
    for (const DVec3& v : points) {
        const DVec3 p = step > 0 ? glm::round(v / step) * step : v;
        if (seen.emplace(p.x, p.y, p.z).second) out.push_back(p);
    }
    return out;
}

// The hull of `points` with at most kMaxModelHullFaces faces: the points as they are, then snapped coarser.
Result<brush::Brush> capped_hull(std::span<const DVec3> points) {
    Error last("the model has no volume");
    for (int cells : {0, 64, 32, 16, 8}) {
        const std::vector<DVec3> grid = cells > 0 ? snapped(points, cells) : std::vector<DVec3>();
        const std::span<const DVec3> use = cells > 0 ? std::span<const DVec3>(grid) : points;
        if (use.size() > brush::kMaxHullPoints) continue;
        Result<brush::Brush> hull = brush::make_from_points(use);
        if (!hull) {
            last = hull.error();
            continue;
        }
        if (hull->faces().size() <= kMaxModelHullFaces) return hull;
        last = Error("its hull has more than " + std::to_string(kMaxModelHullFaces) + " faces");
    }
    return last;
}

// The model's vertices scaled, each once.
std::vector<DVec3> scaled_vertices(const modelio::ImportedModel& model, double scale) {
    std::set<std::tuple<double, double, double>> seen;
    std::vector<DVec3> points;
    for (const modelio::ImportedMesh& mesh : model.meshes)
        for (const Vec3& v : mesh.positions) {
            const DVec3 p = DVec3(v) * scale;
            if (seen.emplace(p.x, p.y, p.z).second) points.push_back(p);
        }
    return points;
}

// Every triangle of every mesh of the model, in model space.
CollisionMesh model_triangles(const modelio::ImportedModel& m) {
    CollisionMesh out;
    out.triangles.reserve(m.triangle_count);
    for (const modelio::ImportedMesh& mesh : m.meshes) {
        const auto base = static_cast<std::uint32_t>(out.vertices.size());
        for (const Vec3& v : mesh.positions) out.vertices.push_back(DVec3(v));
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
            out.triangles.push_back(
                {base + mesh.indices[i], base + mesh.indices[i + 1], base + mesh.indices[i + 2]});
    }
    return out;
}

using SharedDecomposition = std::shared_ptr<const Result<brush::ConvexDecomposition>>;

// The model's convex decomposition with at most `hulls` hulls, made once per imported model and cap: every
// entity of a model shares it (scaled), and a changed file (a new import) makes a new one. Later launches
// read it from the disk cache (brush/decomposition_cache.h).
SharedDecomposition model_decomposition(const std::shared_ptr<const modelio::ImportedModel>& model,
                                        int hulls) {
    struct Entry {
        std::weak_ptr<const modelio::ImportedModel> model;
        SharedDecomposition decomposition;
    };
    static std::mutex mutex;
    static std::map<std::pair<const modelio::ImportedModel*, int>, Entry> cache;
    const std::pair key(model.get(), hulls);
    {
        std::lock_guard lock(mutex);
        std::erase_if(cache, [](const auto& entry) { return entry.second.model.expired(); });
        if (auto it = cache.find(key); it != cache.end()) return it->second.decomposition;
    }
    const CollisionMesh mesh = model_triangles(*model);
    brush::DecompositionOptions options;
    options.max_hulls = hulls;
    auto made = std::make_shared<const Result<brush::ConvexDecomposition>>(
        brush::decompose_convex_cached(mesh.vertices, mesh.triangles, options));
    std::lock_guard lock(mutex);
    return cache.try_emplace(key, Entry{model, made}).first->second.decomposition;
}

// The entity's "hulls" collision in model space, scaled.
Result<std::vector<brush::Brush>>
decomposed_brushes(const std::shared_ptr<const modelio::ImportedModel>& model, const ModelProps& props) {
    const SharedDecomposition decomposition =
        model_decomposition(model, std::clamp(props.hulls, 1, kMaxModelHulls));
    if (!*decomposition) return decomposition->error();
    std::vector<brush::Brush> brushes;
    for (const std::vector<DVec3>& hull : (*decomposition)->hulls) {
        std::vector<DVec3> points(hull);
        for (DVec3& p : points) p *= static_cast<double>(props.scale);
        Result<brush::Brush> brush = capped_hull(points);
        if (!brush) return brush.error();
        brushes.push_back(std::move(*brush));
    }
    return brushes;
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

Result<std::vector<brush::Brush>> model_collision(const Entity& entity) {
    const auto* props = entity.try_as<ModelProps>();
    if (!props)
        return Error(std::string(type_name(entity.type())) + " " + std::to_string(entity.id) +
                     " is not a model");
    const std::string& choice = props->collision.value;
    if (choice == "none" || choice == "mesh") return std::vector<brush::Brush>();
    Result<std::shared_ptr<const modelio::ImportedModel>> model = entity_model(entity);
    if (!model) return model.error();
    const double scale = props->scale;
    Result<std::vector<brush::Brush>> local = std::vector<brush::Brush>();
    if (choice == "hulls") {
        local = decomposed_brushes(*model, *props);
    } else {
        Result<brush::Brush> one = choice == "box" ? brush::make_box(DVec3((*model)->bounds.min) * scale,
                                                                     DVec3((*model)->bounds.max) * scale)
                                                   : capped_hull(scaled_vertices(**model, scale));
        if (one)
            local->push_back(std::move(*one));
        else
            local = one.error();
    }
    if (!local)
        return Error(model_subject(entity) + ": no " + choice + " collision: " + local.error().message,
                     Location((*model)->path.string()), "choose collision \"box\" or \"none\"");
    // Placed by carrying each hull's geometry through the entity's motion, as a level places its brush
    // entities: deriving a many-faced hull again after an arbitrary turn can find slivers that no longer
    // close.
    std::vector<brush::Brush> world;
    for (const brush::Brush& brush : *local) {
        Result<brush::Brush> placed = brush::placed(brush, entity_rotation(entity), DVec3(entity.position));
        if (!placed)
            return Error(model_subject(entity) + ": no " + choice + " collision: " + placed.error().message,
                         Location((*model)->path.string()), "choose collision \"box\" or \"none\"");
        world.push_back(std::move(*placed));
    }
    return world;
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
    CollisionMesh out = model_triangles(m);
    for (DVec3& v : out.vertices) v = rotation * (v * scale) + position;
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
