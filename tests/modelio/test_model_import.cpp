// modelio: designers' models through assimp. Every format read from small files the tests write (glTF with
// its .bin, OBJ with its MTL, .glb and FBX made by assimp's exporters), units and axes, and every kind of bad
// file refused with an Error naming the file, never a crash.
#include "modelio/model_import.h"
#include "modelio/model_writers.h"
#include "modelio/scene_conventions.h"
#include "test_support.h"

#include <assimp/scene.h>
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <limits>

using namespace ks;
using namespace ks::modelio;

namespace {

void check_cube_bounds(const ImportedModel& m, Vec3 centre, float half) {
    for (int k = 0; k < 3; ++k) {
        CHECK(m.bounds.min[k] == doctest::Approx(centre[k] - half).epsilon(1e-5));
        CHECK(m.bounds.max[k] == doctest::Approx(centre[k] + half).epsilon(1e-5));
    }
}

// The error names the file and says what is wrong (`what` appears in the message).
void check_refused(const Result<ImportedModel>& r, const std::filesystem::path& file,
                   const std::string& what) {
    REQUIRE_FALSE(r.ok());
    const std::string text = r.error().str();
    INFO(text);
    CHECK(r.error().where.file == file.string());
    CHECK(test::contains_text(text, what));
}

std::string bytes_of(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void write_bytes(const std::filesystem::path& p, const std::string& bytes) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

} // namespace

TEST_CASE("modelio: a glTF cube with its node transform baked, its material and texture") {
    test::ScratchDir dir;
    test::write_file(dir / "crate.png", "not read by the importer; must exist");
    const auto file = test::write_gltf_cube(
        dir.path(), "crate", {.translation = {0, 1, 2}, .node_scale = 2.0f, .texture = "crate.png"});
    Result<ImportedModel> m = import_model(file);
    REQUIRE_MESSAGE(m.ok(), m.error().str());
    CHECK(m->triangle_count == 12);
    REQUIRE(m->meshes.size() == 1);
    CHECK(m->meshes[0].positions.size() == m->meshes[0].normals.size());
    CHECK(m->meshes[0].positions.size() == m->meshes[0].uvs.size());
    check_cube_bounds(*m, {0, 1, 2}, 1.0f);
    CHECK(m->unit_scale == 1.0f);
    REQUIRE(m->materials.size() >= 1);
    const ImportedMaterial& mat = m->materials[static_cast<size_t>(m->meshes[0].material)];
    CHECK(mat.base_color.r == doctest::Approx(0.8f));
    CHECK(mat.base_color.g == doctest::Approx(0.2f));
    CHECK(mat.metallic == doctest::Approx(0.25f));
    CHECK(mat.roughness == doctest::Approx(0.5f));
    CHECK(mat.textures.base_color == "crate.png");
    CHECK_FALSE(mat.double_sided); // glTF's default: the renderer culls its back faces
    test::CubeOptions leaf_options;
    leaf_options.double_sided = true;
    const auto two_sided = test::write_gltf_cube(dir.path(), "leaf", leaf_options);
    Result<ImportedModel> leaf = import_model(two_sided);
    REQUIRE_MESSAGE(leaf.ok(), leaf.error().str());
    CHECK(leaf->materials[static_cast<size_t>(leaf->meshes[0].material)].double_sided);
    // Normals point out of the cube: each triangle's normal agrees with its winding.
    const ImportedMesh& mesh = m->meshes[0];
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const Vec3 a = mesh.positions[mesh.indices[i]], b = mesh.positions[mesh.indices[i + 1]],
                   c = mesh.positions[mesh.indices[i + 2]];
        const Vec3 outward = (a + b + c) / 3.0f - Vec3(0, 1, 2);
        CHECK(glm::dot(glm::cross(b - a, c - a), outward) > 0.0f);
    }
}

TEST_CASE("modelio: .glb and FBX written by assimp read back; FBX's centimetre unit becomes metres") {
    test::ScratchDir dir;
    const auto gltf = test::write_gltf_cube(dir.path(), "cube");
    REQUIRE(test::convert_with_assimp(gltf, dir / "cube.glb", "glb2"));
    Result<ImportedModel> glb = import_model(dir / "cube.glb");
    REQUIRE_MESSAGE(glb.ok(), glb.error().str());
    CHECK(glb->triangle_count == 12);
    check_cube_bounds(*glb, Vec3(0.0f), 0.5f);

    REQUIRE(test::convert_with_assimp(gltf, dir / "cube.fbx", "fbxa"));
    Result<ImportedModel> fbx = import_model(dir / "cube.fbx");
    REQUIRE_MESSAGE(fbx.ok(), fbx.error().str());
    CHECK(fbx->triangle_count == 12);
    // assimp writes UnitScaleFactor 1 (one file unit is a centimetre), so the 1-unit cube is 1 cm.
    CHECK(fbx->unit_scale == doctest::Approx(0.01f));
    check_cube_bounds(*fbx, Vec3(0.0f), 0.005f);
}

