// The dojo panel's key edits, history and save, on the shipped robot clips (read-only; saves go to a
// scratch copy, never to assets/animations/robot.json).
#include "anim/clip_io.h"
#include "anim/player.h"
#include "core/files.h"
#include "model/dojo_keys.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <string>

using namespace ks;

namespace {

std::filesystem::path shipped() {
    return test::source_dir() / "assets" / "animations" / "robot.json";
}

anim::AnimationFile load_shipped_clips() {
    auto loaded = anim::load_animation_file(shipped());
    REQUIRE(loaded);
    REQUIRE(!loaded->clips.empty());
    REQUIRE(!loaded->clips[0].phases.empty());
    return *loaded;
}

bool has_key(const anim::AnimationFile& f, std::size_t clip, std::size_t phase, const std::string& node) {
    for (const auto& t : f.clips[clip].phases[phase].targets)
        if (t.node == node) return true;
    return false;
}

std::size_t clip_index(const anim::AnimationFile& f, const std::string& name) {
    for (std::size_t i = 0; i < f.clips.size(); ++i)
        if (f.clips[i].name == name) return i;
    FAIL("no clip " << name);
    return 0;
}

// The pose a file's clip ends in: compiled against the file's own rig, played without a blend to its end.
anim::Pose final_pose(const anim::AnimationFile& f, const std::string& clip) {
    auto rig = anim::build_rig(f);
    REQUIRE(rig);
    auto clips = anim::compile(f, *rig);
    REQUIRE(clips);
    anim::Player player(*clips, *rig);
    player.play(clips->find(clip), 0.0f);
    player.advance(f.clips[clip_index(f, clip)].duration() + 0.5);
    CHECK(player.finished());
    return player.pose();
}

} // namespace

TEST_CASE("dojo keys: duplicate, move and remove a whole key (phase); refusals leave the file unchanged") {
    auto file = load_shipped_clips();
    const std::string original = anim::save_animation_string(file);
    const std::size_t idle = clip_index(file, "idle");
    const std::size_t phases = file.clips[idle].phases.size();
    REQUIRE(phases >= 2);
    const double duration = file.clips[idle].duration();

    auto copy = editor::duplicate_phase(file, idle, 1);
    REQUIRE(copy);
    CHECK(*copy == 2);
    CHECK(file.clips[idle].phases.size() == phases + 1);
    CHECK(file.clips[idle].duration() == doctest::Approx(duration + file.clips[idle].phases[1].duration));
    CHECK(anim::validate(file).empty());
    // the copy is the phase itself, targets and easing included
    CHECK(file.clips[idle].phases[2].targets.size() == file.clips[idle].phases[1].targets.size());
    REQUIRE(editor::remove_phase(file, idle, 2));
    CHECK(anim::save_animation_string(file) == original);

    // a move there and back is no change; each step swaps neighbours
    const std::string first_key_node = file.clips[idle].phases[0].targets.front().node;
    auto later = editor::move_phase(file, idle, 0, +1);
    REQUIRE(later);
    CHECK(*later == 1);
    CHECK(file.clips[idle].phases[1].targets.front().node == first_key_node);
    CHECK(anim::validate(file).empty());
    auto back = editor::move_phase(file, idle, 1, -1);
    REQUIRE(back);
    CHECK(*back == 0);
    CHECK(anim::save_animation_string(file) == original);

    // refusals: out of range, past either end, more than one place, the last remaining key
    CHECK(!editor::duplicate_phase(file, idle, phases));
    CHECK(!editor::duplicate_phase(file, file.clips.size(), 0));
    CHECK(!editor::remove_phase(file, idle, phases));
    CHECK(!editor::move_phase(file, idle, 0, -1));
    CHECK(!editor::move_phase(file, idle, phases - 1, +1));
    CHECK(!editor::move_phase(file, idle, 0, 2));
    const std::size_t reset = clip_index(file, "reset");
    REQUIRE(file.clips[reset].phases.size() == 1);
    auto last = editor::remove_phase(file, reset, 0);
    REQUIRE(!last);
    CHECK(last.error().hint.find("at least one key") != std::string::npos);
    CHECK(anim::save_animation_string(file) == original);
}

TEST_CASE("dojo keys: a duplicated key of absolute targets holds the pose; the clip ends where it did") {
    auto file = load_shipped_clips();
    const std::size_t shoot = clip_index(file, "shoot_pose");
    REQUIRE(file.clips[shoot].loop == anim::LoopMode::Once);
    for (const auto& t : file.clips[shoot].phases.back().targets)
        REQUIRE((!t.add_rot && !t.add_pos)); // absolute keys only, so a copy has nowhere new to go
    const anim::Pose before = final_pose(file, "shoot_pose");
    const double duration = file.clips[shoot].duration();

    REQUIRE(editor::duplicate_phase(file, shoot, file.clips[shoot].phases.size() - 1));
    CHECK(file.clips[shoot].duration() > duration);
    const anim::Pose after = final_pose(file, "shoot_pose");
    REQUIRE(after.size() == before.size());
    for (int n = 0; n < before.size(); ++n) {
        const auto i = static_cast<std::size_t>(n);
        CHECK(glm::length(after.euler[i] - before.euler[i]) < 1e-5f);
        CHECK(glm::length(after.position[i] - before.position[i]) < 1e-5f);
    }
}

