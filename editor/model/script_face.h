#pragma once
// The script language's face steps (`face select`, `face material`, `face offset`, `face shift`,
// `face scale`, `face rotation`, `face turn`, `face fit`, `face align`, `face copy`, `face paste`,
// `face replace`, `face lock`): each is what its line said, typed; its `run` calls edit_faces.h. Parsed
// and run in script_face_parser.cpp; the `face` entry of the brush table (script_brush_parser.cpp) points
// at parse_face_line.
#include "model/edit_faces.h"
#include "model/script_tokens.h"

#include <variant>
#include <vector>

namespace ks::editor {

struct ScriptContext;
struct ScriptStep;

namespace steps {

// A face named by entity id and either an index or the direction it faces (+x ... -z).
struct FaceName {
    int entity = 0;
    int index = -1;       // when >= 0
    DVec3 direction{0.0}; // when index < 0
};
struct FaceSelect {
    SelectMode mode = SelectMode::Replace;
    bool none = false;    // `face select none`
    bool brushes = false; // `face select brushes`: every face of the selected brushes
    std::vector<FaceName> faces;
    Result<void> run(ScriptContext& c) const;
};
// Everything one number pair or word sets: which edit, and its arguments.
enum class FaceOp { material, offset, shift, scale, rotation, turn, fit, align, copy, paste, replace, lock };
struct FaceEditStep {
    FaceOp op = FaceOp::copy;
    glm::dvec2 pair{1.0};
    double number = 0.0;
    int edge = 0;
    bool on = false;
    std::string word, other; // material; replace's from and to
    Result<void> run(ScriptContext& c) const;
};

} // namespace steps

struct FaceStep {
    std::variant<steps::FaceSelect, steps::FaceEditStep> step;
    Result<void> run(ScriptContext& c) const;
};

// The `face ...` line as a step.
Result<ScriptStep> parse_face_line(const script_tokens::LineWords& words);
inline constexpr const char* kFaceUsage =
    "face select [add|toggle|remove] ID:FACE... | face select none | face select brushes | "
    "face material M | face offset U,V | face shift DU,DV | face scale SU,SV | face rotation D | face turn D "
    "| "
    "face fit [U,V] | face align EDGE | face copy | face paste | face replace OLD NEW | face lock on|off";

} // namespace ks::editor
