#pragma once
// The script language's brush steps (`brush box`, `brush ramp`, `brush extrude`, `brush subtract`,
// `brush hollow`, `brush merge`, `brush intersect`, `brush clip`): each is what its line said, typed; its
// `run` calls the brush edits of edit_brushes.h. Parsed, run and registered in script_brush_parser.cpp.
#include "model/edit_brushes.h"
#include "model/script_face.h"

#include <variant>
#include <vector>

namespace ks::editor {

struct ScriptContext;

namespace steps {

struct BrushBox {
    Vec3 a{0.0f}, b{0.0f}; // opposite corners
    BrushLook look;
    Result<void> run(ScriptContext& c) const;
};
struct BrushRamp {
    Vec3 a{0.0f}, b{0.0f};
    RampRise rise;
    BrushLook look;
    Result<void> run(ScriptContext& c) const;
};
struct BrushExtrude {
    int axis = 1;
    float from = 0.0f, to = 0.0f;
    std::vector<glm::vec2> points;
    BrushLook look;
    Result<void> run(ScriptContext& c) const;
};
struct BrushSubtract {
    Result<void> run(ScriptContext& c) const;
};
struct BrushHollow {
    float thickness = 0.0f;
    Result<void> run(ScriptContext& c) const;
};
struct BrushMerge {
    Result<void> run(ScriptContext& c) const;
};
struct BrushIntersect {
    Result<void> run(ScriptContext& c) const;
};
struct BrushClip {
    Vec3 point{0.0f}, normal{0.0f, 1.0f, 0.0f};
    ClipKeep keep = ClipKeep::back;
    Result<void> run(ScriptContext& c) const;
};

} // namespace steps

struct BrushStep {
    std::variant<steps::BrushBox, steps::BrushRamp, steps::BrushExtrude, steps::BrushSubtract,
                 steps::BrushHollow, steps::BrushMerge, steps::BrushIntersect, steps::BrushClip, FaceStep>
        step;
    Result<void> run(ScriptContext& c) const;
};

} // namespace ks::editor
