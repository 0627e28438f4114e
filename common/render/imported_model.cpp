#include "render/imported_model.h"

#include "modelio/model_lod.h"
#include "render/model_material.h"
#include "render/texture_cache.h"

#include <cstdlib>
#include <string>

namespace ks::render {

namespace {

// A material's "*N": the model's embedded image N, keyed by the model file and the pixels' hash so a file
// exported again with other pixels gets a new texture.
const Texture& embedded(const modelio::ImportedModel& imported, const std::string& ref, ColorSpace space,
                        TextureCache& textures) {
    const std::size_t index = std::strtoull(ref.c_str() + 1, nullptr, 10);
    if (index >= imported.images.size())
        return textures.get_rgba(imported.path.string() + "#" + ref, 0, 0, {}, space);
    const modelio::EmbeddedImage& image = imported.images[index];
    return textures.get_rgba(imported.path.string() + "#" + ref + "#" + std::to_string(image.hash),
                             image.width, image.height, image.rgba, space);
}

Material convert(const modelio::ImportedModel& imported, const modelio::ImportedMaterial& src,
                 TextureCache& textures) {
    const std::filesystem::path dir = imported.path.parent_path();
    return make_model_material(src, dir, textures,
                               [&](const std::string& name, ColorSpace space) -> const Texture& {
                                   return name[0] == '*' ? embedded(imported, name, space, textures)
                                                         : textures.get(dir / name, space);
                               });
}

// Per-vertex tangents from each triangle's UV directions (normal maps need them), made orthogonal to the
// normal.
void add_tangents(MeshData& data) {
    std::vector<Vec3> tangent(data.vertices.size(), Vec3(0.0f)), bitangent(data.vertices.size(), Vec3(0.0f));
    for (size_t i = 0; i + 2 < data.indices.size(); i += 3) {
        const Vertex &a = data.vertices[data.indices[i]], &b = data.vertices[data.indices[i + 1]],
                     &c = data.vertices[data.indices[i + 2]];
        const Vec3 e1 = b.position - a.position, e2 = c.position - a.position;
        const Vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < 1e-12f) continue;
        const Vec3 t = (e1 * d2.y - e2 * d1.y) / det, bt = (e2 * d1.x - e1 * d2.x) / det;
        for (size_t k = 0; k < 3; ++k) {
            tangent[data.indices[i + k]] += t;
            bitangent[data.indices[i + k]] += bt;
        }
    }
    for (size_t v = 0; v < data.vertices.size(); ++v) {
        Vertex& out = data.vertices[v];
        Vec3 t = tangent[v] - out.normal * glm::dot(out.normal, tangent[v]);
        if (glm::length(t) < 1e-12f)
            t = std::abs(out.normal.x) < 0.9f ? glm::cross(out.normal, Vec3(1, 0, 0))
                                              : glm::cross(out.normal, Vec3(0, 1, 0));
        t = glm::normalize(t);
        out.tangent = Vec4(t, glm::dot(glm::cross(out.normal, t), bitangent[v]) < 0.0f ? -1.0f : 1.0f);
    }
}

// One Model of `meshes` (a level of detail of `imported`) with the materials already converted.
std::unique_ptr<Model> model_of_meshes(const modelio::ImportedModel& imported,
                                       const std::vector<modelio::ImportedMesh>& meshes,
                                       const std::vector<Material>& materials) {
    auto model = std::make_unique<Model>();
    model->path = imported.path.string();
    model->materials = materials;
    for (const Material& mat : materials) model->placeholder = model->placeholder || mat.placeholder;
    ModelNode root;
    root.name = imported.path.stem().string();
    for (const modelio::ImportedMesh& mesh : meshes) {
        MeshData data;
        data.vertices.resize(mesh.positions.size());
        for (size_t v = 0; v < mesh.positions.size(); ++v)
            data.vertices[v] = Vertex{mesh.positions[v], mesh.normals[v], mesh.uvs[v], Vec4(1, 0, 0, 1)};
        data.indices = mesh.indices;
        add_tangents(data);
        root.meshes.push_back(static_cast<int>(model->meshes.size()));
        model->meshes.push_back({std::make_unique<GpuMesh>(data), mesh.material});
    }
    model->nodes.push_back(std::move(root));
    model->bounds = imported.bounds; // every level is drawn, culled and placed by the full model's box
    return model;
}

std::vector<Material> materials_of(const modelio::ImportedModel& imported, TextureCache& textures,
                                   int& next_material_id) {
    std::vector<Material> materials;
    for (const modelio::ImportedMaterial& m : imported.materials) {
        Material mat = convert(imported, m, textures);
        mat.id = next_material_id++;
        materials.push_back(std::move(mat));
    }
    return materials;
}

} // namespace

ModelLevels model_levels_from_import(const modelio::ImportedModel& imported, TextureCache& textures,
                                     int& next_material_id) {
    const std::vector<Material> materials = materials_of(imported, textures, next_material_id);
    ModelLevels out;
    out.levels.push_back(model_of_meshes(imported, imported.meshes, materials));
    for (const modelio::ModelLod& lod : imported.lods)
        out.levels.push_back(model_of_meshes(imported, lod.meshes, materials));
    out.relative_errors = modelio::lod_relative_errors(imported);
    return out;
}

std::unique_ptr<Model> marker_model(const std::string& name, TextureCache& textures, int& next_material_id) {
    return placeholder_model(name, textures, next_material_id);
}

} // namespace ks::render
