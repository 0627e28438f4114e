#include "modelio/scene_conventions.h"

#include <assimp/scene.h>

#include <cmath>
#include <cstdint>
#include <string>

namespace ks::modelio {

namespace {

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

bool metadata_int(const aiMetadata* meta, const char* key, int& out) {
    if (!meta) return false;
    std::int32_t i = 0;
    if (meta->Get(key, i)) {
        out = i;
        return true;
    }
    std::uint64_t u = 0;
    if (meta->Get(key, u)) {
        out = static_cast<int>(u);
        return true;
    }
    return false;
}

bool metadata_number(const aiMetadata* meta, const char* key, double& out) {
    if (!meta) return false;
    float f = 0;
    if (meta->Get(key, f)) {
        out = f;
        return true;
    }
    double d = 0;
    if (meta->Get(key, d)) {
        out = d;
        return true;
    }
    return false;
}

// The unit vector of FBX axis `axis` (0 x, 1 y, 2 z) with `sign` (+1 or -1).
Vec3 axis_vector(int axis, int sign) {
    Vec3 v(0.0f);
    v[axis] = sign < 0 ? -1.0f : 1.0f;
    return v;
}

Result<SceneBasis> fbx_basis(const aiScene& scene, const std::filesystem::path& path) {
    const aiMetadata* meta = scene.mMetaData;
    int up = 1, up_sign = 1, front = 2, front_sign = 1, coord = 0, coord_sign = 1;
    metadata_int(meta, "UpAxis", up);
    metadata_int(meta, "UpAxisSign", up_sign);
    metadata_int(meta, "FrontAxis", front);
    metadata_int(meta, "FrontAxisSign", front_sign);
    metadata_int(meta, "CoordAxis", coord);
    metadata_int(meta, "CoordAxisSign", coord_sign);
    const bool in_range = up >= 0 && up < 3 && front >= 0 && front < 3 && coord >= 0 && coord < 3;
    if (!in_range || up == front || up == coord || front == coord)
        return Error(
            "the FBX file's axes (UpAxis " + std::to_string(up) + ", FrontAxis " + std::to_string(front) +
                ", CoordAxis " + std::to_string(coord) + ") are not three different axes 0..2",
            Location(path.string()), "re-export it (Blender: File > Export > FBX, Forward -Z, Up Y)");
    double unit_cm = 1.0;
    metadata_number(meta, "UnitScaleFactor", unit_cm);
    if (!std::isfinite(unit_cm) || unit_cm <= 0.0)
        return Error("the FBX file's UnitScaleFactor " + std::to_string(unit_cm) +
                         " is not a positive number",
                     Location(path.string()), "re-export it with a unit scale of 1.0");
    SceneBasis basis;
    basis.unit_scale = static_cast<float>(unit_cm / 100.0);
    // Rows: the file's right, up and front axes become the level's +x, +y and +z.
    const Vec3 right = axis_vector(coord, coord_sign);
    const Vec3 upv = axis_vector(up, up_sign);
    const Vec3 frontv = axis_vector(front, front_sign);
    Mat4 m(1.0f);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = right[c] * basis.unit_scale;
        m[c][1] = upv[c] * basis.unit_scale;
        m[c][2] = frontv[c] * basis.unit_scale;
    }
    basis.to_level = m;
    basis.mirrored = glm::determinant(Mat3(m)) < 0.0f;
    basis.axes = "FBX: up axis " + std::string(1, "xyz"[up]) + (up_sign < 0 ? " (negative)" : "") +
                 ", unit " + std::to_string(unit_cm) + " cm";
    return basis;
}

} // namespace

Result<SceneBasis> scene_basis(const aiScene& scene, const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    if (ext == ".fbx") return fbx_basis(scene, path);
    SceneBasis basis;
    basis.axes = ext == ".obj" ? "OBJ: read as +Y up, metres" : "glTF: +Y up, metres";
    return basis;
}

} // namespace ks::modelio
