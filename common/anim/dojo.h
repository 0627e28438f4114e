#pragma once
// The Dojo's test robot, without the window: number keys start clips (with the clip set's blend times, so
// any key mid-way blends smoothly), and a legend lists the keys and what is playing. The runtime's Dojo
// screen draws `legend()` and feeds `press()`; the editor's dojo panel can drive the same object.
#include "anim/player.h"
#include "core/result.h"

#include <string>
#include <vector>

namespace ks::anim {

struct DojoKey {
    char key = '1';
    std::string clip;
    int index = -1; // in the clip set
};

// The reference Dojo's keys: 1 alert, 2 shoot pose, 3 shooting, 4 shoot pose reverse, 5 death; 0 resets.
std::vector<std::string> reference_dojo_clips();

class DojoController {
  public:
    // `key_clips[i]` is bound to digit i + 1 ('1'...'9'); `reset_clip` (may be empty) to '0'. Every name must
    // exist in `clips`; the error lists the missing ones and the clips there are.
    static Result<DojoController> create(const ClipSet& clips, const Rig& rig,
                                         const std::vector<std::string>& key_clips,
                                         const std::string& reset_clip = "reset");

    // Plays the clip bound to `key`; false (and nothing changes) for an unbound key.
    bool press(char key);
    void advance(double dt) { player_.advance(dt); }
    const Pose& pose() const { return player_.pose(); }
    Player& player() { return player_; }
    const std::vector<DojoKey>& keys() const { return keys_; }
    // One line per key ("1  alert"), then "playing: <clip>  <time> s" (with "(blending)" while blending).
    std::vector<std::string> legend() const;

  private:
    DojoController(const ClipSet& clips, const Rig& rig) : clips_(&clips), player_(clips, rig) {}
    const ClipSet* clips_;
    Player player_;
    std::vector<DojoKey> keys_;
};

} // namespace ks::anim