TEST_CASE("modelio: OBJ with its MTL; a texture the MTL names must be there") {
    test::ScratchDir dir;
    const auto file = test::write_obj_cube(dir.path(), "box", 1.5f);
    Result<ImportedModel> m = import_model(file);
    REQUIRE_MESSAGE(m.ok(), m.error().str());
    CHECK(m->triangle_count == 12);
    check_cube_bounds(*m, Vec3(0.0f), 1.5f);
    const ImportedMaterial& mat = m->materials[static_cast<size_t>(m->meshes[0].material)];
    CHECK(mat.name == "paint");
    CHECK(mat.base_color.g == doctest::Approx(0.6f));
    CHECK(mat.double_sided); // OBJ cannot say: both sides drawn

    const auto textured = test::write_obj_cube(dir.path(), "painted", 1.0f, "paint.png");
    check_refused(import_model(textured), textured, "\"paint.png\", which is missing");
    test::write_file(dir / "paint.png", "x");
    CHECK(import_model(textured).ok());
}

TEST_CASE(
    "modelio: FBX axes and units from the file's settings; a Z-up file stands up, a mirror flips windings") {
    aiScene scene;
    scene.mMetaData = aiMetadata::Alloc(7);
    scene.mMetaData->Set(0, "UpAxis", std::int32_t{2});
    scene.mMetaData->Set(1, "UpAxisSign", std::int32_t{1});
    scene.mMetaData->Set(2, "FrontAxis", std::int32_t{1});
    scene.mMetaData->Set(3, "FrontAxisSign", std::int32_t{-1});
    scene.mMetaData->Set(4, "CoordAxis", std::int32_t{0});
    scene.mMetaData->Set(5, "CoordAxisSign", std::int32_t{1});
    scene.mMetaData->Set(6, "UnitScaleFactor", 100.0f);
    Result<SceneBasis> basis = scene_basis(scene, "tower.fbx");
    REQUIRE(basis.ok());
    CHECK(basis->unit_scale == doctest::Approx(1.0f));
    const Vec3 up = Vec3(basis->to_level * Vec4(0, 0, 3, 1)); // the file's +Z is up
    CHECK(up.y == doctest::Approx(3.0f));
    CHECK(std::abs(up.x) + std::abs(up.z) < 1e-6f);
    CHECK_FALSE(basis->mirrored);

    scene.mMetaData->Set(5, "CoordAxisSign", std::int32_t{-1}); // a left-handed file
    Result<SceneBasis> mirrored = scene_basis(scene, "tower.fbx");
    REQUIRE(mirrored.ok());
    CHECK(mirrored->mirrored);

    scene.mMetaData->Set(0, "UpAxis", std::int32_t{0}); // up and right both x
    Result<SceneBasis> bad = scene_basis(scene, "tower.fbx");
    REQUIRE_FALSE(bad.ok());
    CHECK(test::contains_text(bad.error().str(), "not three different axes"));
    CHECK(bad.error().where.file == "tower.fbx");
}

