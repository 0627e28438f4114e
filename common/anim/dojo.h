#pragma once
// The Dojo's test robot, without the window: number keys start clips (with the clip set's blend times, so
// any key mid-way blends smoothly), every other clip of the set can be started from the list, and a legend
// lists them and what is playing. The runtime's Dojo screen draws `legend()` / `entries()` and feeds
// `press()` and `play_entry()`.
//
// As the reference's test robot, every clip starts with the root at rest: the controller plays a copy of
// the clips in which the root nodes' channels are anchored to the rig's rest (a relative key such as the
// death clip's spin and tip-over counts from the rest, and a clip that does not move the root holds it
// there). So after the death clip the robot stands up again for the next key, and a second death falls
// the same way. The root eases home within the key's blend time, like every other node.
#include "anim/player.h"
#include "core/result.h"

#include <memory>
#include <string>
#include <vector>

namespace ks::anim {

// One clip in the Dojo's list. `key` is its digit ('1'...'9', '0' for the reset clip), or 0 when the clip
// has no key and is started from the list only.
struct DojoKey {
    char key = '1';
    std::string clip;
    int index = -1; // in the clip set
};

// The reference Dojo's keys: 1 alert, 2 shoot pose, 3 shooting, 4 shoot pose reverse, 5 death; 0 resets.
std::vector<std::string> reference_dojo_clips();

// The runtime Dojo's keys for `clips`: the reference's five on 1-5 (always: a set without one of them is
// refused by create()), then the set's other clips in file order on 6-9, leaving out `reset_clip` (key 0).
// The clips past key 9 stay in the list without a key.
std::vector<std::string> dojo_key_clips(const ClipSet& clips, const std::string& reset_clip = "reset");

// `clips` with every root node of `rig` anchored to its rest: relative root keys count from the rest and a
// clip without a root channel holds the root at rest. The blend table and events are unchanged.
ClipSet anchor_root_to_rest(const ClipSet& clips, const Rig& rig);

class DojoController {
  public:
    // `key_clips[i]` is bound to digit i + 1 ('1'...'9'); `reset_clip` (may be empty) to '0'. Every name must
    // exist in `clips`; the error lists the missing ones and the clips there are. The set's other clips are
    // listed too, without a key. `rig` must outlive the controller (the clips are copied).
    static Result<DojoController> create(const ClipSet& clips, const Rig& rig,
                                         const std::vector<std::string>& key_clips,
                                         const std::string& reset_clip = "reset");

    // Plays the clip bound to `key`; false (and nothing changes) for an unbound key.
    bool press(char key);
    // Plays entry `entry` of entries() (keyed or not); false for an index out of range.
    bool play_entry(std::size_t entry);
    void advance(double dt) { player_->advance(dt); }
    const Pose& pose() const { return player_->pose(); }
    Player& player() { return *player_; }
    const Player& player() const { return *player_; }
    // Every clip of the set: the keyed ones 1-9 in key order, then those without a key in file order, then
    // the reset clip on 0.
    const std::vector<DojoKey>& entries() const { return entries_; }
    // The entry of the clip playing (also one reached by a `next` hand-over), or -1 when nothing plays.
    int playing_entry() const;
    // One line per entry ("1  alert", "   wave" for a clip without a key), then "playing: <clip>  <time> s"
    // (with "(blending)" while blending).
    std::vector<std::string> legend() const;
    // The line of entries()[i] in legend().
    static std::string entry_line(const DojoKey& entry);

  private:
    DojoController() = default;
    // The anchored clips (anchor_root_to_rest) the player plays; on the heap so that a moved controller's
    // player still refers to them.
    std::unique_ptr<const ClipSet> anchored_;
    std::unique_ptr<Player> player_;
    std::vector<DojoKey> entries_;
};

} // namespace ks::anim
