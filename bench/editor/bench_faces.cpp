// ks_bench faces: the face tools and the CSG menu on a level of 2 000 box brushes, headless (the editor's
// model code, no window), against the frame budget (16.7 ms at 60 Hz): replacing a texture across the
// level, a subtract, an intersect, a face edit and a texture-locked move, each with its undo and redo. The
// replace and the subtract are timed against the paths they replaced (every changed brush derived again;
// every brush derived into the world to test it against the cutter), reproduced here, and the replace's
// result is checked equal to the old path's.
#include "bench_registry.h"
#include "brush/brush_build.h"
#include "brush/brush_csg.h"
#include "editor/median_time.h"
#include "level/entity_shapes.h"
#include "model/command.h"
#include "model/edit_brushes.h"
#include "model/edit_faces.h"
#include "model/edit_transforms.h"
#include "model/editor.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>

namespace {

using namespace ks;
constexpr double kFrameMs = 1000.0 / 60.0;

void fail_faces(const Error& e) {
    std::fprintf(stderr, "%s\n", e.str().c_str());
    std::exit(1);
}

// `count` 4 x 4 x 4 box brushes on a grid 6 apart, alternately concrete and metal, standing on y = 0.
level::Level brush_level(int count) {
    level::Level lv;
    lv.name = "faces bench";
    const int side = static_cast<int>(std::ceil(std::sqrt(double(count))));
    for (int i = 0; i < count; ++i) {
        brush::FaceAttributes look;
        look.material = i % 2 ? "metal" : "concrete";
        auto box = brush::make_box({-2, 0, -2}, {2, 4, 2}, look);
        if (!box) fail_faces(box.error());
        level::Entity e;
        e.id = i + 1;
        e.position = Vec3(float(i % side) * 6.0f, 0.0f, float(i / side) * 6.0f);
        e.props = level::BrushProps{*box};
        lv.entities.push_back(std::move(e));
    }
    // The cutter: a 2 x 2 x 2 box over brush 1's corner, first in the level, so that removing it and
    // putting it back moves every other entity (the costly case of an undo).
    brush::FaceAttributes wood;
    wood.material = "wood";
    auto cutter = brush::make_box({-1, -1, -1}, {1, 1, 1}, wood);
    if (!cutter) fail_faces(cutter.error());
    level::Entity c;
    c.id = count + 1;
    c.position = Vec3(2.0f, 1.0f, 2.0f);
    c.props = level::BrushProps{*cutter};
    lv.entities.insert(lv.entities.begin(), std::move(c));
    lv.next_id = count + 2;
    return lv;
}

struct Timing {
    double run, undo_redo;
};

// The edit (undone between runs), and an undo followed by a redo, each the median of `reps`.
Timing time_step(editor::Editor& ed, int reps, const std::function<void()>& edit) {
    Timing t{};
    t.run = bench::median_ms(reps, [&] {
        edit();
        ed.undo();
    });
    edit();
    t.undo_redo = bench::median_ms(reps, [&] {
        ed.undo();
        ed.redo();
    });
    ed.undo();
    return t;
}

template <class R>
void check(const R& r) {
    if (!r) fail_faces(r.error());
}

// Replace texture as it was: every changed brush rebuilt from its planes (derived again), one step.
void replace_rederiving(editor::Editor& ed, const std::string& from, const std::string& to) {
    auto change = std::make_unique<editor::LevelChange>();
    for (const level::Entity& e : ed.level().entities) {
        const auto* props = e.try_as<level::BrushProps>();
        if (!props) continue;
        std::vector<brush::Face> faces = props->brush.anchored_faces();
        bool here = false;
        for (brush::Face& f : faces)
            if (f.attributes.material == from) f.attributes.material = to, here = true;
        if (!here) continue;
        auto rebuilt = brush::Brush::from_anchored_faces(props->brush.anchor(), std::move(faces));
        if (!rebuilt) fail_faces(rebuilt.error());
        level::Entity after = e;
        after.as<level::BrushProps>().brush = std::move(*rebuilt);
        change->updates.push_back({e, std::move(after)});
    }
    change->set_name("Replace texture");
    ed.execute(std::move(change), ed.doc().selection);
}

// What subtract cost before its bounds test: every other brush taken into the world and cut.
void subtract_all_derived(const editor::Editor& ed, int cutter_id) {
    auto cutter = level::world_brush(*ed.level().find(cutter_id));
    if (!cutter) fail_faces(cutter.error());
    size_t cut = 0;
    for (const level::Entity& e : ed.level().entities) {
        if (e.id == cutter_id || !e.try_as<level::BrushProps>()) continue;
        auto world = level::world_brush(e);
        if (!world) fail_faces(world.error());
        auto result = brush::subtract(*world, *cutter);
        if (!result) fail_faces(result.error());
        cut += result->removed ? 1 : 0;
    }
    if (cut != 1) fail_faces(Error("the old subtract path cut " + std::to_string(cut) + " brushes, not 1"));
}

// The fast replace and the re-deriving one leave the same level (brushes compared face by face and by
// their derived vertices).
void check_replace_equal(editor::Editor& ed) {
    check(editor::replace_texture(ed, "metal", "tiles"));
    const level::Level fast = ed.level();
    ed.undo();
    replace_rederiving(ed, "metal", "tiles");
    const level::Level slow = ed.level();
    ed.undo();
    bool same = fast.entities.size() == slow.entities.size();
    for (size_t i = 0; same && i < fast.entities.size(); ++i) {
        same = fast.entities[i] == slow.entities[i];
        const auto* a = fast.entities[i].try_as<level::BrushProps>();
        const auto* b = slow.entities[i].try_as<level::BrushProps>();
        if (same && a && b) same = a->brush.vertices() == b->brush.vertices();
    }
    if (!same) fail_faces(Error("replace texture: the fast path's level differs from the re-deriving one"));
}

void row(const char* name, const Timing& t) {
    std::printf("%-44s %9.3f %9.3f %8.2f\n", name, t.run, t.undo_redo, t.undo_redo / kFrameMs);
}

int run_faces(int argc, const char* const* argv) {
    bool quick = false;
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "--quick")) quick = true;
    const int reps = quick ? 3 : 9;
    editor::Editor ed;
    ed.replace_level(brush_level(2000), {}, {});
    std::printf("faces benchmark: face tools and CSG in the editor model (no window)\n\n");
    std::printf("on a level of %zu box brushes (2000 and a cutter); median of %d; frame = %.1f ms\n",
                ed.level().entities.size(), reps, kFrameMs);
    std::printf("%-44s %9s %9s %8s\n", "operation", "edit ms", "undo+redo", "frames");

    check_replace_equal(ed);
    row("replace texture, re-deriving (before)",
        time_step(ed, reps, [&] { replace_rederiving(ed, "metal", "tiles"); }));
    row("replace texture (1000 brushes, 6000 faces)",
        time_step(ed, reps, [&] { check(replace_texture(ed, "metal", "tiles")); }));

    // The cutter through brush 1's corner: one brush cut, the cutter (first in the level) removed.
    const int cutter = 2001;
    std::printf("%-44s %9.3f %9s\n", "subtract, every brush derived (before)",
                bench::median_ms(reps, [&] { subtract_all_derived(ed, cutter); }), "-");
    row("subtract (one cutter, 2000 brushes looked at)", time_step(ed, reps, [&] {
            ed.set_selection({cutter});
            check(editor::subtract_selected_brushes(ed));
        }));
    row("intersect (two brushes)", time_step(ed, reps, [&] {
            ed.set_selection({1, cutter});
            check(editor::intersect_selected_brushes(ed));
        }));
    check(editor::select_face(ed, 2, 0));
    row("set one face's material",
        time_step(ed, reps, [&] { check(editor::set_face_material(ed, "wood")); }));
    check(editor::select_faces_of_selection(ed));
    row("fit the faces of two brushes", time_step(ed, reps, [&] { check(editor::fit_face_texture(ed)); }));
    std::vector<int> hundred;
    for (int id = 1; id <= 100; ++id) hundred.push_back(id);
    editor::set_texture_lock(ed, true);
    row("move 100 brushes, texture lock on", time_step(ed, reps, [&] {
            ed.set_selection(hundred);
            check(editor::move_selection(ed, {1, 0, 0}));
        }));
    editor::set_texture_lock(ed, false);
    row("move 100 brushes, texture lock off", time_step(ed, reps, [&] {
            ed.set_selection(hundred);
            check(editor::move_selection(ed, {1, 0, 0}));
        }));
    return 0;
}

const bench::Registrar registrar({"faces",
                                  "face tools and CSG on 2000 brushes: replace texture, subtract, intersect, "
                                  "face edits, texture lock; each with undo/redo (--quick)",
                                  run_faces});

} // namespace
