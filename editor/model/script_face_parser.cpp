// The script language's face commands (script_face.h): the `face` line's parser and its steps' `run`.
#include "level/entity_shapes.h"
#include "model/script_command.h"
#include "model/script_face.h"

namespace ks::editor {

namespace {
using namespace script_tokens;

// "U,V" with no spaces.
bool face_pair(std::string_view s, glm::dvec2& out) {
    const size_t comma = s.find(',');
    return comma != std::string_view::npos && to_double(s.substr(0, comma), out.x) &&
           to_double(s.substr(comma + 1), out.y);
}

// "ID:FACE", FACE an index or +x, -x, +y, -y, +z, -z.
bool face_name(std::string_view s, steps::FaceName& out) {
    const size_t colon = s.find(':');
    if (colon == std::string_view::npos || !to_int(s.substr(0, colon), out.entity)) return false;
    const std::string_view face = s.substr(colon + 1);
    if (face.size() == 2 && (face[0] == '+' || face[0] == '-') && face[1] >= 'x' && face[1] <= 'z') {
        out.direction = DVec3(0.0);
        out.direction[face[1] - 'x'] = face[0] == '+' ? 1.0 : -1.0;
        out.index = -1;
        return true;
    }
    return to_int(face, out.index) && out.index >= 0;
}

Result<ScriptStep> face_step(auto step) {
    return step_of<BrushStep>(FaceStep{std::move(step)});
}

Result<ScriptStep> parse_face_select(const LineWords& w) {
    steps::FaceSelect step;
    if (w.size() < 3) return w.fail(w.size(), "expected faces, 'none' or 'brushes'", kFaceUsage);
    if (w.text(2) == "none" || w.text(2) == "brushes") {
        if (auto r = w.need(3, 3, kFaceUsage); !r) return r.error();
        (w.text(2) == "none" ? step.none : step.brushes) = true;
        return face_step(step);
    }
    size_t i = 2;
    const std::string_view mode = w.text(2);
    if (mode == "add" || mode == "toggle" || mode == "remove") {
        step.mode = mode == "add"      ? SelectMode::Add
                    : mode == "toggle" ? SelectMode::Toggle
                                       : SelectMode::Remove;
        ++i;
    }
    for (; i < w.size(); ++i) {
        steps::FaceName name;
        if (!face_name(w.text(i), name))
            return w.fail(i, "expected a face as ID:INDEX or ID:+y (a direction), got '" + w.word(i) + "'",
                          kFaceUsage);
        step.faces.push_back(name);
    }
    if (step.faces.empty()) return w.fail(i, "expected at least one face", kFaceUsage);
    return face_step(step);
}

Result<ScriptStep> parse_pair_edit(const LineWords& w, steps::FaceOp op, bool optional) {
    steps::FaceEditStep step;
    step.op = op;
    if (auto r = w.need(optional ? 2 : 3, 3, kFaceUsage); !r) return r.error();
    if (w.size() == 3 && !face_pair(w.text(2), step.pair))
        return w.fail(2, "expected two numbers, like 1,0.5", kFaceUsage);
    return face_step(step);
}

Result<ScriptStep> parse_number_edit(const LineWords& w, steps::FaceOp op) {
    steps::FaceEditStep step;
    step.op = op;
    if (auto r = w.need(3, 3, kFaceUsage); !r) return r.error();
    if (!to_double(w.text(2), step.number)) return w.fail(2, "expected an angle in degrees", kFaceUsage);
    return face_step(step);
}

} // namespace

Result<ScriptStep> parse_face_line(const LineWords& w) {
    using steps::FaceOp;
    if (w.size() < 2) return w.fail(1, "expected what to do", kFaceUsage);
    const std::string_view what = w.text(1);
    if (what == "select") return parse_face_select(w);
    if (what == "offset") return parse_pair_edit(w, FaceOp::offset, false);
    if (what == "shift") return parse_pair_edit(w, FaceOp::shift, false);
    if (what == "scale") return parse_pair_edit(w, FaceOp::scale, false);
    if (what == "fit") return parse_pair_edit(w, FaceOp::fit, true);
    if (what == "rotation") return parse_number_edit(w, FaceOp::rotation);
    if (what == "turn") return parse_number_edit(w, FaceOp::turn);
    steps::FaceEditStep step;
    if (what == "material") {
        if (auto r = w.need(3, 3, kFaceUsage); !r) return r.error();
        step.op = FaceOp::material, step.word = w.word(2);
    } else if (what == "align") {
        if (auto r = w.need(3, 3, kFaceUsage); !r) return r.error();
        if (!to_int(w.text(2), step.edge)) return w.fail(2, "expected an edge index", kFaceUsage);
        step.op = FaceOp::align;
    } else if (what == "copy" || what == "paste") {
        if (auto r = w.need(2, 2, kFaceUsage); !r) return r.error();
        step.op = what == "copy" ? FaceOp::copy : FaceOp::paste;
    } else if (what == "replace") {
        if (auto r = w.need(4, 4, kFaceUsage); !r) return r.error();
        step.op = FaceOp::replace, step.word = w.word(2), step.other = w.word(3);
    } else if (what == "lock") {
        if (auto r = w.need(3, 3, kFaceUsage); !r) return r.error();
        if (w.text(2) != "on" && w.text(2) != "off") return w.fail(2, "expected on or off", kFaceUsage);
        step.op = FaceOp::lock, step.on = w.text(2) == "on";
    } else {
        return w.fail(1, "unknown face command '" + w.word(1) + "'", kFaceUsage);
    }
    return face_step(step);
}

Result<void> FaceStep::run(ScriptContext& c) const {
    return std::visit([&](const auto& s) { return s.run(c); }, step);
}

namespace steps {

Result<void> FaceSelect::run(ScriptContext& c) const {
    if (none) {
        clear_face_selection(c.editor);
        return ok();
    }
    if (brushes) return select_faces_of_selection(c.editor);
    std::vector<FaceRef> before = c.editor.doc().faces;
    for (size_t i = 0; i < faces.size(); ++i) {
        const FaceName& name = faces[i];
        int index = name.index;
        if (index < 0) {
            const level::Entity* e = c.editor.level().find(name.entity);
            if (!e) return Error("face select: no entity " + std::to_string(name.entity));
            auto facing = face_facing(*e, name.direction);
            if (!facing)
                return Error("face select: " + facing.error().message, Location{}, facing.error().hint);
            index = *facing;
        }
        const SelectMode m = i == 0 ? mode : mode == SelectMode::Replace ? SelectMode::Add : mode;
        if (auto r = select_face(c.editor, name.entity, index, m); !r) {
            c.editor.set_face_selection(std::move(before));
            return r;
        }
    }
    return ok();
}

Result<void> FaceEditStep::run(ScriptContext& c) const {
    Editor& ed = c.editor;
    switch (op) {
    case FaceOp::material:
        return set_face_material(ed, word);
    case FaceOp::offset:
        return set_face_offset(ed, pair);
    case FaceOp::shift:
        return shift_face_offset(ed, pair);
    case FaceOp::scale:
        return set_face_scale(ed, pair);
    case FaceOp::rotation:
        return set_face_rotation(ed, number);
    case FaceOp::turn:
        return turn_face_texture(ed, number);
    case FaceOp::fit:
        return fit_face_texture(ed, pair);
    case FaceOp::align:
        return align_face_texture_to_edge(ed, edge);
    case FaceOp::copy:
        return copy_face_attributes(ed);
    case FaceOp::paste:
        return paste_face_attributes(ed);
    case FaceOp::replace: {
        auto n = replace_texture(ed, word, other);
        if (!n) return n.error();
        return ok();
    }
    case FaceOp::lock:
        set_texture_lock(ed, on);
        return ok();
    }
    return ok();
}

} // namespace steps
} // namespace ks::editor
