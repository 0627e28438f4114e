// The script language's group, layer and prefab lines (script_structure.h): each to a StructureStep, or an
// error at the offending word.
#include "model/script_structure.h"

#include <algorithm>

namespace ks::editor {
namespace {
using namespace script_tokens;

constexpr const char* kLayerUsage =
    "layer add NAME... | layer LAYER rename NAME... | layer LAYER remove|show|hide|lock|unlock|active | "
    "layer LAYER move   (LAYER: a name or an index from 0, the Default layer)";
constexpr const char* kPrefabUsage =
    "prefab folder PATH | prefab save NAME [replace] [title TEXT...] | prefab place NAME at X,Y,Z [yaw D] | "
    "prefab apply GROUP | prefab update | prefab revert GROUP [ID [FIELD]] | prefab unlink GROUP";
constexpr const char* kExpectUsage =
    "expect groups N | expect group GROUP N | expect layers N | expect layer LAYER N [visible|hidden] "
    "[locked|unlocked] | expect instance GROUP PREFAB N | expect override GROUP ID FIELD | expect "
    "no_override GROUP ID FIELD | expect hidden ID | expect shown ID | expect open_group GROUP";

class StructureLineParser : LineWords {
  public:
    StructureLineParser(std::string_view line, const std::vector<Token>& tokens, int line_no,
                        const std::string& file)
        : LineWords(line, tokens, line_no, file) {
        step_.op = ScriptOp::Structure;
        step_.line = line_no;
    }

    Result<ScriptStep> parse() {
        const std::string_view word = tokens_[0].text;
        Result<void> r = ok();
        if (word == "expect")
            r = expect();
        else if (word == "layer")
            r = layer();
        else if (word == "prefab")
            r = prefab();
        else
            r = group_line(word);
        if (!r) return r.error();
        return step_;
    }

  private:
    Result<void> number(size_t token, int& out, const char* what, const char* usage, int min = 1) const {
        if (token >= tokens_.size()) return fail(token, std::string("expected ") + what, usage);
        if (!to_int(tokens_[token].text, out) || out < min)
            return fail(token, std::string("expected ") + what + ", got '" + word(token) + "'", usage);
        return ok();
    }
    StructureStep& s() { return step_.structure; }

    Result<void> group_line(std::string_view word) {
        if (word == "group") {
            s().op = StructureOp::Group;
            if (tokens_.size() > 1) s().name = rest(1);
            return ok();
        }
        if (word == "ungroup" || word == "exit") {
            s().op = word == "ungroup" ? StructureOp::Ungroup : StructureOp::Exit;
            return need(1, 1, word == "ungroup" ? "ungroup" : "exit");
        }
        if (word == "enter") {
            s().op = StructureOp::Enter;
            if (auto r = need(2, 2, "enter GROUP"); !r) return r;
            return number(1, s().id, "a group id", "enter GROUP");
        }
        constexpr const char* usage = "pick [add|toggle] ID   (selects what a click on the entity selects)";
        s().op = StructureOp::Pick;
        size_t at = 1;
        if (tokens_.size() > 1 && (tokens_[1].text == "add" || tokens_[1].text == "toggle")) {
            s().mode = tokens_[1].text == "add" ? SelectMode::Add : SelectMode::Toggle;
            at = 2;
        }
        if (auto r = need(at + 1, at + 1, usage); !r) return r;
        return number(at, s().id, "an entity id", usage);
    }

    Result<void> layer() {
        if (tokens_.size() < 3) return fail(tokens_.size(), "missing words", kLayerUsage);
        if (tokens_[1].text == "add") {
            s().op = StructureOp::LayerAdd;
            s().name = rest(2);
            return ok();
        }
        s().layer = word(1);
        const std::string_view verb = tokens_[2].text;
        if (verb == "rename") {
            s().op = StructureOp::LayerRename;
            if (tokens_.size() < 4) return fail(3, "expected the new name", kLayerUsage);
            s().name = rest(3);
            return ok();
        }
        static constexpr std::pair<std::string_view, StructureOp> kVerbs[] = {
            {"remove", StructureOp::LayerRemove}, {"show", StructureOp::LayerShow},
            {"hide", StructureOp::LayerHide},     {"lock", StructureOp::LayerLock},
            {"unlock", StructureOp::LayerUnlock}, {"active", StructureOp::LayerActive},
            {"move", StructureOp::LayerMove}};
        for (const auto& [name, op] : kVerbs)
            if (verb == name) {
                s().op = op;
                return need(3, 3, kLayerUsage);
            }
        return fail(2, "unknown layer command '" + word(2) + "'", kLayerUsage);
    }

    Result<void> prefab() {
        if (tokens_.size() < 2) return fail(1, "missing words", kPrefabUsage);
        const std::string_view verb = tokens_[1].text;
        if (verb == "update") {
            s().op = StructureOp::PrefabUpdate;
            return need(2, 2, kPrefabUsage);
        }
        if (tokens_.size() < 3) return fail(2, "missing words", kPrefabUsage);
        if (verb == "folder") {
            s().op = StructureOp::PrefabFolder;
            s().text = rest(2);
            return ok();
        }
        if (verb == "save") return prefab_save();
        if (verb == "place") return prefab_place();
        if (verb == "apply" || verb == "unlink") {
            s().op = verb == "apply" ? StructureOp::PrefabApply : StructureOp::PrefabUnlink;
            if (auto r = need(3, 3, kPrefabUsage); !r) return r;
            return number(2, s().id, "a group id", kPrefabUsage);
        }
        if (verb == "revert") {
            s().op = StructureOp::PrefabRevert;
            if (auto r = need(3, 5, kPrefabUsage); !r) return r;
            if (auto r = number(2, s().id, "a group id", kPrefabUsage); !r) return r;
            if (tokens_.size() > 3)
                if (auto r = number(3, s().entity_id, "an entity id", kPrefabUsage); !r) return r;
            if (tokens_.size() > 4) s().text = word(4);
            return ok();
        }
        return fail(1, "unknown prefab command '" + std::string(verb) + "'", kPrefabUsage);
    }

