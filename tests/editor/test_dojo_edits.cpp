// The dojo window's edit state (model/dojo_edits.h): an applied edit is one undo step that marks the file
// dirty and compiles it into the playback; a refused one leaves the file, shows the model's message and
// hint and logs it; a drag is one undo step however many frames change it; an invalid file keeps the last
// good clips playing.
#include "dojo_test_util.h"
#include "model/dojo_clips.h"
#include "model/dojo_edits.h"

#include <string>
#include <vector>

using namespace ks;
using namespace ks::editor;
using ks::dojo_test::index_of;
using ks::dojo_test::shipped_clips;

namespace {
struct Session {
    DojoPlayback playback;
    std::vector<std::string> lines;
    DojoEdits edits{playback, [this](const std::string& line, bool) { lines.push_back(line); }};
    Session() {
        auto rig = anim::build_rig(shipped_clips());
        REQUIRE(rig.ok());
        playback.set_rig(*rig);
        edits.reset(shipped_clips());
        alert = index_of(edits.file(), "alert");
    }
    std::size_t alert = 0;
    std::size_t clips() const { return playback.clips().clips.size(); }
    double alert_length() const { return playback.clips().clips[alert].duration; }
};
} // namespace

TEST_CASE("dojo edits: a fresh file is clean and compiled into the playback") {
    Session s;
    CHECK_FALSE(s.edits.dirty());
    CHECK(s.edits.issues().empty());
    CHECK(s.edits.compile_error().empty());
    REQUIRE(s.playback.has_clips());
    CHECK(s.clips() == s.edits.file().clips.size());
}

TEST_CASE("dojo edits: an applied edit is one undo step, dirty, and reaches the playback") {
    Session s;
    const auto revision = s.edits.revision();
    const std::size_t count = s.clips();
    REQUIRE(
        s.edits.apply("duplicate clip", [&](anim::AnimationFile& f) { return duplicate_clip(f, s.alert); }));
    CHECK(s.edits.dirty());
    CHECK(s.edits.revision() > revision);
    CHECK(s.edits.history().undo_count() == 1);
    CHECK(s.edits.history().undo_name() == "duplicate clip");
    CHECK(s.clips() == count + 1);
    REQUIRE(s.edits.undo());
    CHECK(s.clips() == count);
    REQUIRE(s.edits.redo());
    CHECK(s.clips() == count + 1);
}

TEST_CASE("dojo edits: a refused edit leaves the file, shows the message and hint, and logs it") {
    Session s;
    const std::string before = ks::dojo_test::text(s.edits.file());
    // alert is a required clip: the model refuses to delete it.
    CHECK_FALSE(
        s.edits.apply("delete clip", [&](anim::AnimationFile& f) { return delete_clip(f, s.alert); }));
    CHECK(ks::dojo_test::text(s.edits.file()) == before);
    CHECK(s.edits.history().undo_count() == 0);
    CHECK_FALSE(s.edits.message().empty());
    REQUIRE(s.lines.size() == 1);
    CHECK(s.lines[0].rfind("dojo: ", 0) == 0);
    // The next successful edit clears the message.
    REQUIRE(
        s.edits.apply("duplicate clip", [&](anim::AnimationFile& f) { return duplicate_clip(f, s.alert); }));
    CHECK(s.edits.message().empty());
}

TEST_CASE("dojo edits: a drag is one undo step back to where it began") {
    Session s;
    const std::string before = ks::dojo_test::text(s.edits.file());
    const double first = s.edits.file().clips[s.alert].phases[0].duration, length = s.alert_length();
    for (double d : {0.5, 0.6, 0.7}) {
        s.edits.begin_drag("key duration");
        s.edits.file_in_place().clips[s.alert].phases[0].duration = d;
        s.edits.changed();
    }
    s.edits.end_drag();
    CHECK(s.edits.history().undo_count() == 1);
    CHECK(s.alert_length() == doctest::Approx(length - first + 0.7));
    REQUIRE(s.edits.undo());
    CHECK(ks::dojo_test::text(s.edits.file()) == before);
    // record_drag records the origin given, once per drag.
    anim::AnimationFile edited = s.edits.file();
    edited.clips[s.alert].phases[0].duration = 0.2;
    s.edits.record_drag(s.edits.file(), "drag key 1 of chest");
    s.edits.replace(edited);
    s.edits.record_drag(s.edits.file(), "drag key 1 of chest");
    CHECK(s.edits.history().undo_count() == 1);
}

TEST_CASE("dojo edits: an invalid file keeps the last good clips playing until it is valid again") {
    Session s;
    const double first = s.edits.file().clips[s.alert].phases[0].duration, length = s.alert_length();
    s.edits.begin_drag("key duration");
    s.edits.file_in_place().clips[s.alert].phases[0].duration = -1.0;
    s.edits.changed();
    CHECK_FALSE(s.edits.issues().empty());
    CHECK(s.alert_length() == doctest::Approx(length)); // the last good compile
    s.edits.file_in_place().clips[s.alert].phases[0].duration = first + 0.1;
    s.edits.changed();
    CHECK(s.edits.issues().empty());
    CHECK(s.alert_length() == doctest::Approx(length + 0.1));
}