TEST_CASE("dojo keys: add a node's key, refuse bad requests unchanged, remove it again") {
    auto file = load_shipped_clips();
    const std::string original = anim::save_animation_string(file);
    const auto free_nodes = editor::unkeyed_nodes(file, 0, 0);
    REQUIRE(!free_nodes.empty());
    const std::string node = free_nodes.front();
    CHECK(!has_key(file, 0, 0, node));

    const DVec3 reached = editor::key_values(file, 0, node, false).front();
    REQUIRE(editor::add_node_key(file, 0, 0, node));
    CHECK(has_key(file, 0, 0, node));
    const auto& added = file.clips[0].phases[0].targets.back();
    CHECK(added.node == node);
    REQUIRE(added.rot);
    CHECK(*added.rot == reached); // an absolute key where the node is: no pose changes
    CHECK(!added.add_rot);
    CHECK(anim::validate(file).empty());
    CHECK(editor::unkeyed_nodes(file, 0, 0).size() == free_nodes.size() - 1);

    const std::string with_key = anim::save_animation_string(file);
    auto twice = editor::add_node_key(file, 0, 0, node);
    REQUIRE(!twice);
    CHECK(twice.error().message.find("already has a key") != std::string::npos);
    auto unknown = editor::add_node_key(file, 0, 0, "no_such_node");
    REQUIRE(!unknown);
    CHECK(unknown.error().message.find("not in the rig") != std::string::npos);
    CHECK(!editor::add_node_key(file, file.clips.size(), 0, node));
    CHECK(!editor::add_node_key(file, 0, file.clips[0].phases.size(), node));
    CHECK(!editor::remove_node_key(file, 0, 0, "no_such_node"));
    CHECK(anim::save_animation_string(file) == with_key); // every refusal left the file as it was

    REQUIRE(editor::remove_node_key(file, 0, 0, node));
    CHECK(anim::save_animation_string(file) == original);
    CHECK(editor::unkeyed_nodes(file, 99, 0).empty());
}

TEST_CASE("dojo keys: undo and redo restore the file exactly, a new edit drops the redo steps") {
    auto file = load_shipped_clips();
    const std::string original = anim::save_animation_string(file);
    editor::DojoHistory history;
    CHECK(!history.undo(file));
    CHECK(!history.redo(file));

    const std::string node = editor::unkeyed_nodes(file, 0, 0).front();
    history.record(file, "add key " + node);
    REQUIRE(editor::add_node_key(file, 0, 0, node));
    const std::string added = anim::save_animation_string(file);
    // remove an existing key of another phase (or the same one) as a second step
    const std::string existing = file.clips[0].phases[0].targets.front().node;
    history.record(file, "remove key " + existing);
    REQUIRE(editor::remove_node_key(file, 0, 0, existing));
    const std::string removed = anim::save_animation_string(file);
    CHECK(history.undo_name() == "remove key " + existing);

    REQUIRE(history.undo(file));
    CHECK(anim::save_animation_string(file) == added);
    REQUIRE(history.undo(file));
    CHECK(anim::save_animation_string(file) == original);
    CHECK(!history.can_undo());
    REQUIRE(history.redo(file));
    REQUIRE(history.redo(file));
    CHECK(anim::save_animation_string(file) == removed);
    CHECK(!history.can_redo());

    REQUIRE(history.undo(file));
    CHECK(history.can_redo());
    history.record(file, "another edit");
    CHECK(!history.can_redo());
}

TEST_CASE("dojo keys: save validates and writes a scratch copy atomically; an invalid file is not written") {
    test::ScratchDir dir;
    const auto copy = dir / "robot.json";
    auto shipped_text = files::read_text(shipped());
    REQUIRE(shipped_text);
    REQUIRE(files::write_atomic(copy, *shipped_text));

    auto loaded = anim::load_animation_file(copy);
    REQUIRE(loaded);
    anim::AnimationFile file = *loaded;
    const std::string node = editor::unkeyed_nodes(file, 0, 0).front();
    REQUIRE(editor::add_node_key(file, 0, 0, node));
    REQUIRE(editor::save_dojo_file(copy, file));
    auto reloaded = anim::load_animation_file(copy);
    REQUIRE(reloaded);
    CHECK(has_key(*reloaded, 0, 0, node));
    CHECK(anim::save_animation_string(*reloaded) == anim::save_animation_string(file));
    // no temporary left beside it
    int entries = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++entries;
    CHECK(entries == 1);

    const auto good_text = files::read_text(copy);
    REQUIRE(good_text);
    file.clips[0].phases[0].duration = -1.0;
    auto refused = editor::save_dojo_file(copy, file);
    REQUIRE(!refused);
    CHECK(refused.error().where.file == copy.string());
    CHECK(!refused.error().where.path.empty());
    CHECK(refused.error().message.find("not saved") != std::string::npos);
    CHECK(*files::read_text(copy) == *good_text); // the file on disk is untouched

    CHECK(*files::read_text(shipped()) == *shipped_text); // and the shipped file was never written
}
