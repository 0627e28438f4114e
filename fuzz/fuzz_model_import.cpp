// libFuzzer target: designers' model files through assimp (common/modelio). The first byte picks the format
// (.glb, .gltf, .obj, .fbx: its value modulo 4), the rest is the file, written to a RAM folder because
// assimp reads by path (the importer is what the editor and the game run). For an OBJ whose first byte has
// its top bit set, the same bytes are also its material library model.mtl, which any `mtllib` line opens
// (by name, or as the reader's fallback to the OBJ's own name): one text holds both files' statements, and
// each reader skips the other's. Assimp is Debian's and not instrumented: coverage
// guides the fuzzer through our checks, and a crash inside assimp is still a finding, since it would take
// the editor down with a designer's unsaved work.
#include "fuzz_oracle.h"
#include "modelio/model_import.h"

#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

std::filesystem::path scratch_folder() {
    static const std::filesystem::path folder = [] {
        std::filesystem::path base = std::filesystem::exists("/dev/shm") ? "/dev/shm" : "/tmp";
        std::filesystem::path f = base / ("ks-fuzz-model-" + std::to_string(::getpid()));
        std::filesystem::create_directories(f);
        return f;
    }();
    return folder;
}

bool finite(const ks::Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    static const char* kExtensions[] = {".glb", ".gltf", ".obj", ".fbx"};
    const std::filesystem::path file = scratch_folder() / (std::string("model") + kExtensions[data[0] % 4]);
    const auto write = [&](const std::filesystem::path& to) {
        std::ofstream out(to, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    };
    write(file);
    const std::filesystem::path library = scratch_folder() / "model.mtl";
    std::error_code absent;
    if (data[0] % 4 == 2 && (data[0] & 0x80) != 0)
        write(library);
    else
        std::filesystem::remove(library, absent);
    const ks::modelio::ImportLimits limits;
    auto model = ks::modelio::import_model(file, limits);
    if (!model.ok()) {
        ks::fuzz::check_clear_error(model.error(), file.filename().string());
        return 0;
    }
    if (model->triangle_count == 0 || model->triangle_count > limits.max_triangles)
        ks::fuzz::fail("accepted a model with no or too many triangles");
    if (model->materials.empty()) ks::fuzz::fail("accepted a model without a material");
    for (const ks::modelio::ImportedMesh& mesh : model->meshes) {
        if (mesh.normals.size() != mesh.positions.size() || mesh.uvs.size() != mesh.positions.size())
            ks::fuzz::fail("a mesh's attributes differ in count");
        if (mesh.indices.size() % 3 != 0) ks::fuzz::fail("a mesh's indices are not triangles");
        for (std::uint32_t i : mesh.indices)
            if (i >= mesh.positions.size()) ks::fuzz::fail("an index past the mesh's vertices");
        for (const ks::Vec3& p : mesh.positions)
            if (!finite(p)) ks::fuzz::fail("accepted a non-finite vertex");
        if (mesh.material < 0 || static_cast<std::size_t>(mesh.material) >= model->materials.size())
            ks::fuzz::fail("a mesh names a material that does not exist");
    }
    return 0;
}