TEST_CASE("modelio: bad files are refused with the file and what is wrong") {
    test::ScratchDir dir;
    check_refused(import_model(dir / "absent.glb"), dir / "absent.glb", "no such model file");
    const auto blend = test::write_file(dir / "scene.blend", "BLENDER");
    check_refused(import_model(blend), blend, "not a model format");
    const auto empty = test::write_file(dir / "empty.obj", "");
    check_refused(import_model(empty), empty, "empty");

    test::CubeOptions no_buffer;
    no_buffer.write_buffer = false;
    const auto gltf = test::write_gltf_cube(dir.path(), "nobuffer", no_buffer);
    check_refused(import_model(gltf), gltf, "cannot read the model");
    test::CubeOptions poisoned;
    poisoned.poison = std::numeric_limits<float>::quiet_NaN();
    const auto nan = test::write_gltf_cube(dir.path(), "nan", poisoned);
    check_refused(import_model(nan), nan, "not a number");
    const auto notex = test::write_gltf_cube(dir.path(), "notex", {.texture = "gone.png"});
    check_refused(import_model(notex), notex, "gone.png");

    const auto lines = test::write_file(dir / "lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n");
    CHECK_FALSE(import_model(lines).ok());
    const auto huge = test::write_obj_cube(dir.path(), "huge", 1.0e5f);
    check_refused(import_model(huge), huge, "units across");
    const auto tiny = test::write_obj_cube(dir.path(), "tiny", 1.0e-6f);
    check_refused(import_model(tiny), tiny, "no size");
    const auto cube = test::write_obj_cube(dir.path(), "cube");
    check_refused(import_model(cube, {.max_triangles = 11}), cube, "more than the 11");
    check_refused(import_model(cube, {.max_file_bytes = 16}), cube, "MiB");

    // A file its extension's reader declines goes to no other format's reader: assimp offered a ".gltf"
    // holding "geometrynode" to its OpenGEX reader, which read past the end of its buffer (fuzz finding,
    // crash-cb2d9cce…), and would read an STL or PLY text named .gltf as one.
    const char* stl_triangle =
        "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
        "endloop\nendfacet\nendsolid t\n";
    for (const char* text : {"geometrynode ", "Metric {} GeometryNode { }", stl_triangle,
                             "ply\nformat ascii 1.0\nelement vertex 0\nend_header\n"}) {
        CAPTURE(text);
        const auto other = test::write_file(dir / "other.gltf", text);
        check_refused(import_model(other), other, "cannot read the model");
    }
}

TEST_CASE("modelio: truncated and corrupted files of every format never crash") {
    test::ScratchDir dir;
    const auto gltf = test::write_gltf_cube(dir.path(), "cube");
    REQUIRE(test::convert_with_assimp(gltf, dir / "cube.glb", "glb2"));
    REQUIRE(test::convert_with_assimp(gltf, dir / "cube.fbx", "fbxa"));
    const auto obj = test::write_obj_cube(dir.path(), "cube");
    int refused = 0, runs = 0;
    for (const char* ext : {".glb", ".fbx", ".gltf", ".obj"}) {
        const std::string good = bytes_of(dir / (std::string("cube") + ext));
        REQUIRE(good.size() > 16);
        const int cuts = test::iterations(8, 0.5);
        for (int i = 0; i < cuts; ++i) {
            const auto bad = dir / (std::string("bad") + ext);
            std::string bytes = good;
            if (i % 2 == 0) {
                bytes.resize(good.size() * static_cast<size_t>(i + 1) / static_cast<size_t>(cuts + 2));
            } else {
                for (size_t k = static_cast<size_t>(i) * 7; k < bytes.size(); k += 13)
                    bytes[k] = static_cast<char>(bytes[k] ^ 0x5a);
            }
            write_bytes(bad, bytes);
            Result<ImportedModel> r = import_model(bad);
            ++runs;
            if (!r) {
                ++refused;
                CHECK(r.error().where.file == bad.string());
                CHECK_FALSE(r.error().message.empty());
            } else {
                CHECK(r->triangle_count > 0); // a cut that still reads is a model with triangles
            }
        }
    }
    CHECK(refused > runs / 2);
}

TEST_CASE("modelio: texture coordinates come out top-down (v = 0 at the image's top), whatever assimp does") {
    // OBJ's vt is bottom-up; a corner at the image's bottom-left (0, 0) is (0, 1) in the project's
    // convention, the convention the renderer's textures are uploaded in (docs/assets.md).
    test::ScratchDir dir;
    const auto file = test::write_file(
        dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 0.75\nf 1/1 2/2 3/3\n");
    Result<ImportedModel> m = import_model(file);
    REQUIRE_MESSAGE(m.ok(), m.error().str());
    REQUIRE(m->meshes.size() == 1);
    const ImportedMesh& mesh = m->meshes[0];
    REQUIRE(mesh.positions.size() == 3);
    for (size_t i = 0; i < 3; ++i) {
        CAPTURE(i);
        const Vec3 p = mesh.positions[i];
        const Vec2 uv = mesh.uvs[i];
        if (p.y > 0.5f) // the top corner: vt 0 0.75
            CHECK(uv.y == doctest::Approx(0.25f));
        else
            CHECK(uv.y == doctest::Approx(1.0f));
        CHECK(uv.x == doctest::Approx(p.x));
    }
}
