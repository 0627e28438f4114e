#include "render/model_lod_list.h"

#include "jsonio/document.h"
#include "jsonio/object_reader.h"

#include <cmath>

namespace ks::render {

namespace {
constexpr const char* kFormat = "killswitch-model-lods";

bool plain_model_name(const std::string& name) {
    if (name.empty() || name.find_first_of("/\\") != std::string::npos || name == "." || name == "..")
        return false;
    const std::filesystem::path p(name);
    const std::string ext = p.extension().string();
    return ext == ".gltf" || ext == ".glb";
}

void read_level(const jsonio::Json& value, const std::string& path, jsonio::ProblemSink& sink,
                std::vector<ModelLodEntry>& out) {
    jsonio::ObjectReader in(value, path, sink, "level");
    ModelLodEntry e;
    bool good = in.text("file", e.file, jsonio::Need::Required, 200,
                        "the level's glTF file name, e.g. \"robot_lod1.gltf\"");
    if (good && !plain_model_name(e.file)) {
        sink.report(jsonio::Severity::Error, in.path_of("file"),
                    "\"" + e.file + "\" is not a .gltf or .glb file name in the model's folder",
                    "name a file beside the model, without a folder (ks_assetgen --out assets writes them)");
        good = false;
    }
    good =
        in.number("deviation", e.deviation, jsonio::Range(0.0, 1e6, "model units"), jsonio::Need::Required) &&
        good;
    good = in.whole("triangles", e.triangles, jsonio::Range(0.0, 1e9), jsonio::Need::Required) && good;
    in.finish();
    if (good) out.push_back(e);
}
} // namespace

std::filesystem::path model_lods_path(const std::filesystem::path& model) {
    std::filesystem::path list = model;
    list.replace_extension(".lods.json");
    return list;
}

Result<std::vector<ModelLodEntry>> parse_model_lods(std::string_view text, const std::string& list_file,
                                                    const std::string& model_file) {
    const std::string example = std::string("a level list starts with {\"format\": \"") + kFormat +
                                "\" (ks_assetgen --out assets writes it)";
    const jsonio::Document document = jsonio::Document::parse(text, list_file, {"level list", example});
    jsonio::Problems problems(list_file, &document.positions());
    document.report_to(problems);
    std::vector<ModelLodEntry> levels;
    if (const jsonio::Json* root = document.root()) {
        jsonio::ObjectReader in(*root, "", problems, "level list");
        std::string format, model;
        int version = 0;
        if (in.text("format", format, jsonio::Need::Required, 0, example) && format != kFormat)
            problems.report(jsonio::Severity::Error, in.path_of("format"), "not a Killswitch level list",
                            example);
        in.whole("version", version, jsonio::Range(1.0, 1.0), jsonio::Need::Required);
        if (in.text("model", model, jsonio::Need::Required, 200) && model != model_file)
            problems.report(jsonio::Severity::Error, in.path_of("model"),
                            "the list is for \"" + model + "\", not \"" + model_file + "\"",
                            "regenerate the models (ks_assetgen --out assets)");
        const jsonio::Json* list =
            in.get("levels", jsonio::Need::Required, "an array of {\"file\", \"deviation\", \"triangles\"}");
        if (list && (!list->is_array() || list->empty() || list->size() > kMaxModelLods)) {
            problems.report(jsonio::Severity::Error, in.path_of("levels"),
                            "expected 1 to " + std::to_string(kMaxModelLods) + " levels in an array",
                            "list the model itself first, then its coarser levels");
        } else if (list) {
            for (std::size_t i = 0; i < list->size(); ++i)
                read_level((*list)[i], in.path_of("levels") + "[" + std::to_string(i) + "]", problems,
                           levels);
        }
        in.finish();
        if (!problems.has_errors() && !levels.empty()) {
            if (levels.front().file != model_file || levels.front().deviation != 0.0f)
                problems.report(jsonio::Severity::Error, in.path_of("levels") + "[0]",
                                "the first level must be the model itself (\"" + model_file +
                                    "\") at deviation 0",
                                "list the model first");
            for (std::size_t i = 1; i < levels.size(); ++i)
                if (levels[i].deviation < levels[i - 1].deviation)
                    problems.report(jsonio::Severity::Error,
                                    in.path_of("levels") + "[" + std::to_string(i) + "].deviation",
                                    "a coarser level's deviation is smaller than the finer one's before it",
                                    "list the levels finest first");
        }
    }
    problems.pass_warnings(nullptr);
    if (problems.has_errors()) return problems.combined();
    return levels;
}

} // namespace ks::render
