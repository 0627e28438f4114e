// The script language's brush commands (script_brush.h): the `brush` line's parser, its steps' `run`, and
// the table entry that registers it (script_command.h).
#include "model/script_command.h"

namespace ks::editor {
namespace {
using namespace script_tokens;

constexpr const char* kBrushUsage = "brush box X,Y,Z X,Y,Z [material M] [name TEXT] | "
                                    "brush ramp X,Y,Z X,Y,Z up +x|-x|+z|-z [material M] [name TEXT] | "
                                    "brush extrude x|y|z FROM TO U,V U,V U,V... [material M] [name TEXT] | "
                                    "brush subtract | brush hollow THICKNESS | brush merge | brush intersect "
                                    "| brush clip X,Y,Z NX,NY,NZ [back|front|both]";

template <class T>
Result<ScriptStep> brush_step(T step) {
    return step_of<BrushStep>(std::move(step));
}

// "U,V": two numbers with no spaces.
bool to_vec2(std::string_view s, glm::vec2& out) {
    const size_t comma = s.find(',');
    return comma != std::string_view::npos && to_float(s.substr(0, comma), out.x) &&
           to_float(s.substr(comma + 1), out.y);
}

// The optional `material M` and `name TEXT` from word `i` on (name last: it takes the rest of the line).
Result<void> look_from(const LineWords& w, size_t i, BrushLook& look) {
    if (i < w.size() && w.text(i) == "material") {
        if (i + 1 >= w.size()) return w.fail(i + 1, "expected a material after 'material'", kBrushUsage);
        look.material = w.word(i + 1);
        i += 2;
    }
    if (i < w.size()) {
        if (w.text(i) != "name" || i + 1 >= w.size())
            return w.fail(i, "expected 'material M' or 'name TEXT'", kBrushUsage);
        look.name = w.rest(i + 1);
    }
    return ok();
}

Result<ScriptStep> parse_box(const LineWords& w) {
    steps::BrushBox step;
    if (w.size() < 4) return w.fail(w.size(), "expected two corners", kBrushUsage);
    if (auto r = w.vec(2, step.a); !r) return r.error();
    if (auto r = w.vec(3, step.b); !r) return r.error();
    if (auto r = look_from(w, 4, step.look); !r) return r.error();
    return brush_step(std::move(step));
}

Result<ScriptStep> parse_ramp(const LineWords& w) {
    steps::BrushRamp step;
    if (w.size() < 6) return w.fail(w.size(), "expected two corners and 'up' with a direction", kBrushUsage);
    if (auto r = w.vec(2, step.a); !r) return r.error();
    if (auto r = w.vec(3, step.b); !r) return r.error();
    if (w.text(4) != "up") return w.fail(4, "expected 'up'", kBrushUsage);
    const std::string_view d = w.text(5);
    if (d.size() != 2 || (d[0] != '+' && d[0] != '-') || (d[1] != 'x' && d[1] != 'z'))
        return w.fail(5, "expected the high side: +x, -x, +z or -z", kBrushUsage);
    step.rise = {d[1] == 'x' ? 0 : 2, d[0] == '+' ? 1 : -1};
    if (auto r = look_from(w, 6, step.look); !r) return r.error();
    return brush_step(std::move(step));
}

Result<ScriptStep> parse_extrude(const LineWords& w) {
    steps::BrushExtrude step;
    if (w.size() < 8)
        return w.fail(w.size(), "expected an axis, two ends and at least 3 points", kBrushUsage);
    const std::string_view axis = w.text(2);
    if (axis.size() != 1 || axis[0] < 'x' || axis[0] > 'z')
        return w.fail(2, "expected x, y or z", kBrushUsage);
    step.axis = axis[0] - 'x';
    if (!to_float(w.text(3), step.from)) return w.fail(3, "expected where the sweep starts", kBrushUsage);
    if (!to_float(w.text(4), step.to)) return w.fail(4, "expected where the sweep ends", kBrushUsage);
    size_t i = 5;
    for (glm::vec2 p; i < w.size() && w.text(i) != "material" && w.text(i) != "name"; ++i) {
        if (!to_vec2(w.text(i), p))
            return w.fail(i, "expected a point as two numbers, got '" + w.word(i) + "'",
                          "write it without spaces, like 2,-1.5");
        step.points.push_back(p);
    }
    if (step.points.size() < 3) return w.fail(i, "a polygon needs at least 3 points", kBrushUsage);
    if (auto r = look_from(w, i, step.look); !r) return r.error();
    return brush_step(std::move(step));
}

Result<ScriptStep> parse_clip(const LineWords& w) {
    steps::BrushClip step;
    if (auto r = w.need(4, 5, kBrushUsage); !r) return r.error();
    if (auto r = w.vec(2, step.point); !r) return r.error();
    if (auto r = w.vec(3, step.normal); !r) return r.error();
    if (w.size() == 5) {
        const std::string_view keep = w.text(4);
        if (keep != "back" && keep != "front" && keep != "both")
            return w.fail(4, "expected back, front or both", kBrushUsage);
        step.keep = keep == "back" ? ClipKeep::back : keep == "front" ? ClipKeep::front : ClipKeep::both;
    }
    return brush_step(step);
}

Result<ScriptStep> parse_brush(const LineWords& w) {
    if (w.size() < 2) return w.fail(1, "expected what to do", kBrushUsage);
    const std::string_view what = w.text(1);
    if (what == "box") return parse_box(w);
    if (what == "ramp") return parse_ramp(w);
    if (what == "extrude") return parse_extrude(w);
    if (what == "clip") return parse_clip(w);
    if (what == "hollow") {
        steps::BrushHollow step;
        if (auto r = w.need(3, 3, kBrushUsage); !r) return r.error();
        if (!to_float(w.text(2), step.thickness) || step.thickness <= 0.0f)
            return w.fail(2, "expected the wall thickness, a positive number", kBrushUsage);
        return brush_step(step);
    }
    if (what == "subtract" || what == "merge" || what == "intersect") {
        if (auto r = w.need(2, 2, kBrushUsage); !r) return r.error();
        if (what == "intersect") return brush_step(steps::BrushIntersect{});
        return what == "merge" ? brush_step(steps::BrushMerge{}) : brush_step(steps::BrushSubtract{});
    }
    return w.fail(1, "unknown brush command '" + w.word(1) + "'", kBrushUsage);
}

constexpr CommandSpec kCommands[] = {
    {"brush", false, kBrushUsage,
     "place a box, ramp or extruded-polygon brush (selected); cut the selected brushes from the brushes they "
     "overlap (the cutters go), hollow, merge, intersect (keep their common part) or clip the selected "
     "brushes",
     parse_brush},
    {"face", false, kFaceUsage,
     "select brush faces (by index or the direction they face); set their material, offset, scale or "
     "rotation, fit or align their texture, copy and paste their attributes; replace a material across the "
     "level; texture lock on or off",
     parse_face_line},
};

// An edit's result without its value.
Result<void> done(const auto& r) {
    if (!r) return r.error();
    return ok();
}

} // namespace

std::span<const CommandSpec> brush_commands() {
    return kCommands;
}

Result<void> BrushStep::run(ScriptContext& c) const {
    return std::visit([&](const auto& s) { return s.run(c); }, step);
}

namespace steps {

Result<void> BrushBox::run(ScriptContext& c) const {
    return done(place_box_brush(c.editor, a, b, look));
}
Result<void> BrushRamp::run(ScriptContext& c) const {
    return done(place_ramp_brush(c.editor, a, b, rise, look));
}
Result<void> BrushExtrude::run(ScriptContext& c) const {
    return done(place_extruded_brush(c.editor, axis, from, to, points, look));
}
Result<void> BrushSubtract::run(ScriptContext& c) const {
    return subtract_selected_brushes(c.editor);
}
Result<void> BrushHollow::run(ScriptContext& c) const {
    return hollow_selected_brushes(c.editor, thickness);
}
Result<void> BrushMerge::run(ScriptContext& c) const {
    return merge_selected_brushes(c.editor);
}
Result<void> BrushIntersect::run(ScriptContext& c) const {
    return intersect_selected_brushes(c.editor);
}
Result<void> BrushClip::run(ScriptContext& c) const {
    return clip_selected_brushes(c.editor, point, normal, keep);
}

} // namespace steps
} // namespace ks::editor