    Result<void> prefab_save() {
        s().op = StructureOp::PrefabSave;
        s().name = word(2);
        for (size_t i = 3; i < tokens_.size(); ++i) {
            if (tokens_[i].text == "replace") {
                s().replace = true;
            } else if (tokens_[i].text == "title" && i + 1 < tokens_.size()) {
                s().text = rest(i + 1);
                break;
            } else {
                return fail(i, "expected 'replace' or 'title TEXT...'", kPrefabUsage);
            }
        }
        return ok();
    }

    Result<void> prefab_place() {
        s().op = StructureOp::PrefabPlace;
        s().name = word(2);
        if (tokens_.size() < 5 || tokens_[3].text != "at")
            return fail(3, "expected 'at X,Y,Z'", kPrefabUsage);
        if (!to_vec3(tokens_[4].text, s().position))
            return fail(4, "expected three numbers separated by commas, got '" + word(4) + "'", kPrefabUsage);
        if (tokens_.size() == 5) return ok();
        if (tokens_.size() != 7 || tokens_[5].text != "yaw" || !to_float(tokens_[6].text, s().yaw))
            return fail(5, "expected 'yaw DEGREES'", kPrefabUsage);
        return ok();
    }

    Result<void> expect() {
        const std::string_view what = tokens_[1].text;
        if (what == "groups" || what == "layers") {
            s().op = what == "groups" ? StructureOp::ExpectGroups : StructureOp::ExpectLayers;
            if (auto r = need(3, 3, kExpectUsage); !r) return r;
            return number(2, s().count, "a count", kExpectUsage, 0);
        }
        if (what == "group") {
            s().op = StructureOp::ExpectGroup;
            if (auto r = need(4, 4, kExpectUsage); !r) return r;
            if (auto r = number(2, s().id, "a group id", kExpectUsage); !r) return r;
            return number(3, s().count, "a count of entities", kExpectUsage, 0);
        }
        if (what == "layer") {
            s().op = StructureOp::ExpectLayer;
            if (auto r = need(4, 6, kExpectUsage); !r) return r;
            s().layer = word(2);
            if (auto r = number(3, s().count, "a count of entities", kExpectUsage, 0); !r) return r;
            for (size_t i = 4; i < tokens_.size(); ++i) {
                const std::string w = word(i);
                if (w != "visible" && w != "hidden" && w != "locked" && w != "unlocked")
                    return fail(i, "expected visible, hidden, locked or unlocked", kExpectUsage);
                s().state.push_back(w);
            }
            return ok();
        }
        if (what == "instance") {
            s().op = StructureOp::ExpectInstance;
            if (auto r = need(5, 5, kExpectUsage); !r) return r;
            if (auto r = number(2, s().id, "a group id", kExpectUsage); !r) return r;
            s().name = word(3);
            return number(4, s().count, "a count of members", kExpectUsage, 0);
        }
        if (what == "override" || what == "no_override") {
            s().op = what == "override" ? StructureOp::ExpectOverride : StructureOp::ExpectNoOverride;
            if (auto r = need(5, 5, kExpectUsage); !r) return r;
            if (auto r = number(2, s().id, "a group id", kExpectUsage); !r) return r;
            if (auto r = number(3, s().entity_id, "an entity id", kExpectUsage); !r) return r;
            s().text = word(4);
            return ok();
        }
        if (what == "open_group") {
            s().op = StructureOp::ExpectOpenGroup;
            if (auto r = need(3, 3, kExpectUsage); !r) return r;
            return number(2, s().id, "a group id (0: none)", kExpectUsage, 0);
        }
        s().op = what == "hidden" ? StructureOp::ExpectHidden : StructureOp::ExpectShown;
        if (auto r = need(3, 3, kExpectUsage); !r) return r;
        return number(2, s().entity_id, "an entity id", kExpectUsage);
    }

    ScriptStep step_;
};

} // namespace

bool is_structure_command(std::string_view word) {
    static constexpr std::string_view kWords[] = {"group", "ungroup", "enter", "exit",
                                                  "pick",  "layer",   "prefab"};
    return std::find(std::begin(kWords), std::end(kWords), word) != std::end(kWords);
}

bool is_structure_expectation(std::string_view word) {
    static constexpr std::string_view kWords[] = {"groups",   "group",       "layers", "layer", "instance",
                                                  "override", "no_override", "hidden", "shown", "open_group"};
    return std::find(std::begin(kWords), std::end(kWords), word) != std::end(kWords);
}

Result<ScriptStep> parse_structure_line(std::string_view line, const std::vector<Token>& tokens, int line_no,
                                        const std::string& file) {
    return StructureLineParser(line, tokens, line_no, file).parse();
}

} // namespace ks::editor
