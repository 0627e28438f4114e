#pragma once
// What every part of the dojo tab works through (docs/architecture.md, "The editor window's panels"): the
// clip file being edited (model/dojo_edits.h: every change one undo step), the playback (the compiled clips,
// the player, the transport), the selection the parts share (the shown key, event and page), the log, the
// sound audition and the status file's spots. Each part keeps its own widgets' state in its own object;
// DojoPanel owns the shared state and arranges the parts.
#include "core/math.h"
#include "model/dojo_edits.h"
#include "model/dojo_frames.h"
#include "model/dojo_playback.h"
#include "ui/sound_widgets.h"
#include "ui/ui_spots.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

namespace ks::editor::ui {

// The right-hand pages of the dojo tab.
enum class DojoPage : std::uint8_t { Keys, Curves, Blends, Events, Count };
const char* dojo_page_name(DojoPage page); // "keys", "curves", "blends", "events"

// Places the status file reports (window pixels), for tests that click them.
enum class DojoSpot : std::uint8_t {
    AddKey,
    DuplicateKey,
    NewClip,
    ClipNameField,
    ClipDialogOk,
    PageKeys,
    PageCurves,
    PageBlends,
    PageEvents,
    Save,
    Reload,
    ReloadNotice,
    AddEvent,
    QuitCancel,
    QuitDiscard,
    KeyPose,
    AutoKey,
    Ik,
    Count
};
const char* dojo_spot_name(DojoSpot spot);
using DojoSpots = std::array<Vec2, static_cast<size_t>(DojoSpot::Count)>; // centres; (0, 0): not drawn

// What the parts select for one another: the key (phase) shown in the key table, the curve view and the
// timeline; the event selected on the lane or the Events page; the page shown (a part may ask for one).
struct DojoSelection {
    int phase = 0;
    int event = -1;
    DojoPage page = DojoPage::Keys;
    std::string node; // the node posed in the preview and highlighted in the key table (empty: none)
    bool page_requested = false; // select `page`'s tab on the next frame

    void request_page(DojoPage wanted) { page = wanted, page_requested = true; }
};

struct DojoContext {
    DojoEdits& edits;
    DojoPlayback& playback;
    DojoSelection& selection;
    DojoSpots& spots;
    // Widgets a script or test clicks that come and go (a key's radio, a combo's entries, the timeline's
    // diamonds): "key:2", "easing", "combo:Quadratic.InOut", "loop:next", "marker:3", "event_lane", ...
    UiSpots& named;
    const DojoLogFn& log;
    const SoundAudition& audition; // may be unset: no Audition buttons, no event sounds
    const std::filesystem::path& clip_file;

    // The shown clip's definition in the file; null in the transition test's absence of a clip.
    const anim::ClipDef* shown_def() const;
    std::size_t clip_index() const { return static_cast<std::size_t>(playback.clip()); }
    // The playhead within the shown clip's pass (0 in the transition test).
    double clip_time() const;
    // Frames at the shown clip's stored frame rate, or seconds when it stores none (clip_time_units).
    TimeUnits time_units() const {
        const anim::ClipDef* def = shown_def();
        return def ? clip_time_units(*def) : TimeUnits{};
    }
    // An event time as the dojo writes it: a whole frame in frames mode, else a whole millisecond (both
    // read well in the file).
    double event_time(double seconds) const {
        const TimeUnits units = time_units();
        return units.frames ? units.snap(seconds) : std::round(seconds * 1000.0) / 1000.0;
    }
    // Plays clip `index` from the start with its first key and no event selected.
    void show_clip(int index) const;
    // The last ImGui item's centre as `spot` (not while its window appears: a popup is only measured in its
    // first frame, and a click that follows the spot reported then comes too early for it).
    void mark(DojoSpot spot) const;
};

} // namespace ks::editor::ui
