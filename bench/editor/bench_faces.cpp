// ks_bench faces: the face tools and the CSG menu on a level of 2 000 box brushes, headless (the editor's
// model code, no window), against the frame budget (16.7 ms at 60 Hz): replacing a texture across the
// level, a subtract, an intersect, a face edit and a texture-locked move, each with its undo and redo.
#include "bench_registry.h"
#include "brush/brush_build.h"
#include "editor/median_time.h"
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

void row(const char* name, const Timing& t) {
    std::printf("%-44s %9.3f %9.3f %8.2f\n", name, t.run, t.undo_redo, t.undo_redo / kFrameMs);
}

template <class R>
void check(const R& r) {
    if (!r) fail_faces(r.error());
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

    row("replace texture (1000 brushes, 6000 faces)",
        time_step(ed, reps, [&] { check(replace_texture(ed, "metal", "tiles")); }));

    // The cutter through brush 1's corner: one brush cut, the cutter (first in the level) removed.
    const int cutter = 2001;
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
